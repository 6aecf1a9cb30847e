"""Writes constant/triSurface/terrain.stl, the closed terrain solid of
terrain.py (ASCII STL)."""
import os
import terrain

tris = terrain.triangles()
os.makedirs("constant/triSurface", exist_ok=True)
with open("constant/triSurface/terrain.stl", "w") as f:
    f.write("solid terrain\n")
    for t in tris:
        f.write(" facet normal 0 0 0\n  outer loop\n")
        for v in t:
            f.write("   vertex %.9g %.9g %.9g\n" % tuple(v))
        f.write("  endloop\n endfacet\n")
    f.write("endsolid terrain\n")
print("wrote constant/triSurface/terrain.stl: %d triangles" % len(tris))
