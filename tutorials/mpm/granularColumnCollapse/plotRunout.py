#!/usr/bin/env python3
"""Runout against aspect ratio for the runs of ./sweepAspectRatio.

For each run directory (sweep/<material>_a<a>_h<h>) measures the runout
(L_f - a0)/a0 with plotProfile.measure (front of the deposit: 99.9 % of
the mass behind it; the farthest point's runout is printed beside it),
prints it with Lube et al.'s (2005)
quasi-2D law

    (L_f - a0)/a0 = 1.2 a          a < 2.3
                    1.9 a^(2/3)    a > 2.3

and the change of the runout when the cell size halves, and writes
runoutVsAspectRatio.png. It also prints the fronts behind which 90, 95, 98,
99, 99.5 and 99.9 % of the mass lie, and their change per halving: they show
whether the whole deposit or only its thinnest tip moves with the cell size.
Where three or more runs halve the cell size in turn, it prints each
measure's observed order, Richardson limit and error band
(mpmPost.richardson).
Usage: plotRunout.py RUN... [--no-plot]
"""
import math
import os
import re
import sys

import numpy as np

import mpmPost
from plotProfile import mass_front, mass_order, measure


# The shares of the final mass behind the fronts of the convergence table
FRONT_FRACTIONS = (0.9, 0.95, 0.98, 0.99, 0.995, 0.999)

# The materials of constant/mpmProperties, by law
LABELS = {"sand": "Drucker-Prager (sand)", "glassBeads": "mu(I) (glassBeads)"}


def lube(a):
    return 1.2*a if a < 2.3 else 1.9*a**(2.0/3.0)


def run_parameters(run):
    """(material [with '_E<E>' when the sweep set E, '_geostatic' when it started geostatic,
    '_PIC' or '_FLIP' for another transfer than APIC, '_ppc<N>' for N x N points per cell],
    a, h) from the run's name."""
    m = re.search(r"([A-Za-z0-9]+)_a([0-9.]+)_h([0-9.]+)(_E[-+0-9.e]+)?(_geostatic)?(_PIC|_FLIP)?(_ppc[0-9]+)?$",
                  os.path.basename(run.rstrip("/")))
    return ("".join([m.group(1)] + [g or "" for g in m.group(4, 5, 6, 7)]),
            float(m.group(2)), float(m.group(3)))


def bulk_measures(x0, mass0, x1, mass1, a0):
    """The bulk of the deposit, both relative to a0: (front90, travel) with
    front90 = (L90 - a0)/a0, L90 the x behind which 90 % of the final mass
    lies, and travel the x displacement of the centre of mass (from the
    first cloud x0, mass0 to the last x1, mass1) over a0."""
    front90 = (mass_front(x1, mass1, 0.9) - a0)/a0
    travel = (np.dot(mass1, x1[:, 0])/mass1.sum() - np.dot(mass0, x0[:, 0])/mass0.sum())/a0
    return front90, travel


def fronts(x, m, a0, fractions=FRONT_FRACTIONS):
    """(L_q - a0)/a0 for each share q of the mass behind the front L_q."""
    ordered = mass_order(x, m)
    return [(mass_front(x, m, q, ordered) - a0)/a0 for q in fractions]


def halvings(by_h):
    """The neighbours in cell size of by_h = [(h, value), ...] whose sizes differ by a factor
    of two, coarse first: [(h coarse, h fine, value coarse, value fine,
    relative change)]. A value may be a numpy array (the change is then per
    element)."""
    by_h = sorted(by_h, key=lambda pair: pair[0], reverse=True)
    return [(h1, h2, v1, v2, (v2 - v1)/v1)
            for (h1, v1), (h2, v2) in zip(by_h, by_h[1:]) if abs(h1/h2 - 2) < 1e-6]


def halving_chain(rows):
    """The longest run of rows (coarsest first, r[2] the cell size) whose cell
    size halves from one to the next, ending at the finest."""
    chain = rows[-1:]
    for r in reversed(rows[:-1]):
        if abs(r[2]/chain[0][2] - 2) > 1e-6:
            break
        chain.insert(0, r)
    return chain


def main():
    runs = [r for r in sys.argv[1:] if not r.startswith("--")]
    rows = []
    print("%-26s %5s %7s %6s %8s %8s %8s %7s %10s %8s %9s %9s" % ("material", "a", "h [m]", "points", "runout",
          "farthest", "Lube", "ratio", "maxU end", "t end", "front90", "travel"))
    for run in runs:
        law, a, h = run_parameters(run)
        m = measure(run)
        runout = (m["Lf"] - m["a0"])/m["a0"]
        s = mpmPost.read_summary(run)
        front90, travel = bulk_measures(m["x0"], mpmPost.read_cloud_field(run, m["times"][0], "mass"),
                                        m["x1"], m["m1"], m["a0"])
        rows.append((law, a, h, runout, travel, np.array(fronts(m["x1"], m["m1"], m["a0"]))))
        farthest = (m["LfMax"] - m["a0"])/m["a0"]
        print("%-26s %5g %7g %6d %8.3f %8.3f %8.3f %7.3f %10.3g %8s %9.3f %9.4f" % (
              law, m["h0"]/m["a0"], h, len(m["x1"]), runout, farthest, lube(a), runout/lube(a),
              s["maxU"][-1], m["times"][-1], front90, travel))

    # The runout (99.9 % of the mass) and the centre of mass; the fronts of
    # other shares of the mass follow.
    for column, name in ((3, "runout"), (4, "centre-of-mass travel")):
        print("Change of the %s when the cell size halves:" % name)
        for law in sorted({r[0] for r in rows}):
            for a in sorted({r[1] for r in rows if r[0] == law}):
                by_h = [(r[2], r[column]) for r in rows if r[0] == law and r[1] == a]
                for h1, h2, r1, r2, change in halvings(by_h):
                    print("  %-16s a = %-4g h %g -> %g: %.3f -> %.3f (%+.1f %%)"
                          % (law, a, h1, h2, r1, r2, 100*change))

    # Which part of the deposit moves with the cell size: the fronts of a
    # growing share of the mass (docs/druckerPrager.md, "Convergence").
    print("Fronts (L_q - a0)/a0 behind which q of the mass lies, and their change when the cell size halves:")
    print("  %-22s %5s %13s " % ("material", "a", "h [m]") + " ".join("%8s" % ("%g %%" % (100*q)) for q in FRONT_FRACTIONS))
    for law in sorted({r[0] for r in rows}):
        for a in sorted({r[1] for r in rows if r[0] == law}):
            mine = sorted(((r[2], r[5]) for r in rows if r[0] == law and r[1] == a), key=lambda pair: -pair[0])
            for h, values in mine:
                print("  %-22s %5g %13g " % (law, a, h) + " ".join("%8.3f" % v for v in values))
            for h1, h2, _, _, changes in halvings(mine):
                print("  %-22s %5g %13s " % (law, a, "%g->%g" % (h1, h2))
                      + " ".join("%+7.1f%%" % (100*c) for c in changes))

    # Where three or more grids halve the cell size in turn: the observed
    # order, the Richardson limit and its error band (issue 29, validation 4).
    print("Richardson extrapolation over halvings of the cell size (mpmPost.richardson):")
    for law in sorted({r[0] for r in rows}):
        for a in sorted({r[1] for r in rows if r[0] == law}):
            mine = sorted((r for r in rows if r[0] == law and r[1] == a), key=lambda r: -r[2])
            chain = halving_chain(mine)
            if len(chain) < 3:
                continue
            for name, value in (("runout", lambda r: r[3]), ("front90", lambda r: r[5][0]),
                                ("travel", lambda r: r[4])):
                print("  %-16s a = %-4g %-8s h %s: %s" % (law, a, name, " ".join("%g" % r[2] for r in chain),
                      mpmPost.richardson_line([value(r) for r in chain])))

    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    aa = np.linspace(0.3, 10, 400)
    ax.plot(aa[aa < 2.3], [lube(a) for a in aa[aa < 2.3]], "k-", lw=1.2, label="Lube et al. 2005: 1.2 a")
    ax.plot(aa[aa > 2.3], [lube(a) for a in aa[aa > 2.3]], "k--", lw=1.2,
            label="Lube et al. 2005: 1.9 a$^{2/3}$")
    sizes = sorted({r[2] for r in rows}, reverse=True)
    markers = ["o", "s", "^", "v"]
    colours = {}
    for law in sorted({r[0] for r in rows}):
        colour = colours.setdefault(law, "C%d" % len(colours))
        for h, mk in zip(sizes, markers):
            pts = sorted((r[1], r[3]) for r in rows if r[0] == law and r[2] == h)
            if pts:
                ax.plot(*zip(*pts), mk, color=colour, mfc="none" if h != sizes[-1] else colour,
                        ms=6, label="%s, h = %g m" % (LABELS.get(law, law), h))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("aspect ratio a = h$_0$/a$_0$")
    ax.set_ylabel("runout (L$_f$ - a$_0$)/a$_0$")
    ax.set_title("Granular column collapse: runout against aspect ratio")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig("runoutVsAspectRatio.png", dpi=120)
    print("Wrote runoutVsAspectRatio.png")


if __name__ == "__main__":
    main()
