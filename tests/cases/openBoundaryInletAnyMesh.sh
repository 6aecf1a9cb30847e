#!/bin/bash
#------------------------------------------------------------------------------
# Inlets off the lattice box's sides (level-set inlets, docs/openBoundaries.md):
# the inlet stream of openBoundaryInlet.sh (U = 1 m/s into the domain,
# massFlowRate table ((0 0) (0.1 4) (1 4)) [kg/s], 2 points per cell, an
# outlet behind, no gravity) on meshes whose inlet patch is no side of the
# MPM lattice's box:
#   1. the mesh as it is, the lattice its own with h = 0.019 (the top patch
#      at y = 0.4 falls inside the lattice's last cell row);
#   2. the whole case rotated by 30 degrees about z (transformPoints; the
#      stream and the block's velocity rotated with it): every patch is a
#      tilted plane, the lattice h = 0.02 over the rotated bounding box.
# Checked in each:
#   - the log names the inlet a level-set wall;
#   - injected mass within half a layer of the integral of the rate on every
#     step, in whole layers (the layer's mass from the log);
#   - each injected point where the material entering at its layer's
#     mid-volume instant t_k has moved: at U (t - t_k) from the inlet's
#     plane along its inward normal (the stream keeps the inlet velocity),
#     and across the stream within the patch (0 to 0.2 m);
#   - the balance, initial + injected - removed = present, on every step,
#     and what leaves through the outlet once the stream reaches it.
#   The rotated case also on 2 ranks, and on 3 with frequent rebalances by
#   points: the serial cloud.
#   3. bad input: an inlet off the box that is not one plane, and one partly
#      on a side of the lattice's box and partly off it.
# A wrong normal, layer spacing, point volume or Dirichlet velocity breaks
# the positions or the mass; a missing inlet condition on the nodes lets
# the stream slow down at the inlet (its points then lag behind U (t - t_k)).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/openBoundaryCases"

. "$CASES/inletStreamChecks"

# 1. The top patch off the box: the lattice's own spacing 0.019
c="$SCRATCH/offBox"
cp -r "$CASES/inletStream" "$c"
sed -i 's/^timeStep .*/&\nlattice         { spacing 0.019; }/' "$(props "$c")"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: offBox run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); }
checkStream "$c" "aligned, off the box" "(0 0.4 0)" "(0 -1 0)" "(1 0 0)" levelSet

# 2. The case rotated by 30 degrees about z
r="$SCRATCH/rotated"
cp -r "$CASES/inletStream" "$r"
s=0.5; co=0.8660254037844386
sed -i "s/^timeStep .*/&\nlattice         { spacing 0.02; }/; s/velocity      (0 -1 0);/velocity      ($s -$co 0);/" "$(props "$r")"
sed -i "s/value (0 -1 0)/value ($s -$co 0)/" "$r/system/mpmSetParticlesDict"
# The block: a smaller axis-aligned one inside the rotated channel, moving
# with the stream
sed -i 's/type box; min (0 0.1 0); max (0.2 0.2 0.02);/type box; min (-0.03 0.21 0); max (0 0.24 0.02);/' "$r/system/mpmSetParticlesDict"
(cd "$r" && blockMesh > log.blockMesh 2>&1 && transformPoints -rotate "((0 1 0) (-$s $co 0))" > log.transformPoints 2>&1) \
    || { echo "FAIL: rotated mesh"; failures=$((failures + 1)); }
runApps "$r" mpmSetParticles mpmFoam || { echo "FAIL: rotated run"; tail -20 "$r/log.mpmFoam"; failures=$((failures + 1)); }
# The top's plane through the rotated (0 0.4 0); inward the rotated -y;
# across the rotated x
checkStream "$r" "rotated 30 deg" "(-0.2 0.3464101615137755 0)" "($s -$co 0)" "($co $s 0)" levelSet

# The rotated case on 2 ranks (scotch): every rank builds the same layer
# from the gathered patch and adds the points of its lattice cells; the
# cloud at 0.6 is the serial one
rp="$SCRATCH/rotatedPar"
cp -r "$r" "$rp"
rm -rf "$rp"/0.[0-9]* "$rp"/[1-9]* "$rp"/postProcessing "$rp"/processor*
decomposeCase "$rp" 2 scotch
(cd "$rp" && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: rotated, 2 ranks"; tail -20 "$rp/log.mpmFoam"; failures=$((failures + 1)); }
cmp=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$r" "$rp" 0.6 --fields U)
echo "$cmp" | sed 's/^/    2 ranks: /'
check "rotated 30 deg on 2 ranks: the serial cloud at 0.6 (ids, positions within 1e-10)" \
    "i == 1 and p <= 1e-10 and n > 500" i="$(echo "$cmp" | awk '$1=="ids"{print $3}')" \
    p="$(echo "$cmp" | awk '$1=="positions"{print $2}')" n="$(echo "$cmp" | awk '$1=="count"{print $2}')"

# The same on 3 ranks with frequent rebalances (lattice { maxImbalance
# 1.01; }, loadBalance.sh): the stream enters and leaves while the lattice's
# owners follow the points; the cloud at 0.6 is still the serial one
r3="$SCRATCH/rotatedRebalanced"
cp -r "$r" "$r3"
rm -rf "$r3"/0.[0-9]* "$r3"/[1-9]* "$r3"/postProcessing "$r3"/processor*
sed -i 's/^lattice .*{ *spacing \([0-9.]*\); *}/lattice { spacing \1; maxImbalance 1.01; }/' "$(props "$r3")"
grep -q "maxImbalance 1.01" "$(props "$r3")" || { echo "FAIL: rotated, maxImbalance not set"; failures=$((failures + 1)); }
decomposeCase "$r3" 3 scotch
(cd "$r3" && mpirun -np 3 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: rotated, 3 ranks"; tail -20 "$r3/log.mpmFoam"; failures=$((failures + 1)); }
nb=$(grep -c "^MPM load balance at time" "$r3/log.mpmFoam")
cmp=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$r" "$r3" 0.6 --fields U)
echo "$cmp" | sed 's/^/    3 ranks, rebalanced: /'
check "rotated 30 deg on 3 ranks, the lattice partitioned by points $nb times: the serial cloud at 0.6 (ids, positions within 1e-10)" \
    "i == 1 and p <= 1e-10 and n > 500 and nb >= 3" i="$(echo "$cmp" | awk '$1=="ids"{print $3}')" \
    p="$(echo "$cmp" | awk '$1=="positions"{print $2}')" n="$(echo "$cmp" | awk '$1=="count"{print $2}')" nb="$nb"

# 3. Bad input: the top patch (off the lattice's sides, h = 0.019) joined by
#    a side of the channel, which leaves its own patch and walls entry
# badInlet <name> <side patch> <its face> <the remaining wall>: the case
badInlet()
{
    local v="$SCRATCH/$1"
    cp -r "$CASES/inletStream" "$v"
    sed -i 's/^timeStep .*/&\nlattice         { spacing 0.019; }/' "$(props "$v")"
    sed -i "s/    $2 *{ type wall; faces ( $3 ); }//; s/    top    { type patch; faces ( (3 7 6 2) ); }/    top    { type patch; faces ( (3 7 6 2) $3 ); }/" "$v/system/blockMeshDict"
    sed -i "s/\"(left|right)\"  { type slip; }/$4 { type slip; }/" "$(props "$v")"
    runApps "$v" blockMesh mpmSetParticles || { echo "FAIL: $1 set-up" >&2; failures=$((failures + 1)); }
    echo "$v"
}
# The right side (off the lattice's sides too): not one plane
b=$(badInlet notPlanar right "(1 2 6 5)" left)
expectFailure "an inlet off the box that is not one plane" "The inlet top is not one plane: its face at .* has the normal" runIn "$b" mpmFoam
# The left side (x = 0, a side of the lattice's box): partly on, partly off
b=$(badInlet partlyOnSide left "(0 4 7 3)" right)
expectFailure "an inlet partly on a side of the box and partly off it" "The inlet top lies partly on a side of the lattice's box and partly off it \(10 faces\)" runIn "$b" mpmFoam

finish
