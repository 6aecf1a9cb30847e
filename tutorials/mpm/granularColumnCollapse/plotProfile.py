#!/usr/bin/env python3
"""Granular column collapse: final deposit against plane-strain references.

Reads the material points at the first and the last write time, measures
the runout L_f (front of the deposit: the x behind which 99.9 % of the
mass lies, so that a few points thrown ahead do not set it; the farthest
point + half the point spacing is printed beside it) and the final height
H_f (top of the deposit, centre + half the point spacing). It compares the
runout with plane-strain DEM collapses without side walls (Kumar 2015:
1.67 a for a <= 2.7), the same physics as this plane-strain continuum
(issue 29). The channel experiments' scaling (Lube et al. 2005, Lajeunesse
et al. 2005; as recalled, approximate) is only drawn on the picture: their
side walls shorten the runout, so a ratio to it is not a validation:

    (L_f - a0)/a0 ~ 1.2 a          a small (Lube: a < 1.8)
    (L_f - a0)/a0 ~ 1.9 a^(2/3)    a large (Lube: a > 2.8)
    H_f/a0        ~ a^(2/5)        a > ~1.15 (Lube), H_f = h0 below

with a = h0/a0. The prefactors scatter with the material by some 10-20 %
and a = 2 sits in the transition between the two runout laws.

Writes granularColumnCollapse.png: final points coloured by the equivalent
plastic strain, the initial column outline and the free surface at a few
times. Usage: plotProfile.py [case] [--no-plot]
"""
import sys

import numpy as np

import mpmPost

A0, H0 = 0.2, 0.4          # initial column width and height [m]


def spacing(x0):
    """Point spacing of the initial regular lattice (x direction)."""
    u = np.unique(np.round(x0[:, 0], 10))
    return float(np.min(np.diff(u)))


def surface(x, dp):
    """Free surface y(x): top of the points in x bins about 4 point spacings
    wide (edge = centre + dp/2)."""
    xmax = x[:, 0].max() + dp/2
    nbins = max(5, int(round(xmax/(4*dp))))
    edges = np.linspace(0.0, xmax, nbins + 1)
    k = np.clip(np.digitize(x[:, 0], edges) - 1, 0, nbins - 1)
    xs, ys = [], []
    for b in range(nbins):
        sel = k == b
        if np.any(sel):
            xs.append(0.5*(edges[b] + edges[b + 1]))
            ys.append(x[sel, 1].max() + dp/2)
    xs = [0.0] + xs + [x[:, 0].max() + dp/2]
    ys = [ys[0]] + ys + [0.0]
    return np.array(xs), np.array(ys)


def mass_order(x, m):
    """The points in increasing x and the share of the mass at or behind
    each: (order, cumulative)."""
    order = np.argsort(x[:, 0])
    return order, np.cumsum(m[order])/m.sum()


def mass_front(x, m, fraction=0.999, ordered=None):
    """Front of the deposit: the x behind which `fraction` of the mass lies
    (`ordered`: mass_order(x, m) when the caller has it already).
    A fixed share of the mass is a fixed amount of material whatever the
    resolution, so this front has a limit under refinement, while the
    farthest point is set by a single point (a grain thrown ahead, or one
    point of a tongue stretched thinner than the point spacing)."""
    order, cumulative = ordered or mass_order(x, m)
    return float(x[order[min(np.searchsorted(cumulative, fraction), len(order) - 1)], 0])


def measure(case="."):
    ts = mpmPost.times(case)
    x0 = mpmPost.read_positions(case, ts[0])
    x1 = mpmPost.read_positions(case, ts[-1])
    dp = spacing(x0)
    a0 = x0[:, 0].max() + dp/2 - (x0[:, 0].min() - dp/2)
    h0 = x0[:, 1].max() + dp/2 - (x0[:, 1].min() - dp/2)
    m1 = mpmPost.read_cloud_field(case, ts[-1], "mass")
    Lf = mass_front(x1, m1)
    LfMax = x1[:, 0].max() + dp/2
    Hf = x1[:, 1].max() + dp/2
    return dict(times=ts, x0=x0, x1=x1, m1=m1, dp=dp, a0=a0, h0=h0, Lf=Lf, LfMax=LfMax, Hf=Hf)


def empirical(a):
    """(runout (L_f-a0)/a0 small-a law, large-a law, H_f/a0) of the channel
    experiments (Lube et al. 2005): drawn on the picture, not compared."""
    return 1.2*a, 1.9*a**(2.0/3.0), (a if a < 1.15 else a**0.4)


def planeStrain(a):
    """(L_f - a0)/a0 of plane-strain DEM collapses, no side walls: 1.67 a for
    a <= 2.7 (Kumar 2015, Cambridge PhD thesis, as quoted in issue 29; not
    re-read here), or None outside its range."""
    return 1.67*a if a <= 2.7 else None


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    m = measure(case)
    a0, h0, Lf, Hf = m["a0"], m["h0"], m["Lf"], m["Hf"]
    a = h0/a0
    runout = (Lf - a0)/a0
    height = Hf/a0
    lawSmall, lawLarge, lawH = empirical(a)

    s = mpmPost.read_summary(case)
    print("Granular column collapse, final time %s s" % m["times"][-1])
    print("  initial column a0 = %.4f m, h0 = %.4f m, aspect ratio a = %.3f" % (a0, h0, a))
    print("  point spacing dp = %.4g m, %d points" % (m["dp"], len(m["x1"])))
    print("  runout L_f = %.4f m (99.9 %% of the mass behind it; farthest point %.4f m), final height H_f = %.4f m"
          % (Lf, m["LfMax"], Hf))
    print("  normalised runout (L_f - a0)/a0 = %.3f" % runout)
    # The comparison for this physics: plane strain, no side walls. The
    # channel experiments' laws (Lube et al. 2005: 1.2 a, 1.9 a^(2/3)) had
    # side walls, which shorten the runout: not a fair reference here.
    ref = planeStrain(a)
    if ref is not None:
        print("      plane-strain DEM, no side walls (Kumar 2015): 1.67 a = %.2f; this run / it = %.2f"
              % (ref, runout/ref))
    print("      not converged in the cell size: the runout grows on finer grids"
          " (README, 'Richardson extrapolation': limits and error bands)")
    print("  final height H_f/a0 = %.3f  (H_f/h0 = %.3f)" % (height, Hf/h0))
    print("  final max |U| = %.3g m/s = %.3g sqrt(g h0)"
          % (s["maxU"][-1], s["maxU"][-1]/np.sqrt(9.81*h0)))

    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ep = mpmPost.read_cloud_field(case, m["times"][-1], "plasticStrain")
    fig, ax = plt.subplots(figsize=(10, 4.6))
    ax.plot([0, a0, a0, 0], [0, 0, h0, h0], "k--", lw=1.5, label="initial column")
    ts = m["times"]
    picks = [t for t in ts[1:-1] if abs(float(t)/0.1 - round(float(t)/0.1)) < 1e-6
             and float(t) <= 0.5]
    greys = plt.cm.Greys(np.linspace(0.35, 0.75, max(len(picks), 1)))
    for t, c in zip(picks, greys):
        xs, ys = surface(mpmPost.read_positions(case, t), m["dp"])
        ax.plot(xs, ys, "-", color=c, lw=1, label="surface t = %g s" % float(t))
    sc = ax.scatter(m["x1"][:, 0], m["x1"][:, 1], c=ep, s=4, cmap="viridis",
                    vmin=0, vmax=np.percentile(ep, 99))
    xs, ys = surface(m["x1"], m["dp"])
    ax.plot(xs, ys, "r-", lw=1.5, label="final surface t = %g s" % float(ts[-1]))
    ax.axvline(a0 + a0*lawSmall, color="C1", lw=1, ls=":",
               label="empirical runout 1.2a: %.2f m" % (a0*(1 + lawSmall)))
    ax.axvline(a0 + a0*lawLarge, color="C3", lw=1, ls=":",
               label=r"empirical runout 1.9a$^{2/3}$: %.2f m" % (a0*(1 + lawLarge)))
    fig.colorbar(sc, ax=ax, label="equivalent plastic strain", pad=0.01)
    ax.set_xlim(0, 1.0)
    ax.set_ylim(0, 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("Granular column collapse, a = %.1f: (L$_f$-a$_0$)/a$_0$ = %.2f, "
                 "H$_f$/a$_0$ = %.2f" % (a, runout, height))
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig("granularColumnCollapse.png", dpi=130)
    print("Wrote granularColumnCollapse.png")


if __name__ == "__main__":
    main()
