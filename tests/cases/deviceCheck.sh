#!/bin/bash
#------------------------------------------------------------------------------
# The GPU device check (docs/gpu.md), run as the page says:
#     bash benchmarks/gpu/deviceCheck.sh <logDir>
# On a machine without a GPU it must still configure and build the core, run
# the GPU tests (skipped, not failed), say why there is no throughput table,
# exit 0 and leave its logs in the folder; with nvcc absent it must say that
# instead. On a GPU machine the same command prints the table (checked here
# too, where one is present).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

logs="$SCRATCH/deviceCheckLogs"
out="$(cd "$MPMFOAM_ROOT" && timeout 1500 bash benchmarks/gpu/deviceCheck.sh "$logs" 2>&1)"
rc=$?
echo "$out" | tail -15
check "the device check exits 0" "rc == 0" rc="$rc"
for f in machine.txt configure.log
do
    [ -s "$logs/$f" ] && n=1 || n=0
    check "log $f written" "n == 1" n="$n"
done
if echo "$out" | grep -q "nothing to check: CMake found no CUDA compiler"; then
    echo "PASS: no nvcc here: the check says so"
else
    for f in build.log ctest.log
    do
        [ -s "$logs/$f" ] && n=1 || n=0
        check "log $f written" "n == 1" n="$n"
    done
    if echo "$out" | grep -q "no throughput table: SKIP: the cuda back-end needs a usable GPU"; then
        n=$(grep -c "Skipped" "$logs/ctest.log")
        check "without a GPU the GPU tests are skipped, not failed" "n >= 3" n="$n"
    else
        # A GPU: the tests passed and the table has the resident rows
        n=$(grep -cE "^(linearHat|quadraticBSpline|cubicBSpline) +cuda " "$logs/gpuThroughput64.txt")
        check "the throughput table has a resident cuda row per shape" "n == 3" n="$n"
    fi
fi
exit $failures
