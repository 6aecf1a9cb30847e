#!/usr/bin/env python3
"""Underwater against dry granular column collapse: final deposits.

Measures runout and final height of this case and of the dry case
(tutorials/mpm/granularColumnCollapse, same column, same Drucker-Prager
sand) with the dry tutorial's own measuring code, prints both and their
ratio, and writes underwaterGranularCollapse.png.
Usage: plotUnderwater.py [case] [dryCase] [--no-plot]
"""
import importlib.util
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
# The dry tutorial (its measuring code and, by default, its results):
# found through $MPMFOAM_DIR, so a copied case still finds it.
root = os.environ.get("MPMFOAM_DIR", os.path.join(here, "..", "..", ".."))
dry_dir = os.path.join(root, "tutorials", "mpm", "granularColumnCollapse")
spec = importlib.util.spec_from_file_location("plotProfile", os.path.join(dry_dir, "plotProfile.py"))
profile = importlib.util.module_from_spec(spec)
spec.loader.exec_module(profile)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    dry = args[1] if len(args) > 1 else dry_dir
    wet_m, dry_m = profile.measure(case), profile.measure(dry)
    a0 = wet_m["a0"]
    rw, rd = (wet_m["Lf"] - a0)/a0, (dry_m["Lf"] - a0)/a0
    print(f"underwater: runout (L_f - a0)/a0 = {rw:.3f}, final height H_f/a0 = {wet_m['Hf']/a0:.3f}, "
          f"t = {wet_m['times'][-1]} s")
    print(f"dry:        runout (L_f - a0)/a0 = {rd:.3f}, final height H_f/a0 = {dry_m['Hf']/a0:.3f}, "
          f"t = {dry_m['times'][-1]} s")
    print(f"underwater/dry runout ratio = {rw/rd:.3f}")
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(10, 4.2))
    ax.plot([0, a0, a0], [wet_m["h0"], wet_m["h0"], 0], "k--", label="initial column")
    for m, name, col in [(dry_m, "dry", "C1"), (wet_m, "under water", "C0")]:
        xs, ys = profile.surface(m["x1"], m["dp"])
        ax.plot(xs, ys, "-", color=col, lw=2, label=f"{name}: runout {(m['Lf'] - a0)/a0:.2f} a0")
        ax.scatter(m["x1"][:, 0], m["x1"][:, 1], s=1, color=col, alpha=0.25)
    ax.set_aspect("equal")
    ax.set_xlim(0, 1.0)
    ax.set_ylim(0, 0.45)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"Granular column collapse, dry and under water: runout ratio {rw/rd:.2f}")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "underwaterGranularCollapse.png"), dpi=120)
    print("wrote underwaterGranularCollapse.png")


if __name__ == "__main__":
    main()
