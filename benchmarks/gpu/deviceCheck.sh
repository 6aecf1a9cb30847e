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
# tool's), else ./deviceCheckLogs. Takes about two and a half minutes on
# an H200 with a 16-core host. Without nvcc it says so after configuring,
# without a GPU after the (skipped) GPU tests; both exit 0. Otherwise the
# exit status is that of the ctest run.
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

# The GPU's own architecture; without a GPU (nothing to detect) the
# default list, so that the build still compiles the CUDA code
arch=native
nvidia-smi -L >/dev/null 2>&1 || arch="75;80;90"
echo "== build ($build, CUDA architectures $arch)"
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "-DMPM_CUDA_ARCHITECTURES=$arch" \
      -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON \
      > "$logs/configure.log" 2>&1 || { tail -30 "$logs/configure.log"; exit 1; }
# Only what the check runs: the GPU tests and the throughput benchmark
targets=(gpuThroughput)
for t in tests/gpu/*.cu; do targets+=("$(basename "$t" .cu)"); done
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}" > "$logs/build.log" 2>&1 \
    || { grep -m 20 -i error "$logs/build.log"; exit 1; }
grep "CUDA back-end" "$logs/configure.log"
if ! grep -q "CUDA back-end: on" "$logs/configure.log"; then
    echo "deviceCheck: nothing to check: CMake found no CUDA compiler (nvcc) on this machine"
    exit 0
fi

echo "== ctest -L gpu"
ctest --test-dir "$build" -L gpu -V > "$logs/ctest.log" 2>&1
status=$?
grep -E "PASS|FAIL|SKIP|tests passed|failed out of|cases failed" "$logs/ctest.log" | grep -v "^ *[0-9]*/[0-9]* Test" | tail -80
tail -3 "$logs/ctest.log"

# Without a usable GPU the GPU tests were skipped (exit 77) and there is
# nothing to time
if grep -q "Skipped" "$logs/ctest.log"; then
    echo "deviceCheck: no throughput table: $("$build/tests/stepOnDevice" 2>&1 | grep -m1 'SKIP: ')"
    exit $status
fi

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
