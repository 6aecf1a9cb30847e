"""terrainFlow: nothing leaks through the terrain.

For every HDF5 write of the run (HDF5/materialPoints_<t>.h5): the points'
height above the STL's own surface (terrain.py, the same single-precision
triangles), the point count and the total mass against the seeded ones, and
the front (the largest x reached by 99 % of the mass). Prints a table and
the verdict, and draws terrainFlow.png: side and plan views of the points at
several times over the valley.

    python3 checkTerrain.py [case=.] [--no-plot]
"""
import glob
import os
import sys

import h5py
import numpy as np

import terrain

args = [a for a in sys.argv[1:] if not a.startswith("--")]
case = args[0] if args else "."
plot = "--no-plot" not in sys.argv
files = sorted(glob.glob(os.path.join(case, "HDF5", "materialPoints_*.h5")),
               key=lambda f: float(f.rsplit("_", 1)[1][:-3]))
if not files:
    sys.exit("checkTerrain.py: no HDF5/materialPoints_*.h5 in %s: run the case first (./Allrun)" % case)

h = 0.02
rows, clouds = [], []
for f in files:
    t = float(f.rsplit("_", 1)[1][:-3])
    with h5py.File(f, "r") as d:
        x = d["materialPoints/position"][...]
        m = d["materialPoints/mass"][...].reshape(-1)
        ids = d["materialPoints/pointId"][...].reshape(-1)
    above = x[:, 2] - terrain.surface_height(x[:, 0], x[:, 1])
    order = np.argsort(x[:, 0])
    cum = np.cumsum(m[order])/m.sum()
    front = x[order][np.searchsorted(cum, 0.99), 0]
    rows.append((t, len(m), m.sum(), above.min(), front, int(ids.astype(np.int64).sum())))
    clouds.append((t, x))

# The seeded cloud at time 0 (HDF5 writes start at the first write time
# after 0): count, mass and id sum, exact
import mpmPost
seeded = None
if os.path.isdir(os.path.join(case, "0", "lagrangian", "materialPoints")):
    m = mpmPost.read_cloud_field(case, "0", "mass").reshape(-1)
    ids = mpmPost.read_cloud_field(case, "0", "pointId").reshape(-1)
    seeded = (len(m), m.sum(), int(ids.astype(np.int64).sum()))
t0, n0, m0, _, _, id0 = rows[0]
if seeded:
    n0, m0, id0 = seeded
print("terrainFlow: points against the terrain (%s)" % case)
print("%6s %8s %14s %16s %10s" % ("t [s]", "points", "mass error", "lowest above [m]", "front [m]"))
for t, n, m, low, front, ids in rows:
    print("%6.2f %8d %14.2e %16.2e %10.3f" % (t, n, m/m0 - 1, low, front))
lowest = min(r[3] for r in rows)
same = all(r[1] == n0 and r[5] == id0 for r in rows)
if seeded:
    print("seeded (time 0): %d points, mass %.9g kg" % seeded[:2])
dm = max(abs(r[2]/m0 - 1) for r in rows)
# A point may sit a hair below a concave stretch of the surface (the valley
# floor): containment holds it outside the tangent planes of the nearby
# lattice nodes, within h^2/(2 R) of the surface (R its radius of curvature,
# >= 0.3 m here: 7e-4 m). Deeper would be a leak.
tol = h*h/(2*0.3)
print("lowest point above the terrain over all times: %.2e m (bound for the concave valley floor: -%.1e m)" % (lowest, tol))
print("points and ids the same at every time: %s; largest mass error %.1e" % (same, dm))
print("nothing leaked: %s" % (lowest > -tol and same and dm < 1e-12))
print("runout: front at %.3f m at t = %.2f s (released between x = 0.04 and 0.24 m)" % (rows[-1][4], rows[-1][0]))

if plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (side, top) = plt.subplots(2, 1, figsize=(9, 7), gridspec_kw={"height_ratios": [1, 1.1]})
    xs = np.linspace(0, 1.2, 200)
    side.plot(xs, terrain.height(xs, 0.3), "k-", lw=1.5, label="terrain, valley axis")
    if seeded:
        clouds.insert(0, (0.0, mpmPost.read_positions(case, "0")))
    shown = [c for c in clouds if c[0] in (0.0, 0.3, 0.6) or c is clouds[-1]]
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(shown)))
    for (t, x), col in zip(shown, colours):
        side.scatter(x[:, 0], x[:, 2], s=1, color=col, label="t = %.1f s" % t)
    side.set_xlim(0, 1.2); side.set_ylim(0, 0.45); side.set_aspect("equal")
    side.set_xlabel("x [m]"); side.set_ylabel("z [m]"); side.legend(fontsize=7, markerscale=6)
    side.set_title("Sand down an STL valley (decomposed, HDF5): side view")
    X, Y = np.meshgrid(xs, np.linspace(0, 0.6, 60))
    top.contour(X, Y, terrain.height(X, Y), 12, colors="0.7", linewidths=0.7)
    t, x = clouds[-1]
    sc = top.scatter(x[:, 0], x[:, 1], s=1, c=x[:, 2] - terrain.surface_height(x[:, 0], x[:, 1]), cmap="viridis")
    fig.colorbar(sc, ax=top, label="point height above the ground [m]")
    top.set_xlim(0, 1.2); top.set_ylim(0, 0.6); top.set_aspect("equal")
    top.set_xlabel("x [m]"); top.set_ylabel("y [m]"); top.set_title("plan view at t = %.1f s (terrain contours)" % t)
    fig.tight_layout()
    out = os.path.join(case, "terrainFlow.png")
    fig.savefig(out, dpi=120)
    print("wrote %s" % out)
