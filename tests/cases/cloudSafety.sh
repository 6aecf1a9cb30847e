#!/bin/bash
#------------------------------------------------------------------------------
# The lagrangian cloud (pointOutput foam) is safe to restart from:
#  - materials by name: the cloud carries its material name table
#    (<time>/uniform/mpmMaterials); inserting a material before the others
#    after seeding keeps each point's law, a name mpmProperties no longer
#    defines stops with a clear message, an old cloud without the table is
#    read in the current order with a warning;
#  - a half-written time (a run killed during the write) has no completion
#    marker (<time>/uniform/mpmComplete): a restart from it is refused with
#    its name, the last complete time and what to do, and that advice works.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

seededCopy mpm/axialBar
shortRun() { sed -i 's/^endTime .*/endTime 2;/; s/^writeInterval .*/writeInterval 1;/' "$1/system/controlDict"; }
shortRun "$BASE_CASE"

# Reference: the bar as seeded
ref=$(freshCopy reference)
runIn "$ref" mpmFoam > "$ref/log.mpmFoam" 2>&1 || { echo "FAIL: reference run"; tail -20 "$ref/log.mpmFoam"; failures=$((failures + 1)); }

# A material inserted before the bar's after seeding: stiffer and denser, so
# a point that took it (index 0) would move differently.
c=$(freshCopy insertedMaterial)
"$PY" - "$(props "$c")" <<'PYEOF'
import re, sys
p = sys.argv[1]; s = open(p).read()
s = s.replace("materials\n{\n", "materials\n{\n    steel { model linearElastic; rho 7800; E 2000; nu 0.3; }\n", 1)
open(p, "w").write(s)
PYEOF
out=$(runIn "$c" mpmFoam 2>&1); rc=$?
echo "$out" > "$c/log.mpmFoam"
if [ $rc -eq 0 ] && echo "$out" | grep -q "materials mapped by name from the cloud's table 1(bar) to mpmProperties 2(steel bar)"; then
    echo "PASS: inserted material: the points are mapped by name (log)"
else
    echo "FAIL: inserted material: no mapping by name (rc $rc)"; echo "$out" | grep -i "material" | tail -5; failures=$((failures + 1))
fi
read -r dU mats table <<< "$("$PY" - "$ref" "$c" <<'PYEOF'
import re, sys
import numpy as np, mpmPost
ref, c = sys.argv[1:]
dU = np.abs(mpmPost.read_cloud_field(ref, "2", "U") - mpmPost.read_cloud_field(c, "2", "U")).max()
mat = set(mpmPost.read_cloud_field(c, "2", "material").astype(int).tolist())
table = re.search(r"materials\s*\d*\s*\(([^)]*)\)", open(c + "/2/uniform/mpmMaterials").read()).group(1).split()
print(dU, ",".join(map(str, sorted(mat))), ",".join(table))
PYEOF
)"
check "inserted material: every point keeps the bar's law (U as without the insertion)" "dU <= 1e-12" dU="$dU"
if [ "$mats" = "1" ] && [ "$table" = "steel,bar" ]; then
    echo "PASS: inserted material: written indices ($mats) refer to the written table ($table)"
else
    echo "FAIL: inserted material: indices $mats, table $table"; failures=$((failures + 1))
fi

c=$(freshCopy renamedMaterial)
sed -i 's/^    bar$/    rod/' "$(props "$c")"
expectFailure "a material of the cloud that mpmProperties no longer defines" "The material points of time 0 include material 'bar', which constant/mpmProperties materials does not define 1\(rod\)" runIn "$c" mpmFoam
expectFailure "a missing material names the table file" "file: .*0/uniform/mpmMaterials" runIn "$c" mpmFoam

c=$(freshCopy oldCloud)
rm "$c/0/uniform/mpmMaterials"
out=$(runIn "$c" mpmFoam 2>&1); rc=$?
if [ $rc -eq 0 ] && echo "$out" | grep -q "No material name table .* assuming its material indices follow the current order"; then
    echo "PASS: a cloud without a material table is read in the current order, with a warning"
else
    echo "FAIL: a cloud without a material table (rc $rc)"; echo "$out" | tail -5; failures=$((failures + 1))
fi

# A run killed while writing time 2: the marker is missing, a field is cut.
c=$(freshCopy killedDuringWrite)
runIn "$c" mpmFoam > "$c/log.mpmFoam" 2>&1
check "every write time is marked complete" "n == 3" n="$(ls "$c"/[0-9]*/uniform/mpmComplete | wc -l)"
rm "$c/2/uniform/mpmComplete"
head -c 300 "$c/2/lagrangian/materialPoints/U" > "$c/U.cut" && mv "$c/U.cut" "$c/2/lagrangian/materialPoints/U"
sed -i 's/^endTime .*/endTime 3;/' "$c/system/controlDict"
expectFailure "restart from a half-written time names it" "Time 2 is incomplete: .*2/uniform/mpmComplete\"? is missing" runIn "$c" mpmFoam
expectFailure "restart from a half-written time: delete it, the last complete time" "Delete it \(foamListTimes -time 2 -rm\) and restart: startFrom latestTime then continues from time 1, the last complete one" runIn "$c" mpmFoam
out=$(runIn "$c" mpmFoam 2>&1)
if echo "$out" | grep -qi "seed"; then echo "FAIL: the advice says to re-seed"; failures=$((failures + 1)); else echo "PASS: the advice does not say to re-seed"; fi
(cd "$c" && foamListTimes -time 2 -rm > /dev/null 2>&1)
if runIn "$c" mpmFoam > "$c/log.restart" 2>&1 && [ -f "$c/3/uniform/mpmComplete" ] && grep -q "^Create time\|Starting time loop" "$c/log.restart"; then
    echo "PASS: the advice works: after deleting time 2 the run continues from 1 to 3"
else
    echo "FAIL: restart after deleting the incomplete time"; tail -10 "$c/log.restart"; failures=$((failures + 1))
fi
finish
