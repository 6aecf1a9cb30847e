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
# Predictions confirmed with the old scheme (coupling fluidResponse frozen,
# an analysis aid): at aS 0.5 and stiff drag the mode grows with the
# predicted negative (period-2) gain; at aS 0.4 the mode decays at 0.95 of
# the predicted limit in Dt/tau_p and grows at 1.2 of it (the grain diameter
# sets tau_p, so the fluid's own numbers stay the same); the current scheme
# decays at the same 1.2.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"
caseSrc="$MPMFOAM_ROOT/tests/cases/coupledModeCase"

# runCheck mode deltaT subCycles flipRatio [fluidResponse aS d steps amplitude]
runCheck()
{
    local response=${5:-linearised} aS=${6:-0.3} d=${7:-1e-3} steps=${8:-12} amp=${9:-1e-9}
    c="$SCRATCH/m_$1_$2_$3_$4_${response}_${aS}_$d"
    cp -r "$caseSrc" "$c"
    sed -i "s/^\( *mode \+\).*/\1$1;/; s/^\( *subCycles \+\).*/\1$3;\n    fluidResponse $response;/; s/^flipRatio .*/flipRatio       $4;/; s/d 1e-3;/d $d;/" \
        "$c/constant/mpmProperties"
    sed -i "s/^\( *solidFraction \+\).*/\1$aS;/; s/amplitude  (0 1e-9 0)/amplitude  (0 $amp 0)/" "$c/system/mpmSetParticlesDict"
    sed -i "s/^deltaT .*/deltaT          $2;/; s/^endTime .*/endTime         $("$PY" -c "print($steps*$2)");/" \
        "$c/system/controlDict"
    runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: run $c"; failures=$((failures + 1)); return; }
    if "$PY" "$c/compareWithAnalysis.py" "$c" "$tool" --tol 1e-6 --fluid-tol 1e-5 > "$c/log.compare" 2>&1; then
        echo "PASS: $1 deltaT=$2 subCycles=$3 flipRatio=$4 $response aS=$aS d=$d: $(grep 'largest' "$c/log.compare")"
    else
        cat "$c/log.compare"
        echo "FAIL: $1 deltaT=$2 subCycles=$3 flipRatio=$4 $response aS=$aS d=$d"; failures=$((failures + 1))
    fi
}

for mode in twoWay twoWayMomentum oneWay; do
    for dt in 0.02 0.2; do
        runCheck "$mode" "$dt" 2 0
    done
done
runCheck twoWay 0.2 1 1

# growth <case>: the grains' mode |v_N|/|v_0| the run measured
growth() { awk '/^growth over/ {print $6; exit}' "$1/log.compare" | tr -d ,; }

# The old scheme's period-2 mode: aS 0.5, Dt/tau_p 12, the gain of the
# analysis' dominant eigenvalue (stiff-drag limit -aS (1 + aF)/aF^2 = -3)
runCheck twoWay 0.2 2 0 frozen 0.5 1e-3 8 1e-11
lead=$(awk '/^dominant eigenvalue/ {print $3; exit}' "$c/log.compare")
last=$(awk '/^dominant eigenvalue/ {print $7; exit}' "$c/log.compare")
check "frozen fluid, aS 0.5: period-2 growth at the analysis' gain ($lead; measured last step $last)" \
    "G < -1 and abs(g - G) < 1e-2*abs(G)" G="${lead:-0}" g="${last:-0}"

# Its onset: the limit in Dt/tau_p of the run's kh (aS 0.4, 2 sub-cycles,
# nu Dt/h^2 0.025), crossed by changing the grain diameter:
# Dt/tau_p = Dt 150 aS mu/(rho_s aF d^2)
kh=$("$PY" -c "import math; print(2*math.pi/128)")
limit=$("$tool" --model coupled --variant frozen --shape LH --offsets 0.25,0.75 --aS 0.4 --sub-cycles 2 \
    --density-ratio 0.4 --viscous 0.025 --limit dtOverTau --limit-kh "$kh" --max-number 100 | awk '/limit/ {v=$NF} END {print v}')
echo "predicted limit of the frozen fluid: Dt/tau_p = $limit"
for f in 0.95 1.2; do
    d=$("$PY" -c "print((0.1*150*0.4*1e-3/(2500*0.6*$f*$limit))**0.5)")
    runCheck twoWay 0.1 2 0 frozen 0.4 "$d" 30 1e-11
    check "frozen fluid at $f x the limit: the mode $( [ "$f" = 0.95 ] && echo decays || echo grows ) over 30 steps" \
        "(g < 1) == (f < 1)" g="$(growth "$c")" f="$f"
done
runCheck twoWay 0.1 2 0 linearised 0.4 "$d" 30 1e-11
check "current scheme at 1.2 x the frozen fluid's limit: the mode decays" "g < 1e-3" g="$(growth "$c")"

finish
