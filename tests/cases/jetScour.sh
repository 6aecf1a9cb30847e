#!/bin/bash
#------------------------------------------------------------------------------
# Robustness: the jetScour tutorial (2D, a 1.5 m/s water jet into a 6 cm
# sand bed, druckerPrager + alphaContact, Gidaspow, twoWay; 1 s, ~16 s run).
# No quantitative reference: this is a hard, strongly coupled case that must
# stay stable and keep the coupled invariants.
#
#  1. The run completes (no non-finite state; the solver would stop with a
#     message naming the point).
#  2. The jet digs a hole: the bed surface under the jet drops by more than
#     1 cm (measured 2.1 cm), and the sand heaps up beside it (4.5 cm).
#  3. Solid mass exact, alpha.fluid >= 1 - alphaMax in every written field,
#     fluid continuity at solver tolerance.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial multiphase/jetScour jet)
runApps "$c" blockMesh mpmSetParticles mpmFoam \
    || { echo "FAIL: run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); finish; }
out=$(cd "$c" && "$PY" plotJetScour.py --no-plot) || { echo "$out"; failures=$((failures + 1)); finish; }
echo "$out"
summary=$(echo "$out" | sed -n 's/^SUMMARY //p')
val() { echo "$summary" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
check "ran to the end (t = 1)" "t == 1" t="$(val tEnd)"
check "the jet digs a hole deeper than 1 cm" "d > 0.01" d="$(val scourDepth)"
check "the sand heaps up beside it" "h > 0" h="$(val heapHeight)"
coupledInvariants "$c" 0.63
finish
