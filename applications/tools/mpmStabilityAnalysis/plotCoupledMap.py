#!/usr/bin/env python3
"""Map of the coupled step's stability over (Dt/tau_p, aS), one panel per
(mode, variant), from mpmStabilityAnalysis --model coupled --map-csv.

Usage: plotCoupledMap.py map.csv out.png
Colour: log10 of the largest spectral radius over kh; the black line is
|G| = 1 (unstable to the right/above where the colour is red).
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    src, out = sys.argv[1], sys.argv[2]
    panels = {}
    with open(src) as f:
        for r in csv.DictReader(f):
            key = (r["mode"], r["variant"])
            panels.setdefault(key, []).append((float(r["dtOverTau"]), float(r["alphaS"]), float(r["maxSpectralRadius"])))
    keys = list(panels)
    modes = list(dict.fromkeys(k[0] for k in keys))
    variants = list(dict.fromkeys(k[1] for k in keys))
    fig, axes = plt.subplots(len(modes), len(variants), figsize=(4.2*len(variants), 3.4*len(modes)),
                             squeeze=False, sharex=True, sharey=True)
    first = next(iter(csv.DictReader(open(src))))
    for i, m in enumerate(modes):
        for j, v in enumerate(variants):
            ax = axes[i][j]
            pts = np.array(panels.get((m, v), []))
            if pts.size == 0:
                ax.set_visible(False)
                continue
            D = np.unique(pts[:, 0])
            A = np.unique(pts[:, 1])
            R = np.full((len(A), len(D)), np.nan)
            for d, a, rho in pts:
                R[np.searchsorted(A, a), np.searchsorted(D, d)] = rho
            im = ax.pcolormesh(D, A, np.log10(np.maximum(R, 1e-3)), shading="nearest",
                               cmap="RdBu_r", vmin=-1.5, vmax=1.5)
            if np.nanmax(R) > 1 > np.nanmin(R):
                ax.contour(D, A, R, levels=[1.0], colors="k", linewidths=1.5)
            ax.set_xscale("log")
            ax.set_title(f"{m}, {v}", fontsize=10)
            if i == len(modes) - 1:
                ax.set_xlabel("Dt / tau_p")
            if j == 0:
                ax.set_ylabel("alpha_s")
    fig.colorbar(im, ax=axes, label="log10 max |G| over kh")
    fig.suptitle(f"coupled step, {first['solid']} {first['shape']} alpha={first['alpha']}, "
                 f"rho_f/rho_s={float(first['densityRatio']):g}, subCycles={first['subCycles']}, "
                 f"number={float(first['number']):g}, pressureGradient={first['pressureGradient']}", fontsize=9)
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
