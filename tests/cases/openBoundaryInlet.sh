#!/bin/bash
#------------------------------------------------------------------------------
# Inlet (tests/cases/openBoundaryCases/inletStream): a stream enters through
# the top at U = 1 m/s, massFlowRate table ((0 0) (0.1 4) (1 4)) [kg/s]
# (4 kg/s = rho U A: full density), 2 points per cell, and leaves through a
# bottom outlet behind a block moving at 1 m/s; no gravity. Checked:
#   - injected mass against the integral of the rate,
#       I(t) = 20 t^2 (t <= 0.1), 0.2 + 4 (t - 0.1) (t > 0.1),
#     within half a layer (0.02 kg) on every step, whole layers only;
#   - each injected point where the material entering at its layer's
#     mid-volume instant t_k (I(t_k) = (k + 1/2) layer mass) has moved:
#     y = 0.4 - U (t - t_k), at the written times (the stream keeps the
#     inlet velocity, its layers h/2 apart at full density);
#   - what leaves equals what enters once the stream reaches the outlet
#     (0.5 < t < 0.6: 0.4 kg each, within a layer);
#   - the balance, initial + injected - removed = present, on every step;
#   - a restart from t = 0.4 (a whole number of layers in: the totals and
#     the rate's integral start again there, docs/openBoundaries.md) ends
#     with the uninterrupted run's cloud (same ids, positions to 1e-12);
#   - bad inputs: an outward velocity, no flow rate or both, a wall keyword
#     on an inlet, an inlet keyword on an outlet, a negative rate.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/openBoundaryCases"
c="$SCRATCH/inletStream"
cp -r "$CASES/inletStream" "$c"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: inletStream run"; tail -20 "$c/log.mpmFoam"; exit 1; }

. "$CASES/inletStreamChecks"
checkStream "$c" "inlet" "(0 0.4 0)" "(0 -1 0)" "(1 0 0)"

# Restart from a written time
r="$SCRATCH/restart"
cp -r "$c" "$r"; rm -rf "$r/0.6"
(cd "$r" && mpmFoam > log.restart 2>&1) || { echo "FAIL: restart"; tail -20 "$r/log.restart"; failures=$((failures + 1)); }
out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$c" "$r" 0.6 --fields U)
pos=$(echo "$out" | awk '$1=="positions"{print $2}'); same=$(echo "$out" | awk '$1=="ids"{print $3}')
n=$(echo "$out" | awk '$1=="count"{print $2}')
check "restart from t = 0.4: the cloud at 0.6 equals the uninterrupted run ($n points)" \
    "same == 1 and pos <= 1e-12 and n == 800" same="${same:-0}" pos="${pos:-1}" n="${n:-0}"

# Bad input
BASE_CASE="$c"   # meshed and seeded; each variant drops its results
v=$(unrunCopy outward); sed -i 's/velocity      (0 -1 0);/velocity (0 1 0);/' "$(props "$v")"
expectFailure "inlet velocity pointing out of the domain" "velocity \(0 1 0\) does not point into the domain" runIn "$v" mpmFoam
v=$(unrunCopy noRate); sed -i '/massFlowRate/d' "$(props "$v")"
expectFailure "inlet without a flow rate" "needs exactly one of massFlowRate \[kg/s\] and volumeFlowRate" runIn "$v" mpmFoam
v=$(unrunCopy twoRates); sed -i 's/massFlowRate  table/volumeFlowRate constant 1; massFlowRate table/' "$(props "$v")"
expectFailure "inlet with both flow rates" "needs exactly one of massFlowRate" runIn "$v" mpmFoam
v=$(unrunCopy noVelocity); sed -i '/velocity      (0 -1 0);/d' "$(props "$v")"
expectFailure "inlet without a velocity" "Missing keyword velocity for the inlet top" runIn "$v" mpmFoam
v=$(unrunCopy wallKeyword); sed -i 's/pointsPerCell 2;/pointsPerCell 2; frictionCoefficient 0.3;/' "$(props "$v")"
expectFailure "friction coefficient on an inlet" "Unknown keyword 'frictionCoefficient' in inlet top" runIn "$v" mpmFoam
v=$(unrunCopy outletKeyword); sed -i 's/bottom          { type outlet; }/bottom { type outlet; massFlowRate constant 1; }/' "$(props "$v")"
expectFailure "flow rate on an outlet" "Unknown keyword 'massFlowRate' in outlet bottom" runIn "$v" mpmFoam
v=$(unrunCopy badType); sed -i 's/type outlet;/type outflow;/' "$(props "$v")"
expectFailure "unknown open type" "Unknown type 'outflow'.*|Valid type choices: noSlip slip friction periodic outlet inlet" runIn "$v" mpmFoam
v=$(unrunCopy negative); sed -i 's/massFlowRate  table ((0 0) (0.1 4) (1 4));/massFlowRate constant -1;/' "$(props "$v")"
expectFailure "negative flow rate" "flow rate of the inlet top is negative" runIn "$v" mpmFoam
v=$(unrunCopy badMaterial); sed -i 's/material      stream;/material sand;/' "$(props "$v")"
expectFailure "inlet of an unknown material" "sand" runIn "$v" mpmFoam

finish
