#!/bin/bash
#------------------------------------------------------------------------------
# Outlet (tests/cases/openBoundaryCases/outletFall): an elastic block of 240
# points falls freely (g = 10, fixed dt = 1e-3) through a box whose floor is
# an outlet. The velocity field is uniform, so after n steps every point has
# fallen exactly g dt^2 n (n + 1)/2 (symplectic Euler) and leaves at the
# first step that takes it below y = 0. Checked against that:
#   - removed count at every step of postProcessing/openBoundaries/0/
#     bottom.dat equals the number of seeded points with y0 < g dt^2 n(n+1)/2,
#     and the removed mass that count times the point mass;
#   - the points still in the box have fallen exactly that far (the outlet
#     is open: a mirror there would have stopped the lower rows);
#   - every written cloud holds exactly the points the balance says;
#   - the balance (massBalance.dat): initial - removed = present, count
#     exact, mass to round-off, on every step; nothing clamped;
#   - the log's balance line.
# The same block on a slip floor keeps its 240 points (no removal), and a
# block thrown at a noSlip floor far too fast (points cross the wall in one
# step) is clamped: counted in massBalance.dat and warned about in the log.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/openBoundaryCases"
c="$SCRATCH/outletFall"
cp -r "$CASES/outletFall" "$c"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: outletFall run"; tail -20 "$c/log.mpmFoam"; exit 1; }

res=$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np, mpmPost
c = sys.argv[1]
g, dt = 10.0, 1e-3
x0 = mpmPost.read_positions(c, "0")
m0 = mpmPost.read_cloud_field(c, "0", "mass")
id0 = mpmPost.read_cloud_field(c, "0", "pointId").astype(int)
y0 = dict(zip(id0, x0[:, 1]))
fall = lambda n: g*dt*dt*n*(n + 1)/2
out = mpmPost.read_open_boundary(c, "bottom")
bal = mpmPost.read_open_boundary(c, "massBalance")
n = np.rint(out["time"]/dt).astype(int)
expect = np.array([(x0[:, 1] < fall(k)).sum() for k in n])
badCount = int((out["removedPoints"] != expect).sum())
massErr = np.abs(out["removedMass"] - expect*m0[0]).max()/m0.sum()
# points left in the box, at the written times
posErr, cloudBad = 0.0, 0
for t in mpmPost.times(c)[1:]:
    k = int(round(float(t)/dt))
    ids = np.atleast_1d(mpmPost.read_cloud_field(c, t, "pointId")).astype(int)
    row = np.argmin(np.abs(bal["time"] - float(t)))
    cloudBad += len(ids) != bal["presentPoints"][row] or len(ids) != 240 - expect[np.argmin(np.abs(n - k))]
    if len(ids):
        y = mpmPost.read_positions(c, t)[:, 1]
        posErr = max(posErr, np.abs(y - (np.array([y0[i] for i in ids]) - fall(k))).max())
balCount = int((bal["presentPoints"] != bal["initialPoints"] + bal["injectedPoints"] - bal["removedPoints"]).sum())
balMass = np.abs(bal["massError"]).max()/bal["initialMass"][0]
print(len(out["time"]), badCount, massErr, posErr, cloudBad, balCount, balMass,
      int(bal["clamped"].max()), int(out["removedPoints"][-1]), int(expect[n == 200][0]), int(out["removedPoints"][n == 200][0]))
PYEOF
)
read -r rows badCount massErr posErr cloudBad balCount balMass clamped last mid got <<< "$res"
echo "    rows $rows; removed by t = 0.2: $got points (analytic $mid: y0 < g dt^2 n(n+1)/2 = 0.201); at the end: $last of 240"
check "outlet: removed count equals the discrete free-fall count on every step ($rows rows)" \
    "rows >= 250 and bad == 0 and last == 240 and mid > 0 and mid < 240" rows="$rows" bad="$badCount" last="$last" mid="$mid"
check "outlet: removed mass = count x point mass" "e <= 1e-14" e="$massErr"
check "outlet: the points in the box fall exactly as in free fall (the outlet adds no wall)" "e <= 1e-9" e="$posErr"
check "outlet: written clouds hold the points the balance says" "bad == 0" bad="$cloudBad"
check "balance: present = initial - removed (count exact, mass to round-off) every step" \
    "bc == 0 and bm <= 1e-14" bc="$balCount" bm="$balMass"
check "nothing clamped at the walls" "n == 0" n="$clamped"
if grep -q "^    balance: initial 240 (0.48.*) + in 0 (0) - out 240 (0.48.*) = 0; present 0 (0), mass error 0" "$c/log.mpmFoam"; then
    echo "PASS: log: $(grep '^    balance:' "$c/log.mpmFoam" | tail -1 | sed 's/^ *//')"
else
    echo "FAIL: log balance line"; grep "^    balance:" "$c/log.mpmFoam" | tail -1; failures=$((failures + 1))
fi

# Contrast: a slip floor keeps every point
w="$SCRATCH/slipFloor"
cp -r "$c" "$w"; rm -rf "$w"/0.* "$w"/postProcessing
sed -i 's/bottom *{ type outlet; }/bottom { type slip; }/' "$w/constant/mpmProperties"
(cd "$w" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: slip floor run"; failures=$((failures + 1)); }
n=$("$PY" -c "import mpmPost; print(len(mpmPost.read_cloud_field('$w', mpmPost.times('$w')[-1], 'mass')))")
check "slip floor: every point stays ($n)" "n == 240" n="$n"
check "slip floor: no open boundary, no postProcessing/openBoundaries" \
    "x == 0" x="$(ls -d "$w"/postProcessing/openBoundaries 2>/dev/null | wc -l)"

# A step far too large at a wall: points cross it in one step and are put
# back inside; counted and warned, never silent.
k="$SCRATCH/clamped"
cp -r "$c" "$k"; rm -rf "$k"/0.* "$k"/postProcessing "$k"/0/lagrangian
sed -i 's/bottom *{ type outlet; }/bottom { type noSlip; } left { type outlet; }/; s/"(left|right)"/right/' "$k/constant/mpmProperties"
sed -i 's/pointsPerCell 2;/pointsPerCell 2; velocity { type uniform; value (0 -40 0); }/' "$k/system/mpmSetParticlesDict"
sed -i 's/endTime 0.25;/endTime 0.02;/' "$k/system/controlDict"
(cd "$k" && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1)
nc=$("$PY" -c "import mpmPost; print(int(mpmPost.read_open_boundary('$k')['clamped'].max()))" 2>/dev/null || echo -1)
check "clamping at a wall is counted in massBalance.dat ($nc points)" "n > 0" n="$nc"
if grep -q "material points crossed a wall and were put back inside it" "$k/log.mpmFoam"; then
    echo "PASS: clamping warned: $(grep -m1 'crossed a wall' "$k/log.mpmFoam" | sed 's/^ *//')"
else
    echo "FAIL: no warning for clamped points"; failures=$((failures + 1))
fi

finish
