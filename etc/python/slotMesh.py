#!/usr/bin/env python3
"""Writes system/blockMeshDict for a quasi-2D box with a slot in its floor:
width W and height H, square cells of side h (one cell thick), the floor
split into 'floorLeft', a centred slot of width D (the patch 'slot', an
outlet in mpmProperties) and 'floorRight' (three blocks along x). Used by
the flat silo (tutorials/mpm/siloDischarge) and the wedge hopper
(tutorials/mpm/wedgeHopper, whose inclined walls are obstacles).

    python3 -m slotMesh --width 0.6 --height 0.55 --slot 0.06 --cell 0.01
"""
import argparse


def cells(length, h, what):
    n = round(length/h)
    if n < 1 or abs(n*h - length) > 1e-9*max(length, h):
        raise SystemExit("slotMesh: %s %g is not a whole number of cells of %g" % (what, length, h))
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
    v = []
    for z in (0, h):
        for y in (0, H):
            for x in xs:
                v.append("(%.12g %.12g %.12g)" % (x, y, z))
    # vertex index: x index i (0..3), y index (0, 1), z index (0, 1)
    idx = lambda i, yi, zi: i + 4*yi + 8*zi
    blocks, faces = [], {"floorLeft": [], "slot": [], "floorRight": [], "top": [], "empty": []}
    for b in range(3):
        i = b
        blocks.append("hex (%d %d %d %d %d %d %d %d) (%d %d 1) simpleGrading (1 1 1)"
                      % (idx(i, 0, 0), idx(i + 1, 0, 0), idx(i + 1, 1, 0), idx(i, 1, 0),
                         idx(i, 0, 1), idx(i + 1, 0, 1), idx(i + 1, 1, 1), idx(i, 1, 1), nx[b], ny))
        bottom = "(%d %d %d %d)" % (idx(i, 0, 0), idx(i + 1, 0, 0), idx(i + 1, 0, 1), idx(i, 0, 1))
        faces[["floorLeft", "slot", "floorRight"][b]].append(bottom)
        faces["top"].append("(%d %d %d %d)" % (idx(i, 1, 0), idx(i, 1, 1), idx(i + 1, 1, 1), idx(i + 1, 1, 0)))
        faces["empty"].append("(%d %d %d %d)" % (idx(i, 0, 0), idx(i, 1, 0), idx(i + 1, 1, 0), idx(i + 1, 0, 0)))
        faces["empty"].append("(%d %d %d %d)" % (idx(i, 0, 1), idx(i + 1, 0, 1), idx(i + 1, 1, 1), idx(i, 1, 1)))
    left = "(%d %d %d %d)" % (idx(0, 0, 0), idx(0, 0, 1), idx(0, 1, 1), idx(0, 1, 0))
    right = "(%d %d %d %d)" % (idx(3, 0, 0), idx(3, 1, 0), idx(3, 1, 1), idx(3, 0, 1))
    with open(a.out, "w") as f:
        f.write("/* Written by slotMesh: box W = %g, H = %g, slot D = %g, h = %g */\n" % (W, H, D, h))
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
