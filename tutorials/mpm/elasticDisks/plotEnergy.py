#!/usr/bin/env python3
"""Two colliding elastic disks (Sulsky, Chen & Schreyer 1994): kinetic,
elastic and total energy against time, from postProcessing/mpmSummary.

Prints the figures of the run (one "name = value" line each, parsed by
tests/cases/elasticDisks.sh) and writes elasticDisks.png.
Usage: plotEnergy.py [case] [--no-plot]
"""
import os
import re
import sys

import numpy as np

import mpmPost

RHO, R, V0 = 1000.0, 0.2, np.array([0.1, 0.1])   # density, radius, speed
CENTRES = np.array([[0.2, 0.2], [0.8, 0.8]])
CONTACT_FRACTION = 1e-3   # first contact: elastic energy > 1e-3 KE0


def block_mesh_extent(case):
    """Cell size h and thickness (z extent) of system/blockMeshDict, from
    its vertices and the x cell count."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    text = re.sub(r"//.*", "", text)
    body = text[text.index("vertices"):]
    body = body[body.index("(") + 1:]
    verts = re.findall(r"\(\s*([-+.\deE]+)\s+([-+.\deE]+)\s+([-+.\deE]+)\s*\)",
                       body[:body.index(");")])
    v = np.array(verts, dtype=float)
    n = int(re.search(r"nCells\s+(\d+)\s*;", text).group(1))
    return (v[:, 0].max() - v[:, 0].min())/n, v[:, 2].max() - v[:, 2].min()


def figures(case="."):
    s = mpmPost.read_summary(case)
    t, ke, el = s["time"], s["kineticEnergy"], s["elasticEnergy"]
    tot = ke + el
    h, thickness = block_mesh_extent(case)
    v2 = float(V0 @ V0)
    f = {}
    f["thickness"] = thickness
    # Continuum: two disks of area pi r^2, per unit thickness x thickness.
    f["KE0_analytic"] = 2*0.5*RHO*np.pi*R**2*v2*thickness
    f["KE0"] = ke[0]
    f["KE0_error"] = ke[0]/f["KE0_analytic"] - 1
    i0 = np.argmax(el > CONTACT_FRACTION*ke[0])
    f["t_contact"] = t[i0] if el[i0] > CONTACT_FRACTION*ke[0] else np.nan
    # Continuum first touch: gap |c2 - c1| - 2r closed at speed 2|v|.
    f["t_contact_continuum"] = (np.linalg.norm(CENTRES[1] - CENTRES[0]) - 2*R)/(2*np.sqrt(v2))
    imin = int(np.argmin(ke))
    f["KE_min"], f["t_KE_min"] = ke[imin], t[imin]
    f["KE_min_ratio"] = ke[imin]/ke[0]
    imax = int(np.argmax(el))
    f["El_max"], f["t_El_max"] = el[imax], t[imax]
    f["El_max_ratio"] = el[imax]/ke[0]
    drift = np.abs(tot - tot[0])/tot[0]
    f["drift_max"] = drift.max()
    f["t_drift_max"] = t[int(np.argmax(drift))]
    # After the rebound: from as long after the KE minimum as contact took
    # to reach it (the mirror of the approach) to the end of the run.
    t_after = 2*f["t_KE_min"] - f["t_contact"]
    after = t >= t_after
    f["t_after_rebound"] = t_after
    f["drift_after_rebound"] = drift[after].max() if after.any() else np.nan
    f["KE_end_ratio"] = ke[-1]/ke[0]
    ucm = np.sqrt(s["Ux"]**2 + s["Uy"]**2 + s["Uz"]**2)
    f["Ucm_max"] = ucm.max()
    f["t_end"] = t[-1]
    f["samples"] = len(t)
    return f, (t, ke, el, tot)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    f, (t, ke, el, tot) = figures(case)
    print(f"elasticDisks: t = {t[0]:g} .. {t[-1]:g}, {len(t)} samples, "
          f"thickness {f['thickness']:g}")
    for k, v in f.items():
        print(f"elasticDisks: {k} = {v:.9g}")
    print(f"elasticDisks: initial KE {f['KE0']:.6g} vs continuum "
          f"2 (rho pi r^2 |v|^2 / 2) t = {f['KE0_analytic']:.6g} "
          f"({100*f['KE0_error']:+.2f} %, the lattice area of the disks)")
    print(f"elasticDisks: first contact t = {f['t_contact']:.4g} "
          f"(continuum disks touch at {f['t_contact_continuum']:.4g})")
    print(f"elasticDisks: min KE {f['KE_min']:.4g} = {100*f['KE_min_ratio']:.1f} % "
          f"of KE0 at t = {f['t_KE_min']:.4g}; max elastic {f['El_max']:.4g} = "
          f"{100*f['El_max_ratio']:.1f} % of KE0 at t = {f['t_El_max']:.4g}")
    print(f"elasticDisks: total-energy drift max {100*f['drift_max']:.2f} % "
          f"(t = {f['t_drift_max']:.4g}), after rebound (t >= "
          f"{f['t_after_rebound']:.3g}) {100*f['drift_after_rebound']:.2f} %")
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(t, ke, "-", label="kinetic")
    ax.plot(t, el, "-", label="elastic (strain)")
    ax.plot(t, tot, "k-", lw=2, label="total")
    ax.axhline(f["KE0_analytic"], color="grey", ls=":", lw=1,
               label="continuum initial KE")
    ax.axvline(f["t_contact"], color="grey", ls="--", lw=1)
    ax.text(f["t_contact"], 0.5*tot[0], " first contact", color="grey",
            rotation=90, va="center")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"energy [J] (thickness {f['thickness']:g} m)")
    ax.set_xlim(t[0], t[-1])
    ax.set_ylim(bottom=0)
    ax.set_title("Two colliding elastic disks: max drift "
                 f"{100*f['drift_max']:.1f} % (contact), "
                 f"{100*f['drift_after_rebound']:.1f} % after rebound",
                 fontsize=10)
    ax.legend(loc="center right")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "elasticDisks.png"), dpi=120)
    print("elasticDisks: wrote elasticDisks.png")


if __name__ == "__main__":
    main()
