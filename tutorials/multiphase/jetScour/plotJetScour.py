#!/usr/bin/env python3
"""jetScour: the sand bed under the jet, at the start, half-way and the end.

Prints the bed surface (the 95th percentile of the points' heights in 1 cm
wide columns) under the jet and at the walls, the scour depth (initial
surface minus the lowest surface under the jet) and the heap height beside
it; writes jetScour.png unless --no-plot. A SUMMARY line is for the test.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python"))
import mpmPost  # noqa: E402

WIDTH, JET = 0.3, (0.135, 0.165)


def surface(x, y, bins):
    """Bed surface per column: 95th percentile of the point heights."""
    idx = np.digitize(x, bins)
    return np.array([np.percentile(y[idx == k], 95) if (idx == k).sum() > 5 else 0.0
                     for k in range(1, len(bins))])


def main():
    args = mpmPost.plot_parser().parse_args()
    case = args.case
    ts = mpmPost.times(case)
    bins = np.linspace(0, WIDTH, 31)
    mid = 0.5*(bins[1:] + bins[:-1])
    under = (mid > JET[0] - 0.03) & (mid < JET[1] + 0.03)
    shown = [ts[0], ts[len(ts)//2], ts[-1]]
    surf = {}
    for t in shown:
        x = mpmPost.read_positions(case, t)
        surf[t] = surface(x[:, 0], x[:, 1], bins)
    s0, s1 = surf[ts[0]], surf[ts[-1]]
    scour = s0[under].mean() - s1[under].min()
    heap = s1[~under].max() - s0[~under].mean()
    for t in shown:
        print("t = %-5s surface under the jet [cm]: %s" % (t, " ".join("%.1f" % (100*v) for v in surf[t][under])))
    print("scour depth %.2f cm, heap height beside it %.2f cm (initial bed %.2f cm)"
          % (100*scour, 100*heap, 100*s0.mean()))
    print("SUMMARY scourDepth=%.6g heapHeight=%.6g bed0=%.6g tEnd=%s" % (scour, heap, s0.mean(), ts[-1]))
    if args.no_plot:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(15, 4))
    for ax, t in zip(axs, shown):
        x = mpmPost.read_positions(case, t)
        v = mpmPost.read_cloud_field(case, t, "U")
        sc = ax.scatter(x[:, 0], x[:, 1], s=1, c=np.hypot(v[:, 0], v[:, 1]), cmap="viridis", vmin=0, vmax=0.3)
        ax.plot(mid, surf[t], "r-", lw=1)
        ax.axvspan(*JET, ymin=0.95, color="tab:blue", alpha=0.5)
        ax.set_xlim(0, WIDTH)
        ax.set_ylim(0, 0.2)
        ax.set_aspect("equal")
        ax.set_title("t = %s s" % t)
    fig.colorbar(sc, ax=axs, label="grain speed [m/s]", shrink=0.8)
    fig.savefig(os.path.join(case, "jetScour.png"), dpi=100)
    print("wrote jetScour.png")


if __name__ == "__main__":
    main()
