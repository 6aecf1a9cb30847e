#!/usr/bin/env python3
"""Writes system/blockMeshDict for the quasi-2D wedge hopper's box: width W,
height H, square cells of side h (one cell thick), its floor split into
'floorLeft', the centred outlet slot 'slot' of width D, and 'floorRight'
(three blocks along x). The hopper's inclined walls are plane obstacles in
constant/mpmProperties (Allrun sets them through the slot's edges); the
floor beside the slot lies inside them.

    hopperMesh.py --width 0.3 --height 0.45 --slot 0.06 --cell 0.01
"""
import argparse


def cells(length, h, what):
    n = round(length/h)
    if n < 1 or abs(n*h - length) > 1e-9*max(length, h):
        raise SystemExit("hopperMesh.py: %s %g is not a whole number of cells of %g" % (what, length, h))
    return n


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--width", type=float, required=True)
    ap.add_argument("--height", type=float, required=True)
    ap.add_argument("--slot", type=float, required=True)
    ap.add_argument("--cell", type=float, required=True)
    ap.add_argument("--out", default="system/blockMeshDict")
    a = ap.parse_args()
    W, H, D, h = a.width, a.height, a.slot, a.cell
    side = (W - D)/2
    nx = [cells(side, h, "floor width (W - D)/2"), cells(D, h, "slot"), cells(side, h, "floor width (W - D)/2")]
    ny = cells(H, h, "height")
    xs = [0, side, side + D, W]
    v = ["(%.12g %.12g %.12g)" % (x, y, z) for z in (0, h) for y in (0, H) for x in xs]
    idx = lambda i, yi, zi: i + 4*yi + 8*zi
    names = ["floorLeft", "slot", "floorRight"]
    blocks, faces = [], {n: [] for n in names + ["top", "empty"]}
    for b in range(3):
        blocks.append("hex (%d %d %d %d %d %d %d %d) (%d %d 1) simpleGrading (1 1 1)"
                      % (idx(b, 0, 0), idx(b + 1, 0, 0), idx(b + 1, 1, 0), idx(b, 1, 0),
                         idx(b, 0, 1), idx(b + 1, 0, 1), idx(b + 1, 1, 1), idx(b, 1, 1), nx[b], ny))
        faces[names[b]].append("(%d %d %d %d)" % (idx(b, 0, 0), idx(b + 1, 0, 0), idx(b + 1, 0, 1), idx(b, 0, 1)))
        faces["top"].append("(%d %d %d %d)" % (idx(b, 1, 0), idx(b, 1, 1), idx(b + 1, 1, 1), idx(b + 1, 1, 0)))
        faces["empty"].append("(%d %d %d %d)" % (idx(b, 0, 0), idx(b, 1, 0), idx(b + 1, 1, 0), idx(b + 1, 0, 0)))
        faces["empty"].append("(%d %d %d %d)" % (idx(b, 0, 1), idx(b + 1, 0, 1), idx(b + 1, 1, 1), idx(b, 1, 1)))
    left = "(%d %d %d %d)" % (idx(0, 0, 0), idx(0, 0, 1), idx(0, 1, 1), idx(0, 1, 0))
    right = "(%d %d %d %d)" % (idx(3, 0, 0), idx(3, 1, 0), idx(3, 1, 1), idx(3, 0, 1))
    with open(a.out, "w") as f:
        f.write("/* Written by hopperMesh.py: box W = %g, H = %g, slot D = %g, h = %g */\n" % (W, H, D, h))
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n\n")
        f.write("vertices\n(\n    " + "\n    ".join(v) + "\n);\n\n")
        f.write("blocks\n(\n    " + "\n    ".join(blocks) + "\n);\n\n")
        f.write("boundary\n(\n")
        for name, kind in (("floorLeft", "wall"), ("slot", "patch"), ("floorRight", "wall"), ("top", "patch")):
            f.write("    %s { type %s; faces ( %s ); }\n" % (name, kind, " ".join(faces[name])))
        f.write("    left { type wall; faces ( %s ); }\n" % left)
        f.write("    right { type wall; faces ( %s ); }\n" % right)
        f.write("    frontAndBack { type empty; faces ( %s ); }\n" % " ".join(faces["empty"]))
        f.write(");\n\nmergePatchPairs ();\n")


if __name__ == "__main__":
    main()
