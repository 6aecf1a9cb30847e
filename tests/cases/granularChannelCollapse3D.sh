#!/bin/bash
#------------------------------------------------------------------------------
# Case test: tutorials/mpm/granularChannelCollapse3D (issue 29, validation 3):
# the 2D flagship's column (a0 = 0.2 m, h0 = 0.4 m, a = 2, druckerPrager
# phi = 30 deg, floor friction 0.45) in 3D in a channel of width W = 0.2 m,
# half of it computed, on h = 0.02 m: once with the side wall `slip` (plane
# strain) and once with a Coulomb side wall, coefficient 0.45. ~35 s.
# Checks:
#   - both runs: every written cloud holds the seeded points with their
#     masses (seededPoints); at rest: the front moved < h/4 over the last
#     0.1 s
#   - slip side wall = plane strain: the front of the half nearer the side
#     wall equals that of the half nearer the centre plane (within h/4 /
#     a0 in runout), and the runout is 3.00 +-5 % (measured 3.002; the 2D
#     flagship with the same quadratic B-splines on the same h gives 3.064)
#   - the side walls shorten the runout: channel/slip ratio within
#     [0.80, 0.91] (measured 0.853; a side wall that did nothing gives
#     1.00), and the front of the half nearer the side wall trails that of
#     the centre half by more than 0.2 a0 (measured 0.456 a0; 0 with slip)
# Env: WALL=<mu_w> runs the channel with that side-wall coefficient instead
#      of 0.45 (WALL=0, a frictionless wall, must fail the ratio checks).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

src="$MPMFOAM_ROOT/tutorials/mpm/granularChannelCollapse3D"
c="$SCRATCH/granularChannelCollapse3D"
mkdir -p "$c"
# The set-up only (copyTutorial would also copy the tutorial's runs/)
cp -r "$src/constant" "$src/system" "$src/sweepChannel" "$src/runoutChannel.py" "$c"/
wall="${WALL:-0.45}"
[ "$wall" != 0.45 ] && echo "side-wall friction set to $wall (WALL)"
(cd "$c" && ./sweepChannel -h 0.02 -W 0.2 -wall "slip $wall" > log.sweep 2>&1) \
    || { echo "FAIL: sweepChannel did not run"; tail -30 "$c/log.sweep"; tail -20 "$c"/runs/*/log.*; exit 1; }
cat "$c/log.sweepChannel"

seededPoints "$c/runs/h0.02_W0.2_slip" "slip side wall: "
seededPoints "$c/runs/h0.02_W0.2_$wall" "friction side wall: "

# csv columns: 10 runout, 11 ratio, 12 runout_centre, 13 runout_wall, 14 dLf_last
read -r Rs cs ws ds <<< "$(awk -F, '$4 == "slip" { print $10, $12, $13, $14 }' "$c/runoutChannel.csv")"
read -r Rc ratio cc wc dc <<< "$(awk -F, -v w="$wall" '$4 == w { print $10, $11, $12, $13, $14 }' "$c/runoutChannel.csv")"

check "slip side wall: at rest (front moved < h/4 over the last 0.1 s)" "abs(d) < 0.02/4" d="$ds"
check "friction side wall: at rest (front moved < h/4 over the last 0.1 s)" "abs(d) < 0.02/4" d="$dc"
check "slip side wall is plane strain: wall-half front = centre-half front (within h/4)" \
    "abs(w - c)*0.2 < 0.02/4" w="$ws" c="$cs"
check "slip side wall: runout (L_f - a0)/a0 within 3.00 +-5 % (measured 3.002; 2D, same h and B-splines: 3.064)" \
    "2.85 <= R <= 3.15" R="$Rs"
check "side walls shorten the runout: channel/slip within [0.80, 0.91] (measured 0.853; no effect: 1)" \
    "0.80 <= r <= 0.91" r="$ratio"
check "friction side wall: the wall-half front trails the centre half by > 0.2 a0 (measured 0.456)" \
    "c - w > 0.2" c="$cc" w="$wc"
finish
