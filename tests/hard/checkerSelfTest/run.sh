#!/bin/bash
#------------------------------------------------------------------------------
# The shared checker can fail: a short clean run of the axial bar passes
# tests/hard/checkRun.py; then each defect is put into a copy of it and the
# check that must catch it has to FAIL:
#   - a NaN in a written cloud field and an inf in the log;
#   - a point missing from a cloud, a point duplicated, a point's mass
#     changed by 1e-12 relative;
#   - the logged energy grown by 2e-2 of E0 against a 1e-2 bound (the
#     clean run's swing: 4.3e-3);
#   - a stop (FOAM FATAL) where completion is expected, and a stop whose
#     message does not say what the case expects;
#   - a written alpha.fluid below 1 - alphaMax.
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c=$(copyTutorial mpm/axialBar clean)
sed -i 's/^endTime .*/endTime         10;/; s/^writeInterval .*/writeInterval   5;/' "$c/system/controlDict"
setUp "$c"
solve "$c"
run() { "$PY" "$HARD_DIR/checkRun.py" "$@" 2>&1; }
out=$(run "$c" --energy-growth 1e-2)
check "a clean run passes every check" "f == 0 and p >= 6" f="$(echo "$out" | grep -c "^FAIL")" p="$(echo "$out" | grep -c "^PASS")"

# defect <name> <regex of the check that must fail> <checkRun options> -- <shell edit of $d>
defect()
{
    local name="$1" what="$2" opts="$3" edit="$4" d="$SCRATCH/$1" out
    cp -r "$c" "$d"
    (cd "$d" && eval "$edit")
    out=$(run "$d" $opts)
    if echo "$out" | grep -q "^FAIL: .*$what"; then
        echo "PASS: $name is caught: $(echo "$out" | grep -m1 "^FAIL: .*$what" | cut -c1-150)"
    else
        echo "FAIL: $name is not caught by /$what/"; echo "$out" | sed 's/^/    /'; failures=$((failures + 1))
    fi
}
u=5/lagrangian/materialPoints
defect nanInCloud "no NaN/inf in any written file" "" "sed -i '0,/^(\([-0-9.e]*\) /s//(nan /' $u/U"
defect infInLog "no NaN/inf in the solver log" "" "sed -i '0,/kinetic energy [-0-9.e]*,/s//kinetic energy inf,/' log.mpmFoam"
defect missingPoint "holds the seeded" "" "$PY - <<'P'
import re
for f in ['pointId', 'mass']:
    p = '$u/' + f; s = open(p).read()
    s = re.sub(r'\n50\n\(\n([^\n]*\n)', r'\n49\n(\n', s, count=1); open(p, 'w').write(s)
P"
defect duplicatePoint "each id once" "" "$PY - <<'P'
import re
p = '$u/pointId'; s = open(p).read()
m = re.search(r'\n50\n\(\n([^\n]*)\n([^\n]*)\n', s)
s = s[:m.start(2)] + m.group(1) + s[m.end(2):]; open(p, 'w').write(s)
P"
defect massChanged "keeps its seeded mass" "" "$PY - <<'P'
import re
p = '$u/mass'; s = open(p).read()
m = re.search(r'\n(\d+)\{([^}]*)\}', s)     # all equal: N{value}
n, v = int(m.group(1)), float(m.group(2))
body = '\n%d\n(\n%s\n%s\n)' % (n, repr(v*(1 + 1e-12)), '\n'.join([repr(v)]*(n - 1)))
open(p, 'w').write(s[:m.start()] + body + s[m.end():])
P"
defect energyGrowth "energy grows by" "--energy-growth 1e-2" "$PY - <<'P'
import glob
p = glob.glob('postProcessing/mpmSummary/*/summary.dat')[0]
rows = open(p).read().splitlines()
last = rows[-1].split(); last[1] = repr(float(last[1]) + 2e-2*0.0625); rows[-1] = ' '.join(last)
open(p, 'w').write('\n'.join(rows) + '\n')
P"
defect unexpectedStop "the run completes" "" "sed -i 's/^End\$/--> FOAM FATAL ERROR: something/' log.mpmFoam"
defect stopWithoutAdvice "stops with a message saying what to change" "--expect-stop Reduce.the.time.step" "sed -i 's/^End\$/--> FOAM FATAL ERROR: something/' log.mpmFoam"
defect alphaAboveMax "alpha.fluid <= alphaMax" "--alpha-max 0.63" "printf '%s\\n' 'FoamFile { version 2.0; format ascii; class volScalarField; object alpha.fluid; }' 'dimensions [0 0 0 0 0 0 0];' 'internalField uniform 0.3;' 'boundaryField { \".*\" { type zeroGradient; } }' > 5/alpha.fluid"
finish
