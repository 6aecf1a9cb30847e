#!/bin/bash
#------------------------------------------------------------------------------
# Bad input in a coupled (fluid) case: a clear error naming the keyword and
# the valid choices, or a warning with the number, never a crash.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

base=$(copyTutorial multiphase/packedBed base)
(cd "$base" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1) \
    || { echo "FAIL: base case set-up"; exit 1; }
fresh() { cp -r "$base" "$SCRATCH/$1"; echo "$SCRATCH/$1"; }
props() { echo "$1/constant/mpmProperties"; }
run() { (cd "$1" && shift && timeout 120 "$@"); }

c=$(fresh unknownDrag)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergn; d 1e-3; }/' "$(props "$c")"
expectFailure "unknown drag law" "unknown drag law 'Ergn'; valid drag laws are: SchillerNaumann, WenYu, Ergun, Gidaspow, DiFelice, Beetstra" run "$c" mpmFoam
expectFailure "unknown drag law names the file" "constant/mpmProperties" run "$c" mpmFoam

c=$(fresh missingDiameter)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; }/' "$(props "$c")"
expectFailure "missing grain diameter" "missing required parameter 'd' \(grain diameter \[m\], valid range \(0, inf\)\)" run "$c" mpmFoam

c=$(fresh negativeDiameter)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d -1e-3; }/' "$(props "$c")"
expectFailure "negative grain diameter" "parameter 'd' .* has invalid value -0.001" run "$c" mpmFoam

c=$(fresh bigGrains)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d 0.02; }/' "$(props "$c")"
sed -i 's/^endTime .*/endTime 0.02;/' "$c/system/controlDict"
out=$(run "$c" mpmFoam 2>&1); rc=$?
if [ $rc -eq 0 ] && echo "$out" | grep -q "d = 0.02 is larger than the cell size h = 0.005 (d/h = 4)"; then
    echo "PASS: grain larger than the cell: warning with the ratio d/h = 4"
else
    echo "FAIL: no warning with the ratio for d > h (rc $rc)"; failures=$((failures + 1))
fi

c=$(fresh unknownForce)
sed -i 's/forces      (drag pressureGradient);/forces      (drag lift);/' "$(props "$c")"
expectFailure "unknown coupling force" "Unknown force 'lift' in forces" run "$c" mpmFoam
expectFailure "coupling forces listed" "Valid forces: drag pressureGradient gravity" run "$c" mpmFoam

c=$(fresh unknownMode)
sed -i 's/mode        twoWay;/mode        threeWay;/' "$(props "$c")"
expectFailure "unknown coupling mode" "Valid mode choices: oneWay twoWayMomentum twoWay" run "$c" mpmFoam

c=$(fresh noCoupling)
sed -i '/^coupling/,/^}/d' "$(props "$c")"
expectFailure "fluid case without coupling dictionary" "has no coupling" run "$c" mpmFoam

c=$(fresh noPressure)
rm "$c/0/p"
expectFailure "fluid case without p" "but no field p at time 0" run "$c" mpmFoam
expectFailure "fluid case without p is a FatalIOError on transportProperties" "constant/transportProperties" run "$c" mpmFoam

finish
