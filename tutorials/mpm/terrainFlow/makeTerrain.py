"""Writes constant/triSurface/terrain.stl, the closed terrain solid of
terrain.py (ASCII STL)."""
import os

import mpmPost
import terrain

tris = terrain.triangles()
os.makedirs("constant/triSurface", exist_ok=True)
mpmPost.write_stl("constant/triSurface/terrain.stl", tris, "terrain")
print("wrote constant/triSurface/terrain.stl: %d triangles" % len(tris))
