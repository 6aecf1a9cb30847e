#!/bin/bash
#------------------------------------------------------------------------------
# The coupled spectral analysis (mpmStabilityAnalysis --model coupled) checked
# against the solver: mpmFoam runs one Fourier mode of frozen stress-free
# grains in water on the periodic 1D lattice (tests/cases/coupledModeCase);
# at every fluid step the measured one-step map must equal the analysis'
# amplification matrix: the grains' per-step amplification, their mode and
# the fluid flux to 1e-6 relative, the fluid's U and p to 1e-5 (OpenFOAM's
# ddtCorr coefficient, see compareWithAnalysis.py), for the three coupling
# modes, two Dt/tau_p (0.51 and 5.1), 1 and 2 sub-cycles, PIC and FLIP.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"
caseSrc="$MPMFOAM_ROOT/tests/cases/coupledModeCase"

runCheck()   # mode deltaT subCycles flipRatio
{
    local c="$SCRATCH/m_$1_$2_$3_$4"
    cp -r "$caseSrc" "$c"
    sed -i "s/^\( *mode \+\).*/\1$1;/; s/^\( *subCycles \+\).*/\1$3;/; s/^flipRatio .*/flipRatio       $4;/" \
        "$c/constant/mpmProperties"
    sed -i "s/^deltaT .*/deltaT          $2;/; s/^endTime .*/endTime         $("$PY" -c "print(12*$2)");/" \
        "$c/system/controlDict"
    (cd "$c" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 \
        && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: run $c"; failures=$((failures + 1)); return; }
    if "$PY" "$c/compareWithAnalysis.py" "$c" "$tool" --tol 1e-6 --fluid-tol 1e-5 > "$c/log.compare" 2>&1; then
        echo "PASS: $1 deltaT=$2 subCycles=$3 flipRatio=$4: $(grep 'largest' "$c/log.compare")"
    else
        cat "$c/log.compare"
        echo "FAIL: $1 deltaT=$2 subCycles=$3 flipRatio=$4"; failures=$((failures + 1))
    fi
}

for mode in twoWay twoWayMomentum oneWay; do
    for dt in 0.02 0.2; do
        runCheck "$mode" "$dt" 2 0
    done
done
runCheck twoWay 0.2 1 1

finish
