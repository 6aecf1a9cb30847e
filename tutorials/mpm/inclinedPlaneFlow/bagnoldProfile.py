#!/usr/bin/env python3
"""Steady velocity profile of an inclined-plane case against Bagnold's.

For a layer of depth H on a rough incline at angle theta, with p = rho g
cos(theta) (H - z) and tau/p = tan(theta) everywhere, mu(I) = tan(theta)
fixes the inertial number,

    I(theta) = I0 (tan(theta) - muS)/(mu2 - tan(theta)),

so the shear rate is gammaDot = I sqrt(p/rhoS)/d and the velocity
(u = 0 on the base) is Bagnold's profile

    u(z) = (2 I/(3 d)) sqrt(g cos(theta) rho/rhoS) (H^(3/2) - (H - z)^(3/2)).

rho is the bulk density of the points, rhoS the grain density. Every
parameter is read from the case: the law's coefficients from the solver's
echo in log.mpmFoam (so the defaults count), theta and g from constant/g,
H from the seeded box (system/mpmSetParticlesDict).

The profile error is the rms over the points of u_x - u(y), divided by the
exact surface velocity u(H), at the last write; the error at the write
before is printed too, to show that the flow is steady.

    bagnoldProfile.py [--plot FILE] CASE...
prints one line per case and, with --plot, draws the profiles.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

import mpmPost


def law_coefficients(case):
    """Coefficients of the (single) muIRheology material, as echoed by the
    solver in log.mpmFoam."""
    text = open(os.path.join(case, "log.mpmFoam")).read()
    start = re.search(r"^Material \w+: muIRheology", text, re.M)
    if start is None:
        raise ValueError("%s: no muIRheology material in log.mpmFoam" % case)
    coeffs = {}
    for line in text[start.end():].splitlines()[1:]:
        m = re.match(r"^    (\w+) ([-+0-9.eE]+)", line)
        if m is None:
            break
        coeffs[m.group(1)] = float(m.group(2))
    return coeffs


def gravity(case):
    """(|g|, theta [rad]) from constant/g = |g| (sin theta, -cos theta, 0)."""
    text = re.sub(r"//.*", "", open(os.path.join(case, "constant", "g")).read())
    gx, gy, _ = (float(v) for v in re.search(r"value\s*\(([^)]*)\)", text).group(1).split())
    return math.hypot(gx, gy), math.atan2(gx, -gy)


def layer_depth(case):
    text = re.sub(r"//.*", "", open(os.path.join(case, "system", "mpmSetParticlesDict")).read())
    return float(re.search(r"max\s*\(([^)]*)\)", text).group(1).split()[1])


class Bagnold:
    """The exact steady profile of a case."""

    def __init__(self, case):
        c = law_coefficients(case)
        self.g, self.theta = gravity(case)
        self.H = layer_depth(case)
        t = math.tan(self.theta)
        if not c["muS"] < t < c["mu2"]:
            raise ValueError("theta = %.2f deg is outside (atan muS, atan mu2): no steady flow"
                             % math.degrees(self.theta))
        self.I = c["I0"]*(t - c["muS"])/(c["mu2"] - t)
        self.scale = 2*self.I/(3*c["d"])*math.sqrt(self.g*math.cos(self.theta)*c["rho"]/c["rhoS"])

    def u(self, z):
        return self.scale*(self.H**1.5 - np.clip(self.H - np.asarray(z), 0, None)**1.5)

    @property
    def surface(self):
        return self.u(self.H)


def profile_error(case, time, exact):
    """(rms error / u(H), surface velocity / u(H)) of the points at a time."""
    x = mpmPost.read_positions(case, time)
    u = mpmPost.read_cloud_field(case, time, "U")[:, 0]
    err = np.sqrt(np.mean((u - exact.u(x[:, 1]))**2))/exact.surface
    return err, u.max()/exact.surface


def resolution(case):
    """Cells across the layer, from the mesh size dz = h (system/blockMeshDict)."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    h = float(re.search(r"^dz\s+([-+0-9.eE]+);", text, re.M).group(1))
    return int(round(layer_depth(case)/h))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--plot", help="PNG of the profiles against Bagnold's")
    args = ap.parse_args()

    rows = []
    print("%-28s %6s %4s %8s %9s %10s %10s %10s" % ("case", "theta", "nH", "I", "u(H) m/s",
          "err", "err(prev)", "uMax/u(H)"))
    for case in args.cases:
        exact = Bagnold(case)
        ts = mpmPost.times(case)
        err, top = profile_error(case, ts[-1], exact)
        prev = profile_error(case, ts[-2], exact)[0] if len(ts) > 2 else float("nan")
        n = resolution(case)
        rows.append((case, exact, n, err, ts[-1]))
        print("%-28s %6.2f %4d %8.5f %9.5f %10.5f %10.5f %10.4f" % (os.path.basename(case.rstrip("/")),
              math.degrees(exact.theta), n, exact.I, exact.surface, err, prev, top))

    # Observed order per angle between successive resolutions
    by_angle = {}
    for case, exact, n, err, _ in rows:
        by_angle.setdefault(round(math.degrees(exact.theta), 6), []).append((n, err))
    for theta, runs in sorted(by_angle.items()):
        runs.sort()
        for (n1, e1), (n2, e2) in zip(runs, runs[1:]):
            print("order theta = %g deg, nH %d -> %d: %.2f" % (theta, n1, n2,
                  math.log(e1/e2)/math.log(n2/n1)))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 4.8))
        colours = {}
        for case, exact, n, err, t in rows:
            key = round(math.degrees(exact.theta), 3)
            colour = colours.setdefault(key, "C%d" % len(colours))
            x = mpmPost.read_positions(case, t)
            u = mpmPost.read_cloud_field(case, t, "U")[:, 0]
            marker = {10: "x", 20: "+"}.get(n, ".")
            ax.plot(u, x[:, 1]/exact.H, marker, color=colour, ms=4, alpha=0.7,
                    label="MPM %g deg, nH = %d (err %.3f)" % (key, n, err))
            z = np.linspace(0, exact.H, 200)
            if n == min(r[2] for r in rows if round(math.degrees(r[1].theta), 3) == key):
                ax.plot(exact.u(z), z/exact.H, "-", color=colour, lw=1.2,
                        label="Bagnold, %g deg (I = %.3f)" % (key, exact.I))
        ax.set_xlabel("u [m/s]")
        ax.set_ylabel("z / H")
        ax.set_ylim(0, 1.02)
        ax.set_title("Steady flow down a rough incline: mu(I) vs Bagnold")
        ax.legend(fontsize=7, loc="lower right")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print("wrote", args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
