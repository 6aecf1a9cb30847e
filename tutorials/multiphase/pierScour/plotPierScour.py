"""pierScour: the bed around the pier, and the grain mass balance.

For the seeded cloud (HDF5/seededPoints.h5, checked against the ASCII cloud
mpmSetParticles wrote in 0/) and every HDF5 write (HDF5/materialPoints_<t>.h5):

* grain mass balance, exact: every seeded point id once, each point's mass
  bit-equal to its seeded mass, the total equal to the seeded total;
* bed surface per 1 cm x 1 cm column (the MPM lattice's columns): the height
  of the highest point in the column (points start 2 per cell in z, the top
  ones at 3.75 cm, 2.5 mm under the 4 cm bed top), minus the seeded one;
* the lowering at the pier's front (the columns just upstream of it, on its
  axis), its two sides (the columns beside it, across its centre) and far
  from it (x = 0.30-0.45 m, outside the wake band |y - 0.125| < 0.05 m);
  reported as the mean lowering of those columns [m] (positive = lower).

Prints a table and a SUMMARY line, and draws pierScour.png: plan view of the
bed elevation change at the last write, and lowering against time.

    python3 plotPierScour.py [case=.] [--no-plot]
"""
import glob
import os
import sys

import h5py
import numpy as np

import mpmPost

args = [a for a in sys.argv[1:] if not a.startswith("--")]
case = args[0] if args else "."
plot = "--no-plot" not in sys.argv

# Geometry (system/blockMeshDict, system/snappyHexMeshDict)
L, W, HB = 0.5, 0.25, 0.04
XP, YP, D = 0.17, 0.125, 0.05
h = 0.01                                    # lattice spacing: column size
nx, ny = int(round(L/h)), int(round(W/h))

files = sorted(glob.glob(os.path.join(case, "HDF5", "materialPoints_*.h5")),
               key=lambda f: float(f.rsplit("_", 1)[1][:-3]))
if not files:
    sys.exit("plotPierScour.py: no HDF5/materialPoints_*.h5 in %s: run the case first (./Allrun)" % case)


def read(f):
    with h5py.File(f, "r") as d:
        g = d["materialPoints"]
        x = g["position"][...]
        m = g["mass"][...].reshape(-1)
        ids = g["pointId"][...].reshape(-1).astype(np.int64)
    o = np.argsort(ids, kind="stable")
    return x[o], m[o], ids[o]


def top(x):
    """Highest point per column (nan where a column holds none)."""
    i = np.clip((x[:, 0]/h).astype(int), 0, nx - 1)
    j = np.clip((x[:, 1]/h).astype(int), 0, ny - 1)
    z = np.full(nx*ny, -np.inf)
    np.maximum.at(z, i*ny + j, x[:, 2])
    z[np.isinf(z)] = np.nan
    return z.reshape(nx, ny)


# Seeded cloud: what mpmSetParticles wrote (ASCII, time 0) and mpmFoam's copy
x0, m0, id0 = read(os.path.join(case, "HDF5", "seededPoints.h5"))
mA = mpmPost.read_cloud_field(case, "0", "mass").reshape(-1)
iA = mpmPost.read_cloud_field(case, "0", "pointId").reshape(-1).astype(np.int64)
oA = np.argsort(iA, kind="stable")
seededSame = np.array_equal(iA[oA], id0) and np.array_equal(mA[oA], m0)
M0 = m0.sum()
z0 = top(x0)

xc = (np.arange(nx) + 0.5)*h
yc = (np.arange(ny) + 0.5)*h
X, Y = np.meshgrid(xc, yc, indexing="ij")
R = np.hypot(X - XP, Y - YP)
# Columns whose whole square lies outside the pier (its edge within the
# column would make the top point depend on how much of it the pier takes)
clear = R > D/2 + h/np.sqrt(2)
front = clear & (np.abs(Y - YP) < h) & (X < XP) & (X > XP - D/2 - 2*h)
side = clear & (np.abs(X - XP) < h) & (np.abs(Y - YP) < D/2 + 2*h)
far = (X > 0.30) & (X < 0.45) & (np.abs(Y - YP) > 0.05) & (Y > h) & (Y < W - h)
regions = (("front", front), ("side", side), ("far", far))

rows = []
for f in files:
    t = float(f.rsplit("_", 1)[1][:-3])
    x, m, ids = read(f)
    sameIds = len(ids) == len(id0) and np.array_equal(ids, id0)
    sameMass = sameIds and np.array_equal(m, m0)
    dz = top(x) - z0
    low = {n: -np.nanmean(dz[r]) for n, r in regions}
    deepest = -np.nanmin(dz[clear])
    k = np.nanargmin(np.where(clear, dz, np.nan))
    rows.append(dict(t=t, n=len(ids), ids=sameIds, mass=sameMass, dM=m.sum() - M0,
                     deepest=deepest, where=(X.flat[k], Y.flat[k]), dz=dz, **low))

print("pierScour: bed lowering (highest point per 1 cm column vs seeded) in %s" % os.path.abspath(case))
print("columns: front %d, side %d, far %d" % (front.sum(), side.sum(), far.sum()))
print("%6s %8s %6s %6s %10s %10s %10s %10s %10s  %s" % (
    "t [s]", "points", "ids", "mass", "dM [kg]", "front [m]", "side [m]", "far [m]", "deepest", "at (x, y)"))
for r in rows:
    print("%6.2f %8d %6s %6s %10.1e %10.4f %10.4f %10.4f %10.4f  (%.3f, %.3f)" % (
        r["t"], r["n"], r["ids"], r["mass"], r["dM"], r["front"], r["side"], r["far"],
        r["deepest"], r["where"][0], r["where"][1]))
exact = seededSame and all(r["ids"] and r["mass"] for r in rows)
print("seeded: %d points, %.9g kg; mpmSetParticles' cloud and HDF5/seededPoints.h5 the same: %s"
      % (len(id0), M0, seededSame))
print("grain mass balance exact at every write (each id once, each mass bit-equal): %s" % exact)
last = rows[-1]
print("SUMMARY tEnd=%g exact=%d front=%.5f side=%.5f far=%.5f deepest=%.5f"
      % (last["t"], int(exact), last["front"], last["side"], last["far"], last["deepest"]))

if plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.2), gridspec_kw={"width_ratios": [1.6, 1]})
    v = max(np.nanmax(np.abs(last["dz"])), 1e-4)*1e3
    im = a.pcolormesh(np.arange(nx + 1)*h, np.arange(ny + 1)*h, last["dz"].T*1e3,
                      cmap="RdBu", vmin=-v, vmax=v, shading="flat")
    a.add_patch(plt.Circle((XP, YP), D/2, color="k"))
    for n, r in regions:
        a.contour(xc, yc, r.T.astype(float), [0.5], colors="k", linewidths=0.6)
    a.set_aspect("equal")
    a.set_xlabel("x [m] (flow +x)")
    a.set_ylabel("y [m]")
    a.set_title("bed elevation change at t = %g s [mm]" % last["t"])
    fig.colorbar(im, ax=a)
    t = [r["t"] for r in rows]
    for n, _ in regions:
        b.plot(t, [r[n]*1e3 for r in rows], "o-", label=n)
    b.plot(t, [r["deepest"]*1e3 for r in rows], "k:", label="deepest column")
    b.set_xlabel("t [s]")
    b.set_ylabel("bed lowering [mm]")
    b.legend()
    b.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(case, "pierScour.png"), dpi=110)
    print("wrote %s" % os.path.join(case, "pierScour.png"))
