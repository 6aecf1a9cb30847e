#!/usr/bin/env python3
"""Aluminium-bar column collapse (Bui et al. 2008): final deposit and failure
line against the experiment.

Reads the material points at the first and the last write time and the
digitised experiment in experiment/ (surface.csv: final free surface;
failure.csv: the failure line, the boundary of the bars that did not move),
and measures

  L_f      runout: the x behind which 99.9 % of the mass lies (a few points
           thrown ahead do not set it); the farthest point + dp/2 beside it
  H_f      final height: top of the deposit, point centre + dp/2
  y(0.2)   the free surface at the initial front x = l0 = 0.2 m
  rms      root mean square of y_sim(x) - y_exp(x) over the experiment's
           surface points (x <= 0.44 m)
  x_f(h/2) the failure line at mid-height y = 0.05 m: the smallest initial x
           of the points that moved more than 1 mm (the threshold the
           reproduction of MaterialPointSolver.jl used), against the
           experiment's line
  angle    the failure line's inclination, a least-squares line through the
           boundary points between y = 0.01 and 0.09 m

Writes aluminiumBarsCollapse.png (final points coloured by their
displacement, moved > 1 mm or not, the simulated and the experimental free
surface and failure line). Usage: plotProfile.py [case] [--no-plot]
"""
import os
import sys

import numpy as np

import mpmPost

L0, H0 = 0.2, 0.1          # initial column length and height [m]
MOVED = 1e-3               # displacement that marks a point as failed [m]
HERE = os.path.dirname(os.path.abspath(__file__))


def experiment(name):
    """The digitised experiment: (x, y) arrays of experiment/<name>.csv."""
    d = np.loadtxt(os.path.join(HERE, "experiment", name + ".csv"), delimiter=",", comments="#")
    return d[:, 0], d[:, 1]


def spacing(x0):
    """Point spacing of the initial regular lattice (x direction)."""
    u = np.unique(np.round(x0[:, 0], 10))
    return float(np.min(np.diff(u)))


def surface_at(x, dp, xq):
    """Free surface height at the abscissae xq: the top (centre + dp/2) of
    the points within 2 dp of each; 0 where there is none."""
    y = np.zeros(len(xq))
    for i, xi in enumerate(xq):
        sel = np.abs(x[:, 0] - xi) <= 2*dp
        if np.any(sel):
            y[i] = x[sel, 1].max() + dp/2
    return y


def mass_front(x, m, fraction=0.999):
    """Front of the deposit: the x behind which `fraction` of the mass lies."""
    order = np.argsort(x[:, 0])
    cumulative = np.cumsum(m[order])/m.sum()
    return float(x[order[min(np.searchsorted(cumulative, fraction), len(order) - 1)], 0])


def failure_boundary(x0, moved, dp):
    """The failure line in the initial configuration: for each row of points
    (height y), the smallest initial x of a point that moved; rows where none
    moved are left out. Returns (x, y) arrays."""
    rows = np.unique(np.round(x0[:, 1], 10))
    xs, ys = [], []
    for r in rows:
        sel = (np.abs(x0[:, 1] - r) < dp/4) & moved
        if np.any(sel):
            xs.append(x0[sel, 0].min() - dp/2)
            ys.append(r)
    return np.array(xs), np.array(ys)


def line_at(xl, yl, y):
    """x of a polyline (xl, yl), monotone in y, at height y."""
    o = np.argsort(yl)
    return float(np.interp(y, yl[o], xl[o]))


def angle(xl, yl):
    """Inclination [deg] of a least-squares line x(y) through the points
    between y = 0.01 and 0.09 m."""
    sel = (yl >= 0.01) & (yl <= 0.09)
    slope = np.polyfit(yl[sel], xl[sel], 1)[0]          # dx/dy < 0
    return float(np.degrees(np.arctan2(1.0, -slope)))


def by_id(case, t, x):
    ids = mpmPost.read_cloud_field(case, t, "pointId").astype(np.int64)
    return x[np.argsort(ids)]


def measure(case="."):
    ts = mpmPost.times(case)
    x0 = mpmPost.read_positions(case, ts[0])
    x1 = mpmPost.read_positions(case, ts[-1])
    m1 = mpmPost.read_cloud_field(case, ts[-1], "mass")
    dp = spacing(x0)
    moved = np.linalg.norm(by_id(case, ts[-1], x1) - by_id(case, ts[0], x0), axis=1) > MOVED
    x0s = by_id(case, ts[0], x0)
    xe, ye = experiment("surface")
    xfe, yfe = experiment("failure")
    ys = surface_at(x1, dp, xe)
    xf, yf = failure_boundary(x0s, moved, dp)
    s = mpmPost.read_summary(case)
    return dict(
        times=ts, x0=x0s, x1=by_id(case, ts[-1], x1), moved=moved, dp=dp, m1=m1,
        Lf=mass_front(x1, m1), LfMax=x1[:, 0].max() + dp/2, Hf=x1[:, 1].max() + dp/2,
        y02=float(surface_at(x1, dp, [L0])[0]), y02exp=float(np.interp(L0, xe, ye)),
        rms=float(np.sqrt(np.mean((ys - ye)**2))), xe=xe, ye=ye, ys=ys,
        xf=xf, yf=yf, xfe=xfe, yfe=yfe,
        xmid=line_at(xf, yf, H0/2) if len(yf) > 1 else float("nan"),
        xmidExp=line_at(xfe, yfe, H0/2),
        angle=angle(xf, yf) if len(yf) > 3 else float("nan"), angleExp=angle(xfe, yfe),
        LfExp=float(xe[-1]), HfExp=float(ye.max()), maxU=float(s["maxU"][-1]))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    r = measure(case)
    rel = lambda a, b: 100.0*(a - b)/b
    print("Aluminium-bar collapse (Bui et al. 2008), final time %s s" % r["times"][-1])
    print("  point spacing dp = %.4g m, %d points" % (r["dp"], len(r["x1"])))
    print("  runout L_f = %.4f m (99.9 %% of the mass behind it; farthest point %.4f m); experiment %.3f m (%+.1f %%)"
          % (r["Lf"], r["LfMax"], r["LfExp"], rel(r["Lf"], r["LfExp"])))
    print("  final height H_f = %.4f m; experiment %.4f m (%+.1f %%)"
          % (r["Hf"], r["HfExp"], rel(r["Hf"], r["HfExp"])))
    print("  surface at x = 0.2 m: %.4f m; experiment %.4f m (%+.1f %%)"
          % (r["y02"], r["y02exp"], rel(r["y02"], r["y02exp"])))
    print("  surface rms difference over the experiment's points: %.4f m (%.1f %% of h0)"
          % (r["rms"], 100*r["rms"]/H0))
    print("  failure line at mid-height: x = %.4f m; experiment %.4f m (%+.4f m)"
          % (r["xmid"], r["xmidExp"], r["xmid"] - r["xmidExp"]))
    print("  failure line inclination: %.1f deg; experiment %.1f deg"
          % (r["angle"], r["angleExp"]))
    print("  final max |U| = %.3g m/s" % r["maxU"])
    print("RESULT Lf=%.5f LfMax=%.5f Hf=%.5f y02=%.5f rms=%.5f xmid=%.5f angle=%.2f maxU=%.4g"
          % (r["Lf"], r["LfMax"], r["Hf"], r["y02"], r["rms"], r["xmid"], r["angle"], r["maxU"]))

    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(11, 3.4))
    x1, mv = r["x1"], r["moved"]
    ax.plot([0, L0, L0], [H0, H0, 0], "k--", lw=1, label="initial column")
    ax.scatter(x1[~mv, 0], x1[~mv, 1], s=3, c="#00008e", label="points moved <= 1 mm")
    ax.scatter(x1[mv, 0], x1[mv, 1], s=3, c="#ef0000", label="points moved > 1 mm")
    xq = np.linspace(0, r["LfMax"], 200)
    ax.plot(xq, surface_at(x1, r["dp"], xq), "m-", lw=1.2, label="simulated surface")
    ax.plot(r["xf"], r["yf"], "c-", lw=1.5, label="simulated failure line")
    ax.plot(r["xe"], r["ye"], "gD-", ms=4, lw=1.5, label="experiment: surface")
    ax.plot(r["xfe"], r["yfe"], "g^-", ms=5, lw=1.5, label="experiment: failure line")
    ax.set_xlim(-0.01, 0.52)
    ax.set_ylim(-0.005, 0.115)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("Bui et al. (2008) aluminium bars, dp = %.3g mm: L$_f$ = %.3f m (exp. %.3f), "
                 "surface rms %.1f mm" % (1e3*r["dp"], r["Lf"], r["LfExp"], 1e3*r["rms"]), fontsize=10)
    ax.legend(fontsize=7, loc="upper right", ncol=2)
    fig.tight_layout()
    fig.savefig("aluminiumBarsCollapse.png", dpi=130)
    print("Wrote aluminiumBarsCollapse.png")


if __name__ == "__main__":
    main()
