#!/bin/bash
#------------------------------------------------------------------------------
# Verification: Terzaghi's 1D consolidation (tutorial multiphase/
# consolidation). A saturated layer (H = 0.1 m, aS = 0.6, linear elastic
# skeleton M = 1.35e6 Pa, Ergun drag of 0.1 mm grains: c_v = 0.016 m^2/s)
# starts unstressed on an impermeable base and drains through its top under
# its own buoyant weight. Run as shipped (48 cells, h = 2.5 mm) and at
# h/2 (96 cells); plotConsolidation.py --no-plot compares with the series
# solution:
#
#  1. Excess pore-pressure profiles at T = 0.04 ... 1 within 3 % of gamma'H
#     (measured 2.2 % at 48 cells, 1.1 % at 96).
#  2. Degree of consolidation U(T) at every write within 3 % (measured
#     2.1 %, 1.1 %); the simulation leads slightly: the layer's top edge,
#     the drainage boundary, is smeared over ~2h by the B-splines.
#  3. That error is first order in h: error ratio 48/96 cells in [1.6, 2.4].
#  4. Terzaghi's principle in the skeleton at T = 2.4: the points' effective
#     stress sigma'_yy = -gamma'(H - y) + u within 1.5 % of gamma'H (0.8 %).
#  5. Solid mass, continuity, alphaMax (as shipped).
#  6. The same case with massMatrix consistent (the coupling's implicit
#     diagonal in the Jacobi sweeps): 1., 2. and 4. hold.
# A model-B drag normalisation or a lost aF in Darcy's k/mu = aF^2/beta
# changes c_v by 1/aF or more: U(T) off by > 10 %.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

declare -A prof uerr
for n in 48 96 48c; do
    c=$(copyTutorial multiphase/consolidation "consolidation$n")
    [ "$n" = 48c ] && sed -i 's/^massMatrix .*/massMatrix      consistent;/' "$c/constant/mpmProperties"
    if [ "$n" = 96 ]; then
        resizeColumn "$c" 0.12 "$n" 0.1 > /dev/null
        "$PY" "$c/hydrostaticPressure.py" "$c"   # hydrostatic initial p on the finer mesh
    fi
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: run ($n cells)"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    out=$(cd "$c" && "$PY" plotConsolidation.py --no-plot) || { echo "$out"; failures=$((failures + 1)); continue; }
    echo "$out" | sed "s/^/[$n cells] /"
    summary=$(echo "$out" | sed -n 's/^SUMMARY //p')
    val() { echo "$summary" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
    prof[$n]=$(val profileErrMax); uerr[$n]=$(val UErrMax)
    if [ "$n" = 48c ]; then
        check "48 cells, consistent mass: pore-pressure profiles within 3 % of gamma'H" "e <= 0.03" e="${prof[$n]}"
        check "48 cells, consistent mass: degree of consolidation within 3 %" "e <= 0.03" e="${uerr[$n]}"
        check "48 cells, consistent mass: effective stress within 1.5 % of gamma'H" "e <= 0.015" e="$(val stressErr)"
    fi
    if [ "$n" = 48 ]; then
        check "48 cells: pore-pressure profiles within 3 % of gamma'H" "e <= 0.03" e="${prof[$n]}"
        check "48 cells: degree of consolidation within 3 % at every write" "e <= 0.03" e="${uerr[$n]}"
        check "48 cells: effective stress = -gamma'(H - y) + u within 1.5 % of gamma'H" "e <= 0.015" e="$(val stressErr)"
        check "48 cells: consolidation complete (T_end >= 2)" "t >= 2" t="$(val Tend)"
        coupledInvariants "$c" 0.63
    fi
done
check "profile error first order in h (ratio 48/96 cells in [1.6, 2.4])" "1.6 <= a/b <= 2.4" a="${prof[48]:-nan}" b="${prof[96]:-nan}"
check "U(T) error first order in h (ratio 48/96 cells in [1.6, 2.4])" "1.6 <= a/b <= 2.4" a="${uerr[48]:-nan}" b="${uerr[96]:-nan}"
finish
