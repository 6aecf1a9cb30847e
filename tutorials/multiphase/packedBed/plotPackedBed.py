#!/usr/bin/env python3
"""Packed bed: pressure along the column against the Ergun equation.

Ergun (1952), superficial velocity U0, bed fraction aS, fluid aF = 1 - aS:
    dP/dy = 150 mu U0 aS^2 / (aF^3 d^2) + 1.75 rho U0^2 aS / (aF^3 d)
Prints the gradient inside the bed (away from its smoothed top edge) and the
drop over the whole bed, both against Ergun, and writes packedBed.png.
Usage: plotPackedBed.py [case] [--no-plot]
"""
import os
import sys

import numpy as np

import mpmPost

RHO, NU, D, ALPHA_S, U0, L_BED, HEIGHT = 1000.0, 1e-6, 1e-3, 0.6, 0.005, 0.1, 0.2


def ergun_gradient():
    mu, aF = RHO*NU, 1 - ALPHA_S
    return 150*mu*U0*ALPHA_S**2/(aF**3*D**2) + 1.75*RHO*U0**2*ALPHA_S/(aF**3*D)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    last = mpmPost.field_times(case, "p")[-1]
    p = RHO*mpmPost.read_internal_field(case, last, "p")          # [Pa]
    aF = mpmPost.read_internal_field(case, last, "alpha.fluid")
    # Cell heights: the written cell centres (postProcess -func
    # writeCellCentres) where there are, for a graded mesh; else uniform
    if os.path.exists(os.path.join(case, last, "C")):
        y = mpmPost.read_internal_field(case, last, "C")[:, 1]
    else:
        y = (np.arange(len(p)) + 0.5)*HEIGHT/len(p)
    # Inside the bed: cells whose stencil does not reach its top edge
    inner = (y > 0.02) & (y < L_BED - 0.02)
    grad = np.polyfit(y[inner], p[inner], 1)[0]
    ergun = ergun_gradient()
    drop = p.max()                                                  # outlet p = 0
    print(f"packedBed: time {last}, superficial velocity {U0} m/s, d {D} m, alpha.solid {ALPHA_S}")
    print(f"packedBed: pressure gradient inside the bed {grad:.6g} Pa/m, Ergun {ergun:.6g} Pa/m, "
          f"ratio {grad/ergun:.6f}")
    print(f"packedBed: pressure drop over the whole bed {drop:.6g} Pa, Ergun x L {ergun*L_BED:.6g} Pa, "
          f"ratio {drop/(ergun*L_BED):.6f} (the bed top is smoothed over ~2 cells by the cubic B-splines)")
    print(f"packedBed: min alpha.fluid {aF.min():.6f}")
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(p, y, "o", ms=3, label="mpmFoam")
    yb = np.linspace(0, L_BED, 50)
    ax.plot(ergun*(L_BED - yb) + (drop - ergun*L_BED), yb, "k-", lw=1,
            label=f"Ergun slope {ergun:.0f} Pa/m")
    ax.axhline(L_BED, color="grey", ls=":", label="bed top")
    ax2 = ax.twiny()
    ax2.plot(1 - aF, y, "C1-", lw=1)
    ax2.set_xlabel("alpha.solid", color="C1")
    ax.set_xlabel("p [Pa] (outlet at y = 0)")
    ax.set_ylabel("y [m]")
    ax.set_title(f"Packed bed: inner gradient / Ergun = {grad/ergun:.4f}")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig("packedBed.png", dpi=120)
    print("packedBed: wrote packedBed.png")


if __name__ == "__main__":
    main()
