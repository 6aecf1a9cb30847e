#!/usr/bin/env python3
"""damBreakSandBed: the dam break over the movable sand bed (this case) and
over the fixed bed (fixedBed/, interFoam, the floor at the bed's top),
against Ritter's solution.

At every write of both runs: the free surface (the topmost crossing of
alpha.water = 0.5 in each column of cells, interpolated), the water depth
over the bed, the front (the furthest column downstream of the gate where
the water is deeper than 5 mm, interpolated) and the depth at the gate. For the
movable bed also the bed level from the points: in 2 cm wide columns, the
height the column's sand would fill packed at the seeded solid fraction 0.6
(the sum of the points' solid volume m/rho_s over 0.6 x width x dz; exact
mass, so what leaves one column is found in others). Prints a table per write, the bed's lowering near the gate,
the deposit, the bed far from the wave, the exact grain balance (every
seeded id once, each mass bit-equal to its seeded mass) and a SUMMARY line
for the test; writes damBreakSandBed.png (profiles at 0.25, 0.5, 0.75 and
1 s) and damBreakSandBed_front.png (the bed's change and the fronts against
time) unless --no-plot.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python"))
import mpmPost  # noqa: E402

G = 9.81
X0 = 1.5            # the gate [m] (system/setFieldsDict)
H0 = 0.35           # water depth over the bed behind the gate [m]
BED = 0.1           # the seeded bed's top [m] (system/mpmSetParticlesDict)
RHO_S, AS0 = 2650.0, 0.6
DMIN = 0.005        # the front: the furthest water deeper than 5 mm
C0 = np.sqrt(G*H0)
SHOWN = (0.25, 0.5, 0.75, 1.0)


def mesh(case):
    """Cell-centre coordinates of the uniform blockMesh (x fastest)."""
    d = os.path.join(case, "system", "blockMeshDict")
    L, H, y0 = (mpmPost.dict_scalar(d, k) for k in ("L", "H", "yFloor"))
    nx, ny = (int(mpmPost.dict_scalar(d, k)) for k in ("nx", "ny"))
    h = L/nx
    return (np.arange(nx) + 0.5)*h, y0 + (np.arange(ny) + 0.5)*(H - y0)/ny, h


def free_surface(case, t, xc, yc):
    """Height of the topmost crossing of alpha.water = 0.5 per column."""
    nx, ny = len(xc), len(yc)
    a = np.clip(mpmPost.read_internal_field(case, t, "alpha.water").reshape(ny, nx), 0, 1)
    eta = np.full(nx, np.nan)
    dy = yc[1] - yc[0]
    for i in range(nx):
        js = np.flatnonzero(a[:, i] >= 0.5)
        if len(js):
            j = js.max()
            eta[i] = yc[j] + (dy*(a[j, i] - 0.5)/(a[j, i] - a[j + 1, i]) if j + 1 < ny else 0.5*dy)
    return eta


def front(xc, depth):
    """The furthest column downstream of the gate whose depth exceeds DMIN,
    interpolated to where the depth falls to DMIN (as the surge front on
    the floor of tests/cases/vofColumnCollapse.sh)."""
    d = np.nan_to_num(depth, nan=0.0)
    wet = np.flatnonzero((d > DMIN) & (xc > X0))
    if not len(wet):
        return X0
    i = wet.max()
    if i + 1 >= len(xc):
        return xc[-1]
    return xc[i] + (xc[i + 1] - xc[i])*(d[i] - DMIN)/(d[i] - d[i + 1])


def ritter_depth(x, t):
    """Ritter (1892): dam break of depth H0 at X0 over a dry frictionless bed."""
    xi = (np.asarray(x) - X0)/t
    h = (2*C0 - xi)**2/(9*G)
    return np.where(xi <= -C0, H0, np.where(xi >= 2*C0, 0.0, h))


def bed_surface(case, t, width=0.02):
    """Bed level per column of the given width: the height its points' sand
    would fill packed at the seeded fraction (sum of m/rho_s over
    AS0 width dz); one point moved in or out changes it by 1.25 mm."""
    x = mpmPost.read_positions(case, t)
    vs = mpmPost.read_cloud_field(case, t, "mass")/RHO_S
    d = os.path.join(case, "system", "blockMeshDict")
    dz, length = mpmPost.dict_scalar(d, "dz"), mpmPost.dict_scalar(d, "L")
    nb = int(round(length/width))
    ib = np.clip((x[:, 0]/width).astype(int), 0, nb - 1)
    level = np.bincount(ib, weights=vs, minlength=nb)/(AS0*width*dz)
    return (np.arange(nb) + 0.5)*width, level, x, mpmPost.read_cloud_field(case, t, "U")


def grain_balance(case):
    """1 when every written cloud holds each seeded id once with its seeded
    mass bit-equal; the seeded count and mass."""
    ts = mpmPost.times(case)

    def cloud(t):
        ids = mpmPost.read_cloud_field(case, t, "pointId").astype(np.int64)
        o = np.argsort(ids)
        return ids[o], mpmPost.read_cloud_field(case, t, "mass")[o]
    ids0, m0 = cloud(ts[0])
    exact = all(np.array_equal(i, ids0) and np.array_equal(m, m0) for i, m in (cloud(t) for t in ts[1:]))
    return int(exact), len(ids0), m0.sum(), len(ts)


def water_balance(case):
    """Largest |balance| of the VOF water volume over the logged steps."""
    log = os.path.join(case, "log.mpmFoam")
    if not os.path.isfile(log):
        return float("nan"), 0
    v = [abs(float(m)) for m in re.findall(r"balance \(V - V0 \+ out\)/V0 (\S+);", open(log).read())]
    return (max(v) if v else float("nan")), len(v)


def main():
    ap = mpmPost.plot_parser()
    ap.add_argument("--fixed", default=None, help="the fixed-bed case (default: <case>/fixedBed)")
    args = ap.parse_args()
    case = args.case
    fixed = args.fixed or os.path.join(case, "fixedBed")
    xc, yc, _ = mesh(case)
    xf_, yf_, _ = mesh(fixed)
    tsM = [t for t in mpmPost.times(case)]
    tsF = set(mpmPost.field_times(fixed, "alpha.water"))
    xb, bed0, _, _ = bed_surface(case, tsM[0])

    rows, prof = [], {}
    print("   t   Ritter front | fixed bed: front  (x_f-x0)/(Ritter's)  depth at gate | movable bed: front  "
          "(x_f-x0)/fixed's  depth at gate | bed lowering, x0 - 0.2 < x < x0 + 0.1: mean, deepest (at x) | "
          "deposit: highest (at x) | far bed: upstream end, ahead of the wave [mm]")
    for t in tsM[1:]:
        tf = float(t)
        etaM = free_surface(case, t, xc, yc)
        xb, bed, pts, U = bed_surface(case, t)
        dM = etaM - np.interp(xc, xb, bed)
        fM = front(xc, dM)
        gM = np.interp(X0, xc, dM)
        if t in tsF:
            etaF = free_surface(fixed, t, xf_, yf_)
            dF = etaF - BED
            fF, gF = front(xf_, dF), np.interp(X0, xf_, dF)
            fan = (xf_ > X0) & (xf_ < fF - 0.3)         # the gate to 0.3 m behind the front
            eR = dF[fan] - ritter_depth(xf_[fan], tf)
            dR, mR = (np.abs(eR).max(), eR.mean()) if fan.any() else (float("nan"), float("nan"))
        else:
            etaF, fF, gF, dR, mR = None, float("nan"), float("nan"), float("nan"), float("nan")
        fR = X0 + 2*C0*tf
        low = bed0 - bed
        gate = (xb > X0 - 0.2) & (xb < X0 + 0.1)
        iDeep = int(np.argmax(low))
        iHigh = int(np.argmax(-low))
        up = xb < 0.5
        ahead = xb > fF + 0.2 if np.isfinite(fF) else xb > fM + 0.2
        r = dict(t=tf, dR=dR, mR=mR, fR=fR, fF=fF, rF=(fF - X0)/(fR - X0), gF=gF, fM=fM, rM=(fM - X0)/(fF - X0), gM=gM,
                 lowGate=low[gate].mean(), lowMax=low[iDeep], xDeep=xb[iDeep], rise=-low[iHigh], xRise=xb[iHigh],
                 farUp=np.abs(low[up]).max(), farAhead=np.abs(low[ahead]).max() if ahead.any() else 0.0,
                 eroded=np.sum(np.clip(low, 0, None))*(xb[1] - xb[0]), deposited=np.sum(np.clip(-low, 0, None))*(xb[1] - xb[0]))
        rows.append(r)
        prof[tf] = (etaM, etaF, bed, pts, U)
        print("%5.3f  %6.3f       |          %6.3f  %6.3f               %6.4f         |            %6.3f  %6.3f"
              "            %6.4f        |  %5.1f, %5.1f (%.2f)  |  %5.1f (%.2f)  |  %.2f, %.2f"
              % (tf, fR, fF, r["rF"], gF, fM, r["rM"], gM, 1e3*r["lowGate"], 1e3*r["lowMax"], r["xDeep"],
                 1e3*r["rise"], r["xRise"], 1e3*r["farUp"], 1e3*r["farAhead"]))
    print("Ritter: front x0 + 2 sqrt(g h0) t (front speed %.3f m/s), depth at the gate 4 h0/9 = %.4f m" % (2*C0, 4*H0/9))
    # front speeds between consecutive writes
    sF = [(rows[k]["fF"] - rows[k - 1]["fF"])/(rows[k]["t"] - rows[k - 1]["t"]) for k in range(1, len(rows))]
    sM = [(rows[k]["fM"] - rows[k - 1]["fM"])/(rows[k]["t"] - rows[k - 1]["t"]) for k in range(1, len(rows))]
    print("front speed between writes [m/s]: fixed bed %s; movable bed %s (Ritter %.3f)"
          % (" ".join("%.3f" % s for s in sF), " ".join("%.3f" % s for s in sM), 2*C0))
    for r in rows:
        print("t = %.3f: fixed bed's depth - Ritter's from the gate to 0.3 m behind the front: max |.| %.4f m, mean %+.4f m"
              % (r["t"], r["dR"], r["mR"]))
    for r in rows:
        print("t = %.3f: bed eroded %.3g m^2, deposited %.3g m^2 (per unit width, bed volume)" % (r["t"], r["eroded"], r["deposited"]))
    exact, n, m, nw = grain_balance(case)
    wb, nwb = water_balance(case)
    print("seeded: %d points, %.6g kg; exact at every write (%d): %s; water volume balance max %.3g over %d steps"
          % (n, m, nw, "yes" if exact else "NO", wb, nwb))
    byT = {round(r["t"], 6): r for r in rows}
    summ = ["tEnd=%g" % rows[-1]["t"], "exact=%d" % exact, "nPoints=%d" % n, "waterBalance=%.6g" % wb]
    for t in SHOWN:
        r = byT.get(t)
        if r:
            k = ("%g" % t).replace(".", "")
            summ += ["fixedRatio%s=%.6g" % (k, r["rF"]), "movableRatio%s=%.6g" % (k, r["rM"]),
                     "gateDepthFixed%s=%.6g" % (k, r["gF"]), "lowGate%s=%.6g" % (k, r["lowGate"]),
                     "deposit%s=%.6g" % (k, r["rise"]), "xDeposit%s=%.6g" % (k, r["xRise"]),
                     "farUp%s=%.6g" % (k, r["farUp"]), "farAhead%s=%.6g" % (k, r["farAhead"])]
    summ += ["fixedSpeedLast=%.6g" % (sF[-1] if sF else float("nan")),
             "movableSpeedLast=%.6g" % (sM[-1] if sM else float("nan"))]
    print("SUMMARY " + " ".join(summ))
    if args.no_plot:
        return

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shown = [t for t in SHOWN if t in prof]
    fig, axs = plt.subplots(len(shown), 1, figsize=(13, 2.6*len(shown)), sharex=True)
    for ax, t in zip(np.atleast_1d(axs), shown):
        etaM, etaF, bed, pts, U = prof[t]
        sp = np.hypot(U[:, 0], U[:, 1])
        sc = ax.scatter(pts[:, 0], pts[:, 1], s=0.3, c=sp, cmap="copper_r", vmin=0, vmax=1.0, rasterized=True)
        ax.plot(xb, bed, color="saddlebrown", lw=1.2, label="bed level (movable)")
        ax.axhline(BED, color="0.6", lw=0.6)
        ax.plot(xc, etaM, color="tab:blue", lw=1.4, label="free surface, movable bed")
        if etaF is not None:
            ax.plot(xf_, etaF, "--", color="tab:red", lw=1.2, label="free surface, fixed bed")
        xr = np.linspace(0, 5, 1001)
        ax.plot(xr, BED + ritter_depth(xr, t), ":", color="k", lw=1.2, label="Ritter")
        ax.axvline(X0, color="0.5", lw=0.5, ls="--")
        ax.set_ylim(0, 0.5)
        ax.set_xlim(0, 5)
        ax.set_ylabel("y [m]")
        ax.set_title("t = %g s" % t, loc="left", fontsize=10)
    np.atleast_1d(axs)[0].legend(loc="upper right", fontsize=8, ncol=2)
    np.atleast_1d(axs)[-1].set_xlabel("x [m] (gate at x0 = %.1f m)" % X0)
    fig.colorbar(sc, ax=axs, label="grain speed [m/s]", shrink=0.6)
    fig.savefig(os.path.join(case, "damBreakSandBed.png"), dpi=110)

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(13, 4.2))
    for t in shown:
        a1.plot(xb, 1e3*(prof[t][2] - bed0), label="t = %g s" % t)
    a1.axvline(X0, color="0.5", lw=0.5, ls="--")
    a1.set_xlim(X0 - 0.7, X0 + 2.0)
    a1.set_xlabel("x [m]")
    a1.set_ylabel("bed level - seeded [mm]")
    a1.set_title("movable bed: the bed's change", fontsize=10)
    a1.legend(fontsize=8)
    tt = np.array([r["t"] for r in rows])
    a2.plot(np.r_[0, tt], X0 + 2*C0*np.r_[0, tt], "k:", label="Ritter, x0 + 2 sqrt(g h0) t")
    a2.plot(tt, [r["fF"] for r in rows], "s--", color="tab:red", label="fixed bed (interFoam)")
    a2.plot(tt, [r["fM"] for r in rows], "o-", color="tab:blue", label="movable bed (mpmFoam)")
    a2.set_xlabel("t [s]")
    a2.set_ylabel("front x_f [m]")
    a2.set_title("front: depth > 5 mm", fontsize=10)
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(case, "damBreakSandBed_front.png"), dpi=110)
    print("wrote damBreakSandBed.png, damBreakSandBed_front.png")


if __name__ == "__main__":
    main()
