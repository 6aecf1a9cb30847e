"""Runout of the 3D collapses of sweepAspectRatio against Lube et al. (2004).

    python3 runout3D.py sweep/a1_h0.02 sweep/a0.5_h0.02 ...

Reads each case's points from its HDF5 checkpoints (HDF5/materialPoints_<t>.h5,
pointOutput hdf5) and its column (the file `column`: r0, h0, a, h). The front
radius r_f is the largest distance of a point from the axis plus half the
point spacing (h/2 at 2 points per cell), as renderPoints3D.py measures it;
the final height H_f likewise. The front must be at rest: its advance over
the last write interval is printed (dr_last). Also printed: the spread of the
front over the quarter (r_f per 10 deg sector, min-max) and the runout of the
sectors' mean front (mean): the front runs furthest along the grid axes. Writes
runoutVsAspectRatio3D.csv and runoutVsAspectRatio3D.png (runout against a,
with Lube et al.'s law and a +-20 % band, see README "Validation").
"""
import glob
import os
import re
import sys

import h5py
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))


def lube(a):
    """Lube et al. (2004), axisymmetric: (r_inf - r_i)/r_i."""
    a = np.asarray(a, dtype=float)
    return np.where(a < 1.7, 1.24*a, 1.6*np.sqrt(a))


BAND = 0.20     # the scatter band about the law (README, "Validation": assumed, not read off the paper)
WINDOW = 1.25   # glass-bead experiments within a factor 1.25 of a run's a are its neighbours


def glass_beads():
    """Lajeunesse et al.'s glass-bead collapses, digitised (lajeunesseGlassBeads.csv: a, runout)."""
    lines = [l for l in open(os.path.join(here, "lajeunesseGlassBeads.csv")) if not l.startswith("#")]
    assert lines[0].strip() == "a,runout", lines[0]
    data = np.array([[float(x) for x in l.split(",")] for l in lines[1:] if l.strip()])
    return {"a": data[:, 0], "runout": data[:, 1]}


def neighbours(beads, a):
    """The experiments' runouts near a, each divided by Lube's law at its own a
    (so that experiments at slightly different a compare): the ratios."""
    near = np.abs(np.log(beads["a"]/a)) <= np.log(WINDOW)
    return beads["runout"][near]/lube(beads["a"][near])


def positions(path):
    with h5py.File(path, "r") as f:
        return np.asarray(f["materialPoints/position"])


def measure(case):
    col = open(os.path.join(case, "column")).read().split()
    c = {col[i]: float(col[i + 1]) for i in range(0, len(col), 2)}
    files = glob.glob(os.path.join(case, "HDF5", "materialPoints_*.h5"))
    times = sorted((float(re.search(r"materialPoints_(.*)\.h5$", f).group(1)), f) for f in files)
    if len(times) < 2:
        sys.exit("runout3D.py: %s: fewer than two HDF5 checkpoints" % case)
    dx = c["h"]/2
    fronts = []
    for t, f in times[-2:]:
        x = positions(f)
        fronts.append(np.hypot(x[:, 0], x[:, 1]).max() + dx/2)
    r = np.hypot(x[:, 0], x[:, 1])
    th = np.degrees(np.arctan2(x[:, 1], x[:, 0]))
    sectors = np.array([r[(th >= s) & (th < s + 10)].max() for s in range(0, 90, 10)]) + dx/2
    rf = fronts[-1]
    return dict(case=case, a=c["a"], h=c["h"], r0=c["r0"], h0=c["h0"], t=times[-1][0], n=len(x),
                rf=rf, runout=(rf - c["r0"])/c["r0"], dr_last=fronts[-1] - fronts[-2],
                smin=sectors.min(), smax=sectors.max(), Hf=x[:, 2].max() + dx/2,
                runout_mean=(sectors.mean() - c["r0"])/c["r0"])


beads = glass_beads()
rows = [measure(c) for c in sys.argv[1:]]
rows.sort(key=lambda d: (d["case"], d["a"]))
print("%-34s %5s %6s %6s %6s %6s %7s %7s %7s %6s %7s %8s %11s %6s"
      % ("case", "a", "h", "r0", "t_end", "n", "r_f", "runout", "Lube", "ratio", "mean", "dr_last", "sectors", "Hf/h0"))
for d in rows:
    d["lube"] = float(lube(d["a"]))
    d["ratio"] = d["runout"]/d["lube"]
    print("%-34s %5.2f %6.4f %6.3f %6.2f %6d %7.3f %7.3f %7.3f %6.3f %7.3f %8.4f %5.3f-%5.3f %6.3f"
          % (d["case"], d["a"], d["h"], d["r0"], d["t"], d["n"], d["rf"], d["runout"], d["lube"],
             d["ratio"], d["runout_mean"], d["dr_last"], d["smin"], d["smax"], d["Hf"]/d["h0"]))
# The experiments' scatter: every runout between a = 0.3 and 4 divided by
# Lube's law at its a, its median and the standard deviation of the logs
inRange = (beads["a"] >= 0.3) & (beads["a"] <= 4)
allRatios = beads["runout"][inRange]/lube(beads["a"][inRange])
median, sigma = np.median(allRatios), np.std(np.log(allRatios), ddof=1)
print("\nAgainst the glass-bead experiments (lajeunesseGlassBeads.csv, digitised), each runout"
      " divided by Lube's law at its own a:")
print("  all %d between a = 0.3 and 4: median %.3f, standard deviation of ln %.3f (a factor %.3f)"
      % (len(allRatios), median, sigma, np.exp(sigma)))
print("  z: ln(model/median)/sigma; the neighbours: the experiments within a factor %g of the run's a" % WINDOW)
print("%-34s %5s %7s %6s %4s %13s %8s" % ("case", "a", "model", "z", "n", "neighbours", "median"))
for d in rows:
    r = neighbours(beads, d["a"])
    d["beads_n"], d["beads_min"], d["beads_max"] = len(r), (r.min() if len(r) else np.nan), (r.max() if len(r) else np.nan)
    d["beads_median"] = np.median(r) if len(r) else np.nan
    d["beads_z"] = np.log(d["ratio"]/median)/sigma
    print("%-34s %5.2f %7.3f %6.2f %4d %6.3f-%6.3f %8.3f"
          % (d["case"], d["a"], d["ratio"], d["beads_z"], len(r), d["beads_min"], d["beads_max"], d["beads_median"]))

csv = os.path.join(here, "runoutVsAspectRatio3D.csv")
with open(csv, "w") as f:
    f.write("case,a,h,r0,h0,t_end,points,r_f,runout,lube,ratio,runout_sector_mean,dr_last,sector_min,sector_max,Hf_over_h0,"
            "beads_n,beads_min,beads_max,beads_median,beads_z\n")
    for d in rows:
        f.write("%s,%g,%g,%.6g,%.6g,%g,%d,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%d,%.5f,%.5f,%.5f,%.5f\n"
                % (d["case"], d["a"], d["h"], d["r0"], d["h0"], d["t"], d["n"], d["rf"], d["runout"],
                   d["lube"], d["ratio"], d["runout_mean"], d["dr_last"], d["smin"], d["smax"], d["Hf"]/d["h0"],
                   d["beads_n"], d["beads_min"], d["beads_max"], d["beads_median"], d["beads_z"]))
print("Wrote %s" % csv)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(7, 5))
aa = np.linspace(0.3, 4, 300)
ax.plot(aa, lube(aa), "k-", label="Lube et al. (2004): 1.24 a, 1.6 a$^{1/2}$")
ax.fill_between(aa, (1 - BAND)*lube(aa), (1 + BAND)*lube(aa), color="0.85",
                label="$\\pm$%d %% about the law (scatter band, README)" % round(100*BAND))
ax.plot(beads["a"], beads["runout"], "x", color="0.45", ms=5,
        label="glass beads, Lajeunesse et al. (digitised, lajeunesseGlassBeads.csv)")
def label(tag):
    """h0.02_mu0.577_floor0.45 -> 'h = 0.02 m, mu = 0.577 (30.0 deg), floor mu_w 0.45'"""
    parts = dict(re.match(r"(h|muI|mu|phi|floor)(.*)", p).groups() for p in tag.split("_"))
    text = "h = %s m" % parts["h"]
    if "muI" in parts:
        text += ", mu(I), glass beads (muS = tan 22 deg)"
    elif "phi" in parts:
        text += ", phi = %s deg" % parts["phi"]
    else:
        mu = float(parts.get("mu", 0.601))
        text += ", mu = %.3f (tan %.1f deg)" % (mu, np.degrees(np.arctan(mu)))
    if "floor" in parts:
        text += ", floor " + ("noSlip" if parts["floor"] == "noSlip" else "mu_w = " + parts["floor"])
    return text


groups = {}
for d in rows:
    tag = os.path.basename(d["case"]).split("_", 1)[1]       # h<h>[_...]
    groups.setdefault(tag, []).append(d)
markers = "osD^v<>"
for i, (tag, ds) in enumerate(sorted(groups.items())):
    ds.sort(key=lambda d: d["a"])
    ax.plot([d["a"] for d in ds], [d["runout"] for d in ds], markers[i % len(markers)] + "-",
            label="mpmFoam " + label(tag))
ax.set_xlabel("aspect ratio a = h$_0$/r$_0$")
ax.set_ylabel("runout (r$_f$ - r$_0$)/r$_0$")
ax.set_xlim(0, 4)
ax.set_ylim(0, None)
ax.grid(alpha=0.3)
ax.legend(fontsize=8, loc="upper left")
ax.set_title("Axisymmetric collapse (3D, quarter domain): runout vs aspect ratio", fontsize=10)
png = os.path.join(here, "runoutVsAspectRatio3D.png")
fig.tight_layout()
fig.savefig(png, dpi=120)
print("Wrote %s" % png)
