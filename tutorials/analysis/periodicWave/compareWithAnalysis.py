#!/usr/bin/env python3
"""Per-step amplification measured in an mpmFoam run against the spectral
analysis (mpmStabilityAnalysis) for the same shape, alpha, scheme and CFL.

With one point per cell on a periodic lattice, a Fourier mode of the point
velocity v_n (complex projection sum v_p exp(-i k x_p)) obeys the two-term
recurrence v_{n+2} = t v_{n+1} - d v_n of the 2x2 (velocity, stress) symbol,
with t = G1 + G2, d = G1 G2. A least-squares fit of t, d over all steps gives
the measured eigenvalues G1, G2; they are compared with the analysis.

Usage: compareWithAnalysis.py <case> <tool> [--tol 1e-6]
Prints one line per eigenvalue and exits 1 if any |G| differs by more than tol.
"""
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np

import mpmPost


def read_setting(case, key):
    with open(os.path.join(case, "constant", "mpmProperties")) as f:
        for line in f:
            parts = line.split()
            if parts and parts[0] == key:
                return parts[1].rstrip(";")
    raise KeyError(key)


def main():
    case, tool = sys.argv[1], sys.argv[2]
    tol = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 1e-6
    shape = {"linearHat": "LH", "quadraticBSpline": "QBS", "cubicBSpline": "CBS"}[read_setting(case, "shapeFunction")]
    alpha = float(read_setting(case, "flipRatio"))
    scheme = read_setting(case, "stressUpdate")
    with open(os.path.join(case, "system", "controlDict")) as f:
        dt = float([l.split()[1].rstrip(";") for l in f if l.split()[:1] == ["deltaT"]][0])
    cfl = dt   # c = h = 1

    times = mpmPost.times(case)
    x = mpmPost.read_positions(case, times[0])[:, 0]
    L = 16.0
    k = 2*np.pi*2/L
    vhat = []
    for t in times:
        u = mpmPost.read_cloud_field(case, t, "U")[:, 0]
        vhat.append(np.sum(u*np.exp(-1j*k*x)))
    vhat = np.array(vhat)
    # Lattice nodes sit at cell centres (docs/gridDesign.md): a point's
    # offset in its lattice cell is measured from the node at x = h/2.
    offsets = sorted(set(np.mod(np.round(np.mod(x - 0.5, 1.0), 12), 1.0)))
    offsets_arg = ",".join(repr(float(o)) for o in offsets)
    # v_{n+2} = t v_{n+1} - d v_n, real t and d, fitted on real and imaginary parts
    A = np.r_[np.c_[vhat[1:-1].real, -vhat[:-2].real], np.c_[vhat[1:-1].imag, -vhat[:-2].imag]]
    b = np.r_[vhat[2:].real, vhat[2:].imag]
    (tr, det), *_ = np.linalg.lstsq(A, b, rcond=None)
    measured = np.roots([1, -tr, det])

    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "g.csv")
        subprocess.run([tool, "--model", "wave", "--shape", shape, "--alpha", repr(alpha), "--scheme", scheme,
                        "--offsets", offsets_arg, "--CFL", repr(cfl), "--nk", "8", "--csv", out],
                       check=True, stdout=subprocess.DEVNULL)
        with open(out) as f:
            rows = [r for r in csv.DictReader(f) if abs(float(r["kh"]) - k) < 1e-9]
    predicted = np.array([complex(float(r["Gre"]), float(r["Gim"])) for r in rows])

    worst = 0.0
    for g in sorted(measured, key=lambda z: (z.imag, z.real)):
        p = predicted[np.argmin(np.abs(predicted - g))]
        rel = abs(abs(g) - abs(p))/max(abs(p), 1e-300)
        worst = max(worst, rel)
        print(f"{shape} alpha={alpha:g} {scheme} CFL={cfl:g} offsets={offsets_arg} kh=pi/4: measured G = {g.real:+.12f}{g.imag:+.12f}i "
              f"|G| = {abs(g):.12f}, analysis |G| = {abs(p):.12f}, relative difference {rel:.3e}")
    print(f"worst relative |G| difference {worst:.3e} (tolerance {tol:g})")
    sys.exit(0 if worst <= tol else 1)


if __name__ == "__main__":
    main()
