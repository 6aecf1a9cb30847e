#!/bin/bash
#------------------------------------------------------------------------------
# Parameter studies of the coupled analysis (adviseCoupledCase.py with an
# override -> mpmStabilityAnalysis --model coupled --advise) on the shipped
# fluidised bed: the drag's relaxation time from the core's law equals
# Ergun's by hand (Gidaspow is Ergun below alpha.fluid 0.8); the product's
# scheme is stable at the case's step, packed (--aS 0.6) and lifted; the old
# frozen-fluid scheme is unstable once the bed is lifted (stress-free at aS
# 0.55), as observed before the fix; a study says it is not the case's
# advice (that is mpmAdviseTimeStep, tests/cases/coupledSolverAdvice.sh); a
# study of a case whose blockMeshDict has no cell size asks for --h.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"
advise="$MPMFOAM_ROOT/applications/tools/mpmStabilityAnalysis/adviseCoupledCase.py"
bed="$MPMFOAM_ROOT/tutorials/multiphase/fluidisedBed"

packed=$("$PY" "$advise" "$bed" --tool "$tool" --aS 0.6)
echo "$packed"
lifted=$("$PY" "$advise" "$bed" --tool "$tool" --stress-free --aS 0.55)
echo "$lifted"
field() { echo "$1" | awk -v key="$2" 'index($0, key) {print $NF; exit}'; }
D=$(echo "$packed" | awk -F'Dt/tau_p = ' '/tau_p =/ {print $2; exit}')
# Ergun at aS 0.6: beta = 150 aS^2 mu/(aF d^2), tau_p = aS rho_s/beta, Dt 0.02 s
check "fluidised bed: Dt/tau_p from the core's drag law = Ergun by hand" \
    "abs(D - 0.02/(0.6*2500/(150*0.36*1e-3/(0.4*5e-4**2)))) < 1e-9*D" D="${D:-0}"
check "fluidised bed, packed: the product's scheme is stable" "g < 1" g="$(field "$packed" "linearised (the product)")"
check "fluidised bed, lifted (aS 0.55, stress-free): the product's scheme is stable" \
    "g < 1" g="$(field "$lifted" "linearised (the product)")"
check "fluidised bed, lifted: the old frozen-fluid scheme is not" "g > 1" g="$(field "$lifted" "frozen")"

if echo "$packed" | grep -q "^adviseCoupledCase.py: a parameter study, not the case's advice (that is mpmAdviseTimeStep"; then
    echo "PASS: a study says it is not the case's advice and names mpmAdviseTimeStep"
else
    echo "FAIL: a study does not say it is not the case's advice"; failures=$((failures + 1))
fi

c=$(copyTutorial multiphase/jetScour noCellSize)
expectFailure "a study, no cell size in blockMeshDict" "give the cell size with --h \(mpmAdviseTimeStep <case> reads it from the mesh\)" \
    "$PY" "$advise" "$c" --tool "$tool" --aS 0.6

finish
