#!/bin/bash
#------------------------------------------------------------------------------
# Verification: the Drucker-Prager sand on a rough incline holds below, and
# flows above, the friction it mobilises in simple shear, for a thin and a
# thick layer alike (the floor and the wall treatment do not depend on how
# many cells the layer has).
#
# Reference (docs/druckerPrager.md): with the plane-strain match and no
# dilatancy, steady simple shear is coaxial, the deviatoric normal stresses
# vanish, and the yield condition sqrt(J2) = eta p reads tau/sigma_n = eta
# on the planes parallel to the slope. For phi = 30 deg,
# eta = 3 tan(phi)/sqrt(9 + 12 tan^2(phi)) = 0.48038, so a layer on a noSlip
# (rough) base yields at theta* = atan(eta) = 25.66 deg; above it a
# rate-independent layer accelerates, at most as a rigid block sliding on a
# plane of friction eta, g (sin(theta) - eta cos(theta)).
#
# Case: tutorial mpm/inclinedPlaneFlow with its material replaced by the
# sand of granularColumnCollapse (druckerPrager, phi 30, psi 0, E 2e6), a
# layer H = 4 cm of 4 and of 16 cells, x periodic, noSlip floor, t = 0..0.5 s.
#  1. theta = 25 deg (tan = 0.466 < eta): the mean velocity along the slope
#     stays below 1e-3 m/s at every write (measured ~1e-5);
#  2. theta = 26.5 deg (tan = 0.499 > eta): it accelerates; the mean
#     acceleration over t = 0.1..0.5 s is within [0.5, 1] of the rigid
#     block's 0.160 m/s^2 (measured 0.71 at 4 cells, 0.78 at 16);
#  3. the 4-cell and the 16-cell layers' accelerations agree within 25 %;
#  4. on a horizontal friction floor (mu = 0.45, cells of 5 mm), a layer one
#     point row (2.5 mm), 2 cells and 8 cells thick, thrown at 1 m/s,
#     decelerates at mu g within 2 %: the floor brakes a thin layer as it
#     brakes a thick one.
#  5. (issue 29) theta = 30 deg on friction floors: mu_w = 0.45 < eta, the
#     layer slides on the floor as a block, g (sin - 0.45 cos) = 1.082 m/s^2;
#     mu_w = 1.0 > eta, the wall could hold it but the sand next to it
#     yields at eta first, so the layer moves at the rate its own friction
#     allows, at most g (sin - eta cos) = 0.824: within 2 % of it. Before the
#     fix the wall held the first node layers at mu_w = 1.0 and the layer
#     crept at 0.25 m/s^2, slowing (on a noSlip floor: 0.61, the mirror
#     wall transmitting tau/sigma_n = 0.51).
#  6. (issue 29) the friction given as mu = 0.5, the coefficient mobilised
#     in simple shear, instead of phi (8 cells, noSlip floor): the layer
#     holds at 26 deg (tan = 0.488 < 0.5) and flows at 28 deg (tan = 0.532),
#     within [0.5, 1] of the rigid block's g (sin - 0.5 cos); the log says
#     phi = 31.48 deg in the plane-strain match.
#  7. (issue 29) the same on a level-set wall: the bed an obstacle plane at
#     y = 0.0205 m (4 cells above the box floor, now slip, out of the
#     stencil's reach), 30 deg: friction 0.45 slides at g (sin - 0.45 cos),
#     friction 1.0 at g (sin - eta cos), within 2 % (before the cap: 0.54
#     and slowing).
# A law that mobilised tan(phi) = 0.577 (30 deg) or the Mohr-Coulomb
# sin(phi) = 0.5 (26.57 deg) would not flow at 26.5 deg; a friction below
# 0.466 would flow at 25 deg. ~15 s.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

eta=0.48038
meanVelocity()  # case -> "t u" per written time (mean x velocity of the points)
{
    "$PY" - "$1" <<'EOF'
import sys
import mpmPost
case = sys.argv[1]
for t in mpmPost.times(case)[1:]:
    print(t, mpmPost.read_cloud_field(case, t, "U")[:, 0].mean())
EOF
}

# sandMaterial FILE: the tutorial's material replaced by the sand of
# granularColumnCollapse, with the time-step cap of that tutorial
sandMaterial()
{
    "$PY" - "$1" <<'EOF'
import re, sys
p = sys.argv[1]; s = open(p).read()
sand = """materials
{
    sand { model druckerPrager; rho 1600; E 2e6; nu 0.3; phi 30; c 0; psi 0; }
}
"""
s = re.sub(r"materials\s*\{.*?\n\}\n", sand, s, flags=re.S)
s = re.sub(r"maxDeltaT\s+[^;]*;", "maxDeltaT 1e-3;", s)
open(p, "w").write(s)
EOF
}

# meanAcceleration: "t u" lines (meanVelocity) -> (u_last - u_first)/(t_last - t_first)
meanAcceleration() { awk 'NR == 1 {t0 = $1; u0 = $2} {t1 = $1; u1 = $2} END {print (u1 - u0)/(t1 - t0)}'; }
# rigidBlock THETA MU: g (sin(theta) - mu cos(theta)), a block sliding with friction mu
rigidBlock() { awk -v t="$1" -v m="$2" 'BEGIN {r = t*atan2(0, -1)/180; print 9.81*(sin(r) - m*cos(r))}'; }

# slopeRun <name> <theta> <cells across> [sed on mpmProperties]: the sand
# layer (4 cm, t = 0..0.5 s) on the tutorial's incline, run; prints its
# directory, or nothing when it failed (the caller counts the failure: this
# runs in a command substitution)
slopeRun()
{
    local c
    c=$(copyTutorial mpm/inclinedPlaneFlow "$1")
    rm -rf "$c/run"
    sandMaterial "$c/constant/mpmProperties"
    [ -n "${4:-}" ] && sed -i -e "$4" "$c/constant/mpmProperties"
    sed -i -e 's/^\( *material \).*;/\1 sand;/' "$c/system/mpmSetParticlesDict"
    sed -i -e 's/^endTime .*/endTime 0.5;/' -e 's/^writeInterval .*/writeInterval 0.1;/' "$c/system/controlDict"
    if (cd "$c" && ./setCase "$2" "$3" 0.04 > log.setCase && blockMesh > log.blockMesh 2>&1 \
        && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1); then
        echo "$c"
    else
        echo "FAIL: run $1" >&2; tail -20 "$c/log.mpmFoam" >&2
    fi
}

for theta in 25 26.5; do
    for nH in 4 16; do
        c=$(slopeRun "theta${theta}_n$nH" "$theta" "$nH")
        [ -n "$c" ] || { failures=$((failures + 1)); continue; }
        u=$(meanVelocity "$c")
        echo "theta = $theta deg, $nH cells across the layer: mean velocity [m/s] at t =" $u
        seededPoints "$c" "theta = $theta deg, nH = $nH: "
        if [ "$theta" = 25 ]; then
            umax=$(echo "$u" | awk '{v = $2 < 0 ? -$2 : $2; if (v > m) m = v} END {print m + 0}')
            check "theta = 25 deg < atan(eta), nH = $nH: the layer holds (max |mean u| < 1e-3 m/s)" \
                "u < 1e-3" u="$umax"
        else
            acc=$(echo "$u" | meanAcceleration)
            ratio=$(awk -v a="$acc" -v r="$(rigidBlock "$theta" "$eta")" 'BEGIN {print a/r}')
            echo "theta = $theta deg, nH = $nH: mean acceleration $acc m/s^2, $ratio of the rigid block's"
            check "theta = 26.5 deg > atan(eta), nH = $nH: it flows, acceleration / rigid block in [0.5, 1]" \
                "0.5 <= r <= 1" r="$ratio"
            eval "acc$nH=$acc"
        fi
    done
done
# 4. Thin and thick layers sliding on the friction floor
for delta in 0.0025 0.01 0.04; do
    c=$(copyTutorial mpm/inclinedPlaneFlow "slide$delta")
    rm -rf "$c/run"
    sandMaterial "$c/constant/mpmProperties"
    sed -i -e 's/^ *floor .*/    floor   { type friction; frictionCoefficient 0.45; }/' "$c/constant/mpmProperties"
    (cd "$c" && ./setCase 0 8 0.04 > log.setCase) || { failures=$((failures + 1)); continue; }
    sed -i -e 's/^\( *material \).*;/\1 sand;/' -e "s/^\( *max \).*;/\1          (0.02 $delta 0.005);/" \
        -e 's/value (0 0 0);/value (1 0 0);/' "$c/system/mpmSetParticlesDict"
    sed -i -e 's/^endTime .*/endTime 0.15;/' -e 's/^writeInterval .*/writeInterval 0.05;/' "$c/system/controlDict"
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: run slide, layer $delta m"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    u=$(meanVelocity "$c")
    ratio=$(awk -v a="$(echo "$u" | meanAcceleration)" 'BEGIN {print -a/(0.45*9.81)}')
    echo "layer $delta m on the friction floor: mean velocity [m/s] at t =" $u
    check "layer $delta m thick (h = 0.005 m) on a mu = 0.45 floor decelerates at mu g within 2 %" \
        "abs(r - 1) <= 0.02" r="$ratio"
done
# slidesAtCoulomb <case> <mu_w> <wall>: on the 30 deg slope the layer
# accelerates at g (sin - min(mu_w, eta) cos) within 2 % (sections 5, 7)
slidesAtCoulomb()
{
    local u acc ref
    u=$(meanVelocity "$1")
    acc=$(echo "$u" | meanAcceleration)
    ref=$(rigidBlock 30 "$(awk -v m="$2" -v e="$eta" 'BEGIN {print m < e ? m : e}')")
    echo "30 deg, $3 mu $2: mean velocity [m/s] at t =" $u "; acceleration $acc m/s^2 (reference $ref)"
    check "30 deg on a $3 mu_w = $2: acceleration g (sin - min(mu_w, eta) cos) within 2 %" \
        "abs(a/r - 1) <= 0.02" a="$acc" r="$ref"
}

# 5. A rough friction floor: the material yields before the wall does
for mu in 0.45 1.0; do
    c=$(slopeRun "rough$mu" 30 8 "s/^ *floor .*/    floor   { type friction; frictionCoefficient $mu; }/")
    [ -n "$c" ] || { failures=$((failures + 1)); continue; }
    slidesAtCoulomb "$c" "$mu" "friction floor"
    [ "$mu" = 1.0 ] && { grep -h "^Friction walls:" "$c/log.mpmFoam" \
        && echo "PASS: the log says the rough wall acts as the material's friction" \
        || { echo "FAIL: no 'Friction walls:' line in the log"; failures=$((failures + 1)); }; }
done
# 6. The friction as mu, the coefficient mobilised in simple shear
for theta in 26 28; do
    c=$(slopeRun "mu0.5_theta$theta" "$theta" 8 's/phi 30;/mu 0.5;/')
    [ -n "$c" ] || { failures=$((failures + 1)); continue; }
    u=$(meanVelocity "$c")
    echo "mu 0.5, theta = $theta deg: mean velocity [m/s] at t =" $u
    if [ "$theta" = 26 ]; then
        umax=$(echo "$u" | awk '{v = $2 < 0 ? -$2 : $2; if (v > m) m = v} END {print m + 0}')
        check "mu 0.5 at 26 deg (tan 0.488 < 0.5): the layer holds (max |mean u| < 1e-3 m/s)" "u < 1e-3" u="$umax"
        grep -h "mu 0.5 in simple shear: phi = 31.48 deg" "$c/log.mpmFoam" \
            && echo "PASS: the log says which friction is in force" \
            || { echo "FAIL: no 'mu 0.5 in simple shear' line in the log"; failures=$((failures + 1)); }
    else
        ratio=$(awk -v a="$(echo "$u" | meanAcceleration)" -v r="$(rigidBlock 28 0.5)" 'BEGIN {print a/r}')
        check "mu 0.5 at 28 deg (tan 0.532 > 0.5): it flows, acceleration / rigid block in [0.5, 1]" \
            "0.5 <= r <= 1" r="$ratio"
    fi
done
# 7. A level-set friction wall: the cap holds there too
for mu in 0.45 1.0; do
    c=$(slopeRun "plane$mu" 30 8 "s/^ *floor .*/    floor   { type slip; }/; \$a obstacles { bed { shape plane; point (0 0.0205 0); normal (0 1 0); type friction; frictionCoefficient $mu; } }")
    [ -n "$c" ] || { failures=$((failures + 1)); continue; }
    slidesAtCoulomb "$c" "$mu" "level-set friction plane"
done
[ -n "${acc4:-}" ] && [ -n "${acc16:-}" ] && check "26.5 deg: 4-cell and 16-cell layers accelerate alike (within 25 %)" \
    "abs(a - b)/b < 0.25" a="$acc4" b="$acc16"
finish
