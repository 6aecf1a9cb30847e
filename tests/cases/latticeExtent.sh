#!/bin/bash
#------------------------------------------------------------------------------
# The MPM lattice's extent (lattice { extent ((min) (max)); extentWall {...} },
# docs/geometry.md): the lattice covers the part of the mesh inside it, and
# its sides inside the mesh are walls.
#   1. The elasticDisks box (uniform, so its cells would be the lattice) with
#      an extent that cuts 2 cells off its x+ and y+ sides (h = 0.05, the
#      disks never come within 2 cells of the cut): the lattice is its own,
#      smaller, and the positions equal the full box's at every written time
#      (1e-12 m; the same lattice cells, the same points). The same on 2
#      ranks (simple, split across x) equals the serial run (1e-10 m), and
#      on 3 ranks (manual) with one rank holding only cells beyond the
#      extent, so owning no lattice cell.
#   2. One disk thrown at 0.5 m/s against the extent's x+ side at 0.6
#      (extentWall slip), against the same disk in a box mesh that ends at
#      0.6 with a slip wall there: positions equal at every written time
#      (1e-12 m): the extent's side is the same mirrored wall. And no point
#      beyond 0.6; the cells beyond the extent have alpha.solid 0.
#   3. An inlet partly beyond the extent: the rate kept, nothing beyond.
#   4. Bad input: an extent outside the mesh, extentWall without extent,
#      an inlet extentWall, a friction extentWall without its coefficient,
#      a seeding region beyond the extent, an unknown balance, maxImbalance 1,
#      a negative migrationRatio.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# 1. An extent the material never reaches
u=$(copyTutorial mpm/elasticDisks full)
sed -i 's/^endTime .*/endTime 1.5;/; s/^writePrecision .*/writePrecision 17;/' "$u/system/controlDict"
e=$(copyTutorial mpm/elasticDisks extent)
cp "$u/system/controlDict" "$e/system/"
printf 'lattice { extent ((-1 -1 -1) (1.1 1.1 2)); }\n' >> "$(props "$e")"
runApps "$u" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: full run"; exit 1; }
runApps "$e" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: extent run"; tail -30 "$e/log.mpmFoam"; exit 1; }
grep "MPM lattice\|extent" "$e/log.mpmFoam" | head -4
grep -qE "^MPM lattice: 2D, h = 0.0(5|49999[0-9]*), cells \(26 26 1\)" "$e/log.mpmFoam"
check "extent: the lattice is its own, 26 x 26 cells (the box's 28 less 2 each way)" "r == 0" r=$?
read -r d n <<< "$(samePositions "$u" "$e")"
check "extent the material never reaches: positions equal the full box's at $n written times (max difference $d)" \
    "d <= 1e-12 and n >= 4" d="$d" n="$n"

# onRanks <case> <n> <method> [coeffs]: the serial extent run's settings,
# seeded serially, decomposed (decomposeCase), run and reconstructed
onRanks()
{
    cp "$e/system/controlDict" "$1/system/"
    cp "$(props "$e")" "$(props "$1")"
    runApps "$1" blockMesh mpmSetParticles || { echo "FAIL: $1 setup"; failures=$((failures + 1)); }
    decomposeCase "$1" "$2" "$3" "${4:-}"
    (cd "$1" && mpirun -np "$2" --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1 && reconstructPar > log.reconstructPar 2>&1) \
        || { echo "FAIL: extent on $2 ranks"; tail -30 "$1/log.mpmFoam"; failures=$((failures + 1)); }
}

# 1b. The same extent on 2 ranks, split across x (simple): the lattice's
#     owners follow the mesh's cells, and the cut sides are the lattice's.
#     Positions equal the serial extent run's at every written time.
ep=$(copyTutorial mpm/elasticDisks extentPar)
onRanks "$ep" 2 simple 'n (2 1 1);'
read -r d n <<< "$(samePositions "$e" "$ep")"
check "extent on 2 ranks: positions equal the serial extent run's at $n written times (max difference $d)" \
    "d <= 1e-10 and n >= 4" d="$d" n="$n"

# 1c. On 3 ranks (manual): processor 2 holds only the cells beyond the
#     extent (x > 1.1) and owns no lattice cell; the middle one has two
#     processor patches, the others one (the patches every rank has come
#     first: the walls off the lattice's sides are counted over those).
#     Positions equal the serial extent run's.
e3=$(copyTutorial mpm/elasticDisks extentThreeRanks)
"$PY" - "$e3/constant/cellDecomposition" <<'PYEOF'
import sys
# 28 x 28 cells of 0.05 m from -0.2, x fastest: columns 26, 27 lie beyond 1.1
cells = [2 if i >= 26 else (0 if i < 13 else 1) for j in range(28) for i in range(28)]
open(sys.argv[1], "w").write(
    "FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }\n"
    + "%d\n(\n%s\n)\n" % (len(cells), "\n".join(map(str, cells))))
PYEOF
onRanks "$e3" 3 manual 'dataFile "cellDecomposition";'
grep -q "processor 2 owns no lattice cell" "$e3/log.mpmFoam"
check "extent on 3 ranks: the log says processor 2 owns no lattice cell" "r == 0" r=$?
read -r d n <<< "$(samePositions "$e" "$e3")"
check "extent on 3 ranks, one with no lattice cell: positions equal the serial extent run's at $n written times (max difference $d)" \
    "d <= 1e-10 and n >= 4" d="$d" n="$n"

# 2. A disk thrown at the extent's side, against a mesh that ends there
oneDisk()
{
    sed -i 's/^endTime .*/endTime 1.2;/; s/^writeInterval .*/writeInterval 0.3;/; s/^writePrecision .*/writePrecision 17;/' "$1/system/controlDict"
    "$PY" - "$1/system/mpmSetParticlesDict" <<'PYEOF'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"upperDisk\s*\{.*?\}\s*\}", "", s, flags=re.S)           # the lower disk alone
s = s.replace("value (0.1 0.1 0);", "value (0.5 0 0);")
open(p, "w").write(s)
PYEOF
}
w=$(copyTutorial mpm/elasticDisks wall)
oneDisk "$w"
sed -i 's/(1.2 -0.2 0) (1.2 1.2 0)/(0.6 -0.2 0) (0.6 1.2 0)/; s/(1.2 -0.2 1) (1.2 1.2 1)/(0.6 -0.2 1) (0.6 1.2 1)/; s/^nCells .*/nCells 28;/; s/(\$nCells \$nCells 1)/(16 $nCells 1)/' "$w/system/blockMeshDict"
x=$(copyTutorial mpm/elasticDisks extentWall)
oneDisk "$x"
printf 'lattice { extent ((-1 -1 -1) (0.6 2 2)); extentWall { type slip; } }\n' >> "$(props "$x")"
runApps "$w" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: wall run"; tail -20 "$w/log.mpmFoam"; failures=$((failures + 1)); }
runApps "$x" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: extentWall run"; tail -20 "$x/log.mpmFoam"; failures=$((failures + 1)); }
grep "extent" "$x/log.mpmFoam" | head -2
read -r d n <<< "$(samePositions "$w" "$x")"
check "a disk against the extent's slip side: positions equal the mesh that ends there at $n written times (max difference $d)" \
    "d <= 1e-12 and n >= 4" d="$d" n="$n"
res=$("$PY" - "$x" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
xmax, reached, beyond = -1e9, 0.0, 0.0
for t in mpmPost.times(c)[1:]:
    x = mpmPost.read_positions(c, t)
    xmax = max(xmax, x[:, 0].max())
    a = mpmPost.read_internal_field(c, t, "alpha.solid")
    n = int(round(len(a)**0.5))            # 28 x 28 cells, x fastest
    a = a.reshape(n, n)
    reached = max(reached, a[:, 14:16].max())     # the two cell columns inside the side
    beyond = max(beyond, np.abs(a[:, 16:]).max()) # the 12 beyond it
print(xmax, reached, beyond)
PYEOF
)
read -r xmax reached beyond <<< "$res"
check "no point beyond the extent's side (largest x $xmax)" "x <= 0.6 + 1e-12" x="${xmax:-1}"
check "the disk reached the side (alpha.solid $reached in the cells inside it) and the cells beyond have none ($beyond)" \
    "r > 0.1 and b == 0" r="${reached:-0}" b="${beyond:-1}"

# 3. An inlet partly beyond the extent (the inlet stream of
#    openBoundaryInlet.sh, its top patch off the lattice's sides with
#    h = 0.019, the lattice cut at x = 0.1 by a slip extent wall): the part
#    beyond lets nothing in, the rate is kept (within half a layer), and no
#    point ever lies beyond the extent
s3="$SCRATCH/inletBeyond"
cp -r "$MPMFOAM_ROOT/tests/cases/openBoundaryCases/inletStream" "$s3"
sed -i 's/^timeStep .*/&\nlattice         { spacing 0.019; extent ((-1 -1 -1) (0.1 1 1)); extentWall { type slip; } }/' "$(props "$s3")"
sed -i 's/min (0 0.1 0); max (0.2 0.2 0.02);/min (0 0.1 0); max (0.09 0.2 0.02);/' "$s3/system/mpmSetParticlesDict"
sed -i 's/^endTime .*/endTime 0.3;/' "$s3/system/controlDict"
runApps "$s3" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: inlet beyond the extent run"; tail -20 "$s3/log.mpmFoam"; failures=$((failures + 1)); }
layerMass=$(sed -n 's/.*a layer of [0-9]* points (mass \([0-9.eE+-]*\)).*/\1/p' "$s3/log.mpmFoam" | head -1)
read -r dev xmax <<< "$("$PY" - "$s3" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
top = mpmPost.read_open_boundary(c, "top")
t = top["time"]
I = np.where(t <= 0.1, 20*t*t, 0.2 + 4*(t - 0.1))
xmax = max(mpmPost.read_positions(c, tw)[:, 0].max() for tw in mpmPost.times(c))
print(np.abs(top["injectedMass"] - I).max(), xmax)
PYEOF
)"
check "an inlet partly beyond the extent: injected mass within half a layer ($layerMass kg) of the rate's integral ($dev)" \
    "d <= 0.5*m + 1e-12 and m > 0" d="${dev:-1}" m="${layerMass:-0}"
check "and no point beyond the extent (largest x $xmax; the lattice ends at 5 x 0.019 = 0.095)" "x <= 0.095 + 1e-12" x="${xmax:-1}"

# 4. Bad input
BASE_CASE="$e"
v=$(unrunCopy outside); sed -i 's/^lattice .*/lattice { extent ((2 2 -1) (3 3 2)); }/' "$(props "$v")"
expectFailure "an extent outside the mesh" "lattice extent .* does not overlap the mesh's bounding box" runIn "$v" mpmFoam
v=$(unrunCopy noExtent); sed -i 's/^lattice .*/lattice { extentWall { type slip; } }/' "$(props "$v")"
expectFailure "extentWall without extent" "extentWall without extent" runIn "$v" mpmFoam
v=$(unrunCopy inletWall); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (1.1 1.1 2)); extentWall { type inlet; } }/' "$(props "$v")"
expectFailure "an inlet as the extent's wall" "Valid type choices: noSlip slip friction outlet" runIn "$v" mpmFoam
v=$(unrunCopy frictionNoMu); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (1.1 1.1 2)); extentWall { type friction; } }/' "$(props "$v")"
expectFailure "a friction extentWall without its coefficient" "Missing keyword frictionCoefficient for the friction extentWall" runIn "$v" mpmFoam
v=$(unrunCopy region); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (0.9 1.1 2)); }/' "$(props "$v")"
expectFailure "a seeding region beyond the extent" "enlarge the mesh \(or the MPM lattice's extent" runIn "$v" mpmSetParticles
v=$(unrunCopy badBalance); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (1.1 1.1 2)); balance metis; }/' "$(props "$v")"
expectFailure "an unknown balance, in a serial run too" "Valid balance choices: scotch none" runIn "$v" mpmFoam
v=$(unrunCopy lowImbalance); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (1.1 1.1 2)); maxImbalance 1; }/' "$(props "$v")"
expectFailure "maxImbalance 1 (max/mean is never below 1)" "Keyword maxImbalance = 1 is out of range \(1, " runIn "$v" mpmFoam
v=$(unrunCopy negativeMigration); sed -i 's/^lattice .*/lattice { extent ((-1 -1 -1) (1.1 1.1 2)); migrationRatio -1; }/' "$(props "$v")"
expectFailure "a negative migrationRatio" "Keyword migrationRatio = -1 is out of range \[0, 100\]" runIn "$v" mpmFoam

finish
