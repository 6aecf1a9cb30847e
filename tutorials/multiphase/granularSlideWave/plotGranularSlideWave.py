#!/usr/bin/env python3
"""granularSlideWave: the slide's impact, the impulse wave at the gauges,
and Heller & Hager's (2010) prediction of the maximum wave amplitude.

Reads (case = . by default):
* the seeded cloud (0/lagrangian) and postProcessing/mpmSummary (the
  slide's centre-of-mass velocity every 10 MPM steps);
* postProcessing/g<k>/0/volFieldValue.dat: the water volume in gauge k's
  column of cells every fluid step (system/topoSetDict, controlDict);
* log.mpmFoam: the water volume balance and the range of alpha.water;
* the written clouds and fields (0/C from postProcess -func
  writeCellCentres) for the grain balance and the pictures.

Measures:
* impact: the time t_i at which the slide front (its lowest point) reaches
  the still water level y = h, its front moving rigidly with the centre of
  mass until then (y_front(t) = y_front(0) + int Ucm_y dt); V_s = |Ucm(t_i)|,
  the mean (mass-weighted) velocity of the points at that moment;
* the slide thickness s normal to the slope (the seeded points' largest
  distance from it plus half the point spacing) and its mass per unit
  width m_s = sum m / b (b: the 2D mesh's thickness, 0.01 m);
* P = F S^(1/2) M^(1/4) cos(6/7 alpha)^(1/2), F = V_s/sqrt(g h),
  S = s/h, M = m_s/(rho_w b h^2); predicted a_M/h = (4/9) P^(4/5),
  x_M/h = (11/2) P^(1/2);
* at each gauge the first crest's amplitude a_c1 (the largest eta between
  the wave's arrival, eta first above a fifth of the gauge's maximum, and
  the first fall of eta below half of its largest value since) and its
  time; the measured a_M is the largest a_c1 over the gauges the whole
  crest has passed (eta back below half of it, a_c1 >= h/20);
* the first crest's celerity, a straight line through its times at those
  gauges, against sqrt(g (h + a)); the wave front's (eta first >= h/20)
  arrival times at the gauges and its speed, against sqrt(g (h + a_M)).

Prints a table and a SUMMARY line, and draws granularSlideWave_snapshots.png
and granularSlideWave_gauges.png.

    python3 plotGranularSlideWave.py [case=.] [--no-plot]
"""
import glob
import os
import re
import sys

import numpy as np

import mpmPost

args = [a for a in sys.argv[1:] if not a.startswith("--")]
case = args[0] if args else "."
plot = "--no-plot" not in sys.argv

# Geometry and materials (system/blockMeshDict, setFieldsDict, mpmProperties)
g, rhoW = 9.81, 1000.0
h = 0.2                         # still water depth [m]
alpha = np.radians(45.0)        # slope angle
yTop = 0.55                     # the tank's top [m]
# The slide's width b: the 2D mesh's thickness (0/C from postProcess -func
# writeCellCentres); the seeded points' spacing: the lattice's over the
# points per cell (2 x 2)
b = 2*mpmPost.read_internal_field(case, "0", "C")[:, 2].mean()
dPoint = float(re.search(r"lattice\s*\{\s*spacing\s+([0-9.eE+-]+)",
                         open(os.path.join(case, "constant", "mpmProperties")).read()).group(1))/2
nSlope = np.array([np.sin(alpha), np.cos(alpha)])   # unit normal of the slope, into the tank
# The slope passes through the impact point (0, h): distance from it
slopeDist = lambda x: x[:, 0]*nSlope[0] + (x[:, 1] - h)*nSlope[1]


# ---- the seeded slide ----------------------------------------------------------
x0 = mpmPost.read_positions(case, "0")
m0 = mpmPost.read_cloud_field(case, "0", "mass").reshape(-1)
id0 = mpmPost.read_cloud_field(case, "0", "pointId").reshape(-1).astype(np.int64)
u0 = mpmPost.read_cloud_field(case, "0", "U")
ms = m0.sum()/b                                     # [kg/m]
s = slopeDist(x0).max() + 0.5*dPoint                # thickness normal to the slope
rhoBulk = ms/(len(m0)*dPoint**2)                    # grains per unit slide area [kg/m^3]

# ---- impact: the front reaches the still water level ---------------------------
S_ = mpmPost.read_summary(case)
t = np.concatenate([[0.0], S_["time"]])
ux = np.concatenate([[np.sum(m0*u0[:, 0])/m0.sum()], S_["Ux"]])
uy = np.concatenate([[np.sum(m0*u0[:, 1])/m0.sum()], S_["Uy"]])
dy = np.concatenate([[0.0], np.cumsum(0.5*(uy[1:] + uy[:-1])*np.diff(t))])


def crossing(y0):
    """Time at which y0 + int Ucm_y dt reaches h, and |Ucm| then."""
    y = y0 + dy
    if not np.any(y <= h):
        return np.nan, np.nan           # never reached by the end
    k = int(np.flatnonzero(y <= h)[0])
    f = (y[k - 1] - h)/(y[k - 1] - y[k])
    ti = t[k - 1] + f*(t[k] - t[k - 1])
    vi = np.hypot(np.interp(ti, t, ux), np.interp(ti, t, uy))
    return ti, vi


tImpact, Vs = crossing(x0[:, 1].min())
yc0 = np.sum(m0*x0[:, 1])/m0.sum()
tCentroid, VsCentroid = crossing(yc0)

F = Vs/np.sqrt(g*h)
S = s/h
M = ms/(rhoW*h**2)              # m_s per unit width / (rho_w h^2) = m_s/(rho_w b h^2)
P = F*np.sqrt(S)*M**0.25*np.sqrt(np.cos(6.0/7.0*alpha))
aMpred = 4.0/9.0*P**0.8*h
HMpred = 5.0/9.0*P**0.8*h
xMpred = 5.5*np.sqrt(P)*h

# ---- gauges ------------------------------------------------------------------------
topo = open(os.path.join(case, "system", "topoSetDict")).read()
boxes = re.findall(r"name (g\d+); type cellSet;.*?box \(([-0-9.e]+) [^)]*\) \(([-0-9.e]+)", topo)
gauges = []
for name, lo, hi in boxes:
    f = os.path.join(case, "postProcessing", name, "0", "volFieldValue.dat")
    vol = float(re.search(r"# Volume\s*:\s*(\S+)", open(f).read()).group(1))
    d = np.loadtxt(f, comments="#", ndmin=2)
    eta = d[:, 1]/vol*yTop - h            # water height in the column minus h
    gauges.append(dict(name=name, x=0.5*(float(lo) + float(hi)), t=d[:, 0], eta=eta))
gauges.sort(key=lambda q: q["x"])

for q in gauges:
    e = q["eta"]
    q["max"] = e.max()
    i0 = int(np.flatnonzero(e >= 0.2*e.max())[0])              # arrival
    runMax = np.maximum.accumulate(e[i0:])
    after = np.flatnonzero(e[i0:] < 0.5*runMax)
    i1 = i0 + (int(after[0]) if len(after) else len(e) - i0)   # first fall below half the crest
    k = i0 + int(np.argmax(e[i0:i1]))
    # complete: a crest of at least h/20 that has passed (eta back below half of it)
    q["a1"], q["t1"], q["complete"] = e[k], q["t"][k], bool(len(after)) and e[k] >= 0.05*h
    q["eta0"] = abs(e[0])
    up = np.flatnonzero(e >= 0.05*h)
    q["tArr"] = q["t"][up[0]] if len(up) else np.nan        # the wave front: eta first >= h/20

if not any(q["complete"] for q in gauges):
    sys.exit("plotGranularSlideWave.py: no gauge has seen a whole first crest")
iM = int(np.argmax([q["a1"] if q["complete"] else -1 for q in gauges]))
aMmeas, xMmeas = gauges[iM]["a1"], gauges[iM]["x"]
# The first crest's celerity: a straight line through its times at the
# gauges it has passed, against the solitary wave's sqrt(g (h + a))
xs = np.array([q["x"] for q in gauges])
t1 = np.array([q["t1"] for q in gauges])
a1 = np.array([q["a1"] for q in gauges])
done = np.array([q["complete"] for q in gauges])
cMeas = 1.0/np.polyfit(xs[done], t1[done], 1)[0] if done.sum() >= 2 else np.nan
cSol = np.sqrt(g*(h + a1[done].mean()))
# The wave front (eta = h/20): its arrival times and speed over the gauges
# it has reached, against sqrt(g (h + a_M)) with the measured a_M
tArr = np.array([q["tArr"] for q in gauges])
reached = np.isfinite(tArr)
arrOrdered = int(np.all(np.diff(tArr[reached]) > 0))
cFront = 1.0/np.polyfit(xs[reached], tArr[reached], 1)[0]

# ---- water volume and grains ------------------------------------------------------
bal, amin, amax = [], 1.0, 0.0
for line in open(os.path.join(case, "log.mpmFoam")):
    if line.startswith("VOF: water volume"):
        bal.append(float(re.search(r"balance \(V - V0 \+ out\)/V0 (\S+);", line).group(1)))
        lo, hi = re.search(r"in \[(\S+), (\S+)\]", line).groups()
        amin, amax = min(amin, float(lo)), max(amax, float(hi))
balance = max(abs(v) for v in bal)
times = mpmPost.times(case)
exact = 1
for tt in times:
    ids = mpmPost.read_cloud_field(case, tt, "pointId").reshape(-1).astype(np.int64)
    m = mpmPost.read_cloud_field(case, tt, "mass").reshape(-1)
    o, o0 = np.argsort(ids), np.argsort(id0)
    if len(ids) != len(id0) or not np.array_equal(ids[o], id0[o0]) or not np.array_equal(m[o], m0[o0]):
        exact = 0

# ---- report -------------------------------------------------------------------------
lim = dict(F=(0.86, 6.83, F), S=(0.09, 1.64, S), M=(0.11, 10.02, M), P=(0.17, 8.13, P),
           D=(0.59, 1.72, rhoBulk/rhoW), alpha=(30, 90, np.degrees(alpha)))
print("slide: %d points, m_s = %.3f kg/m (b = %.2f m), bulk density %.0f kg/m^3 (D = %.2f), s = %.4f m"
      % (len(m0), ms, b, rhoBulk, rhoBulk/rhoW, s))
print("impact: front at the still water level at t = %.4f s, V_s = %.3f m/s (centroid at it: t = %.4f s, %.3f m/s)"
      % (tImpact, Vs, tCentroid, VsCentroid))
print("Heller & Hager (2010): F = %.3f, S = %.3f, M = %.3f, alpha = %.0f deg -> P = %.3f" % (F, S, M, np.degrees(alpha), P))
print("    predicted a_M = (4/9) P^(4/5) h = %.4f m (a_M/h %.3f), H_M = %.4f m, x_M = (11/2) P^(1/2) h = %.3f m (X_M %.2f)"
      % (aMpred, aMpred/h, HMpred, xMpred, xMpred/h))
print("    inside their experiments' ranges: " + ", ".join(
    "%s %.3g %s [%g, %g]" % (k, v, "in" if lo <= v <= hi else "OUTSIDE", lo, hi) for k, (lo, hi, v) in lim.items()))
print("gauges (first crest; t_end %.3f s):" % gauges[0]["t"][-1])
print("    %-4s %7s %6s %9s %8s %8s %s" % ("", "x [m]", "X=x/h", "a_c1 [m]", "a_c1/h", "t [s]", "max eta over the record"))
for q in gauges:
    print("    %-4s %7.3f %6.2f %9.4f %8.3f %8.3f %.4f%s" % (q["name"], q["x"], q["x"]/h, q["a1"], q["a1"]/h, q["t1"], q["max"],
                                                       "" if q["complete"] else "  (no whole crest by t_end)"))
print("first-crest celerity (fit over %d gauges): %.3f m/s; sqrt(g (h + mean a_c1)) = %.3f m/s; ratio %.3f"
      % (done.sum(), cMeas, cSol, cMeas/cSol))
print("wave front (eta = h/20) at %d gauges, in order: %s; speed %.3f m/s, over sqrt(g (h + a_M)) %.3f"
      % (reached.sum(), "yes" if arrOrdered else "NO", cFront, cFront/np.sqrt(g*(h + aMmeas))))
print("measured a_M = %.4f m (a_M/h %.3f) at x = %.3f m (X %.2f); measured/predicted = %.3f"
      % (aMmeas, aMmeas/h, xMmeas, xMmeas/h, aMmeas/aMpred))
print("water volume balance: max |(V - V0 + out)/V0| = %.2e over the %d logged steps; alpha.water in [%.3g, %.4g]"
      % (balance, len(bal), amin, amax))
print("grains: %d writes, every seeded id once with its seeded mass: %s" % (len(times), "yes" if exact else "NO"))
print("SUMMARY tEnd=%s nPoints=%d ms=%.6g s=%.6g tImpact=%.6g Vs=%.6g VsCentroid=%.6g F=%.6g S=%.6g M=%.6g P=%.6g "
      "aMpred=%.6g aMmeas=%.6g ratio=%.6g xMmeas=%.6g xMpred=%.6g c=%.6g cRatio=%.6g nFront=%d frontOrdered=%d cFront=%.6g cFrontRatio=%.6g eta0=%.3g "
      "balance=%.3g alphaMin=%.6g alphaMax=%.6g exact=%d nGauges=%d"
      % (times[-1], len(m0), ms, s, tImpact, Vs, VsCentroid, F, S, M, P, aMpred, aMmeas, aMmeas/aMpred, xMmeas, xMpred,
         cMeas, cMeas/cSol, reached.sum(), arrOrdered, cFront, cFront/np.sqrt(g*(h + aMmeas)), max(q["eta0"] for q in gauges), balance, amin, amax, exact, len(gauges)))

if not plot:
    sys.exit(0)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri

# ---- snapshots: water (alpha.water) and the slide ---------------------------------------
C = mpmPost.read_internal_field(case, "0", "C")
tri = mtri.Triangulation(C[:, 0], C[:, 1])
# drop the triangles outside the mesh (across the slope)
cx = C[tri.triangles, 0].mean(axis=1)
cy = C[tri.triangles, 1].mean(axis=1)
tri.set_mask(cx*nSlope[0] + (cy - h)*nSlope[1] < 0)
fieldTimes = mpmPost.field_times(case, "alpha.water")
want = [0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0]
shown = []
for w in want:
    c = min(fieldTimes, key=lambda tt: abs(float(tt) - w))
    if c not in shown and abs(float(c) - w) < 0.026:
        shown.append(c)
fig, axes = plt.subplots(len(shown), 1, figsize=(12, 1.75*len(shown) + 0.6), sharex=True)
axes = np.atleast_1d(axes)
for ax, tt in zip(axes, shown):
    a = mpmPost.read_internal_field(case, tt, "alpha.water")
    ax.tricontourf(tri, np.clip(a, 0, 1), levels=[0.5, 1.01], colors=["#9ecae1"])
    ax.tricontour(tri, a, levels=[0.5], colors="C0", linewidths=1)
    if os.path.isdir(os.path.join(case, tt, "lagrangian", "materialPoints")):
        xp = mpmPost.read_positions(case, tt)
        ax.scatter(xp[:, 0], xp[:, 1], s=0.6, color="#8c6d31")
    ax.fill([-0.35, 0.2, -0.35], [0.55, 0, 0], color="0.6")
    ax.axhline(h, color="k", lw=0.5, ls=":")
    for q in gauges:
        ax.plot([q["x"]]*2, [0, 0.03], color="k", lw=0.6)
    ax.set_ylim(0, yTop)
    ax.set_xlim(-0.35, 2.2)
    ax.set_aspect("equal")
    ax.set_ylabel("y [m]")
    ax.text(0.995, 0.92, "t = %s s" % tt, transform=ax.transAxes, ha="right", va="top")
axes[0].set_title("Granular slide into still water (h = %.1f m, 45° slope): water (alpha.water > 0.5), "
                  "sand points; ticks: the gauges" % h, fontsize=10)
axes[-1].set_xlabel("x [m] (0: the impact point)")
fig.tight_layout()
fig.savefig(os.path.join(case, "granularSlideWave_snapshots.png"), dpi=110)

# ---- gauges ---------------------------------------------------------------------------------
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5))
for i, q in enumerate(gauges):
    off = 0.25*i
    ax1.plot(q["t"], q["eta"]/h + off, "C0", lw=1)
    ax1.plot(q["t1"], q["a1"]/h + off, "k.", ms=4)
    ax1.text(q["t"][-1] + 0.01, off, "X=%.1f" % (q["x"]/h), fontsize=7, va="center")
ax1.set_xlabel("t [s]")
ax1.set_ylabel("eta/h (offset 0.25 per gauge)")
ax1.set_title("Free surface at the gauges (dots: first crests)", fontsize=10)
X = xs/h
ax2.plot(X, a1/h, "o-", label="first crest a_c1/h (mpmFoam)")
ax2.axhline(aMpred/h, color="C3", label="Heller & Hager a_M/h = (4/9) P^(4/5) = %.3f" % (aMpred/h))
ax2.axhspan(0.7*aMpred/h, 1.3*aMpred/h, color="C3", alpha=0.12, label="+-30 %")
ax2.axvline(xMpred/h, color="C3", ls=":", label="x_M/h = (11/2) P^(1/2) = %.2f" % (xMpred/h))
Xf = np.linspace(max(xMpred/h, X.min()), X.max(), 50)
ax2.plot(Xf, 0.8*0.75*(P*Xf**(-1.0/3.0))**0.8, "C3--", lw=1,
         label="(4/5) H(X)/h, H(X)/h = (3/4)(P X^(-1/3))^(4/5) (X > X_M)")
ax2.set_xlabel("X = x/h")
ax2.set_ylabel("a/h")
ax2.set_ylim(0, max(a1.max(), 1.3*aMpred)/h*1.15)
ax2.legend(fontsize=7, loc="lower left")
ax2.set_title("P = %.2f (F %.2f, S %.2f, M %.2f): measured a_M/predicted = %.2f" % (P, F, S, M, aMmeas/aMpred), fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(case, "granularSlideWave_gauges.png"), dpi=110)
print("wrote granularSlideWave_snapshots.png, granularSlideWave_gauges.png")
