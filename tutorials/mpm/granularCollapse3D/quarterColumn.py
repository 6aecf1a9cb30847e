"""Writes the closed STL surface of a quarter cylinder, x, y >= 0, r <= r0,
0 <= z <= h0: the column of sweepAspectRatio's quarter domain (a cylinder
region may not reach outside the mesh, so the quarter is seeded from this
surface, `type stl;` in system/mpmSetParticlesDict).

    python3 quarterColumn.py r0 h0 constant/triSurface/column.stl
"""
import sys

import numpy as np
import mpmPost

r0, h0, out = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
n = 180                                     # facets on the quarter arc
th = np.linspace(0.0, 0.5*np.pi, n + 1)
arc = np.c_[r0*np.cos(th), r0*np.sin(th)]
tris = []


def p(xy, z):
    return np.array([xy[0], xy[1], z])


o = (0.0, 0.0)
for i in range(n):
    a, b = arc[i], arc[i + 1]
    tris.append([p(o, 0), p(b, 0), p(a, 0)])            # floor, normal -z
    tris.append([p(o, h0), p(a, h0), p(b, h0)])         # top, normal +z
    tris.append([p(a, 0), p(b, 0), p(b, h0)])           # curved side, outwards
    tris.append([p(a, 0), p(b, h0), p(a, h0)])
# the planes y = 0 (normal -y) and x = 0 (normal -x)
tris.append([p(o, 0), p(arc[0], 0), p(arc[0], h0)])
tris.append([p(o, 0), p(arc[0], h0), p(o, h0)])
tris.append([p(o, 0), p(o, h0), p(arc[-1], h0)])
tris.append([p(o, 0), p(arc[-1], h0), p(arc[-1], 0)])
mpmPost.write_stl(out, tris, "column")
