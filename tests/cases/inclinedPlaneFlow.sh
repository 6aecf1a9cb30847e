#!/bin/bash
#------------------------------------------------------------------------------
# Verification: steady granular flow down a rough incline with the mu(I)
# rheology (tutorial mpm/inclinedPlaneFlow, short form). A layer H = 5 mm of
# glass beads (the law's defaults, Jop et al. 2006) on a noSlip base, x
# periodic, gravity tilted by theta, starts at rest; at steady state
# tau/p = tan(theta) fixes I(theta) = I0 (tan(theta) - muS)/(mu2 - tan(theta))
# and the profile is Bagnold's, u(z) = (2I/3d) sqrt(g cos(theta) rho/rhoS)
# (H^1.5 - (H - z)^1.5) (bagnoldProfile.py).
#
# At theta = 22 and 26 deg (I = 0.026 and 0.19), 10 cells across the layer,
# t = 0 .. 2 s, checks:
#  1. steady: the profile error changed by < 0.002 over the last 0.5 s;
#  2. rms profile error / u(H) <= 0.05 (measured 0.025 and 0.040; second
#     order in h: 0.005 and 0.012 at 20 cells, tutorial Allrun);
#  3. surface velocity / u(H) in [0.95, 1.12] (measured 1.05, 1.09; the
#     free-surface row of points runs slightly fast at this resolution);
#  4. the seeded points are all there with their mass;
#  5. the log echoes the glass-bead defaults (muS = tan 20.9 deg).
# A wrong law fails 2.: swapped muS/mu2 does not flow (error ~1), a wrong I
# (d or rhoS misplaced) scales the velocity by orders of magnitude, a
# rate-independent law (mu = muS) never reaches a steady state.
# ~15-30 s on 2 cores.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

for theta in 22 26; do
    c=$(copyTutorial mpm/inclinedPlaneFlow "theta$theta")
    rm -rf "$c/run"
    sed -i 's/^endTime .*/endTime         2.0;/' "$c/system/controlDict"
    (cd "$c" && ./setCase "$theta" 10 > log.setCase && blockMesh > log.blockMesh 2>&1 \
        && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1) \
        || { echo "FAIL: run theta = $theta"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    out=$(cd "$c" && "$PY" bagnoldProfile.py .) || { echo "$out"; failures=$((failures + 1)); continue; }
    echo "$out" | sed "s/^/[theta = $theta] /"
    read -r err prev top <<< "$(echo "$out" | awk 'NR == 2 {print $6, $7, $8}')"
    check "theta = $theta deg: steady (profile error change over the last write)" \
        "abs(e - p) < 0.002" e="$err" p="$prev"
    check "theta = $theta deg: rms profile error vs Bagnold / u(H) <= 0.05" "e <= 0.05" e="$err"
    check "theta = $theta deg: surface velocity / u(H) in [0.95, 1.12]" "0.95 <= r <= 1.12" r="$top"
    seededPoints "$c" "theta = $theta deg: "
done
if grep -q "^    muS 0.3818628674 (default)" "$c/log.mpmFoam"; then
    echo "PASS: the log echoes the default muS = tan(20.9 deg)"
else
    echo "FAIL: the log does not echo the default muS"; failures=$((failures + 1))
fi
finish
