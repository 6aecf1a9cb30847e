#!/bin/bash
#------------------------------------------------------------------------------
# A level-set wall meeting a mirrored box wall: dry sand slides down a 45
# degree slope made by the mesh (a trapezoid block whose left side is the
# slope: a friction level-set wall, mu 0.45) into the corner with the floor
# (a patch on the lattice box's side: a mirrored friction wall), as in
# tutorials/multiphase/granularSlideWave without the water. The lattice
# faces under the slope lie beyond the mesh; they are free ("beyondMesh",
# an outlet condition) and must hold the points that reach them, the level
# set putting them back on the slope.
#
# Measured: every written cloud keeps every seeded id once with its seeded
# mass (the grain mass exact), the log books no point out through
# beyondMesh, and no point lies outside the mesh at any written time.
#
# Before the fix (WallCondition::holdsPoints, src/mpmCore/grid/boundary.hpp)
# this failed: points pressed into the toe, on the slope within a micron of
# the corner, moved on below the floor left of the toe (x < 0.2, y < 0),
# onto the lattice face beyond the mesh there, and left the domain through
# it before the level set could put them back: "beyondMesh: out 7", 17 of
# the 21 written clouds short of seeded points. Now none leaves (the same
# happened once in granularSlideWave, twice with its d = 4 mm). 1-2 s.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/elasticDisks corner)
cat > "$c/system/blockMeshDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
// The slope x + y = 0.2 from (-0.1, 0.3) to its toe (0.2, 0) on the floor
// y = 0; the tank ends at x = 0.5. The lattice (h = 1 cm) covers the mesh's
// bounding box: its floor from x = 0.2 is the patch bottom (mirrored), under
// the slope it lies beyond the mesh.
vertices
(
    (0.2 0 0) (0.5 0 0) (0.5 0.3 0) (-0.1 0.3 0)
    (0.2 0 0.01) (0.5 0 0.01) (0.5 0.3 0.01) (-0.1 0.3 0.01)
);
blocks ( hex (0 1 2 3 4 5 6 7) (30 30 1) simpleGrading (1 1 1) );
boundary
(
    slope  { type wall; faces ( (0 4 7 3) ); }
    bottom { type wall; faces ( (0 1 5 4) ); }
    right  { type wall; faces ( (1 2 6 5) ); }
    top    { type wall; faces ( (3 7 6 2) ); }
    frontAndBack { type empty; faces ( (0 3 2 1) (4 5 6 7) ); }
);
EOF
cat > "$c/system/mpmSetParticlesDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    slide
    {
        type          searchableRotatedBox;
        origin        (-0.0333452 0.2333452 -0.01);   // back foot, on the slope
        e1            (0.70710678 -0.70710678 0);     // down the slope
        e3            (0 0 1);
        span          (0.15 0.06 0.03);
        material      sand;
        pointsPerCell 2;
        offset        (0.25 0 0);
        velocity      { type uniform; value (1.76776695 -1.76776695 0); }  // 2.5 m/s down the slope
    }
}
EOF
cat > "$(props "$c")" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }
shapeFunction   cubicBSpline;
transfer        PICFLIP;
flipRatio       0.95;
stressUpdate    USL;
logInterval     20;
timeStep { type adaptive; courant 0.5; }
lattice { spacing 0.01; }
materials
{
    sand { model druckerPrager; rho 2650; E 1e6; nu 0.3; phi 30; c 0; psi 0; }
}
walls
{
    slope  { type friction; frictionCoefficient 0.45; }
    bottom { type friction; frictionCoefficient 0.45; }
    right  { type slip; }
    top    { type slip; }
}
EOF
setGravity "$c"
sed -i 's/^endTime .*/endTime 0.4;/; s/^writeInterval .*/writeInterval 0.02;/' "$c/system/controlDict"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: run"; tail -30 "$c/log.mpmFoam"; finish; }
grep -q "lattice faces beyond the mesh: .* free (outlet beyondMesh)" "$c/log.mpmFoam"
check "the faces under the slope are free (outlet beyondMesh) in the log" "r == 0" r=$?
seededPoints "$c"
outN=$(grep "beyondMesh: out" "$c/log.mpmFoam" | tail -1 | awk '{print $3}')
check "no point out through the faces beyond the mesh (log: beyondMesh out ${outN:-?})" "n == 0" n="${outN:-nan}"
read -r worst nt <<< "$("$PY" - "$c" <<'PYEOF'
import sys, mpmPost
c = sys.argv[1]
worst, n = -1.0, 0
for t in mpmPost.times(c):
    x = mpmPost.read_positions(c, t)
    # beyond the slope (x + y >= 0.2), the floor, the right side, the top
    worst = max(worst, ((0.2 - x[:, 0] - x[:, 1])/2**0.5).max(), (-x[:, 1]).max(),
                (x[:, 0] - 0.5).max(), (x[:, 1] - 0.3).max())
    n += 1
print(worst, n)
PYEOF
)"
check "no point outside the mesh at $nt written times (furthest: $worst m)" "w <= 1e-9 and n >= 20" w="$worst" n="$nt"
finish
