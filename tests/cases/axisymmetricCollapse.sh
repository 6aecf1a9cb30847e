#!/bin/bash
#------------------------------------------------------------------------------
# Case test: the axisymmetric 3D column collapse of
# tutorials/mpm/granularCollapse3D/sweepAspectRatio (issue 29, validation 1)
# at one aspect ratio, a = h0/r0 = 1 (r0 = h0 = 0.4 m), on the coarse grid
# h = 0.03 m (15 147 points in the quarter x, y > 0, ~30 s), with the sweep's
# calibrated sand (druckerPrager mu = tan 31 deg = 0.601, rough floor).
# Checks:
#   - every seeded point is in the last checkpoint (count)
#   - at rest: the front moved < h/4 over the last 0.1 s
#   - runout (r_f - r0)/r0 within [1.00, 1.22]: the value measured on this
#     grid, 1.107, +-10 % (10 %: the grid study's change from h = 0.03 to
#     0.015 m is +3 %, from 0.02 to 0.015 m +5 %). The band lies inside
#     Lube et al.'s (2004) 1.24 a with the README's +-20 % scatter band,
#     [0.99, 1.49], and is a regression check on this one grid, not an
#     accuracy claim: the grid study (README) gives 0.912, 1.107, 1.084,
#     1.139 on h = 0.04, 0.03, 0.02, 0.015 m. The friction of the 2D
#     tutorials, phi = 30 deg (mobilising mu = 0.480 in simple shear),
#     measures 1.402 on this grid and fails (PHI=30), although 1.402 is
#     itself inside Lube's +-20 %: at a = 1 alone the scatter band does not
#     tell the frictions apart, the calibrated run's value does.
#   - glass beads with mu(I) and their own angle of repose (below): within
#     one standard deviation of Lajeunesse et al.'s experiments at a = 1
# Env: PHI=<deg> runs the case with that plane-strain friction angle instead
#      of the calibrated mu (PHI=30 must fail the runout check). Takes ~15-30 s.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# The set-up only: copyTutorial would also copy the tutorial's sweep/ runs
# (several hundred MB when they have been made).
src="$MPMFOAM_ROOT/tutorials/mpm/granularCollapse3D"
c="$SCRATCH/axisymmetricCollapse"
mkdir -p "$c"
cp -r "$src/constant" "$src/system" "$src/sweepAspectRatio" "$src/quarterColumn.py" "$src/runout3D.py" \
    "$src/lajeunesseGlassBeads.csv" "$c"/
friction=()
if [ -n "${PHI:-}" ]; then
    friction=(-phi "$PHI")
    echo "friction angle set to phi = $PHI deg (expected: the runout check fails)"
fi
(cd "$c" && ./sweepAspectRatio -a 1 -h 0.03 "${friction[@]}" > log.sweep 2>&1) \
    || { echo "FAIL: sweepAspectRatio did not run"; tail -30 "$c/log.sweep"; tail -20 "$c"/sweep/*/log.*; exit 1; }
cat "$c/log.sweepAspectRatio"

run=$(ls -d "$c"/sweep/a1_h0.03*)
nSeed=$(sed -n 's/^Writing \([0-9]*\) material points.*/\1/p' "$run/log.mpmSetParticles" | tail -1)
read -r n runout dr <<< "$(awk -F, 'NR == 2 { print $7, $9, $13 }' "$c/runoutVsAspectRatio3D.csv")"

check "all $nSeed seeded points in the last checkpoint" "n == n0" n="$n" n0="$nSeed"
check "at rest: front moved < h/4 over the last 0.1 s" "dr < 0.03/4" dr="$dr"
check "runout (r_f - r0)/r0 within [1.00, 1.22] (1.107 +-10 %; Lube 2004: 1.24 +-20 %)" \
    "1.00 <= R <= 1.22" R="$runout"

# Glass beads (README, "Glass beads: a friction from the material's own
# angle"): mu(I) with muS = tan 22 deg, Lajeunesse et al.'s measured angle of
# repose, at a = 1 on the same grid. The experiments' runouts, each divided
# by Lube's law, have a median of 0.928 and a standard deviation of ln of
# 0.158, so their one-sigma band at a = 1 is [0.98, 1.35]. Measured 1.257;
# checked within [1.13, 1.35] (-10 %, and the band's top). A Drucker-Prager
# sand with the same angle as a constant friction (mu = tan 22 deg, no rise
# with the shear rate) runs out to 1.827 here and fails; so does mu(I) with
# its rate dependence lost (mu2 = muS: 1.832).
if [ -z "${PHI:-}" ]; then
    (cd "$c" && ./sweepAspectRatio -a 1 -h 0.03 -law muI > log.sweepBeads 2>&1) \
        || { echo "FAIL: sweepAspectRatio -law muI did not run"; tail -30 "$c/log.sweepBeads"; exit 1; }
    tail -6 "$c/log.sweepBeads"
    read -r beads z <<< "$(awk -F, '$1 ~ /muI/ { print $9, $21 }' "$c/runoutVsAspectRatio3D.csv")"
    check "glass beads, mu(I) from their angle of repose: runout within [1.13, 1.35] (1.257 -10 %; the experiments' one-sigma band 0.98-1.35), z = $z" \
        "1.13 <= R <= 1.35" R="${beads:-0}"
fi
finish
