#!/bin/bash
#------------------------------------------------------------------------------
# Bad input for the VOF fluid (constant/transportProperties fluidModel VOF,
# docs/coupling.md): a clear error naming what is missing or wrong, never a
# crash. On interFoam's damBreak set up for mpmFoam (vofMpmCase,
# caseTestFunctions), each variant changing one thing:
#  - an unknown fluidModel, an unknown alphaContinuity (the valid choices,
#    and the closest);
#  - no 0/alpha.water (names the field and setFields), no 0/p_rgh;
#  - the properties of both fluids: no phases, no air { }, no rho in water;
#  - the surface tension: missing (sigma 0 for none), wrong dimensions
#    (a length), negative;
#  - what the VOF fluid does not do yet: turbulence (RAS), the virtualMass
#    force (one fluid density).
# The single fluid's bad input is in coupledBadInput.sh.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

dam=$(damBreakCase damBreak) || exit 1
BASE_CASE=$(vofMpmCase "$dam" base) || exit 1
tp() { echo "$1/constant/transportProperties"; }

c=$(freshCopy unknownModel)
sed -i 's/^fluidModel .*/fluidModel      VoF;/' "$(tp "$c")"
expectFailure "unknown fluidModel" "Unknown fluidModel 'VoF'; did you mean 'VOF'" runIn "$c" mpmFoam
expectFailure "unknown fluidModel: the choices" "Valid fluidModel choices: single VOF" runIn "$c" mpmFoam

c=$(freshCopy unknownContinuity)
sed -i 's/^\( *nLimiterIter .*\)/\1\n        alphaContinuity bounde;/' "$c/system/fvSolution"
expectFailure "unknown alphaContinuity" "Unknown alphaContinuity 'bounde'; did you mean 'bounded'" runIn "$c" mpmFoam
expectFailure "unknown alphaContinuity: the choices" "Valid alphaContinuity choices: corrected conservative bounded" runIn "$c" mpmFoam

c=$(freshCopy noAlphaWater)
rm "$c/0/alpha.water"
expectFailure "VOF without 0/alpha.water" "fluidModel VOF: no field alpha.water at time 0" runIn "$c" mpmFoam
expectFailure "VOF without 0/alpha.water: what to do" "e.g. from a uniform 0 with setFields" runIn "$c" mpmFoam

c=$(freshCopy noPrgh)
rm "$c/0/p_rgh"
expectFailure "VOF without 0/p_rgh" "fluidModel VOF: no field p_rgh at time 0" runIn "$c" mpmFoam

c=$(freshCopy noPhases)
sed -i '/^phases /d' "$(tp "$c")"
expectFailure "VOF without phases" "fluidModel VOF needs the two fluids: no 'phases'" runIn "$c" mpmFoam

c=$(freshCopy noAir)
sed -i '/^air/,/^}/d' "$(tp "$c")"
grep -q "^air" "$(tp "$c")" && { echo "FAIL: could not remove air { }"; failures=$((failures + 1)); }
expectFailure "VOF without the air's properties" "no properties of the fluid 'air'.*both fluids of phases \(water air\) need theirs" runIn "$c" mpmFoam

c=$(freshCopy noWaterRho)
sed -i '0,/^    rho .*/{/^    rho .*/d}' "$(tp "$c")"
expectFailure "VOF without the water's density" "the fluid 'water' has no rho" runIn "$c" mpmFoam

c=$(freshCopy noSigma)
sed -i '/^sigma /d' "$(tp "$c")"
expectFailure "VOF without sigma" "needs the surface tension 'sigma' \[N/m\].*\(sigma 0; for none\)" runIn "$c" mpmFoam

c=$(freshCopy sigmaLength)
sed -i 's/^sigma .*/sigma           [0 1 0 0 0 0 0] 0.07;/' "$(tp "$c")"
expectFailure "sigma with the dimensions of a length" "The surface tension sigma has dimensions \[0 1 0 0 0 0 0\]; a surface tension is a force per length" runIn "$c" mpmFoam

c=$(freshCopy sigmaNegative)
sed -i 's/^sigma .*/sigma           -0.07;/' "$(tp "$c")"
expectFailure "negative sigma" "Keyword sigma = -0.07[0-9]* is out of range \[0, inf\) \(surface tension \[N/m\]\)" runIn "$c" mpmFoam

c=$(freshCopy turbulent)
sed -i 's/^simulationType .*/simulationType  RAS;/' "$c/constant/turbulenceProperties"
expectFailure "VOF with RAS" "fluidModel VOF is laminar \(Stokes\) for now: simulationType RAS" runIn "$c" mpmFoam

c=$(freshCopy virtualMass)
sed -i 's/forces      (gravity);/forces      (gravity virtualMass);/' "$(props "$c")"
expectFailure "VOF with the virtualMass force" "The virtualMass force is not available with fluidModel VOF yet" runIn "$c" mpmFoam

# The base case runs (so each failure above is the one change's)
sed -i 's/^endTime .*/endTime 0.002;/' "$BASE_CASE/system/controlDict"
if runApps "$BASE_CASE" mpmFoam; then echo "PASS: the unchanged base case runs"; else echo "FAIL: the base case"; tail -20 "$BASE_CASE/log.mpmFoam"; failures=$((failures + 1)); fi

finish
