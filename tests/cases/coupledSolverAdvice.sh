#!/bin/bash
#------------------------------------------------------------------------------
# The solver's start-up time-step advice (coupling { timeStepAdvice yes; },
# src/mpmFoam/coupling/coupledTimeStepAdvice) prints the same lines as
# mpmStabilityAnalysis --model coupled --advise run through
# adviseCoupledCase.py on the same case: the drag's tau_p and Dt/tau_p, the
# MPM wave speed, step, pure-MPM limit and margin, the sub-cycles, max |G| of
# each drag variant and the largest stable fluid step. Both print the core's
# adviceLines, so equal text means the solver hands the analysis the same
# case as the script reads from the dictionaries: the drag law (WenYu, Ergun,
# Gidaspow), the constitutive law (stress-free dilute, linearElastic,
# druckerPrager), the solid fraction, h, the fluid, the step, courant, shape
# and FLIP fraction (jetScour: 0.95 changes the pure-MPM limit line). Both
# pass PIMPLE nCorrectors too (jetScour: 2), but 2 or 3 correctors print the
# same digits there, so that one is not checked here. Runs one fluid step of
# three coupled tutorials. Without the keyword the solver prints no advice
# (timeStepAdvice no echoed).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"
advise="$MPMFOAM_ROOT/applications/tools/mpmStabilityAnalysis/adviseCoupledCase.py"
block() { awk '/^Coupled time-step advice/ {f = 1} f {print} /largest stable fluid step/ {f = 0}'; }

# oneStepCase <case> [advice yes|default]: the case set to run one fluid
# step, with timeStepAdvice yes unless default
oneStepCase()
{
    local c="$1" dt
    [ "${2:-yes}" = yes ] && sed -i 's/^\( *subCycles .*\)$/\1\n    timeStepAdvice yes;/' "$(props "$c")"
    dt=$(awk '/^deltaT/ {gsub(";", "", $2); print $2}' "$c/system/controlDict")
    sed -i "s/^endTime .*/endTime $dt;/" "$c/system/controlDict"
}

# runOneStep <case> [advice yes|default]: one fluid step, log in log.mpmFoam
runOneStep()
{
    local c="$1"
    oneStepCase "$@"
    runIn "$c" bash -c "blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1" \
        || { echo "FAIL: $c did not run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); }
}

for t in settlingSuspension:0 consolidation:0 jetScour:0.005; do
    name="${t%%:*}" h="${t##*:}"
    c=$(copyTutorial "multiphase/$name" "$name")
    runOneStep "$c"
    hopt=(); [ "$h" != 0 ] && hopt=(--h "$h")
    solver=$(block < "$c/log.mpmFoam")
    script=$("$PY" "$advise" "$c" --tool "$tool" "${hopt[@]}" | block)
    echo "== $name, solver:"; echo "$solver"
    grep "the analysis took" "$c/log.mpmFoam"
    echo "== $name, adviseCoupledCase.py:"; echo "$script"
    lines=$(echo "$solver" | grep -c .)
    if [ "$lines" -eq 8 ] && [ "$solver" = "$script" ]; then
        echo "PASS: $name: the solver's advice equals the tool's ($lines lines)"
    else
        echo "FAIL: $name: the solver's advice ($lines lines) differs from the tool's:"
        diff <(echo "$solver") <(echo "$script")
        failures=$((failures + 1))
    fi
done

# Decomposed on 2 ranks: jetScour's bed (y < 0.06 m) lies wholly on rank 1,
# the master holds only water (manual split at mid-height, y = 0.1 m). The
# advice must still equal the serial run's: the solid fraction, the
# viscosity and h reach the master reduced over the ranks.
serial=$(block < "$SCRATCH/jetScour/log.mpmFoam")
p=$(copyTutorial multiphase/jetScour jetScourParallel)
oneStepCase "$p"
runApps "$p" blockMesh mpmSetParticles || { echo "FAIL: jetScourParallel set-up"; failures=$((failures + 1)); }
# jetScour's three blocks of 40 rows: rank 0 for the top 20 rows
manualSlices "$p" "0 if j >= 20 else 1" "27 40 1" "6 40 1" "27 40 1"
decomposeCase "$p" 2 manual 'dataFile "cellDecomposition";'
(cd "$p" && timeout 120 mpirun -np 2 mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: jetScour on 2 ranks did not run"; tail -20 "$p/log.mpmFoam"; failures=$((failures + 1)); }
parallel=$(block < "$p/log.mpmFoam")
echo "== jetScour on 2 ranks, solver:"; echo "$parallel"
read -r n0 n1 <<< "$("$PY" - "$p" <<'PYEOF2'
import os, sys
import mpmPost
def points(rank):
    d = os.path.join(sys.argv[1], "processor%d" % rank)
    try:
        return len(mpmPost.read_cloud_field(d, "0", "mass"))
    except (OSError, IndexError, AttributeError):
        return 0
print(points(0), points(1))
PYEOF2
)"
check "jetScour on 2 ranks: the master holds no material point, rank 1 the bed" "n0 == 0 and n1 > 0" n0="$n0" n1="$n1"
if [ "$(echo "$parallel" | grep -c .)" -eq 8 ] && [ "$parallel" = "$serial" ]; then
    echo "PASS: jetScour on 2 ranks (the bed on rank 1 only): the advice equals the serial run's (8 lines)"
else
    echo "FAIL: jetScour on 2 ranks: the advice differs from the serial run's:"
    diff <(echo "$serial") <(echo "$parallel")
    failures=$((failures + 1))
fi

c=$(copyTutorial multiphase/settlingSuspension default)
runOneStep "$c" default
if grep -q "timeStepAdvice no" "$c/log.mpmFoam" && ! grep -q "Coupled time-step advice" "$c/log.mpmFoam"; then
    echo "PASS: without the keyword: timeStepAdvice no, no advice printed"
else
    echo "FAIL: without the keyword the solver printed advice or did not echo timeStepAdvice no"
    failures=$((failures + 1))
fi

finish
