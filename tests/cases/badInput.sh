#!/bin/bash
#------------------------------------------------------------------------------
# Bad input gets a clear error naming the file/keyword and the valid choices,
# never a crash, a hang or silently written NaN. Each case breaks one thing
# in a copy of the axialBar tutorial and asserts the message.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

seededCopy mpm/axialBar

c=$(freshCopy unknownModel)
sed -i 's/model   linearElastic;/model   linearElastik;/' "$(props "$c")"
expectFailure "unknown model" "Unknown model 'linearElastik'" runIn "$c" mpmFoam
expectFailure "unknown model lists valid models" "Valid models: linearElastic, neoHookean, newtonianFluid, druckerPrager, dilute" runIn "$c" mpmFoam
expectFailure "unknown model names the file" "constant/mpmProperties" runIn "$c" mpmFoam

c=$(freshCopy missingCoefficient)
sed -i '/^        E       100;/d' "$(props "$c")"
expectFailure "missing coefficient" "Missing coefficient E for material bar \(model linearElastic\).*valid range \(0, inf\)" runIn "$c" mpmFoam

c=$(freshCopy negativeCoefficient)
sed -i 's/^        E       100;/        E       -100;/' "$(props "$c")"
expectFailure "negative coefficient" "Coefficient E = -100 of material bar \(model linearElastic\) is out of range \(0, inf\)" runIn "$c" mpmFoam

c=$(freshCopy poissonRange)
sed -i 's/^        nu      0;/        nu      0.6;/' "$(props "$c")"
expectFailure "Poisson ratio out of range" "Coefficient nu = 0.6 .* out of range \[0, 0.5\)" runIn "$c" mpmFoam

c=$(freshCopy unknownShape)
sed -i 's/^shapeFunction .*/shapeFunction   cubic;/' "$(props "$c")"
expectFailure "unknown shape function" "Unknown shapeFunction 'cubic'" runIn "$c" mpmFoam
expectFailure "shape function choices" "Valid shapeFunction choices: linearHat quadraticBSpline cubicBSpline" runIn "$c" mpmFoam

c=$(freshCopy unknownWall)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type sticky; }/' "$(props "$c")"
expectFailure "unknown wall type" "Valid type choices: noSlip slip friction periodic" runIn "$c" mpmFoam

c=$(freshCopy frictionWithoutCoefficient)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type friction; }/' "$(props "$c")"
expectFailure "friction wall without coefficient" "Missing keyword frictionCoefficient" runIn "$c" mpmFoam

c=$(freshCopy nonUniformMesh)
sed -i 's/simpleGrading (1 1 1)/simpleGrading (3 1 1)/' "$c/system/blockMeshDict"
runIn "$c" blockMesh > /dev/null 2>&1
expectFailure "graded mesh" "MPM needs a uniform mesh, but cell" runIn "$c" mpmFoam
expectFailure "graded mesh (seeding)" "MPM needs a uniform mesh" runIn "$c" mpmSetParticles

c=$(freshCopy nonHexMesh)
# Collapse one edge of the block: prism cells.
sed -i 's/(0 0 1) (\$length 0 1) (\$length 1 1) (0 1 1)/(0 0 1) ($length 0 1) ($length 0 1) (0 0 1)/' "$c/system/blockMeshDict"
runIn "$c" blockMesh > "$c/log.blockMesh.prism" 2>&1
expectFailure "non-hex mesh" "MPM needs a uniform Cartesian hex mesh, but cell 0 .* is a prism|MPM needs axis-aligned box cells" runIn "$c" mpmFoam

c=$(freshCopy seededOutside)
sed -i 's/max           (25 1 1);/max           (40 1 1);/' "$c/system/mpmSetParticlesDict"
expectFailure "region outside the mesh" "reaches outside the mesh .*points would be seeded outside the mesh" runIn "$c" mpmSetParticles

c=$(freshCopy notSeeded)
rm -rf "$c/0/lagrangian"
expectFailure "no material points" "No material points in" runIn "$c" mpmFoam

expectFailure "no material points: what to do" "Seed them with mpmSetParticles" runIn "$c" mpmFoam

c=$(freshCopy nanDuringRun)
# A fixed step ten times the stability limit: the bar blows up to inf/NaN.
sed -i 's/type        adaptive;/type        fixed;/' "$(props "$c")"
sed -i 's/^deltaT .*/deltaT          1;/; s/^writeInterval .*/writeInterval   1;/; s/^endTime .*/endTime 100000;/' "$c/system/controlDict"
expectFailure "NaN during run names step and point" "non-finite .* at step [0-9]+ in material point id [0-9]+" runIn "$c" mpmFoam
expectFailure "a fixed step above Courant 1 is warned about first" "The MPM step .* set by timeStep fixed .* gives Courant number [0-9.e+]+ > 1" runIn "$c" mpmFoam
bad=$(grep -rliE "\bnan\b|\binf\b" "$c"/[0-9]*/lagrangian "$c"/[0-9]*/*.solid 2>/dev/null | head -3)
if [ -z "$bad" ]; then echo "PASS: no NaN/inf written"; else echo "FAIL: NaN written in $bad"; failures=$((failures + 1)); fi

finish
