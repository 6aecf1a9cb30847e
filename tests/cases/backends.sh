#!/bin/bash
#------------------------------------------------------------------------------
# Back-ends (docs/backends.md): the granular column (Drucker-Prager, walls,
# gravity) for 0.1 s with `backend serial` and with `backend openmp` on 2
# threads, every loop threaded (threadMinLoopSize 1): the written points
# (positions, velocities, stresses, F, plastic strain) must be identical byte for byte. The
# log echoes the back-end in use. Written in binary, so every bit counts.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

seededCopy mpm/granularColumnCollapse

runWith()   # name backend -> case dir
{
    local c
    c=$(freshCopy "$1")
    # binary: the files carry every bit of the doubles
    sed -i 's/^endTime .*/endTime 0.1;/; s/^writeFormat .*/writeFormat binary;/' "$c/system/controlDict"
    echo "backend $2; threadMinLoopSize 1;" >> "$(props "$c")"
    (cd "$c" && OMP_NUM_THREADS=2 timeout 300 mpmFoam > log.mpmFoam 2>&1) \
        || { echo "FAIL: $1 run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); }
    echo "$c"
}

serial=$(runWith serialRun serial | tail -1)
openmp=$(runWith openmpRun openmp | tail -1)
for b in serial openmp
do
    c=$serial; [ $b = openmp ] && c=$openmp
    n=$(grep -c "^ *backend $b$" "$c/log.mpmFoam")
    check "log echoes backend $b" "n == 1" n="$n"
done

# The step's phases, logged once, the same for both back-ends (step/stepPlan.hpp)
for c in "$serial" "$openmp"
do
    n=$(grep -c "^Step plan: scatter+force nodalAfterScatter nodalUpdate gather stress move migrate$" "$c/log.mpmFoam")
    check "log gives the USL step plan once ($(basename "$c"))" "n == 1" n="$n"
done

last=$(cd "$serial" && foamListTimes -latestTime 2>/dev/null | tail -1)
check "the runs reached t = 0.1" "t > 0.0999" t="${last:-0}"
compared=0 differing=0
for f in positions U stress F plasticStrain
do
    a=$(find "$serial/$last" -path "*lagrangian*" -name "$f" | head -1)
    b=${a/$serial/$openmp}
    [ -f "$a" ] || continue
    compared=$((compared + 1))
    cmp -s "$a" "$b" || { differing=$((differing + 1)); echo "differs: $f"; }
done
check "points written by both runs compared (positions, U, stress, F, plasticStrain)" "n == 5" n="$compared"
check "serial and openmp write identical points" "d == 0" d="$differing"
finish
