#!/bin/bash
#------------------------------------------------------------------------------
# foamRun and the mpmFoam solver module (docs/foamRun.md).
#
#  1. Pure MPM (elasticDisks to t = 0.5, 66 steps) and coupled
#     (settlingSuspension to t = 0.1, 20 fluid steps), each run three ways
#     from the same seeded case: `mpmFoam`, `foamRun -solver mpmFoam`, and
#     plain `foamRun` with `solver mpmFoam;` in the controlDict. The same
#     module code runs in all three, so every written file (fields, cloud,
#     uniform/, postProcessing/mpmSummary) must agree to round-off: the
#     largest relative difference of any number is held to 1e-12 (measured
#     0: the files are identical). The log lines of the step (Courant, Time,
#     MPM, fluid, linear-solver residuals) must be identical too.
#  2. foamRun does not link libmpmFoam: it opens it at run time.
#  3. Errors: no solver anywhere gives Foundation's message; an unknown name
#     is a FatalError listing the modules that registered (none, or mpmFoam
#     once libmpmFoam is loaded with -lib).
# A few seconds in all.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# maxRelDiff <reference case> <case>: the largest relative difference of
# the numbers in any file written by the run (time directories but 0,
# postProcessing); "inf" if a file is missing or has another count.
maxRelDiff()
{
    "$PY" - "$1" "$2" <<'PYEOF'
import os, re, sys
ref, case = sys.argv[1:]
num = re.compile(rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
worst, nfiles = 0.0, 0
for top in sorted(os.listdir(ref)):
    written = top == "postProcessing" or (re.fullmatch(r"[0-9.eE+-]+", top) and float(top) > 0)
    if not written:
        continue
    for d, _, files in os.walk(os.path.join(ref, top)):
        for f in files:
            a = os.path.join(d, f)
            b = os.path.join(case, os.path.relpath(a, ref))
            if not os.path.isfile(b):
                print("inf"); sys.exit()
            x = [float(t) for t in num.findall(open(a, "rb").read())]
            y = [float(t) for t in num.findall(open(b, "rb").read())]
            if len(x) != len(y):
                print("inf"); sys.exit()
            scale = max([abs(v) for v in x] + [1e-300])
            worst = max([worst] + [abs(u - v)/scale for u, v in zip(x, y)])
            nfiles += 1
print(worst if nfiles else "inf")
PYEOF
}

stepLog() { grep -E "^(Courant|Time =|MPM:|fluid:)|Solving for" "$1/log.run"; }

# threeWays <tutorial> <name> <endTime>: seeds once, runs the three ways
threeWays()
{
    local base v
    base=$(copyTutorial "$1" "$2")
    (cd "$base" && foamDictionary -entry endTime -set "$3" system/controlDict > /dev/null \
        && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1) \
        || { echo "FAIL: $2 set-up"; failures=$((failures + 1)); return; }
    for v in mpmFoam option dict; do cp -r "$base" "$SCRATCH/$2.$v"; done
    foamDictionary -entry solver -add mpmFoam "$SCRATCH/$2.dict/system/controlDict" > /dev/null
    runIn "$SCRATCH/$2.mpmFoam" mpmFoam > "$SCRATCH/$2.mpmFoam/log.run" 2>&1 \
        || { echo "FAIL: $2: mpmFoam"; failures=$((failures + 1)); return; }
    runIn "$SCRATCH/$2.option" foamRun -solver mpmFoam > "$SCRATCH/$2.option/log.run" 2>&1 \
        || { echo "FAIL: $2: foamRun -solver mpmFoam"; failures=$((failures + 1)); }
    runIn "$SCRATCH/$2.dict" foamRun > "$SCRATCH/$2.dict/log.run" 2>&1 \
        || { echo "FAIL: $2: foamRun (solver in controlDict)"; failures=$((failures + 1)); }

    for v in option dict; do
        local c="$SCRATCH/$2.$v" d n
        d=$(maxRelDiff "$SCRATCH/$2.mpmFoam" "$c")
        check "$2: foamRun ($v) writes what mpmFoam writes" "d <= 1e-12" d="$d"
        n=$(diff <(stepLog "$SCRATCH/$2.mpmFoam") <(stepLog "$c") | grep -c '^[<>]')
        check "$2: foamRun ($v) logs the same step lines ($(stepLog "$c" | wc -l))" "n == 0" n="$n"
    done
}

threeWays mpm/elasticDisks pure 0.5
threeWays multiphase/settlingSuspension coupled 0.1
grep -q "sub-cycles of deltaT" "$SCRATCH/coupled.option/log.run" \
    || { echo "FAIL: the coupled case did not run coupled"; failures=$((failures + 1)); }

# 2. Loaded at run time, not linked
if ldd "$(command -v foamRun)" | grep -q libmpmFoam; then
    echo "FAIL: foamRun links libmpmFoam"; failures=$((failures + 1))
else
    echo "PASS: foamRun does not link libmpmFoam"
fi

# 3. Errors
c="$SCRATCH/pure"
expectFailure "no solver" "solver not specified in the controlDict or on the command-line" \
    runIn "$c" foamRun
expectFailure "unknown solver" "Unknown solver module nonsense" \
    runIn "$c" foamRun -solver nonsense
expectFailure "unknown solver lists the registered modules" "^[0-9]+\(.*mpmFoam.*\)" \
    runIn "$c" foamRun -solver nonsense -lib libmpmFoam.so

finish
