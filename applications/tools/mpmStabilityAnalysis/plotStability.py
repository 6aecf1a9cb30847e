#!/usr/bin/env python3
"""Plots of the 1D MPM von Neumann analysis (docs/stabilityAnalysis.md).

Runs mpmStabilityAnalysis to write the CSVs (unless --no-run), then draws:
  gain_<model>.png             |G| vs kh/pi, rows = shape, columns = alpha,
                               one line per Fo/CFL, exact dashed
  limit_vs_offset_<model>.png  stability limit vs single-point offset per
                               shape, PIC solid, FLIP dashed

Usage:
  plotStability.py --tool build/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis \
                   --outdir stabilityPlots
Needs python3-matplotlib (Debian package).
"""
import argparse
import csv
import os
import subprocess
import sys
from collections import defaultdict

SHAPES = ["LH", "QBS", "CBS"]
ALPHAS = ["0", "0.5", "1"]
MODELS = {
    # name: (tool arguments, parameter label, parameter values)
    "diffusion": (["--model", "diffusion"], "Fo", "0.1,0.25,0.5,1"),
    "wave_USL": (["--model", "wave", "--scheme", "USL"], "CFL", "0.1,0.4,0.7"),
    "wave_USF": (["--model", "wave", "--scheme", "USF"], "CFL", "0.1,0.5,1,1.5"),
}


def run_tool(tool, outdir, offsets):
    """Write gain_<model>.csv and sweep_<model>.csv with the tool."""
    for name, (args, _, values) in MODELS.items():
        gain = os.path.join(outdir, f"gain_{name}.csv")
        sweep = os.path.join(outdir, f"sweep_{name}.csv")
        common = [tool] + args + ["--shape", ",".join(SHAPES)]
        subprocess.run(common + ["--alpha", ",".join(ALPHAS), "--offsets", offsets,
                                 "--Fo", values, "--nk", "128", "--csv", gain],
                       check=True, stdout=subprocess.DEVNULL)
        subprocess.run(common + ["--alpha", "0,1", "--offsets", "0", "--sweep-offsets", "40",
                                 "--theta-intervals", "180", "--sweep-csv", sweep],
                       check=True, stdout=subprocess.DEVNULL)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def same_alpha(a, b):
    return abs(float(a) - float(b)) < 1e-12


def plot_gain(plt, outdir, name, label):
    rows = read_rows(os.path.join(outdir, f"gain_{name}.csv"))
    # Keep the physical branch only (branch 0 diffusion, +1 right-going wave).
    rows = [r for r in rows if r["branch"] in ("0", "1")]
    fig, axes = plt.subplots(len(SHAPES), len(ALPHAS), figsize=(12, 9), sharex=True, sharey=True)
    for i, shape in enumerate(SHAPES):
        for j, alpha in enumerate(ALPHAS):
            ax = axes[i][j]
            curves = defaultdict(list)
            for r in rows:
                if r["shape"] == shape and same_alpha(r["alpha"], alpha):
                    curves[r["number"]].append(r)
            for k, (number, pts) in enumerate(sorted(curves.items(), key=lambda t: float(t[0]))):
                kh = [float(p["kh"]) / 3.141592653589793 for p in pts]
                line, = ax.plot(kh, [float(p["absG"]) for p in pts], label=f"{label}={number}")
                ax.plot(kh, [float(p["absExact"]) for p in pts], "--", color=line.get_color(), lw=0.8)
                ax.plot(kh, [float(p["spectralRadius"]) for p in pts], ":", color=line.get_color(), lw=0.8)
            ax.axhline(1.0, color="k", lw=0.5)
            ax.set_title(f"{shape}, alpha={alpha}")
            ax.set_ylim(0, 1.3)
            if i == len(SHAPES) - 1:
                ax.set_xlabel("kh / pi")
            if j == 0:
                ax.set_ylabel("|G|")
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"{name}: |G| of the physical mode (solid), exact (dashed), spectral radius (dotted)")
    fig.tight_layout()
    out = os.path.join(outdir, f"gain_{name}.png")
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def plot_limits(plt, outdir, name, label):
    rows = read_rows(os.path.join(outdir, f"sweep_{name}.csv"))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for shape in SHAPES:
        for alpha, style in (("0", "-"), ("1", "--")):
            pts = [r for r in rows if r["shape"] == shape and same_alpha(r["alpha"], alpha)]
            ax.plot([float(p["shift"]) for p in pts], [float(p["limit"]) for p in pts], style,
                    label=f"{shape} alpha={alpha}")
    ax.set_xlabel("point offset in the cell (lattice units)")
    ax.set_ylabel(f"stability limit ({label})")
    ax.set_title(f"{name}: one point per cell, lumped mass")
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    out = os.path.join(outdir, f"limit_vs_offset_{name}.png")
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tool", default="build/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis")
    p.add_argument("--outdir", default="stabilityPlots")
    p.add_argument("--offsets", default="0.5", help="offsets for the |G| plots")
    p.add_argument("--no-run", action="store_true", help="plot existing CSVs in --outdir")
    a = p.parse_args()

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plotStability.py needs matplotlib (apt install python3-matplotlib)")

    os.makedirs(a.outdir, exist_ok=True)
    if not a.no_run:
        run_tool(a.tool, a.outdir, a.offsets)
    for name, (_, label, _) in MODELS.items():
        print(plot_gain(plt, a.outdir, name, label))
        print(plot_limits(plt, a.outdir, name, label))


if __name__ == "__main__":
    main()
