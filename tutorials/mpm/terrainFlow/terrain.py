"""The terrain of the terrainFlow tutorial: a valley that runs down along x,
steep at its head, flattening out into a basin and rising gently after it,
with a parabolic cross-section:

    z(x, y) = 0.05 + 0.3 exp(-x/0.4) + 0.2 (x/1.2)^2 + 0.6 (y - 0.3)^2   [m]

(slope 37 deg at x = 0, 21 deg at x = 0.2 m, lowest at x = 0.6 m, rising
16 deg at x = 1.2 m; the valley's sides rise 5 cm over 0.3 m). As an STL it is a closed solid: this surface on a grid of
spacing `step`, vertical sides down to z = -0.1 m and a flat bottom, with
outward normals. Shared by makeTerrain.py (writes it) and checkTerrain.py
(measures the points against the same triangles).
"""
import numpy as np

X0, X1, Y0, Y1 = -0.05, 1.25, -0.05, 0.65   # beyond the 1.2 x 0.6 m mesh
BOTTOM = -0.1
NX, NY = 65, 35                             # grid cells: 2 cm


def height(x, y):
    return 0.05 + 0.3*np.exp(-x/0.4) + 0.2*(x/1.2)**2 + 0.6*(y - 0.3)**2


def grid():
    xs = np.linspace(X0, X1, NX + 1)
    ys = np.linspace(Y0, Y1, NY + 1)
    return xs, ys


def triangles():
    """(n, 3, 3) corners of the closed solid's triangles, normals outward
    (counter-clockwise seen from outside), in single precision as an STL
    stores them."""
    xs, ys = grid()
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    top = np.stack([X, Y, height(X, Y)], axis=-1)
    bot = np.stack([X, Y, np.full_like(X, BOTTOM)], axis=-1)
    tris = []
    for i in range(NX):
        for j in range(NY):
            a, b, c, d = top[i, j], top[i + 1, j], top[i + 1, j + 1], top[i, j + 1]
            tris += [(a, b, c), (a, c, d)]              # up
            a, b, c, d = bot[i, j], bot[i + 1, j], bot[i + 1, j + 1], bot[i, j + 1]
            tris += [(a, c, b), (a, d, c)]              # down
    # Sides: the boundary of the grid, walked counter-clockwise seen from
    # above, each edge joined to the bottom
    ring = [(i, 0) for i in range(NX)] + [(NX, j) for j in range(NY)] \
        + [(i, NY) for i in range(NX, 0, -1)] + [(0, j) for j in range(NY, 0, -1)]
    for k, (i, j) in enumerate(ring):
        i2, j2 = ring[(k + 1) % len(ring)]
        p, q = top[i, j], top[i2, j2]
        pb, qb = bot[i, j], bot[i2, j2]
        tris += [(pb, qb, q), (pb, q, p)]
    return np.asarray(tris, dtype=np.float32).astype(float)


def surface_height(x, y):
    """The STL's own surface height at (x, y): the plane of the grid
    triangle above each point (the triangulation above), from the single
    precision corners."""
    xs, ys = grid()
    i = np.clip(np.searchsorted(xs, x) - 1, 0, NX - 1)
    j = np.clip(np.searchsorted(ys, y) - 1, 0, NY - 1)
    f = lambda v: v.astype(np.float32).astype(float)
    xa, xb, ya, yb = f(xs[i]), f(xs[i + 1]), f(ys[j]), f(ys[j + 1])
    za = f(height(xs[i], ys[j]))
    zb = f(height(xs[i + 1], ys[j]))
    zc = f(height(xs[i + 1], ys[j + 1]))
    zd = f(height(xs[i], ys[j + 1]))
    s, t = (x - xa)/(xb - xa), (y - ya)/(yb - ya)
    # Triangles (a, b, c) below the diagonal a-c (s >= t), (a, c, d) above
    lower = s >= t
    z = np.where(lower, za + s*(zb - za) + t*(zc - zb), za + s*(zc - zd) + t*(zd - za))
    return z
