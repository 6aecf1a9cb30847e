#!/bin/bash
#------------------------------------------------------------------------------
# Case test: tutorials/mpm/aluminiumBarsCollapse, the plane-strain collapse of
# the aluminium-bar column of Bui et al. (2008) (l x h = 0.2 x 0.1 m, phi =
# 19.8 deg, rough base, back wall slip), at the tutorial's resolution (cells of
# 5 mm, 3200 points, t = 1 s), against the digitised experiment in the
# tutorial's experiment/ (README.md there for the sources). Checks:
#   - mass: point count and summed mass, first vs last write, |dm|/m <= 1e-12
#   - rest: final max |U| < 0.02 sqrt(g h0)
#   - runout L_f (99.9 % of the mass behind it) within 10 % of the
#     experiment's 0.442 m. Measured -2.9 %; the band is a check at this one
#     resolution, not an accuracy claim: the grid study (README.md) moves L_f
#     by -15 % (10 mm cells) and +28 % (2.5 mm cells), the runout does not
#     converge. phi = 30 deg instead of 19.8 measures -25 % and fails.
#   - free surface: rms of y_sim - y_exp over the experiment's 23 points
#     <= 5 mm = 5 % of h0 (measured 3.3 mm; 4.7 mm on 10 mm cells, 3.0 mm on
#     2.5 mm cells; phi = 30 deg: 7.3 mm, fails)
#   - surface at the initial front x = 0.2 m within 8 % of the experiment's
#     47.4 mm (measured +3.0 %; +0.5 % on 2.5 mm cells; phi = 30: +9.7 %, fails)
#   - final height H_f within 2 % of the experiment's 99.3 mm (the corner at
#     the back wall does not move; this does not tell frictions apart)
# Env: PHI=<deg> runs the case with another friction angle (PHI=30 must fail:
#      the test's power against a wrong friction). Takes ~20-30 s.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/aluminiumBarsCollapse collapse)
if [ -n "${PHI:-}" ]; then
    sed -i "s/^\( *phi  *\)19.8;/\1$PHI;/" "$c/constant/mpmProperties"
    echo "friction angle set to $PHI deg (expected: the comparison checks fail)"
fi
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: the case did not run"; tail -20 "$c"/log.*; exit 1; }
(cd "$c" && "$PY" plotProfile.py --no-plot > log.plotProfile 2>&1) || { echo "FAIL: plotProfile.py"; cat "$c/log.plotProfile"; exit 1; }
cat "$c/log.plotProfile"

read -r n0 n1 m0 m1 <<< "$("$PY" - "$c" <<'PYEOF'
import sys, mpmPost
c = sys.argv[1]
ts = mpmPost.times(c)
a, b = (mpmPost.read_cloud_field(c, t, "mass") for t in (ts[0], ts[-1]))
print(len(a), len(b), repr(a.sum()), repr(b.sum()))
PYEOF
)"
r=$(sed -n 's/^RESULT //p' "$c/log.plotProfile")
val() { echo "$r" | tr ' ' '\n' | sed -n "s/^$1=//p"; }

check "mass conserved: $n0 -> $n1 points, |dm|/m <= 1e-12" \
    "n0 == n1 and abs(m1 - m0)/m0 <= 1e-12" n0="$n0" n1="$n1" m0="$m0" m1="$m1"
check "at rest: final max |U| < 0.02 sqrt(g h0)" "u < 0.02*(9.81*0.1)**0.5" u="$(val maxU)"
check "runout L_f within 10 % of the experiment's 0.442 m" "abs(L/0.442 - 1) <= 0.10" L="$(val Lf)"
check "free surface rms difference <= 5 mm (5 % of h0)" "rms <= 0.005" rms="$(val rms)"
check "surface at x = 0.2 m within 8 % of the experiment's 0.0474 m" "abs(y/0.0474 - 1) <= 0.08" y="$(val y02)"
check "final height H_f within 2 % of the experiment's 0.0993 m" "abs(H/0.0993 - 1) <= 0.02" H="$(val Hf)"
finish
