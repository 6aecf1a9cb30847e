#!/bin/bash
# The one-command check of the CUDA back-end on a machine with a GPU and only
# CMake, a C++ compiler and nvcc (no OpenFOAM, no GoogleTest needed):
#   1. builds the core, the GPU tests and the benchmarks for this machine's
#      GPU (CUDA architecture "native");
#   2. runs ctest -L gpu (the device against the CPU: tests/gpu);
#   3. prints the throughput table (benchmarks/gpuThroughput: serial, every
#      host core, the host-assisted and the resident cuda step, at 262 k and
#      2.1 M points, with the ratios and the fraction of the card's
#      bandwidth);
#   4. runs compute-sanitizer's memcheck on the resident step's GPU test,
#      where the tool exists.
# Every log goes to one folder: the first argument, else $OUT (the device
# tool's), else ./deviceCheckLogs. Takes about three minutes on an H200
# with a 16-core host. Exit status: that of the ctest run.
#
#   bash benchmarks/gpu/deviceCheck.sh [logDir]
set -u
cd "$(dirname "$0")/../.."
logs=${1:-${OUT:-deviceCheckLogs}}
mkdir -p "$logs"
build=${MPM_DEVICE_BUILD:-build-device}
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
{
    date
    nvidia-smi --query-gpu=name,compute_cap,memory.total,driver_version --format=csv 2>&1
    nvcc --version | tail -2
    cmake --version | head -1
} > "$logs/machine.txt" 2>&1
cat "$logs/machine.txt"

echo "== build ($build)"
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DMPM_CUDA_ARCHITECTURES=native \
      -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON \
      > "$logs/configure.log" 2>&1 || { tail -30 "$logs/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" > "$logs/build.log" 2>&1 || { grep -m 20 -i error "$logs/build.log"; exit 1; }
grep "CUDA back-end" "$logs/configure.log"

echo "== ctest -L gpu"
ctest --test-dir "$build" -L gpu --output-on-failure > "$logs/ctest.log" 2>&1
status=$?
grep -E "PASS|FAIL|SKIP|tests passed|failed out of|cases failed" "$logs/ctest.log" | grep -v "^ *[0-9]*/[0-9]* Test" | tail -80
tail -3 "$logs/ctest.log"

echo "== throughput"
for cells in 32 64; do
    "$build/benchmarks/gpuThroughput" "$cells" 10 2>&1 | tee "$logs/gpuThroughput$cells.txt"
done

if command -v compute-sanitizer >/dev/null; then
    echo "== compute-sanitizer memcheck (stepOnDevice)"
    timeout 240 compute-sanitizer --tool memcheck "$build/tests/stepOnDevice" > "$logs/memcheck.log" 2>&1
    grep -E "ERROR SUMMARY|cases failed" "$logs/memcheck.log" | tail -3
fi
exit $status
