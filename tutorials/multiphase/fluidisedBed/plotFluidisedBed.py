#!/usr/bin/env python3
"""fluidisedBed: bed pressure drop against the superficial velocity.

Reads the inlet record of the run (postProcessing/inlet/0/surfaceFieldValue.dat:
kinematic p, alpha.fluid and U at the plate, every fluid step) and the case
set-up, and compares the bed pressure drop

    dP_bed = rho_f p_inlet - rho_f g H      (p = 0 at the outlet, H column height)

with
  * Ergun's fixed-bed drop over the initial bed (L0, alphaS0), below U_mf,
  * the same Ergun/Gidaspow drag summed over the simulated alpha profile
    ("discrete Ergun": isolates the projection of alpha.solid from the law),
  * the buoyant weight per unit area W = (rho_s - rho_f) g alphaS0 L0.
U_mf(simulated) is where the Ergun fit of the fixed-bed points meets the
fluidised plateau; U_mf(Wen-Yu) from Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7.

Each step of the inlet table is averaged over its last `--window` seconds.
Prints the figures; writes fluidisedBed.png unless --no-plot.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python"))
import mpmPost  # noqa: E402

entry = mpmPost.dict_scalar


def setup(case):
    c = {}
    c["nu"] = entry(os.path.join(case, "constant/transportProperties"), "nu")
    c["rhoF"] = entry(os.path.join(case, "constant/transportProperties"), "rho")
    mp = os.path.join(case, "constant/mpmProperties")
    c["rhoS"] = entry(mp, "rho")
    c["d"] = float(re.search(r"drag\s*\{[^}]*\bd\s+([-+0-9.eE]+)", open(mp).read()).group(1))
    c["model"] = re.search(r"drag\s*\{[^}]*model\s+(\w+)", open(mp).read()).group(1)
    c["alphaMax"] = entry(mp, "alphaMax")
    g = re.search(r"value\s+\(\s*\S+\s+(\S+)\s+\S+\s*\)", open(os.path.join(case, "constant/g")).read())
    c["g"] = abs(float(g.group(1)))
    sp = open(os.path.join(case, "system/mpmSetParticlesDict")).read()
    c["L0"] = float(re.search(r"max\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)", sp).group(1))
    c["alphaS"] = entry(os.path.join(case, "system/mpmSetParticlesDict"), "solidFraction")
    bm = os.path.join(case, "system/blockMeshDict")
    c["H"] = entry(bm, "height")
    c["h"] = entry(bm, "h")
    c["mu"] = c["nu"]*c["rhoF"]
    return c


def ergun(c, U, aS=None):
    """Ergun's drop over the initial bed at superficial velocity U [Pa]."""
    aS = c["alphaS"] if aS is None else aS
    aF = 1 - aS
    return c["L0"]*(150*c["mu"]*aS**2*U/(aF**3*c["d"]**2) + 1.75*c["rhoF"]*aS*U**2/(aF**3*c["d"]))


def beta(c, aF, u):
    """Drag coefficient of the case's law (Ergun, WenYu or Gidaspow), as in
    src/mpmCore/drag (model A, drag only); aF clamped at 0.2."""
    aF = np.clip(aF, 0.2, 1.0)
    aS = 1 - aF
    mu, rho, d = c["mu"], c["rhoF"], c["d"]
    ergunBeta = 150*aS**2*mu/(aF*d**2) + 1.75*aS*rho*u/d
    Re = aF*rho*u*d/mu
    CdRe = np.where(Re < 1000, 24*(1 + 0.15*Re**0.687), 0.44*Re)
    wenYu = 0.75*CdRe*mu/d**2*aS*aF**-2.65   # 3/4 Cd aS aF rho u/d aF^-2.65, Cd = CdRe/Re
    if c["model"] == "Ergun":
        return ergunBeta
    if c["model"] == "WenYu":
        return wenYu
    return np.where(aF < 0.8, ergunBeta, wenYu)


def discreteErgun(c, case, time, U):
    """Drag summed over the written alpha profile, grains at rest:
    sum h beta u / aF with u = U / aF (the fluid's dp/dy in the bed)."""
    aF = mpmPost.read_internal_field(case, time, "alpha.fluid")
    u = U/aF
    return float(np.sum(c["h"]*beta(c, aF, u)*u/aF))


def readRecord(case):
    path = os.path.join(case, "postProcessing/inlet/0/surfaceFieldValue.dat")
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        nums = [float(x) for x in re.findall(r"[-+0-9.eE]+", line)]
        rows.append(nums[:3] + [nums[4]])    # t, p, alpha.fluid, Uy
    a = np.array(rows)
    return a[:, 0], a[:, 1], a[:, 2]*a[:, 3]     # t, p, superficial U


def steps(t, Us, rel=1e-3):
    """(start, end, U) of each constant-inflow stretch of the record."""
    out = []
    i = 0
    n = len(t)
    while i < n:
        j = i
        while j + 1 < n and abs(Us[j + 1] - Us[i]) <= rel*abs(Us[i]):
            j += 1
        if j - i >= 5:
            out.append((t[i], t[j], float(np.mean(Us[i:j + 1]))))
        i = j + 1
    return out


def main():
    ap = mpmPost.plot_parser()
    ap.add_argument("--window", type=float, default=0.5, help="averaging window at the end of each step [s]")
    ap.add_argument("--settle", type=float, default=0.4,
                    help="time after the start of a step before every step is checked [s]")
    args = ap.parse_args()
    case = args.case
    c = setup(case)

    t, p, Us = readRecord(case)
    dP = c["rhoF"]*(p - c["g"]*c["H"])
    W = (c["rhoS"] - c["rhoF"])*c["g"]*c["alphaS"]*c["L0"]

    # Wen-Yu U_mf
    Ar = c["rhoF"]*(c["rhoS"] - c["rhoF"])*c["g"]*c["d"]**3/c["mu"]**2
    ReMf = np.sqrt(33.7**2 + 0.0408*Ar) - 33.7
    UmfWY = ReMf*c["mu"]/(c["rhoF"]*c["d"])
    # Ergun U_mf of the initial packing: ergun(U) = W
    a1 = ergun(c, 1.0) - ergun(c, 0.0) - (ergun(c, 2.0) - 2*ergun(c, 1.0))/2
    a2 = (ergun(c, 2.0) - 2*ergun(c, 1.0))/2
    UmfErgun = (-a1 + np.sqrt(a1**2 + 4*a2*W))/(2*a2)

    times = sorted(mpmPost.times(case), key=float)
    rows = []
    for (t0, t1, U) in steps(t, Us):
        sel = (t >= t1 - args.window - 1e-9) & (t <= t1 + 1e-9)
        m = float(np.mean(dP[sel]))
        wt = [x for x in times if t0 < float(x) <= t1 + 1e-9]
        dE = discreteErgun(c, case, wt[-1], U) if wt else float("nan")
        # Every fluid step after the first `--settle` seconds of the step:
        # catches oscillations and bursts that a mean would hide
        held = (t >= t0 + args.settle - 1e-9) & (t <= t1 + 1e-9)
        rows.append((U, m, float(dP[sel].min()), float(dP[sel].max()), ergun(c, U), dE,
                     float(dP[held].min()), float(dP[held].max())))
    rows = np.array(rows)
    fixed = rows[rows[:, 4] < 0.9*W]       # Ergun below the weight: a packed bed
    fluid = rows[rows[:, 4] > 1.1*W]       # well above U_mf: fluidised

    print("fluidisedBed: d = %g m, rho_s = %g, rho_f = %g, mu = %g, alphaS0 = %g, L0 = %g m, drag %s"
          % (c["d"], c["rhoS"], c["rhoF"], c["mu"], c["alphaS"], c["L0"], c["model"]))
    print("W = (rho_s - rho_f) g alphaS0 L0 = %.2f Pa" % W)
    print("%10s %12s %12s %10s %12s %10s" % ("U [mm/s]", "dP [Pa]", "Ergun [Pa]", "dP/Ergun", "discrete", "dP/W"))
    for U, m, lo, hi, e, de, _, _ in rows:
        print("%10.3f %12.2f %12.2f %10.4f %12.2f %10.4f" % (U*1e3, m, e, m/e, de, m/W))

    # U_mf from the simulation: Ergun-type fit a U + b U^2 of the fixed-bed
    # points, intersected with the mean fluidised plateau
    A = np.vstack([fixed[:, 0], fixed[:, 0]**2]).T
    fa, fb = np.linalg.lstsq(A, fixed[:, 1], rcond=None)[0]
    plateau = float(np.mean(fluid[:, 1]))
    UmfSim = (-fa + np.sqrt(fa**2 + 4*fb*plateau))/(2*fb) if fb > 0 else plateau/fa

    errErgun = fixed[:, 1]/fixed[:, 4] - 1
    errDiscrete = fixed[:, 1]/fixed[:, 5] - 1
    errW = fluid[:, 1]/W - 1
    # worst single fluid step of the fluidised steps, once settled
    devW = np.maximum(np.abs(fluid[:, 6]/W - 1), np.abs(fluid[:, 7]/W - 1))
    print("fixed bed (%d steps): dP/Ergun - 1 in [%.4f, %.4f]; dP/discrete Ergun - 1 in [%.2e, %.2e]"
          % (len(fixed), errErgun.min(), errErgun.max(), errDiscrete.min(), errDiscrete.max()))
    print("fluidised (%d steps): plateau dP/W = %.4f (steps: %s)"
          % (len(fluid), plateau/W, " ".join("%.4f" % (x/W) for x in fluid[:, 1])))
    print("fluidised, every fluid step %.1f s after each step starts: dP/W - 1 within +-%.4f (steps: %s)"
          % (args.settle, devW.max(), " ".join("%.4f" % x for x in devW)))
    print("U_mf simulated = %.3f mm/s, Wen-Yu = %.3f mm/s (sim/WY = %.3f), Ergun(alphaS0) = %.3f mm/s"
          % (UmfSim*1e3, UmfWY*1e3, UmfSim/UmfWY, UmfErgun*1e3))
    # one line for the case test
    print("SUMMARY ergunErrMaxAbs=%.6g discreteErrMaxAbs=%.6g plateauErrMaxAbs=%.6g plateauOverW=%.6g "
          "plateauDevMaxAbs=%.6g UmfSim=%.6g UmfWenYu=%.6g UmfErgun=%.6g nFixed=%d nFluid=%d"
          % (np.abs(errErgun).max(), np.abs(errDiscrete).max(), np.abs(errW).max(), plateau/W, devW.max(),
             UmfSim, UmfWY, UmfErgun, len(fixed), len(fluid)))

    if args.no_plot:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    Uline = np.linspace(0, rows[:, 0].max()*1.05, 200)
    ax.plot(Uline*1e3, ergun(c, Uline), "k--", lw=1, label="Ergun, alphaS = %g" % c["alphaS"])
    ax.axhline(W, color="tab:green", lw=1, label="W = (rho_s - rho_f) g alphaS L0")
    ax.axvline(UmfWY*1e3, color="tab:red", ls=":", label="U_mf Wen-Yu = %.2f mm/s" % (UmfWY*1e3))
    ax.axvline(UmfSim*1e3, color="tab:blue", ls=":", label="U_mf simulated = %.2f mm/s" % (UmfSim*1e3))
    ax.errorbar(rows[:, 0]*1e3, rows[:, 1], yerr=[rows[:, 1] - rows[:, 2], rows[:, 3] - rows[:, 1]],
                fmt="o", color="tab:blue", label="mpmFoam (last %.1f s of each step)" % args.window)
    ax.set_ylim(0, 1.3*W)
    ax.set_xlabel("superficial velocity U [mm/s]")
    ax.set_ylabel("bed pressure drop [Pa]")
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("fluidisedBed: d = %g mm glass in water" % (c["d"]*1e3))
    bx.plot(t, dP/W, lw=1, label="dP / W")
    bx.set_xlabel("t [s]")
    bx.set_ylabel("dP / W")
    bx.set_ylim(0, 1.2)
    bx2 = bx.twinx()
    bx2.plot(t, Us*1e3, color="tab:orange", lw=1)
    bx2.set_ylabel("U [mm/s]", color="tab:orange")
    bx.set_title("history at the plate")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "fluidisedBed.png"), dpi=120)
    print("wrote fluidisedBed.png")


if __name__ == "__main__":
    main()
