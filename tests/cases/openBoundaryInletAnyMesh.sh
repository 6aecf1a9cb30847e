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
#   3. bad input: an inlet off the box that is not one plane.
# A wrong normal, layer spacing, point volume or Dirichlet velocity breaks
# the positions or the mass; a missing inlet condition on the nodes lets
# the stream slow down at the inlet (its points then lag behind U (t - t_k)).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/openBoundaryCases"

# check <case> <label> <inlet plane point> <inward normal> <tangent>
checkStream()
{
    local c=$1 what=$2
    grep -q "patch top, .* faces: inlet" "$c/log.mpmFoam"
    check "$what: the top patch is a level-set inlet" "f == 0" f=$?
    local layerMass perLayer firstId
    read -r perLayer layerMass <<< "$(sed -n 's/.*a layer of \([0-9]*\) points (mass \([0-9.eE+-]*\)).*/\1 \2/p' "$c/log.mpmFoam" | head -1)"
    firstId=$(sed -n 's/^Writing \([0-9]*\) material points.*/\1/p' "$c/log.mpmSetParticles" | tail -1)
    echo "    $what: a layer of $perLayer points, $layerMass kg; $firstId points seeded"
    local res
    res=$("$PY" - "$c" "$layerMass" "$perLayer" "$firstId" "$3" "$4" "$5" <<'PYEOF'
import sys
import numpy as np, mpmPost
c, layerMass, perLayer, firstId = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
x0, n, tng = (np.array([float(v) for v in a.strip("()").split()]) for a in sys.argv[5:8])
U = 1.0
I = lambda t: np.where(t <= 0.1, 20*t*t, 0.2 + 4*(t - 0.1))
def tOf(m):
    return np.sqrt(m/20) if m <= 0.2 else 0.1 + (m - 0.2)/4
top = mpmPost.read_open_boundary(c, "top")
out = mpmPost.read_open_boundary(c, "bottom")
bal = mpmPost.read_open_boundary(c, "massBalance")
t = top["time"]
dev = np.abs(top["injectedMass"] - I(t)).max()
whole = int((top["injectedPoints"] % perLayer != 0).sum())
posErr, across, count = 0.0, [1e9, -1e9], 0
for tw in mpmPost.times(c)[1:]:
    T = float(tw)
    ids = mpmPost.read_cloud_field(c, tw, "pointId").astype(int)
    x = mpmPost.read_positions(c, tw)
    s = ids >= firstId
    k = (ids[s] - firstId)//perLayer
    tk = np.array([tOf((kk + 0.5)*layerMass) for kk in k])
    d = (x[s] - x0) @ n
    posErr = max(posErr, np.abs(d - U*(T - tk)).max())
    a = (x[s] - x0) @ tng
    across = [min(across[0], a.min()), max(across[1], a.max())]
    count += s.sum()
a, b = np.argmin(np.abs(t - 0.5)), len(t) - 1
inLate = top["injectedMass"][b] - top["injectedMass"][a]
outLate = out["removedMass"][b] - out["removedMass"][a]
balCount = int((bal["presentPoints"] != bal["initialPoints"] + bal["injectedPoints"] - bal["removedPoints"]).sum())
balMass = np.abs(bal["massError"]).max()/(bal["initialMass"][0] + bal["injectedMass"][-1])
print(len(t), dev, whole, posErr, count, across[0], across[1], inLate, outLate, balCount, balMass)
PYEOF
)
    local rows dev whole posErr n lo hi inLate outLate balCount balMass
    read -r rows dev whole posErr n lo hi inLate outLate balCount balMass <<< "$res"
    echo "    $what: $res"
    check "$what: injected mass within half a layer of the rate's integral on every step ($rows), whole layers" \
        "rows >= 600 and dev <= 0.5*m + 1e-12 and whole == 0" rows="${rows:-0}" dev="${dev:-1}" m="${layerMass:-0}" whole="${whole:-1}"
    check "$what: injected points at U (t - t_k) from the inlet plane ($n points at the written times)" \
        "n > 500 and e <= 1e-5" n="${n:-0}" e="${posErr:-1}"
    check "$what: and across the stream within the patch (0 to 0.2 m: $lo to $hi)" \
        "lo >= -1e-9 and hi <= 0.2 + 1e-9 and hi - lo > 0.18" lo="${lo:-1}" hi="${hi:-0}"
    check "$what: out = in over 0.5 < t < 0.6 (0.4 kg, within a layer)" \
        "abs(o - i) <= m + 1e-12 and abs(i - 0.4) <= m + 1e-12" o="${outLate:-0}" i="${inLate:-0}" m="${layerMass:-0}"
    check "$what: balance present = initial + injected - removed on every step" \
        "bc == 0 and bm <= 1e-13" bc="${balCount:-1}" bm="${balMass:-1}"
}

# 1. The top patch off the box: the lattice's own spacing 0.019
c="$SCRATCH/offBox"
cp -r "$CASES/inletStream" "$c"
sed -i 's/^timeStep .*/&\nlattice         { spacing 0.019; }/' "$(props "$c")"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: offBox run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); }
checkStream "$c" "aligned, off the box" "(0 0.4 0)" "(0 -1 0)" "(1 0 0)"

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
checkStream "$r" "rotated 30 deg" "(-0.2 0.3464101615137755 0)" "($s -$co 0)" "($co $s 0)"

# 3. Bad input: an inlet off the box that is not one plane (the top and the
#    right side as one patch)
b="$SCRATCH/notPlanar"
cp -r "$CASES/inletStream" "$b"
sed -i 's/^timeStep .*/&\nlattice         { spacing 0.019; }/' "$(props "$b")"
sed -i 's/    right  { type wall; faces ( (1 2 6 5) ); }//; s/    top    { type patch; faces ( (3 7 6 2) ); }/    top    { type patch; faces ( (3 7 6 2) (1 2 6 5) ); }/' "$b/system/blockMeshDict"
sed -i 's/"(left|right)"  { type slip; }/left { type slip; }/' "$(props "$b")"
runApps "$b" blockMesh mpmSetParticles || { echo "FAIL: notPlanar set-up"; failures=$((failures + 1)); }
expectFailure "an inlet off the box that is not one plane" "The inlet top is not one plane: its face at .* has the normal" runIn "$b" mpmFoam

finish
