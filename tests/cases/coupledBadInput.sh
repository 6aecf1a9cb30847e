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
expectFailure "coupling forces listed" "Valid forces: drag gravity pressureGradient virtualMass" runIn "$c" mpmFoam

c=$(freshCopy forceTwice)
sed -i 's/forces      (drag pressureGradient);/forces      (drag pressureGradient drag);/' "$(props "$c")"
expectFailure "force listed twice" "Force 'drag' listed twice in forces" runIn "$c" mpmFoam

c=$(freshCopy negativeCvm)
sed -i 's/forces      (drag pressureGradient);/forces      (drag pressureGradient virtualMass);\n    Cvm         -0.5;/' "$(props "$c")"
expectFailure "virtual-mass coefficient out of range" "Keyword Cvm = -0.5 is out of range \[0, 10\]" runIn "$c" mpmFoam

# A force's keyword is known only with the force selected: Cvm without
# virtualMass would be silently ignored otherwise
c=$(freshCopy CvmWithoutVirtualMass)
sed -i 's/forces      (drag pressureGradient);/forces      (drag pressureGradient);\n    Cvm         0.5;/' "$(props "$c")"
expectFailure "Cvm without the virtualMass force" "Unknown keyword 'Cvm' in coupling" runIn "$c" mpmFoam

c=$(freshCopy unknownMode)
sed -i 's/mode        twoWay;/mode        threeWay;/' "$(props "$c")"
expectFailure "unknown coupling mode" "Valid mode choices: oneWay twoWayMomentum twoWay" runIn "$c" mpmFoam

c=$(freshCopy unknownFluidResponse)
sed -i 's/mode        twoWay;/mode        twoWay;\n    fluidResponse frozn;/' "$(props "$c")"
expectFailure "unknown fluidResponse" "Valid fluidResponse choices: linearised frozen" runIn "$c" mpmFoam

c=$(freshCopy badTimeStepAdvice)
sed -i 's/mode        twoWay;/mode        twoWay;\n    timeStepAdvice maybe;/' "$(props "$c")"
expectFailure "timeStepAdvice not a switch" "Expected 'true/false', 'on/off' ... found maybe" runIn "$c" mpmFoam
expectFailure "timeStepAdvice not a switch names the file and keyword" "mpmProperties.coupling.timeStepAdvice at line" runIn "$c" mpmFoam

c=$(freshCopy noCoupling)
sed -i '/^coupling/,/^}/d' "$(props "$c")"
expectFailure "fluid case without coupling dictionary" "has no coupling" runIn "$c" mpmFoam

# Strict dictionaries in a coupled case: a misspelt keyword is an error
# naming the file, the keyword and the closest valid one, never ignored.
c=$(freshCopy misspeltCoupling)
sed -i 's/alphaMax    0.63;/alphaMx     0.63;/' "$(props "$c")"
expectFailure "misspelt coupling keyword" "Unknown keyword 'alphaMx' in coupling; did you mean 'alphaMax'\?" runIn "$c" mpmFoam
expectFailure "misspelt coupling keyword: file and valid keywords" "file: .*constant/mpmProperties.coupling at line" runIn "$c" mpmFoam
expectFailure "misspelt coupling keyword lists the valid keywords" "Valid keywords: mode forces alphaMax subCycles fluidResponse timeStepAdvice$" runIn "$c" mpmFoam

c=$(freshCopy misspeltDrag)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d 1e-3; alphaFmin 0.1; }/' "$(props "$c")"
expectFailure "misspelt drag keyword" "Unknown keyword 'alphaFmin' in drag of material glass \(model Ergun\); did you mean 'alphaFMin'\?" runIn "$c" mpmFoam
expectFailure "misspelt drag keyword names the file" "file: .*constant/mpmProperties.materials.glass.drag at line" runIn "$c" mpmFoam
expectFailure "misspelt drag keyword (mpmSetParticles reads the materials too)" "Unknown keyword 'alphaFmin' in drag of material glass" runIn "$c" mpmSetParticles

c=$(freshCopy dragNotDict)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    Ergun;/' "$(props "$c")"
expectFailure "drag that is not a dictionary" "Keyword drag must be a sub-dictionary drag \{ ... \}" runIn "$c" mpmFoam

c=$(freshCopy misspeltDilatancy)
sed -i 's/phi     30;/phi     30;\n        pis     5;/' "$(props "$c")"
expectFailure "misspelt granular coefficient" "Unknown keyword 'pis' in material glass \(model druckerPrager\); did you mean 'psi'\?" runIn "$c" mpmFoam

# Numbers that used to end in a floating-point exception (the traps stay on
# in the fluid solver): range errors naming the file and keyword instead.
c=$(freshCopy negativeViscosity)
sed -i 's/^nu .*/nu              -1e-6;/' "$c/constant/transportProperties"
expectFailure "negative fluid viscosity" "Keyword nu = -1e-06 is out of range \(0, inf\)" runIn "$c" mpmFoam
expectFailure "negative fluid viscosity names transportProperties" "file: .*constant/transportProperties" runIn "$c" mpmFoam

c=$(freshCopy zeroDensity)
sed -i 's/^rho .*/rho             0;/' "$c/constant/transportProperties"
expectFailure "zero fluid density" "Keyword rho = 0 is out of range \(0, inf\)" runIn "$c" mpmFoam

c=$(freshCopy fullPacking)
sed -i 's/alphaMax    0.63;/alphaMax    1;/' "$(props "$c")"
sed -i 's/solidFraction 0.6;/solidFraction 1;/' "$c/system/mpmSetParticlesDict"
runIn "$c" mpmSetParticles > /dev/null 2>&1
expectFailure "alphaMax 1 with grains at solidFraction 1" "Keyword alphaMax = 1 is out of range \(0, 1\)" runIn "$c" mpmFoam

c=$(freshCopy zeroFluidStep)
sed -i 's/^deltaT .*/deltaT          0;/' "$c/system/controlDict"
expectFailure "zero fluid time step" "Keyword deltaT = 0 is out of range \(0, inf\) \(the fluid step" runIn "$c" mpmFoam

c=$(freshCopy tinyDiameter)
sed -i 's/drag    { model Ergun; d 1e-3; }/drag    { model Ergun; d 1e-200; }/' "$(props "$c")"
expectFailure "a grain diameter in range but absurd (drag overflows)" "the drag coefficient beta is not finite in cell [0-9]+ at" runIn "$c" mpmFoam
expectFailure "drag overflow: what to check" "check their values and units \(d in m\)" runIn "$c" mpmFoam

c=$(freshCopy noPressure)
rm "$c/0/p"
expectFailure "fluid case without p" "but no field p at time 0" runIn "$c" mpmFoam
expectFailure "fluid case without p is a FatalIOError on transportProperties" "constant/transportProperties" runIn "$c" mpmFoam

finish
