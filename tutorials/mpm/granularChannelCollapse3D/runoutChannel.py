#!/usr/bin/env python3
"""Runout of the channel collapses of sweepChannel, and the side walls' effect.

    python3 runoutChannel.py runs/h0.02_W0.2_slip runs/h0.02_W0.2_0.45 ...

For each case (a run directory with the file `channel`: h, W, side wall,
shape): the front L_f at the last write time is the x behind which 99.9 %
of the mass lies (plotProfile.mass_front of ../granularColumnCollapse, the
2D flagship's measure), the runout (L_f - a0)/a0 with a0 = 0.2 m. Printed
beside it: the same front of the half of the points nearer the centre plane
(y < W/4) and of the half nearer the side wall (y > W/4), the front's
advance over the last write interval (at rest: small), the final height
H_f/h0 (top point + half a point spacing), the count and mass of the points
against the seeded ones (log.mpmSetParticles), and the mpmFoam CPU time
(log.mpmFoam, "ExecutionTime"). ratio: the runout over that of the
slip-side-wall run (plane strain) of the same h, W and shape, when it is
among the cases. Writes runoutChannel.csv.
"""
import os
import re
import sys

import numpy as np

import mpmPost

A0, H0 = 0.2, 0.4
FRACTION = 0.999


def mass_front(x, m, fraction=FRACTION):
    """The x behind which `fraction` of the mass lies (as plotProfile.py)."""
    order = np.argsort(x)
    cumulative = np.cumsum(m[order])/m.sum()
    return float(x[order[min(np.searchsorted(cumulative, fraction), len(order) - 1)]])


def seeded(case):
    text = open(os.path.join(case, "log.mpmSetParticles")).read()
    n, mass = re.findall(r"Writing (\d+) material points \(total mass ([^)]*)\)", text)[-1]
    return int(n), float(mass)


def cpu(case):
    text = open(os.path.join(case, "log.mpmFoam")).read()
    t = re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", text)
    return float(t[-1]) if t else float("nan")


def measure(case):
    words = open(os.path.join(case, "channel")).read().split()
    c = dict(zip(words[0::2], words[1::2]))
    h, W = float(c["h"]), float(c["W"])
    ts = mpmPost.times(case)
    if len(ts) < 2:
        sys.exit("runoutChannel.py: %s: fewer than two write times" % case)
    fronts = []
    for t in ts[-2:]:
        x = mpmPost.read_positions(case, t)
        m = mpmPost.read_cloud_field(case, t, "mass")
        fronts.append(mass_front(x[:, 0], m))
    Lf = fronts[-1]
    inner = x[:, 1] < W/4
    n0, m0 = seeded(case)
    return dict(case=case, h=h, W=W, wall=c["wall"], shape=c["shape"], t=float(ts[-1]), n=len(x), n0=n0,
                mass=float(m.sum()), mass0=m0, Lf=Lf, runout=(Lf - A0)/A0,
                runout_centre=(mass_front(x[inner, 0], m[inner]) - A0)/A0,
                runout_wall=(mass_front(x[~inner, 0], m[~inner]) - A0)/A0,
                dLf=fronts[-1] - fronts[-2], Hf=(x[:, 2].max() + h/4)/H0, cpu=cpu(case))


def main():
    rows = [measure(c) for c in sys.argv[1:]]
    slip = {(d["h"], d["W"], d["shape"]): d["runout"] for d in rows if d["wall"] == "slip"}
    print("%-30s %6s %5s %6s %5s %7s %6s %7s %7s %7s %8s %6s %7s %6s %7s"
          % ("case", "h", "W", "wall", "shape", "points", "t_end", "runout", "ratio", "centre", "wallHalf",
             "dLf", "Hf/h0", "dMass", "cpu_s"))
    for d in rows:
        ref = slip.get((d["h"], d["W"], d["shape"]))
        d["ratio"] = d["runout"]/ref if ref else float("nan")
        print("%-30s %6.4f %5.3f %6s %5s %7d %6.2f %7.3f %7.3f %7.3f %8.3f %6.4f %7.3f %6.0e %7.1f"
              % (os.path.basename(d["case"].rstrip("/")), d["h"], d["W"], d["wall"], d["shape"][:5], d["n"],
                 d["t"], d["runout"], d["ratio"], d["runout_centre"], d["runout_wall"], d["dLf"], d["Hf"],
                 d["mass"]/d["mass0"] - 1, d["cpu"]))
        if d["n"] != d["n0"]:
            print("  WARNING: %d points at the end, %d seeded" % (d["n"], d["n0"]))
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "runoutChannel.csv"), "w") as f:
        f.write("case,h,W,wall,shape,points,seeded,t_end,L_f,runout,ratio,runout_centre,runout_wall,dLf_last,"
                "Hf_over_h0,mass,seeded_mass,cpu_s\n")
        for d in rows:
            f.write("%s,%g,%g,%s,%s,%d,%d,%g,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.8g,%.8g,%.1f\n"
                    % (d["case"], d["h"], d["W"], d["wall"], d["shape"], d["n"], d["n0"], d["t"], d["Lf"],
                       d["runout"], d["ratio"], d["runout_centre"], d["runout_wall"], d["dLf"], d["Hf"],
                       d["mass"], d["mass0"], d["cpu"]))


if __name__ == "__main__":
    main()
