#!/bin/bash
#------------------------------------------------------------------------------
# The coupled time-step advice has one code path: the solver's
# (src/mpmFoam/coupling/coupledTimeStepAdvice, docs/stabilityAnalysis.md
# 7b.7). A run prints it at start-up with coupling { timeStepAdvice yes; };
# `mpmAdviseTimeStep <case>` (bin/, on PATH) runs `mpmFoam -adviseTimeStep`,
# which sets the case up as a run does, prints the same lines and stops.
#
# For five coupled cases - settlingSuspension (WenYu, dilute),
# consolidation (Ergun, linearElastic), jetScour (Gidaspow, druckerPrager,
# FLIP 0.95, no cell size h in its blockMeshDict), and two APIC cases at a
# 2 ms fluid step: underwaterGranularCollapse (no h either) and the
# fluidised bed with transfer APIC and no flipRatio (the issue-28 case: the
# solver analysed APIC as FLIP 0.99, the unused flipRatio default, and
# answered "largest stable fluid step 0.00023671 s, margin 0.1184", while
# adviseCoupledCase.py read flipRatio as 0 and answered ">= 0.016 s, margin
# >= 8") - it checks:
#   * mpmAdviseTimeStep <case> prints the 8 lines the solver's
#     timeStepAdvice yes run prints, character for character, without --h;
#   * it writes nothing: the case's files (names, sizes, times) are the same
#     before and after, no time directory;
#   * adviseCoupledCase.py <case> (no override) prints the same lines (it
#     runs mpmAdviseTimeStep), and as a parameter study with the solver's
#     own alpha.solid (--aS, and --h where blockMeshDict has none) it starts
#     from the solver's numbers: the same 8 lines;
#   * the APIC cases are analysed as PIC (alpha 0) and say so.
# Then: jetScour decomposed on 2 ranks with the bed on rank 1 gives the
# serial advice; without the keyword a run prints none; a case without a
# fluid gets the note and the pure-MPM check; bad input is the solver's
# FatalIOError; and the advisor's commands of docs/stabilityAnalysis.md 7b.7
# (the block marked stability-advisor, runDocBlock), run as
# written.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
study="$MPMFOAM_ROOT/applications/tools/mpmStabilityAnalysis/adviseCoupledCase.py"
doc="$MPMFOAM_ROOT/docs/stabilityAnalysis.md"
block() { awk '/^Coupled time-step advice/ {f = 1} f {print} /largest stable fluid step/ {f = 0}'; }
snapshot() { (cd "$1" && find . -printf '%p %s %T@\n' | sort); }
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# oneStepCase <case> [advice yes|default]: the case set to run one fluid
# step, with timeStepAdvice yes unless default
oneStepCase()
{
    local c="$1" dt
    [ "${2:-yes}" = yes ] && sed -i 's/^\( *subCycles .*\)$/\1\n    timeStepAdvice yes;/' "$(props "$c")"
    dt=$(awk '/^deltaT/ {gsub(";", "", $2); print $2}' "$c/system/controlDict")
    sed -i "s/^endTime .*/endTime $dt;/" "$c/system/controlDict"
}

# same <what> <expected> <actual>: equal, 8 lines
same()
{
    local n
    n=$(echo "$2" | grep -c .)
    if [ "$n" -eq 8 ] && [ "$2" = "$3" ]; then
        echo "PASS: $1 (8 lines)"
    else
        fail "$1: $n lines, or they differ:"
        diff <(echo "$2") <(echo "$3")
    fi
}

# name:tutorial:edit - edit: apic2ms = transfer APIC, no flipRatio, deltaT 2 ms
for t in settlingSuspension:settlingSuspension: consolidation:consolidation: jetScour:jetScour: \
         underwaterAPIC:underwaterGranularCollapse:apic2ms fluidisedBedAPIC:fluidisedBed:apic2ms; do
    IFS=: read -r name tutorial edit <<< "$t"
    c=$(copyTutorial "multiphase/$tutorial" "$name")
    if [ "$edit" = apic2ms ]; then
        sed -i 's/^transfer .*/transfer        APIC;/; /^flipRatio/d' "$(props "$c")"
        sed -i 's/^deltaT .*/deltaT          0.002;/' "$c/system/controlDict"
    fi
    oneStepCase "$c"
    runApps "$c" blockMesh mpmSetParticles || { fail "$name set-up"; continue; }

    before=$(snapshot "$c")
    advisor=$(mpmAdviseTimeStep "$c"); rc=$?
    after=$(snapshot "$c")
    [ $rc -eq 0 ] || fail "$name: mpmAdviseTimeStep exit status $rc"
    if [ "$before" = "$after" ] && ! ls -d "$c"/[0-9]* | grep -qv '/0$'; then
        echo "PASS: $name: mpmAdviseTimeStep wrote nothing (the case's files unchanged, no time directory)"
    else
        fail "$name: mpmAdviseTimeStep changed the case:"; diff <(echo "$before") <(echo "$after")
    fi

    runApps "$c" mpmFoam || { fail "$name did not run"; tail -20 "$c/log.mpmFoam"; continue; }
    solver=$(block < "$c/log.mpmFoam")
    echo "== $name, mpmAdviseTimeStep:"; echo "$advisor"
    same "$name: mpmAdviseTimeStep prints the solver's timeStepAdvice lines" "$solver" "$(echo "$advisor" | block)"

    delegated=$("$PY" "$study" "$c" | block)
    same "$name: adviseCoupledCase.py without an override prints them too (it runs mpmAdviseTimeStep)" "$solver" "$delegated"

    aS=$(sed -n 's/.*alpha.solid \([0-9.e+-]*\): the largest.*/\1/p' "$c/log.mpmFoam")
    hopt=()
    # the cell size where blockMeshDict has no h: the tutorial's own
    case "$tutorial" in jetScour) hopt=(--h 0.005) ;; underwaterGranularCollapse) hopt=(--h 0.01) ;; esac
    studied=$("$PY" "$study" "$c" --aS "$aS" "${hopt[@]}" | block)
    same "$name: adviseCoupledCase.py as a study (--aS $aS${hopt[*]:+ ${hopt[*]}}) starts from the solver's numbers" "$solver" "$studied"

    if [ "$edit" = apic2ms ]; then
        if echo "$solver" | grep -q "(CBS alpha 0 USL)" && grep -q "APIC transfer is analysed as PIC, alpha 0" <<< "$advisor"; then
            echo "PASS: $name: APIC analysed as PIC (alpha 0), and the note says so: $(echo "$solver" | grep 'largest stable')"
        else
            fail "$name: APIC not analysed as PIC (alpha 0) or no note"
        fi
    fi
done
jetScourAdvice=$(block < "$SCRATCH/jetScour/log.mpmFoam")

# Decomposed on 2 ranks: jetScour's bed (y < 0.06 m) lies wholly on rank 1,
# the master holds only water (manual split at mid-height, y = 0.1 m). The
# advice must still equal the serial run's: the solid fraction, the
# viscosity and h reach the master reduced over the ranks.
p=$(copyTutorial multiphase/jetScour jetScourParallel)
oneStepCase "$p"
runApps "$p" blockMesh mpmSetParticles || fail "jetScourParallel set-up"
# jetScour's three blocks of 40 rows: rank 0 for the top 20 rows
manualSlices "$p" "0 if j >= 20 else 1" "27 40 1" "6 40 1" "27 40 1"
decomposeCase "$p" 2 manual 'dataFile "cellDecomposition";'
(cd "$p" && timeout 120 mpirun -np 2 mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { fail "jetScour on 2 ranks did not run"; tail -20 "$p/log.mpmFoam"; }
parallel=$(block < "$p/log.mpmFoam")
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
same "jetScour on 2 ranks (the bed on rank 1 only): the advice equals the serial run's" "$jetScourAdvice" "$parallel"

c=$(copyTutorial multiphase/settlingSuspension default)
oneStepCase "$c" default
runApps "$c" blockMesh mpmSetParticles mpmFoam || fail "settlingSuspension without the keyword did not run"
if grep -q "timeStepAdvice no" "$c/log.mpmFoam" && ! grep -q "Coupled time-step advice" "$c/log.mpmFoam"; then
    echo "PASS: without the keyword: timeStepAdvice no, no advice printed"
else
    fail "without the keyword the solver printed advice or did not echo timeStepAdvice no"
fi

# A case without a fluid: the note and the pure-MPM check, exit status 0
c=$(copyTutorial mpm/axialBar pureMpm)
runApps "$c" blockMesh mpmSetParticles || fail "axialBar set-up"
out=$(mpmAdviseTimeStep "$c"); rc=$?
echo "$out"
if [ $rc -eq 0 ] && grep -q "this case has no fluid.*is for coupled cases" <<< "$out" \
    && grep -q "pure MPM: the solver checks its step against the stable Courant number" <<< "$out"; then
    echo "PASS: a case without a fluid: the coupled advice is for coupled cases, the pure-MPM check instead"
else
    fail "a case without a fluid: status $rc or no clear note"
fi

# Bad input: the solver's error, as a run prints it
c=$(copyTutorial multiphase/settlingSuspension badInput)
runApps "$c" blockMesh mpmSetParticles || fail "badInput set-up"
sed -i 's/^\( *subCycles .*\)$/\1\n    timeStepAdvice maybe;/' "$(props "$c")"
expectFailure "mpmAdviseTimeStep, bad input: the solver's FatalIOError" "FOAM FATAL IO ERROR" mpmAdviseTimeStep "$c"
expectFailure "mpmAdviseTimeStep, bad input: names the file and keyword" "mpmProperties.coupling.timeStepAdvice at line" mpmAdviseTimeStep "$c"
expectFailure "mpmAdviseTimeStep, not a case directory" "no case directory" mpmAdviseTimeStep "$SCRATCH/none"

# The advisor's commands of docs/stabilityAnalysis.md 7b.7, as written there
mkdir -p "$SCRATCH/doc"
runDocBlock docs/stabilityAnalysis.md stability-advisor "$SCRATCH/doc" || fail "the doc's commands failed"
docOut=$(cat "$SCRATCH/doc/log.doc.stability-advisor")
echo "== the doc's commands:"; echo "$docOut"
same "the doc's mpmAdviseTimeStep in a copy of jetScour prints jetScour's advice" "$jetScourAdvice" "$(echo "$docOut" | block | head -8)"
if grep -q "^adviseCoupledCase.py: a parameter study, not the case's advice" <<< "$docOut" \
    && [ "$(echo "$docOut" | grep -c '^Coupled time-step advice')" -eq 2 ]; then
    echo "PASS: the doc's study command says it is a parameter study, not the case's advice, and prints its advice"
else
    fail "the doc's study command: no parameter-study heading or no advice"
fi

finish
