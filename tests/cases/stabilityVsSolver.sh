#!/bin/bash
#------------------------------------------------------------------------------
# The spectral analysis checked against the solver itself: mpmFoam runs the
# periodic 1D lattice (tutorials/analysis/periodicWave: frozen points, one
# Fourier mode, elastic wave) and the measured per-step amplification must
# equal the analysis' |G| to 1e-6 relative, for LH and CBS, PIC and FLIP, at
# two CFL numbers, for USL, and for USF and MUSL with CBS.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"

runCheck()   # shape alpha scheme CFL
{
    local c
    c=$(copyTutorial analysis/periodicWave "w_$1_$2_$3_$4")
    sed -i "s/^shapeFunction .*/shapeFunction   $1;/; s/^flipRatio .*/flipRatio       $2;/; s/^stressUpdate .*/stressUpdate    $3;/" \
        "$c/constant/mpmProperties"
    sed -i "s/^deltaT .*/deltaT          $4;/; s/^endTime .*/endTime         $("$PY" -c "print(40*$4)");/" "$c/system/controlDict"
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: run $c"; failures=$((failures + 1)); return; }
    if "$PY" "$c/compareWithAnalysis.py" "$c" "$tool" --tol 1e-6; then
        echo "PASS: $1 alpha=$2 $3 CFL=$4"
    else
        echo "FAIL: $1 alpha=$2 $3 CFL=$4"; failures=$((failures + 1))
    fi
}

for shape in linearHat cubicBSpline; do
    for alpha in 0 1; do
        for cfl in 0.3 0.6; do
            runCheck "$shape" "$alpha" USL "$cfl"
        done
    done
done
for scheme in USF MUSL; do
    runCheck cubicBSpline 1 "$scheme" 0.6
done
# --kh evaluates the given wavenumbers: at kh = pi/4 it must print the |G|
# of the sampled grid (--nk 4 samples pi/4, pi/2, ...), for a diffusion and
# a wave setup
for args in "--model diffusion --shape CBS --alpha 1 --Fo 0.5" "--model wave --shape LH --alpha 0 --CFL 0.6"; do
    sampled=$("$tool" $args --nk 4 | awk '$2 == "0.250" {print $6; exit}')
    given=$("$tool" $args --kh 0.7853981633974483 | awk '$2 == "0.250" {print $6; exit}')
    check "mpmStabilityAnalysis --kh pi/4 gives the sampled |G| ($args)" \
        "g == s and s > 0" g="${given:-0}" s="${sampled:-0}"
done

finish
