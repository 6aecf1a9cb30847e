#!/bin/bash
#------------------------------------------------------------------------------
# Effects on demand: a case computes only the forces and diagnostics it lists
# (run-time-selected plug-ins), and the end-of-run cost breakdown names each
# selected one and no other.
#  - coupled packedBed, forces (drag pressureGradient), diagnostics
#    (summary materialTotals): the breakdown has exactly "force drag", "force
#    pressureGradient", "diagnostic summary", "diagnostic materialTotals"; the
#    materialTotals table has a row per fluid step, with the seeded points and
#    mass (the sum over 0/lagrangian) on every row;
#  - the same with forces (drag) and diagnostics (): no pressure-gradient
#    cost, no energy line, no postProcessing/mpmSummary, and a different
#    solution (the pressure gradient did act before);
#  - decomposed on 3 ranks, the materialTotals table equals serial;
#  - an unknown or repeated diagnostic is an error listing the valid ones.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial multiphase/packedBed packedBed)
runApps "$c" blockMesh mpmSetParticles || { echo "FAIL: set-up"; exit 1; }
sed -i 's/^endTime .*/endTime 0.2;/; s/^writeInterval .*/writeInterval 0.2;/' "$c/system/controlDict"
d=$(cp -r "$c" "$SCRATCH/fewer" && echo "$SCRATCH/fewer")
sed -i 's/^logInterval .*/logInterval 1;\ndiagnostics (summary materialTotals);/' "$(props "$c")"
# The same case decomposed on 3 ranks along the column: the bed (the lower
# half) spans ranks 0 and 1, so a total the master alone made would differ
p=$(cp -r "$c" "$SCRATCH/parallel" && echo "$SCRATCH/parallel")
decomposeCase "$p" 3 simple "n (1 3 1);"
sed -i 's/^logInterval .*/logInterval 1;\ndiagnostics ();/; s/^\( *forces *\).*/\1(drag);/' "$(props "$d")"

runIn "$c" mpmFoam > "$c/log.mpmFoam" 2>&1 || { echo "FAIL: run with every force and diagnostic"; tail -20 "$c/log.mpmFoam"; exit 1; }
runIn "$d" mpmFoam > "$d/log.mpmFoam" 2>&1 || { echo "FAIL: run with drag only, no diagnostics"; tail -20 "$d/log.mpmFoam"; exit 1; }

# The named lines of the cost breakdown (after "Cost breakdown:")
costs() { sed -n '/Cost breakdown:/,/^$/p' "$1/log.mpmFoam" | grep -oE "(force|diagnostic) [A-Za-z]+" | sort | tr '\n' ' '; }
a=$(costs "$c"); b=$(costs "$d")
if [ "$a" = "diagnostic materialTotals diagnostic summary force drag force pressureGradient " ]; then
    echo "PASS: the cost breakdown names each selected effect: $a"
else
    echo "FAIL: cost breakdown effects: '$a'"; failures=$((failures + 1))
fi
if [ "$b" = "force drag " ]; then
    echo "PASS: unselected effects are neither computed nor listed: $b"
else
    echo "FAIL: drag only, no diagnostics, lists: '$b'"; failures=$((failures + 1))
fi
check "no diagnostics: no energy line and no summary file" "n == 0 and f == 0" \
    n="$(grep -c "kinetic energy" "$d/log.mpmFoam")" f="$([ -e "$d/postProcessing/mpmSummary" ] && echo 1 || echo 0)"

# The mass ledger: every row holds the seeded points and mass
seeded=$("$PY" - "$c" <<'PYEOF'
import sys, mpmPost
m = mpmPost.read_cloud_field(sys.argv[1], "0", "mass")
print(m.size, repr(float(m.sum())))
PYEOF
)
read -r nSeed mSeed <<< "$seeded"
table="$c/postProcessing/materialTotals/0/materialTotals.dat"
rows=$(grep -vc "^#" "$table")
bad=$(awk -v n="$nSeed" -v m="$mSeed" '!/^#/ && ($2 != n || ($3 - m)^2 > (1e-12*m)^2) {b++} END {print b+0}' "$table")
check "materialTotals: a row at the start and per fluid step (10), each with the seeded $nSeed points and mass $mSeed" \
    "r == 11 and b == 0" r="$rows" b="$bad"

# Decomposed: the diagnostic sums over the processors (the master writes)
(cd "$p" && mpirun -np 3 mpmFoam -parallel > log.mpmFoam 2>&1) || { echo "FAIL: 3-rank run"; tail -20 "$p/log.mpmFoam"; failures=$((failures + 1)); }
"$PY" - "$table" "$p/postProcessing/materialTotals/0/materialTotals.dat" <<'PYEOF' && echo "PASS: materialTotals on 3 ranks equals serial (times, points exact; mass to 1e-12)" || { echo "FAIL: materialTotals on 3 ranks differs from serial"; failures=$((failures + 1)); }
import sys, numpy as np
a = np.loadtxt(sys.argv[1]); b = np.loadtxt(sys.argv[2])
ok = a.shape == b.shape and np.array_equal(a[:, [0, 1, 3]], b[:, [0, 1, 3]]) \
    and np.allclose(a[:, [2, 4]], b[:, [2, 4]], rtol=1e-12, atol=0)
print("serial rows", a.shape, "parallel rows", b.shape)
sys.exit(0 if ok else 1)
PYEOF

# The pressure gradient acted: the two runs differ
"$PY" - "$c" "$d" <<'PYEOF' && echo "PASS: dropping the pressure gradient changes the solution" || { echo "FAIL: the pressure gradient had no effect"; failures=$((failures + 1)); }
import sys, mpmPost, numpy as np
a = mpmPost.read_cloud_field(sys.argv[1], "0.2", "U"); b = mpmPost.read_cloud_field(sys.argv[2], "0.2", "U")
sys.exit(0 if np.max(np.abs(a - b)) > 1e-6*np.max(np.abs(a)) else 1)
PYEOF

e=$(cp -r "$d" "$SCRATCH/unknown" && echo "$SCRATCH/unknown")
sed -i 's/^diagnostics .*/diagnostics (summary energy);/' "$(props "$e")"
expectFailure "unknown diagnostic" "Unknown diagnostic 'energy' in diagnostics" runIn "$e" mpmFoam
expectFailure "unknown diagnostic lists the valid ones" "Valid diagnostics: materialTotals summary" runIn "$e" mpmFoam
sed -i 's/^diagnostics .*/diagnostics (summary summary);/' "$(props "$e")"
expectFailure "repeated diagnostic" "Diagnostic 'summary' listed twice in diagnostics" runIn "$e" mpmFoam

[ "$failures" -eq 0 ]
