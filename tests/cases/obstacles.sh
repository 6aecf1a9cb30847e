#!/bin/bash
#------------------------------------------------------------------------------
# Obstacles (level-set walls, docs/geometry.md) through the solver and the
# seeding utility, on the elasticDisks box:
#   * mpmSetParticles leaves out the points a region puts inside an STL
#     obstacle, and says how many (the count of sub-cell points in the
#     overlap, worked out here);
#   * an elastic disk thrown at about one wave speed at a closed STL block
#     never has a point inside it (exact box geometry) at any written time,
#     rebounds, and keeps every seeded point and its mass;
#   * the same run on 2 ranks (scotch) gives the serial positions to 1e-10;
#   * a sphere obstacle described analytically holds the disk the same way;
#   * a moving obstacle: a gate (a box) holds a column of sand and is lifted
#     at 2 m/s from t = 0.1 s (velocity, a Function1 table): until then no
#     point passes it, afterwards the sand flows out beneath it, and no
#     point is ever inside the gate where it is at that time;
#     the same on 3 ranks with the lattice rebalanced by points whenever
#     max/mean exceeds 1.01 (the gate's level set moving with the owners):
#     the serial positions at every written time (1e-10);
#   * resting on a noSlip plane: an elastic block (elasticDisks' material,
#     E = 1e5, cubic B-splines, APIC) dropped at 0.5 m/s on a noSlip plane
#     obstacle at a cell face and 1/4 cell off one comes to rest with its
#     lowest point centres within h/4 of the plane (measured: 0.10 h and
#     0.01 h; the box's mirrored noSlip floor: 0.79 h). Holding the normal
#     velocity of the nodes within a cell of a noSlip plane both ways (a
#     first fix of the axial bar's compliance, docs/geometry.md) kept it
#     1.2-1.5 h above the plane.
#   * bad input stops with a message naming the obstacle: a missing STL, an
#     open STL, inward normals, an unknown shape, friction without its
#     coefficient, points inside an obstacle at start-up.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# stlBox <file> <x0 y0 z0 x1 y1 z1> [open|inward]: a closed box of 12
# triangles with outward normals (open: two missing; inward: reversed)
stlBox()
{
    "$PY" - "$@" <<'PYEOF'
import sys
import mpmPost
f, lo, hi = sys.argv[1], [float(v) for v in sys.argv[2:5]], [float(v) for v in sys.argv[5:8]]
mode = sys.argv[8] if len(sys.argv) > 8 else ""
c = [[(lo, hi)[(i >> a) & 1][a] for a in range(3)] for i in range(8)]
quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
tris = []
for q in quads:
    tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
if mode == "open": tris = tris[2:]
if mode == "inward": tris = [(a, c_, b) for a, b, c_ in tris]
mpmPost.write_stl(f, [[c[v] for v in t] for t in tris], "block")
PYEOF
}

c=$(copyTutorial mpm/elasticDisks blockCase)
mkdir -p "$c/constant/triSurface"
stlBox "$c/constant/triSurface/block.stl" 0.6 0.2 -1 0.9 0.9 2
cat >> "$(props "$c")" <<'EOF'
obstacles
{
    block { shape stl; file "block.stl"; type slip; }
}
EOF
cat > "$c/system/mpmSetParticlesDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    disk
    {
        type          cylinder;
        point1        (0.2 0.5 -1);
        point2        (0.2 0.5  2);
        radius        0.2;
        material      disk;
        pointsPerCell (2 2 1);
        velocity      { type uniform; value (1.2 0 0); }
    }
    strip   // overlaps the block over x 0.6-0.9, y 0.85-0.9: 12 x 2 points
    {
        type          box;
        min           (0.5 0.85 0);
        max           (1.0 1.0 1);
        material      disk;
        pointsPerCell (2 2 1);
    }
}
DEOF
sed -i 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/writeInterval 0.1;/' "$c/system/controlDict"
runApps "$c" blockMesh mpmSetParticles || { echo "FAIL: set-up"; tail -20 "$c/log.mpmSetParticles"; exit 1; }
left=$(sed -n 's/^Obstacle block: left out \([0-9]*\) points inside it/\1/p' "$c/log.mpmSetParticles")
check "seeding leaves out the strip's points inside the STL block" "n == 24" n="${left:--1}"

# insideBlock <case>: the largest depth of a point inside the block at any
# written time, the number of times read and the disk's final mean x speed.
# The block's faces are where the STL puts them: STL stores single
# precision (0.6 is read as 0.6000000238).
insideBlock()
{
    "$PY" - "$1" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
depth, n = -1.0, 0
for t in mpmPost.times(c):
    x = mpmPost.read_cloud_field(c, t, "positions")
    f = lambda v: float(np.float32(v))
    d = np.minimum.reduce([x[:, 0] - f(0.6), f(0.9) - x[:, 0], x[:, 1] - f(0.2), f(0.9) - x[:, 1]])
    depth = max(depth, d.max())
    n += 1
v = mpmPost.read_cloud_field(c, mpmPost.times(c)[-1], "U")
disk = mpmPost.read_cloud_field(c, "0", "positions")[:, 1] < 0.75
print(depth, n, v[disk, 0].mean())
PYEOF
}

runApps "$c" mpmFoam || { echo "FAIL: mpmFoam"; tail -30 "$c/log.mpmFoam"; exit 1; }
read -r depth nt ux <<< "$(insideBlock "$c")"
check "STL block: no point inside it at any of $nt written times (deepest: $depth)" "d < 0 and n >= 7" d="$depth" n="$nt"
check "STL block: the disk rebounded (mean x speed $ux m/s)" "u < 0" u="$ux"
seededPoints "$c"
grep -q "^Obstacles: points put back on their surface so far" "$c/log.mpmFoam"
check "the log reports the points put back on obstacles" "r == 0" r=$?

# Decomposed: the same positions as the serial run
p=$(copyTutorial mpm/elasticDisks parallel)
cp -r "$c/constant" "$c/system" "$p/"
cp -r "$c/0" "$p/"
rm -rf "$p"/0.*
decomposeCase "$p" 2 scotch
(cd "$p" && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1 && reconstructPar -latestTime > log.reconstructPar 2>&1) \
    || { echo "FAIL: decomposed run"; tail -30 "$p/log.mpmFoam"; failures=$((failures + 1)); }
diff=$("$PY" - "$c" "$p" <<'PYEOF'
import sys, numpy as np, mpmPost
a, b = sys.argv[1], sys.argv[2]
t = mpmPost.times(a)[-1]
def sorted_by_id(c):
    ids = mpmPost.read_cloud_field(c, t, "pointId").reshape(-1)
    return mpmPost.read_cloud_field(c, t, "positions")[np.argsort(ids)]
xa, xb = sorted_by_id(a), sorted_by_id(b)
print(np.abs(xa - xb).max() if xa.shape == xb.shape else 1e9)
PYEOF
)
check "2 ranks: final positions equal the serial run's" "d < 1e-10" d="$diff"

# An analytic sphere (a cylinder in this 2D case) instead of the STL
s=$(copyTutorial mpm/elasticDisks sphereCase)
cp "$c/system/mpmSetParticlesDict" "$s/system/"
sed -i 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/writeInterval 0.1;/' "$s/system/controlDict"
cat >> "$(props "$s")" <<'EOF'
obstacles
{
    ball { shape sphere; centre (0.8 0.5 0.5); radius 0.2; type friction; frictionCoefficient 0.3; }
}
EOF
runApps "$s" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: sphere case"; tail -20 "$s/log.mpmFoam"; exit 1; }
ballDepth=$("$PY" - "$s" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
print(max((0.2 - np.hypot(*(mpmPost.read_cloud_field(c, t, "positions")[:, :2] - [0.8, 0.5]).T)).max()
          for t in mpmPost.times(c)))
PYEOF
)
check "sphere: no point inside it at any written time (deepest: $ballDepth)" "d < 0" d="$ballDepth"

# A gate lifted at 2 m/s from t = 0.1 s
gt=$(copyTutorial mpm/elasticDisks gate)
cat > "$(props "$gt")" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }
shapeFunction quadraticBSpline; transfer APIC; logInterval 50;
timeStep { type adaptive; courant 0.3; }
materials { sand { model druckerPrager; rho 1600; E 1e6; nu 0.3; phi 30; c 0; psi 0; } }
walls { "(left|right|bottom|top)" { type slip; } }
obstacles
{
    gate
    {
        shape box; min (0.2 -0.3 -1); max (0.35 1.3 2); type slip;   // 3 cells thick
        velocity table ((0 (0 0 0)) (0.1 (0 0 0)) (0.1001 (0 2 0)) (10 (0 2 0)));
    }
}
EOF
setGravity "$gt"
cat > "$gt/system/mpmSetParticlesDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions { column { type box; min (-0.2 -0.2 0); max (0.2 0.4 1); material sand; pointsPerCell (2 2 1); } }
EOF
sed -i 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/writeInterval 0.05;/' "$gt/system/controlDict"
runApps "$gt" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: gate run"; tail -20 "$gt/log.mpmFoam"; failures=$((failures + 1)); }
read -r before after inside <<< "$("$PY" - "$gt" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
before, after, inside = -1.0, -1.0, -1.0
for t in mpmPost.times(c):
    x = mpmPost.read_positions(c, t)
    tt = float(t)
    lift = 2*max(0.0, tt - 0.10005)   # the table's integral, to 1e-4 m
    if tt <= 0.1:
        before = max(before, x[:, 0].max())
    after = max(after, x[:, 0].max())
    # Depth inside the gate where it is now (negative: outside)
    d = np.minimum.reduce([x[:, 0] - 0.2, 0.35 - x[:, 0], x[:, 1] - (-0.3 + lift), (1.3 + lift) - x[:, 1]])
    inside = max(inside, d.max())
print(before, after, inside)
PYEOF
)"
check "gate: held until lifted (front $before m, the gate at 0.2 m)" "b <= 0.2" b="$before"
check "gate: the sand flows out beneath it once lifted (front $after m, the gate 0.2-0.35 m)" "a > 0.45" a="$after"
check "gate: no point inside the moving gate at any written time (deepest $inside m; the lift known to 1e-4 m)" "d < 1e-4" d="$inside"
grep -q "moves with velocity table" "$gt/log.mpmFoam"
check "gate: the log says the gate moves" "r == 0" r=$?

# The moving gate decomposed (3 ranks, scotch) with the lattice rebalanced
# whenever max/mean points per rank exceeds 1.01 (issue 27): the gate's
# level set moves with the owners (LevelSetWalls::relocate), the points
# as serial at every written time
gp="$SCRATCH/gateBalanced"
cp -r "$gt" "$gp"
rm -rf "$gp"/0.[0-9]* "$gp"/[1-9]* "$gp"/log.mpmFoam
echo "lattice { maxImbalance 1.01; }" >> "$(props "$gp")"
decomposeCase "$gp" 3 scotch ""
(cd "$gp" && mpirun -np 3 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1 && reconstructPar > log.reconstructPar 2>&1) \
    || { echo "FAIL: the gate on 3 ranks"; tail -30 "$gp/log.mpmFoam"; failures=$((failures + 1)); }
nb=$(grep -c "^MPM load balance at time" "$gp/log.mpmFoam")
read -r d nt <<< "$(samePositions "$gt" "$gp")"
check "gate on 3 ranks, rebalanced $((nb - 1)) times while it moves: positions equal the serial run's at $nt written times (max difference $d)" \
    "nb >= 3 and d <= 1e-10 and nt >= 10" nb="$nb" d="${d:-1}" nt="${nt:-0}"

# Bad input, each a message naming the obstacle
seededCopy mpm/elasticDisks
bad()
{
    local name="$1" obstacle="$2" pattern="$3" b
    b=$(freshCopy "$name")
    mkdir -p "$b/constant/triSurface"
    stlBox "$b/constant/triSurface/good.stl" 0.6 0.2 -1 0.9 0.9 2
    stlBox "$b/constant/triSurface/open.stl" 0.6 0.2 -1 0.9 0.9 2 open
    stlBox "$b/constant/triSurface/inward.stl" 0.6 0.2 -1 0.9 0.9 2 inward
    printf 'obstacles\n{\n    %s\n}\n' "$obstacle" >> "$(props "$b")"
    expectFailure "$name" "$pattern" runIn "$b" mpmFoam
}
bad missingStl 'block { shape stl; file "none.stl"; }' "Obstacle block: STL file .*none.stl not found"
bad openStl 'block { shape stl; file "open.stl"; }' "Obstacle block: the STL .*open.stl is not closed \(4 edges"
bad inwardStl 'block { shape stl; file "inward.stl"; }' "Obstacle block: the STL .*inward.stl has inward normals"
bad unknownShape 'block { shape sphre; centre (0 0 0); radius 1; }' "unknown shape 'sphre'; did you mean 'sphere'\?"
bad frictionWithoutMu 'block { shape stl; file "good.stl"; type friction; }' "Missing keyword frictionCoefficient for the friction obstacle block"
bad unknownKeyword 'block { shape sphere; centre (0 0 0); radius 1; radus 2; }' "radus"
bad pointsInside 'block { shape box; min (0.1 0.1 -1); max (0.3 0.3 2); }' "Material points lie inside obstacles: [0-9]+ in block"
# --- resting on a noSlip plane ----------------------------------------------
for plane in -0.1 -0.0875; do
    d=$(copyTutorial mpm/elasticDisks rest$plane)
    setGravity "$d"
    cat > "$d/system/mpmSetParticlesDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions { block { type box; min (0.3 0.3 -1); max (0.7 0.5 2); material disk; pointsPerCell (2 2 1); velocity { type uniform; value (0 -0.5 0); } } }
EOF
    sed -i 's/^endTime .*/endTime         2.5;/' "$d/system/controlDict"
    sed -i 's/E       1000;/E       1e5;/; s/^transfer .*/transfer        APIC;/; s/^flipRatio.*//' "$(props "$d")"
    echo "obstacles { floor { shape plane; point (0 $plane 0); normal (0 1 0); type noSlip; } }" >> "$(props "$d")"
    runApps "$d" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: resting block ($plane)"; tail -20 "$d/log.mpmFoam"; failures=$((failures + 1)); }
    gap=$("$PY" -c "
import mpmPost
t = mpmPost.times('$d')[-1]
print((mpmPost.read_positions('$d', t)[:, 1].min() - ($plane))/0.05)")
    echo "block dropped on a noSlip plane at y = $plane: lowest point centre $gap h above it at rest"
    check "block rests on the noSlip plane at y = $plane (lowest point centre within h/4)" "0 <= g <= 0.25" g="$gap"
done

finish
