#!/usr/bin/env python3
"""Wedge hopper: the steady discharge rate against Beverloo's 2D law with a
hopper-angle factor, per grid and slot width.

For each run (runs/<name>, or the cases given) the removed mass M_out(t)
and the mass present M(t) come from postProcessing/openBoundaries/*/
(slot.dat, massBalance.dat). Rates are per unit thickness (the mesh is one
cell thick, t_z = h):
    steady W    slope of M_out from t = 0.4 s (after the start-up) to the
                end, while at least 40 % of the initial mass is present;
                'change' compares the slopes of the window's two halves
    C           W/(rho sqrt(g) D^1.5)
Runs come in three kinds: 'wedge' (the hopper, walls 30 deg from the
vertical, mu_w 0.3), 'flat' (the same box without the inclined walls: a
flat-bottomed bin) and 'smooth' (the hopper with slip walls).

Reference (README.md): Beverloo for a slot, continuum (k d = 0),
    W_flat = C_B rho sqrt(g) D^1.5,
times the hopper-angle factor of Rose & Tanaka (1959),
    F = (tan theta tan beta)^-0.35 for theta < 90 deg - beta, else 1,
theta = 30 deg (the wall from the vertical), beta the angle of a flat
bin's stagnant-zone boundary to the horizontal: 45 to 60 deg gives
F = 1.21 to 1.00; and Brown's minimum-energy estimate for a wedge (derived
in README.md), F = sqrt(theta/sin^2 theta)/sqrt(pi/2) = 1.155.
Checked per grid: the wedge/flat ratio at the same D and h (the factor,
with the discretisation's own flat-bottom deficit divided out) and the
exponent of W on D.

Writes hopper.png (unless --no-plot): points of the finest wedge run at
mid-discharge coloured by speed, and C against D/h.
Usage: plotHopper.py [case ...] [--no-plot]
"""
import glob
import os
import re
import sys

import numpy as np

import mpmPost

RHO, G = 1600.0, 9.81
THETA = np.radians(30.0)
# Rose & Tanaka's factor for a stagnant-zone angle beta (deg)
roseTanaka = lambda beta: max(1.0, (np.tan(THETA)*np.tan(np.radians(beta)))**-0.35)
F_RT = (roseTanaka(60.0), roseTanaka(45.0))
F_BROWN = np.sqrt(THETA/np.sin(THETA)**2)/np.sqrt(np.pi/2)


def geometry(case):
    """Box width, slot width D and cell size h from slotMesh's header."""
    text = open(os.path.join(case, "system", "blockMeshDict")).read()
    m = re.search(r"box W = ([0-9.eE+-]+), H = [0-9.eE+-]+, slot D = ([0-9.eE+-]+), h = ([0-9.eE+-]+)", text)
    return float(m.group(1)), float(m.group(2)), float(m.group(3))


def kind(case):
    text = re.sub(r"//.*", "", open(os.path.join(case, "constant", "mpmProperties")).read())
    if "hopperLeft" not in text:
        return "flat"
    return "smooth" if re.search(r"hopperLeft\s*\{[^}]*type\s+slip", text) else "wedge"


def slope(t, m):
    return np.polyfit(t, m, 1)[0]


def analyse(case, t0=0.4, keep=0.4):
    out = mpmPost.read_open_boundary(case, "slot")
    bal = mpmPost.read_open_boundary(case, "massBalance")
    width, D, h = geometry(case)
    t, mout, m = out["time"], out["removedMass"], bal["presentMass"]
    steady = (t >= t0) & (m >= keep*bal["initialMass"][0])
    ts = t[steady]
    W = slope(ts, mout[steady])/h
    mid = 0.5*(ts[0] + ts[-1])
    a, b = steady & (t <= mid), steady & (t >= mid)
    Wa, Wb = slope(t[a], mout[a])/h, slope(t[b], mout[b])/h
    return dict(case=case, name=os.path.basename(case), kind=kind(case), D=D, h=h, W=W, Wa=Wa, Wb=Wb,
                t0=ts[0], t1=ts[-1], C=W/(RHO*np.sqrt(G)*D**1.5), clamped=int(bal["clamped"][-1]),
                balance=np.abs(bal["massError"]).max()/bal["initialMass"][0],
                removed=bal["removedMass"][-1], initial=bal["initialMass"][0])


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    cases = [c for c in (args or sorted(glob.glob("runs/*")))
             if os.path.isdir(os.path.join(c, "postProcessing", "openBoundaries"))]
    runs = sorted([analyse(c) for c in cases], key=lambda r: (r["kind"], -r["h"], r["D"]))
    print("rho %g, g %g; rates per unit thickness [kg/(m s)]; window t >= 0.4 s while M >= 0.4 M0" % (RHO, G))
    print("%-20s %-6s %6s %7s %5s %9s %8s %8s %7s %8s" % ("run", "kind", "D", "h", "D/h", "W", "change", "C",
                                                           "t1", "clamped"))
    for r in runs:
        print("%-20s %-6s %6.3f %7.4f %5.0f %9.4g %+7.1f%% %8.3f %7.3f %8d" % (
            r["name"], r["kind"], r["D"], r["h"], r["D"]/r["h"], r["W"], 100*(r["Wb"]/r["Wa"] - 1), r["C"],
            r["t1"], r["clamped"]))
    print("hopper-angle factor F (theta = 30 deg): Rose & Tanaka %.3f (beta = 60 deg) to %.3f (beta = 45 deg);"
          " minimum energy %.3f" % (F_RT[0], F_RT[1], F_BROWN))
    key = lambda r: (round(r["D"], 9), round(r["h"], 9))
    flat = {key(r): r for r in runs if r["kind"] == "flat"}
    for r in runs:
        if r["kind"] in ("wedge", "smooth") and key(r) in flat:
            f = flat[key(r)]
            print("ratio %-6s/flat  D = %.3f, h = %.4f (D/h = %2.0f): %.3f" % (r["kind"], r["D"], r["h"],
                                                                          r["D"]/r["h"], r["W"]/f["W"]))
    for k in ("wedge", "flat"):
        for h in sorted(set(r["h"] for r in runs if r["kind"] == k), reverse=True):
            g = sorted([r for r in runs if r["kind"] == k and r["h"] == h], key=lambda r: r["D"])
            if len(g) >= 2:
                n = np.polyfit(np.log([r["D"] for r in g]), np.log([r["W"] for r in g]), 1)[0]
                print("exponent %-5s h = %.4f: W ~ D^%.2f (D = %s; Beverloo 1.5)"
                      % (k, h, n, " ".join("%g" % r["D"] for r in g)))
    same = {}
    for r in runs:
        if r["kind"] == "wedge":
            same.setdefault(round(r["D"]/r["h"], 6), []).append(r)
    for n, g in sorted(same.items()):
        if len(g) >= 2:
            g.sort(key=lambda r: r["D"])
            e = np.log(g[-1]["W"]/g[0]["W"])/np.log(g[-1]["D"]/g[0]["D"])
            print("exponent wedge at the same D/h = %g: W ~ D^%.2f (%s)" % (n, e, ", ".join(r["name"] for r in g)))
    for h in sorted(set(r["h"] for r in runs), reverse=True):
        pass
    print("max |mass balance error|/initial mass over the runs: %.2g" % max(r["balance"] for r in runs))
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 5), gridspec_kw={"width_ratios": [1, 1.25]})
    wedge = [r for r in runs if r["kind"] == "wedge"]
    show = min(wedge, key=lambda r: (r["h"], -r["D"]))
    ts = [t for t in mpmPost.times(show["case"]) if 0.3 <= float(t) <= 0.7]
    if ts:
        t = ts[-1]
        p = mpmPost.read_positions(show["case"], t)
        U = mpmPost.read_cloud_field(show["case"], t, "U")
        sc = ax0.scatter(p[:, 0], p[:, 1], c=np.linalg.norm(U, axis=1), s=1.5, cmap="viridis", vmin=0)
        fig.colorbar(sc, ax=ax0, label="speed [m/s]")
        width, D, h = geometry(show["case"])
        y = (width - D)/2/np.tan(THETA)
        for x0, s in (((width - D)/2, -1), ((width + D)/2, 1)):
            ax0.plot([x0, x0 + s*y*np.tan(THETA)], [0, y], "k-", lw=1.5)
        ax0.plot([(width - D)/2, (width + D)/2], [0, 0], "r-", lw=3, label="slot (outlet)")
        ax0.set_aspect("equal"); ax0.set_xlim(0, width); ax0.set_ylim(-0.02, 0.45)
        ax0.set_title("%s at t = %s s" % (show["name"], t), fontsize=10); ax0.legend(fontsize=8, loc="upper right")
    for k, mk in (("wedge", "o"), ("flat", "s"), ("smooth", "^")):
        for D in sorted(set(r["D"] for r in runs if r["kind"] == k)):
            g = sorted([r for r in runs if r["kind"] == k and r["D"] == D], key=lambda r: r["h"], reverse=True)
            ax1.plot([r["D"]/r["h"] for r in g], [r["C"] for r in g], mk + "-", label="%s D = %g m" % (k, D))
    ax1.axhspan(1.03*F_RT[0], 1.03*F_RT[1], color="C2", alpha=0.15, label="1.03 x Rose-Tanaka F (beta 45-60)")
    ax1.axhspan(1.21*F_RT[0], 1.24*F_RT[1], color="C3", alpha=0.12,
                label="siloDischarge converged flat C 1.21-1.24 x F")
    ax1.axhline(1.03, color="k", ls=":", lw=1, label="flat 2D Beverloo C = 1.03")
    ax1.set_xlabel("cells across the slot D/h"); ax1.set_ylabel("C = W/(rho sqrt(g) D^1.5)")
    ax1.grid(alpha=0.3); ax1.legend(fontsize=7, loc="lower right")
    ax1.set_title("Discharge constant: 30 deg wedge hopper and flat bin", fontsize=10)
    fig.tight_layout(); fig.savefig("hopper.png", dpi=110)


if __name__ == "__main__":
    main()
