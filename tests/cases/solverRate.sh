#!/bin/bash
#------------------------------------------------------------------------------
# benchmarks/solverRate works as benchmarks/README.md says (a benchmark, not a
# timed test: no wall time is asserted). One round of
#     benchmarks/solverRate/run.sh --rounds 1 --shape quadraticBSpline
# must build the block (about 110 000 points), run the solver on one thread
# and print the solver's own rate and phase shares; the shares must add up
# to nearly the whole MPM time (the summary's other lines are small here).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

out=$("$MPMFOAM_ROOT/benchmarks/solverRate/run.sh" --rounds 1 --shape quadraticBSpline 2>&1)
echo "$out"
row=$(echo "$out" | awk '$1 == "1" && $2 == "this"')
points=$(echo "$row" | awk '{print $3}')
rate=$(echo "$row" | awk '{print $5}')
shares=$(echo "$row" | awk '{print $6 + $7 + $8 + $9}')
check "one round ran the block: $points points, $rate M point-steps/s, phase shares adding to $shares %" \
    "100000 <= n <= 120000 and r > 0 and 95 <= s <= 100.01" n="${points:-0}" r="${rate:-0}" s="${shares:-0}"
check "the median line names the shape" "n == 1" \
    n="$(echo "$out" | grep -c '^quadraticBSpline, one thread: median')"
finish
