#!/bin/bash
#------------------------------------------------------------------------------
# The documentation's commands work when followed literally (issue 28).
#
# A command block that README.md or docs/*.md tells users to run carries the
# line <!-- tested: NAME --> above its fence, and a test runs it as written
# with runDocBlock (caseTestFunctions). This test
#   1. checks the marks: each is followed by a non-empty fenced block, each
#      name is unique and is run by some test under tests/, and the blocks
#      every user meets are marked: the quick start, foamRun, the decomposed
#      workflow, the restart on another number of ranks (both directions;
#      pure MPM and coupled, tests/cases/restartOtherRanks.sh), the
#      accuracy-cost command and the stability advisor;
#   2. runs the README's quick start, foamRun and decomposed-workflow blocks
#      in a copy of tutorials/mpm/elasticDisks (shortened; the decomposed one
#      with etc/caseDicts/decomposeParDict as the README's file table says)
#      and checks what each promises (the cloud written, VTK written, the
#      reconstructed cloud equal to the serial run's);
#   3. runs docs/accuracyCost.md's first-try block in an empty folder and
#      checks its budget answer.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
required="quick-start foamRun decomposed-workflow restart-to-serial restart-decomposed accuracy-cost stability-advisor"

echo "=== 1. the marks"
marks=$(cd "$MPMFOAM_ROOT" && grep -HnoE "^ *<!-- tested: [A-Za-z0-9-]+ -->" README.md docs/*.md \
        | sed -E 's/^([^:]+):[0-9]+: *<!-- tested: ([A-Za-z0-9-]+) -->/\1 \2/')
echo "$marks"
dups=$(echo "$marks" | awk '{print $2}' | sort | uniq -d | tr '\n' ' ')
check "every mark names one block only (duplicates: '${dups}')" "n == 0" n="$(echo -n "$dups" | wc -w)"
while read -r file name; do
    [ -z "$name" ] && continue
    lines=$(docBlock "$file" "$name" | grep -c .)
    users=$(grep -rlE "runDocBlock [^ ]+ $name([ \"']|$)" "$MPMFOAM_ROOT/tests" | wc -l)
    check "$file block '$name': a fenced block follows ($lines lines) and a test runs it" \
        "lines > 0 and users > 0" lines="$lines" users="$users"
done <<< "$marks"
for name in $required; do
    check "the block users meet, '$name', is marked" "n == 1" n="$(echo "$marks" | awk -v n="$name" '$2 == n' | wc -l)"
done

echo "=== 2. the README's commands"
shorten()
{
    foamDictionary -entry endTime -set 0.2 "$1/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 0.1 "$1/system/controlDict" > /dev/null
}
q=$(copyTutorial mpm/elasticDisks quickStart)
shorten "$q"
if runDocBlock README.md quick-start "$q"; then
    check "quick start: the cloud at 0.2 and the VTK files written" "c == 1 and v > 0" \
        c="$([ -f "$q/0.2/lagrangian/materialPoints/U" ] && echo 1 || echo 0)" \
        v="$(find "$q/VTK" -name '*.vt*' 2>/dev/null | wc -l)"
fi

f=$(copyTutorial mpm/elasticDisks foamRun)
shorten "$f"
runApps "$f" blockMesh mpmSetParticles
runDocBlock README.md foamRun "$f" \
    && check "foamRun: the same points as mpmFoam's at 0.2" "same == 1 and d == 0" \
        same="$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$q" "$f" 0.2 | awk '$1=="ids"{print $3}')" \
        d="$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$q" "$f" 0.2 | awk 'NR>2{if($2>m)m=$2}END{print m+0}')"

d=$(copyTutorial mpm/elasticDisks decomposed)
shorten "$d"
cp "$MPMFOAM_ROOT/etc/caseDicts/decomposeParDict" "$d/system/"
if runDocBlock README.md decomposed-workflow "$d"; then
    # (the disks fly free until t = 1.2: their stress is round-off, so not compared)
    out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$q" "$d" 0.2 --fields U F mass volume)
    check "decomposed workflow (4 ranks, reconstructed): the serial run's positions, U, F, mass, volume to 1e-10" \
        "same == 1 and worst <= 1e-10" same="$(echo "$out" | awk '$1=="ids"{print $3}')" \
        worst="$(echo "$out" | awk 'NR>2{if($2>m)m=$2}END{print m+0}')"
fi

echo "=== 3. docs/accuracyCost.md: the first try"
a="$SCRATCH/accuracyFirstTry"
mkdir -p "$a"
if runDocBlock docs/accuracyCost.md accuracy-cost "$a"; then
    check "accuracy cost: 12 runs measured, a budget answer for 0.05" "ok == 12 and b == 1" \
        ok="$(grep -c ',ok,' "$a/myBar/accuracyCost/results.csv")" \
        b="$(grep -c "^Budget: the cheapest measured configuration with error <= 0.05" "$a/log.doc.accuracy-cost")"
fi

finish
