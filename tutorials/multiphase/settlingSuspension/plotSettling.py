"""settlingSuspension: interfaces of a settling suspension vs Richardson-Zaki.

From the written alpha.solid profiles (1D column, cell centres y_i):
  * suspension interface (top, falling): the highest height where
    alpha.solid crosses alpha0/2, linear between cell centres;
  * sediment interface (bottom, rising): the highest height where
    alpha.solid crosses (alpha0 + alphaMax)/2 (none until the bottom cells
    pack beyond the suspension).
The settling velocity is the least-squares slope of the top interface over
the free-settling window: from t = 0.25 s (start-up over) to the last write
before alpha.solid first reaches alphaMax anywhere (the sediment is held only
by the cap and the wall; see README.md). It is compared with

    Richardson-Zaki  u = Ut alphaF^n,  n = (4.7 + 0.41 Re_t^0.75)/(1 + 0.175 Re_t^0.75)
                                               (Rowe 1987; 4.7 as Re_t -> 0)

with Ut, Re_t = rho_f Ut d/mu the Schiller-Naumann single-grain terminal
velocity (fixed-point solution of 18 mu/d^2 (1 + 0.15 Re^0.687) Ut =
(rho_s - rho_f) g). Also printed: the steady settling velocity of the drag
law itself (Wen-Yu, model A: beta slip = alphaF alphaS (rho_s - rho_f) g,
lab-frame solid velocity alphaF slip), the solver's exact target.

Prints "settling velocity ratio measured/Richardson-Zaki <r>". Writes
settlingSuspension.png unless --no-plot.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

import mpmPost

ap = argparse.ArgumentParser()
ap.add_argument("--case", default=".")
ap.add_argument("--no-plot", action="store_true")
ap.add_argument("--t0", type=float, default=0.25, help="start of the fit window [s]")
args = ap.parse_args()
case = args.case


def read_text(path):
    with open(os.path.join(case, path)) as f:
        return re.sub(r"//.*", "", f.read())


def keyword(text, key):
    return float(re.search(r"\b" + key + r"\s+([-+0-9.eE]+)\s*;", text).group(1))


# Case parameters
mpmProps = read_text("constant/mpmProperties")
transport = read_text("constant/transportProperties")
seeding = read_text("system/mpmSetParticlesDict")
rhoS = keyword(mpmProps, "rho")
d = float(re.search(r"drag\s*\{[^}]*\bd\s+([-+0-9.eE]+)", mpmProps).group(1))
alphaMax = keyword(mpmProps, "alphaMax")
nu = keyword(transport, "nu")
rhoF = keyword(transport, "rho")
mu = nu*rhoF
alpha0 = keyword(seeding, "solidFraction")
gvec = [float(x) for x in re.search(r"value\s*\(([^)]*)\)", read_text("constant/g")).group(1).split()]
g = math.sqrt(sum(x*x for x in gvec))
aF = 1 - alpha0


def cdre_sn(re_):
    return 24*(1 + 0.15*re_**0.687) if re_ < 1000 else 0.44*re_


# Single-grain Schiller-Naumann terminal velocity
ust = (rhoS - rhoF)*g*d*d/(18*mu)
Ut = ust
for _ in range(500):
    Ut = ust/(1 + 0.15*(rhoF*Ut*d/mu)**0.687)
Ret = rhoF*Ut*d/mu
n = (4.7 + 0.41*Ret**0.75)/(1 + 0.175*Ret**0.75)
uRZ = Ut*aF**n

# Wen-Yu (model A) steady settling: beta(u) u = aF aS drho g, bisection on u
lo, hi = 0.0, Ut/aF
for _ in range(200):
    u = 0.5*(lo + hi)
    re_ = aF*rhoF*u*d/mu
    beta = 0.75*cdre_sn(re_)*mu*alpha0/d**2*aF**-2.65
    if beta*u > aF*alpha0*(rhoS - rhoF)*g:
        hi = u
    else:
        lo = u
uWY = aF*0.5*(lo + hi)

# Interfaces from the written alpha.solid
times = [t for t in mpmPost.field_times(case, "alpha.solid") if float(t) > 0]
h = None
tt, top, sed, amax = [], [], [], []
for t in times:
    a = np.atleast_1d(mpmPost.read_internal_field(case, t, "alpha.solid"))
    if h is None:
        nc = a.size
        ys = [float(v) for v in re.findall(r"^height\s+([-+0-9.eE]+)", read_text("system/blockMeshDict"), re.M)]
        H = ys[0]
        h = H/nc
        y = (np.arange(nc) + 0.5)*h
        # A graded mesh: its written cell centres (postProcess -func
        # writeCellCentres), h then their mean spacing
        cfile = os.path.join(case, t, "C")
        if os.path.exists(cfile):
            y = np.atleast_2d(mpmPost.read_internal_field(case, t, "C"))[:, 1]

    def crossing(level):
        above = np.flatnonzero(a > level)
        if above.size == 0:
            return np.nan
        k = above.max()
        if k + 1 >= a.size:
            return y[k]
        return y[k] + (a[k] - level)/(a[k] - a[k + 1])*(y[k + 1] - y[k])

    tt.append(float(t))
    top.append(crossing(0.5*alpha0))
    sed.append(crossing(0.5*(alpha0 + alphaMax)))
    amax.append(a.max())
tt, top, sed, amax = map(np.array, (tt, top, sed, amax))

packed = np.flatnonzero(amax >= alphaMax*(1 - 1e-9))
tPacked = tt[packed[0]] if packed.size else np.inf
win = (tt >= args.t0) & (tt < tPacked) & np.isfinite(top)
if win.sum() < 3:
    print("settling: fewer than 3 writes in the free-settling window; cannot fit")
    sys.exit(1)
slope, icpt = np.polyfit(tt[win], top[win], 1)
resid = top[win] - (slope*tt[win] + icpt)
uMeas = -slope
# Standard error of the slope
se = math.sqrt((resid**2).sum()/(win.sum() - 2)/((tt[win] - tt[win].mean())**2).sum())

print("settling: rho_s %g, rho_f %g, mu %g, d %g, alpha.solid %g, g %g" % (rhoS, rhoF, mu, d, alpha0, g))
print("settling: Schiller-Naumann Ut %.6g m/s, Re_t %.4g; Rowe n %.4f" % (Ut, Ret, n))
print("settling: Richardson-Zaki u = Ut alphaF^n = %.6g m/s" % uRZ)
print("settling: Wen-Yu model-A steady settling %.6g m/s (%.4f x Richardson-Zaki)" % (uWY, uWY/uRZ))
print("settling: alpha.solid first reaches alphaMax at t = %s s" % (("%g" % tPacked) if np.isfinite(tPacked) else "never"))
print("settling: fit window %g - %g s (%d writes), interface fell %.4g m = %.3g cells, rms residual %.3g m = %.3g cells"
      % (tt[win][0], tt[win][-1], win.sum(), top[win][0] - top[win][-1], (top[win][0] - top[win][-1])/h,
         math.sqrt((resid**2).mean()), math.sqrt((resid**2).mean())/h))
print("settling: measured settling velocity %.6g m/s (standard error %.2g, %.2g %%)" % (uMeas, se, 100*se/uMeas))
print("settling: measured/Wen-Yu model %.5f" % (uMeas/uWY))
print("settling velocity ratio measured/Richardson-Zaki %.5f" % (uMeas/uRZ))

if not args.no_plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    ax.plot(tt, 1e3*top, "o", ms=3, label="suspension interface (alpha.solid = alpha0/2)")
    ax.plot(tt, 1e3*sed, "s", ms=3, label="sediment interface (alpha.solid = (alpha0+alphaMax)/2)")
    tl = np.array([0, tt[-1]])
    ax.plot(tl, 1e3*(top[win][0] + uRZ*tt[win][0] - uRZ*tl), "k--", lw=1,
            label="Richardson-Zaki, n = %.2f (Rowe 1987)" % n)
    ax.plot(tt[win], 1e3*(slope*tt[win] + icpt), "r-", lw=1, label="fit: %.3g mm/s" % (1e3*uMeas))
    if np.isfinite(tPacked):
        ax.axvline(tPacked, color="grey", lw=0.8, ls=":")
        ax.text(tPacked, 1e3*np.nanmax(top)*0.5, " alphaMax reached", color="grey", fontsize=8)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("height [mm]")
    ax.set_title("Settling suspension: alpha.solid %g, d %g mm, measured/RZ %.3f" % (alpha0, 1e3*d, uMeas/uRZ))
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "settlingSuspension.png"), dpi=120)
