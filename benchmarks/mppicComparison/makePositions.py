#!/usr/bin/env python3
"""Writes the MPPICFoam parcel positions of mppicCase at the places where
mpmSetParticles seeds the MPM material points of mpmCase, and sets the
parcels' nParticle so that each parcel carries the same solid volume as a
material point.

mpmSetParticles (box region, pointsPerCell n, offset 0) puts n points per
direction in every cell whose centre is inside the box, at
    x = x_cell_min + (i + 0.5) h/n,  i = 0..n-1,
and gives each the solid volume solidFraction h^3/n^3. A parcel of
nParticle grains of diameter d carries nParticle pi d^3/6.

Usage:
    makePositions.py CASE [--min X Y Z] [--max X Y Z] [--h H] [--ppc N]
                          [--solid-fraction A] [--d D] [--check MPM_POSITIONS]
Writes CASE/constant/kinematicCloudPositions and edits nParticle in
CASE/constant/kinematicCloudProperties. --check compares the positions with
an mpmFoam cloud file (0/lagrangian/materialPoints/positions, ascii) and
fails if they differ by more than 1e-9 m.
"""
import argparse
import math
import re
import sys

import numpy as np


def bed_positions(lo, hi, h, ppc):
    """Sub-cell points of every cell whose centre is inside [lo, hi]."""
    axes = []
    for k in range(3):
        ncell = int(round((hi[k] - lo[k])/h))
        cells = lo[k] + h*np.arange(ncell)
        sub = (np.arange(ppc) + 0.5)*h/ppc
        axes.append((cells[:, None] + sub[None, :]).ravel())
    X, Y, Z = np.meshgrid(*axes, indexing="ij")
    return np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])


def read_mpm_positions(path):
    pts = []
    pat = re.compile(r"^\(([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+)\)")
    with open(path) as f:
        for line in f:
            m = pat.match(line)
            if m:
                pts.append([float(v) for v in m.groups()])
    return np.array(pts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--min", type=float, nargs=3, default=[0.0, 0.0, 0.0])
    ap.add_argument("--max", type=float, nargs=3, default=[0.1, 0.1, 0.02])
    ap.add_argument("--h", type=float, default=0.005, help="cell size [m]")
    ap.add_argument("--ppc", type=int, default=2, help="points per cell per direction")
    ap.add_argument("--solid-fraction", type=float, default=0.5)
    ap.add_argument("--d", type=float, default=5e-4, help="grain diameter [m]")
    ap.add_argument("--check", help="mpmFoam positions file to compare with")
    a = ap.parse_args()

    pts = bed_positions(a.min, a.max, a.h, a.ppc)
    with open(f"{a.case}/constant/kinematicCloudPositions", "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class vectorField; "
                "object kinematicCloudPositions; }\n")
        f.write(f"// {len(pts)} parcels, written by makePositions.py\n{len(pts)}\n(\n")
        for p in pts:
            f.write(f"({p[0]:.9g} {p[1]:.9g} {p[2]:.9g})\n")
        f.write(")\n")

    vpoint = a.solid_fraction*a.h**3/a.ppc**3
    nparticle = vpoint/(math.pi*a.d**3/6)
    props = f"{a.case}/constant/kinematicCloudProperties"
    text = open(props).read()
    text, n = re.subn(r"(nParticle\s+)[0-9.eE+-]+;", rf"\g<1>{nparticle:.9g};", text)
    if n != 1:
        sys.exit(f"makePositions.py: no single nParticle entry in {props}")
    open(props, "w").write(text)
    print(f"makePositions: {len(pts)} parcels, solid volume {vpoint:.6g} m^3 each, "
          f"nParticle {nparticle:.6g} grains of d = {a.d:g} m")

    if a.check:
        mpm = read_mpm_positions(a.check)
        if len(mpm) != len(pts):
            sys.exit(f"makePositions: {len(mpm)} material points but {len(pts)} parcels")
        key = lambda q: np.lexsort((q[:, 2], q[:, 1], q[:, 0]))  # noqa: E731
        err = np.abs(mpm[key(mpm)] - pts[key(pts)]).max()
        if err > 1e-9:
            sys.exit(f"makePositions: positions differ from {a.check} by {err:g} m")
        print(f"makePositions: same {len(pts)} positions as the material points "
              f"(max difference {err:.2g} m)")


if __name__ == "__main__":
    main()
