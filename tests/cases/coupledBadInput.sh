#!/bin/bash
#------------------------------------------------------------------------------
# Bad input in a coupled (fluid) case: a clear error naming the keyword and
# the valid choices, or a warning with the number, never a crash.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

seededCopy multiphase/packedBed

c=$(freshCopy unknownDrag)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergn; d 1e-3; }/' "$(props "$c")"
expectFailure "unknown drag law" "unknown drag law 'Ergn'; valid drag laws are: SchillerNaumann, WenYu, Ergun, Gidaspow, DiFelice, Beetstra" runIn "$c" mpmFoam
expectFailure "unknown drag law names the file" "constant/mpmProperties" runIn "$c" mpmFoam

c=$(freshCopy missingDiameter)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; }/' "$(props "$c")"
expectFailure "missing grain diameter" "missing required parameter 'd' \(grain diameter \[m\], valid range \(0, inf\)\)" runIn "$c" mpmFoam

c=$(freshCopy negativeDiameter)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d -1e-3; }/' "$(props "$c")"
expectFailure "negative grain diameter" "parameter 'd' .* has invalid value -0.001" runIn "$c" mpmFoam

c=$(freshCopy bigGrains)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d 0.02; }/' "$(props "$c")"
sed -i 's/^endTime .*/endTime 0.02;/' "$c/system/controlDict"
out=$(runIn "$c" mpmFoam 2>&1); rc=$?
if [ $rc -eq 0 ] && echo "$out" | grep -q "d = 0.02 of material glass is larger than the cell size h = 0.0025 (d/h = 8)"; then
    echo "PASS: grain larger than the cell: warning with the ratio d/h = 8"
else
    echo "FAIL: no warning with the ratio for d > h (rc $rc)"; failures=$((failures + 1))
fi

c=$(freshCopy unknownForce)
sed -i 's/forces      (drag pressureGradient);/forces      (drag lift);/' "$(props "$c")"
expectFailure "unknown coupling force" "Unknown force 'lift' in forces" runIn "$c" mpmFoam
expectFailure "coupling forces listed" "Valid forces: drag pressureGradient gravity virtualMass" runIn "$c" mpmFoam

c=$(freshCopy negativeCvm)
sed -i 's/forces      (drag pressureGradient);/forces      (drag pressureGradient virtualMass);\n    Cvm         -0.5;/' "$(props "$c")"
expectFailure "virtual-mass coefficient out of range" "Keyword Cvm = -0.5 is out of range \[0, 10\]" runIn "$c" mpmFoam

c=$(freshCopy unknownMode)
sed -i 's/mode        twoWay;/mode        threeWay;/' "$(props "$c")"
expectFailure "unknown coupling mode" "Valid mode choices: oneWay twoWayMomentum twoWay" runIn "$c" mpmFoam

c=$(freshCopy noCoupling)
sed -i '/^coupling/,/^}/d' "$(props "$c")"
expectFailure "fluid case without coupling dictionary" "has no coupling" runIn "$c" mpmFoam

c=$(freshCopy noPressure)
rm "$c/0/p"
expectFailure "fluid case without p" "but no field p at time 0" runIn "$c" mpmFoam
expectFailure "fluid case without p is a FatalIOError on transportProperties" "constant/transportProperties" runIn "$c" mpmFoam

finish
