#!/bin/bash
#------------------------------------------------------------------------------
# The fluid time step of coupled runs (issue 11, "the fluid time step"):
#   - the fluid Courant number is printed every fluid step;
#   - adjustTimeStep yes; maxCo; maxDeltaT in controlDict set the step as
#     pimpleFoam does: every step's Courant number <= maxCo, deltaT <=
#     maxDeltaT, and the step does vary;
#   - a fixed step with Courant > 1 warns once, naming the step to use;
#     the shipped step (Courant ~0.3) does not warn.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# setup <tutorial> <name> <sed on controlDict>
setup()
{
    local c; c=$(copyTutorial "$1" "$2")
    sed -i "$3" "$c/system/controlDict"
    runApps "$c" blockMesh mpmSetParticles \
        || { echo "FAIL: set-up $2"; failures=$((failures + 1)); }
    echo "$c"
}

# Adjustable step on the underwater collapse (slow flow: a small maxCo)
c=$(setup multiphase/underwaterGranularCollapse adjust "s/^endTime .*/endTime 0.06;/; s/^writeInterval .*/writeInterval 0.06;/")
printf 'adjustTimeStep yes;\nmaxCo 0.05;\nmaxDeltaT 2e-3;\n' >> "$c/system/controlDict"
(cd "$c" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: adjustable run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); }
read -r n coMax dtMin dtMax <<< "$(grep "^fluid: Courant Number max" "$c/log.mpmFoam" \
    | awk '{n++; if ($5 > co) co = $5; if (n == 1 || $8 < lo) lo = $8; if ($8 > hi) hi = $8} END {print n, co, lo, hi}')"
check "adjustTimeStep: fluid Courant number <= maxCo 0.05 on all $n steps" "n > 20 and coMax <= 0.05*(1 + 1e-9)" n="${n:-0}" coMax="${coMax:-1}"
check "adjustTimeStep: deltaT varies and stays <= maxDeltaT 2e-3" "dtMin < 0.9*dtMax and dtMax <= 2e-3*(1 + 1e-12)" dtMin="${dtMin:-0}" dtMax="${dtMax:-1}"

# Fixed steps on the jet: 5x the shipped step (Courant ~2) warns once
c=$(setup multiphase/jetScour big "s/^endTime .*/endTime 0.02;/; s/^writeInterval .*/writeInterval 0.02;/; s/^deltaT .*/deltaT 5e-3;/")
(cd "$c" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: fixed-step run"; failures=$((failures + 1)); }
warned=$(grep -c "gives Courant number .* > 1 at time .*: use deltaT <= " "$c/log.mpmFoam")
check "fixed step with fluid Courant > 1 warns once, naming the step" "warned == 1" warned="$warned"
grep -m1 "gives Courant number" "$c/log.mpmFoam" | sed 's/^ */    /'
c=$(setup multiphase/jetScour shipped "s/^endTime .*/endTime 0.01;/; s/^writeInterval .*/writeInterval 0.01;/")
(cd "$c" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: shipped-step run"; failures=$((failures + 1)); }
warned=$(grep -c "gives Courant number" "$c/log.mpmFoam")
coMax=$(grep "^fluid: Courant Number max" "$c/log.mpmFoam" | awk '{if ($5 > co) co = $5} END {print co + 0}')
check "the shipped jet step (Courant $coMax) does not warn" "warned == 0 and coMax < 1" warned="$warned" coMax="$coMax"

[ "$failures" -eq 0 ]
