#!/usr/bin/env python3
"""Silo discharge: the rate through the slot against time and fill height,
and the steady rate against the slot width D with Beverloo's 2D law.

For each run (runs/<name>, or the cases given) the removed mass M_out(t)
and the mass present M(t) come from postProcessing/openBoundaries/*/
(slot.dat, massBalance.dat). Per unit thickness (the mesh is one cell
thick, t_z = h):
    rate W(t)   slope of M_out over a sliding 0.1 s window, / t_z
    fill H(t)   M(t)/(rho W_silo t_z): the mean height of the material
    steady W    slope of M_out over the steady window: from t = 0.4 s (the
                start-up transient) to the end or until H falls to 2 D
                (the fluid: to the end)
    flatness    the slopes over the two halves of that window, their
                relative difference (a fluid's sqrt(H) gives ~ the
                relative change of sqrt(H))
Beverloo, 2D slot (plane flow): W = C rho_b sqrt(g) (D - k d)^(3/2), with
k d = 0 for a continuum (no grain size). The exponent is fitted by least
squares of log W on log D, and C = W/(rho sqrt(g) D^(3/2)) per width. The
fluid run: W against sqrt(2 g H), Torricelli's W = Cc rho D sqrt(2 g H).

Writes rate.png and beverloo.png (unless --no-plot) and prints the table.

--convergence: the cases are one slot at several cell sizes (Allrun
convergence); per shape function, C = W/(rho sqrt(g) D^1.5) at each h, its
change on each cell halving, and over the last three the observed order, the
Richardson value and its GCI band (mpmPost.richardson);
convergence.png (C against D/h).
Usage: plotDischarge.py [case ...] [--no-plot] [--convergence]
"""
import glob
import os
import re
import sys

import numpy as np

import mpmPost

RHO, G = 1600.0, 9.81


def slab(case):
    """Thickness of the one-cell-thick mesh: the z extent of the fill box."""
    box = open(os.path.join(case, "system", "mpmSetParticlesDict")).read()
    m = re.search(r"max\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)", re.sub(r"//.*", "", box))
    return float(m.group(1))


def silo(case):
    """Silo width and slot width, from slotMesh's header line."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    m = re.search(r"box W = ([0-9.eE+-]+), H = [0-9.eE+-]+, slot D = ([0-9.eE+-]+)", text)
    return float(m.group(1)), float(m.group(2))


def slotCells(case):
    """Cells across the slot, from blockMeshDict's middle block."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    blocks = re.findall(r"hex \([^)]*\) \((\d+) (\d+) 1\)", text)
    return int(blocks[1][0])


def slope(t, m):
    A = np.vstack([t, np.ones_like(t)]).T
    return np.linalg.lstsq(A, m, rcond=None)[0][0]


def analyse(case, t0=0.4, window=0.1, hmin=2.0):
    out = mpmPost.read_open_boundary(case, "slot")
    bal = mpmPost.read_open_boundary(case, "massBalance")
    tz = slab(case)
    width, D = silo(case)
    t, mout, m = out["time"], out["removedMass"], bal["presentMass"]
    H = m/(RHO*width*tz)
    # sliding-window rate
    tr, rate, Hr = [], [], []
    for i in range(len(t)):
        s = (t >= t[i] - window/2) & (t <= t[i] + window/2)
        if t[i] - window/2 < t[0] or t[i] + window/2 > t[-1] or s.sum() < 5:
            continue
        tr.append(t[i]); rate.append(slope(t[s], mout[s])/tz); Hr.append(H[i])
    steady = (t >= t0) & (H >= hmin*D)
    ts = t[steady]
    W = slope(ts, mout[steady])/tz
    mid = 0.5*(ts[0] + ts[-1])
    a, b = steady & (t <= mid), steady & (t >= mid)
    Wa, Wb = slope(t[a], mout[a])/tz, slope(t[b], mout[b])/tz
    Ha, Hb = H[a].mean(), H[b].mean()
    clamped = int(bal["clamped"][-1])
    return dict(case=case, width=width, D=D, W=W, Wa=Wa, Wb=Wb, Ha=Ha, Hb=Hb, t0=ts[0], t1=ts[-1],
                H0=H[steady][0], H1=H[steady][-1], t=np.array(tr), rate=np.array(rate),
                H=np.array(Hr), clamped=clamped, balance=np.abs(bal["massError"]).max()/bal["initialMass"][0])


def fluid(case):
    text = open(os.path.join(case, "system", "mpmSetParticlesDict")).read()
    return "water" in text


def shapeFunction(case):
    text = re.sub(r"//.*", "", open(os.path.join(case, "constant", "mpmProperties")).read())
    return re.search(r"^\s*shapeFunction\s+(\w+)\s*;", text, re.M).group(1)


def convergence(cases):
    """C of one slot under refinement, per shape function."""
    runs = [analyse(c) for c in cases]
    C = lambda r: float(beverlooC(r["D"], r["W"]))
    cell = lambda r: r["D"]/slotCells(r["case"])
    print("rho %g, g %g; steady window t >= 0.4 s while H >= 2 D" % (RHO, G))
    print("%-16s %6s %7s %5s %9s %7s %9s %8s" % ("shape", "D", "h", "D/h", "W", "C", "halving", "clamped"))
    curves = {}
    for shape in sorted(set(shapeFunction(r["case"]) for r in runs)):
        group = sorted([r for r in runs if shapeFunction(r["case"]) == shape], key=cell, reverse=True)
        Cs = [C(r) for r in group]
        for i, r in enumerate(group):
            change = "%+8.1f%%" % (100*(Cs[i]/Cs[i - 1] - 1)) if i else "%9s" % "-"
            print("%-16s %6.3f %7.4f %5.0f %9.4g %7.3f %s %8d"
                  % (shape, r["D"], cell(r), r["D"]/cell(r), r["W"], Cs[i], change, r["clamped"]))
        if len(Cs) >= 3:
            print("%-16s %s" % (shape, mpmPost.richardson_line(Cs)))
        curves[shape] = ([r["D"]/cell(r) for r in group], Cs)
    print("max |mass balance error|/initial mass over the runs: %.2g" % max(r["balance"] for r in runs))
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.4))
    for shape, (n, Cs) in curves.items():
        ax.plot(n, Cs, "o-", label=shape)
    ax.set_xscale("log", base=2)
    ax.set_xlabel("cells across the slot D/h"); ax.set_ylabel("C = W/(rho sqrt(g) D^1.5)")
    ax.grid(alpha=0.3, which="both"); ax.legend(fontsize=8)
    ax.set_title("Discharge constant under refinement (D = %g m)" % runs[0]["D"])
    fig.tight_layout(); fig.savefig("convergence.png", dpi=120)


def beverlooC(D, W, delta=0.0):
    """Beverloo's constant of each run: C = W/(rho sqrt(g) (D - delta)^1.5)."""
    return np.asarray(W)/(RHO*np.sqrt(G)*(np.asarray(D) - delta)**1.5)


def exponentFit(D, W, delta=0.0):
    """Least squares of log W on log (D - delta): (n, ln A, squared residual)
    of W = A (D - delta)^n."""
    (n, lnA), res = np.polyfit(np.log(np.asarray(D) - delta), np.log(W), 1, full=True)[:2]
    return n, lnA, float(res[0]) if len(res) else 0.0


def excludedWidthFit(D, W, steps=981):
    """Beverloo's excluded width k d = delta in [0, 0.98 min D] (steps
    values) of least residual in exponentFit: (n, ln A, delta)."""
    best = min(((exponentFit(D, W, delta), delta) for delta in np.linspace(0, 0.98*np.min(D), steps)),
               key=lambda fit: fit[0][2])
    (n, lnA, _), delta = best
    return n, lnA, delta


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if "--convergence" in sys.argv:
        convergence(args)
        return
    cases = args or sorted(glob.glob("runs/*"))
    cases = [c for c in cases if os.path.isdir(os.path.join(c, "postProcessing", "openBoundaries"))]
    # The fluid's rate has no plateau to wait for: its window runs to the end
    runs = []
    for c in cases:
        try:
            runs.append(analyse(c, hmin=0 if fluid(c) else 2))
        except (IndexError, ValueError):
            print("%s: no steady window yet (a run not past t = 0.4 s), left out" % c)
    if not runs:
        sys.exit("plotDischarge.py: no finished run among %s (a run directory has postProcessing/openBoundaries)"
                 % (" ".join(args) or "runs/*"))
    sand = sorted([r for r in runs if not fluid(r["case"])], key=lambda r: r["D"])
    water = [r for r in runs if fluid(r["case"])]
    print("rho %g, g %g; rates per unit thickness [kg/(m s)]; H: mean fill height [m]" % (RHO, G))
    print("%-22s %6s %9s %9s %9s %8s %8s %8s %8s %8s" % ("run", "D", "W", "W 1st", "W 2nd", "H 1st", "H 2nd",
                                                          "change", "C", "clamped"))
    for r in sand + water:
        C = float(beverlooC(r["D"], r["W"]))
        print("%-22s %6.3f %9.4g %9.4g %9.4g %8.3f %8.3f %+7.1f%% %8.3f %8d" % (
            os.path.basename(r["case"]), r["D"], r["W"], r["Wa"], r["Wb"], r["Ha"], r["Hb"],
            100*(r["Wb"]/r["Wa"] - 1), C, r["clamped"]))
    for r in water:
        sq = np.sqrt(r["Hb"]/r["Ha"])
        Cc = r["W"]/(RHO*r["D"]*np.sqrt(2*G*0.5*(r["Ha"] + r["Hb"])))
        print("fluid %s: W 2nd/1st = %.3f, sqrt(H 2nd/H 1st) = %.3f; Torricelli Cc = W/(rho D sqrt(2 g H)) = %.3f"
              % (os.path.basename(r["case"]), r["Wb"]/r["Wa"], sq, Cc))
    # A sweep per cell size; the fits where it has three widths or more
    cell = lambda r: round(r["D"]/slotCells(r["case"]), 12)
    fits = {}
    for h in sorted(set(cell(r) for r in sand), reverse=True):
        group = [r for r in sand if cell(r) == h]
        D = np.array([r["D"] for r in group]); W = np.array([r["W"] for r in group])
        C = beverlooC(D, W)
        print("cell h = %g m: D/h = %s, C = W/(rho sqrt(g) D^1.5) = %s"
              % (h, " ".join("%.0f" % x for x in D/h), " ".join("%.3f" % c for c in C)))
        if len(group) < 3:
            continue
        n, lnA, _ = exponentFit(D, W)
        print("    Beverloo, k d = 0: W ~ D^%.3f (expected 3/2)" % n)
        # With an excluded width delta (Beverloo's k d): the exponent fitted
        # for each delta, the delta of least residual
        nd, lnAd, delta = excludedWidthFit(D, W)
        Cd = beverlooC(D, W, delta)
        print("    Beverloo, k d fitted: delta = %.4f m = %.2f h; W ~ (D - delta)^%.3f; "
              "C = W/(rho sqrt(g) (D - delta)^1.5) = %s, mean %.3f"
              % (delta, delta/h, nd, " ".join("%.3f" % c for c in Cd), Cd.mean()))
        fits[h] = (D, W, n, lnA, nd, lnAd, delta)
    # The slot resolved (D/h >= 10: C no longer grows with D/h, see the
    # resolution lines below), whatever the cell size: the exponent
    resolved = sorted([r for r in sand if r["D"]/cell(r) >= 10 - 1e-9], key=lambda r: r["D"])
    def printExponentFit(group, label):
        """W ~ D^n (k d = 0) over runs of three widths or more: prints it
        with each run's C under `label`, returns (n, ln A) or None."""
        if len(set(r["D"] for r in group)) < 3:
            return None
        D = np.array([r["D"] for r in group]); W = np.array([r["W"] for r in group])
        n, lnA, _ = exponentFit(D, W)
        C = beverlooC(D, W)
        print("%s: %s; W ~ D^%.3f (k d = 0); C = %s, mean %.3f"
              % (label, " ".join("D = %g (h = %g)" % (r["D"], cell(r)) for r in group), n,
                 " ".join("%.3f" % c for c in C), C.mean()))
        return n, lnA
    resolvedFit = printExponentFit(resolved, "resolved slots (D/h >= 10)")
    # One relative resolution D/h for every width: the exponent without the
    # bias of resolving the narrow slots worse than the wide ones
    for ratio in sorted(set(round(r["D"]/cell(r)) for r in sand)):
        printExponentFit(sorted([r for r in sand if round(r["D"]/cell(r)) == ratio], key=lambda r: r["D"]),
                         "D/h = %d for every width" % ratio)
    for Dv in sorted(set(r["D"] for r in sand)):
        same = sorted([r for r in sand if r["D"] == Dv], key=cell, reverse=True)
        if len(same) > 1:
            print("resolution, D = %g: %s" % (Dv, "; ".join(
                "h = %g (D/h = %.0f) C = %.3f" % (cell(r), r["D"]/cell(r), float(beverlooC(Dv, r["W"])))
                for r in same)))
    print("max |mass balance error|/initial mass over the runs: %.2g" % max(r["balance"] for r in runs))
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for r in sand + water:
        lab = ("fluid, " if r in water else "sand, ") + "D = %g m" % r["D"]
        ax[0].plot(r["t"], r["rate"], label=lab, ls="--" if r in water else "-")
        late = r["t"] >= 0.3          # past the start-up
        line, = ax[1].plot(r["H"][late], r["rate"][late], label=lab, ls="--" if r in water else "-")
        if r in water:
            Hs = np.linspace(r["H"][late].min(), r["H"][late].max(), 50)
            Cc = r["W"]/(RHO*r["D"]*np.sqrt(2*G*0.5*(r["Ha"] + r["Hb"])))
            ax[1].plot(Hs, Cc*RHO*r["D"]*np.sqrt(2*G*Hs), ":", color=line.get_color(),
                       label="Torricelli, Cc = %.2f" % Cc)
    ax[0].set_xlabel("time [s]"); ax[0].set_ylabel("discharge rate W [kg/(m s)]")
    ax[1].set_xlabel("mean fill height H [m] (t > 0.3 s)"); ax[1].set_ylabel("discharge rate W [kg/(m s)]")
    ax[1].legend(fontsize=8)
    for a in ax:
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    ax[0].set_title("Silo discharge: rate against time")
    ax[1].set_title("against fill height: sand flat, fluid ~ sqrt(H)")
    fig.tight_layout(); fig.savefig("rate.png", dpi=120)
    if fits or sand:
        fig, ax = plt.subplots(figsize=(6, 4.4))
        allD = np.array([r["D"] for r in sand])
        Ds = np.linspace(allD.min()*0.95, allD.max()*1.05, 80)
        for h in sorted(set(cell(r) for r in sand), reverse=True):
            group = [r for r in sand if cell(r) == h]
            line, = ax.loglog([r["D"] for r in group], [r["W"] for r in group], "o",
                              label="mpmFoam, Drucker-Prager, h = %g m" % h)
            if h in fits:
                D, W, n, lnA, nd, lnAd, delta = fits[h]
                ax.loglog(Ds, np.exp(lnA)*Ds**n, ":", color=line.get_color(), lw=0.8,
                          label="  fit, k d = 0: W ~ D^%.2f" % n)
                ok = Ds > delta
                ax.loglog(Ds[ok], np.exp(lnAd)*(Ds[ok] - delta)**nd, "-", color=line.get_color(),
                          label="  fit: W ~ (D - %.1f h)^%.2f" % (delta/h, nd))
        if resolvedFit:
            n, lnA = resolvedFit
            ax.loglog(Ds, np.exp(lnA)*Ds**n, "r-", lw=2, alpha=0.5,
                      label="fit, slots resolved (D/h >= 10): W ~ D^%.2f" % n)
        ax.loglog(Ds, 1.03*RHO*np.sqrt(G)*Ds**1.5, "k--", label="Beverloo 2D, C = 1.03, k d = 0")
        ax.set_xlabel("slot width D [m]"); ax.set_ylabel("W [kg/(m s)]")
        ax.grid(alpha=0.3, which="both"); ax.legend(fontsize=7)
        ax.set_title("Discharge rate against slot width")
        fig.tight_layout(); fig.savefig("beverloo.png", dpi=120)

if __name__ == "__main__":
    main()
