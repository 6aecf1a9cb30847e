#!/bin/bash
#------------------------------------------------------------------------------
# Code against code: mpmFoam's VOF fluid (constant/transportProperties
# fluidModel VOF) on interFoam's laminar damBreak tutorial, against interFoam
# run here on the same case: the same mesh (blockMesh), alpha.water from the
# same setFields, the same schemes, solver settings and PIMPLE controls, a
# fixed step of 1 ms (the tutorial's first step; adjustTimeStep off) to
# t = 0.25 s (250 steps: the column collapses and the surge reaches the
# obstacle), written every 50 steps at 16 digits.
# The case is tests/cases/vofDamBreakCase, the tutorial's files as Debian's
# openfoam-examples ships them (examples/multiphase/interFoam/laminar/
# damBreak/damBreak); what the test changes is in this script.
#
# mpmFoam needs material points (a case without any is an error): one
# point is parked in the air in the top right corner, and the coupling is
# oneWay with forces (gravity): the fluid sees alpha.fluid = 1, no drag and
# no solid flux, so no grain takes part in the fluid's equations (checked:
# the log's min alpha.fluid is 1 at every step).
#
#  1. At each write (t = 0.05 ... 0.25 s) alpha.water, U, p_rgh and p equal
#     interFoam's within
#        alpha.water: 1e-3 (absolute)
#        U:           1e-2 x max |U| (interFoam's)
#        p_rgh, p:    1e-3 x max |p_rgh|, max |p|
#     Measured: alpha.water 2.2e-4, U 2.6e-3, p_rgh 2.2e-4, p 3.9e-5 (the
#     largest over the writes). Why not closer: mpmFoam's momentum equation
#     keeps the mass-residual term -U (d(aF rho)/dt + div(aF rhoPhi)) of the
#     volume-averaged form (as MPPICInterFoam and the single fluid); with
#     aF = 1 it is U rho_air div(phi), the pressure solver's tolerance,
#     which interFoam's conservative form does not have. With that term
#     removed (and alphaContinuity bounded's alpha1 div(phi), not on by
#     default) the two runs were bitwise equal at t = 0.05 and 0.25 s (a
#     one-off experiment: every other term, the MULES transport and the
#     flux reconstruction included, reduces to interFoam's exactly at
#     aF = 1).
#     The differences stay at the 1e-4 level while the flow is chaotic
#     enough to amplify them over 250 steps.
#  2. Sensitivity (the tolerances catch a wrong transport): mpmFoam with one
#     alpha corrector fewer (nAlphaCorr 1 against interFoam's 2) must fail
#     1. (measured: alpha.water off by 0.12, U by 0.28 x max |U|, p_rgh by
#     0.16 x max); cAlpha 0 (no interface compression) or MULESCorr no gave
#     larger differences still (0.35-0.49 in alpha.water).
#  3. The water volume int alpha.water alpha.fluid dV, relative to the
#     start, at every step (printed): its balance with the outflow through
#     the boundary stays within 2e-6 (measured 8.2e-7 at worst), and it
#     equals interFoam's (its "Phase-1 volume fraction" x the mesh volume)
#     within 1e-7 of the start's at every step (measured 3.4e-9). interFoam's own water volume
#     changes by -7.8e-7 over the run: the MULESCorr implicit upwind
#     predictor is solved to the alpha solver's tolerance (1e-8), not
#     exactly.
#  4. The log: the interface Courant number is logged, min alpha.fluid is 1.
#  5. The adjustable step, as the tutorial runs (adjustTimeStep yes; maxCo 1;
#     maxAlphaCo 1; to 0.1 s): mpmFoam takes interFoam's steps, the same
#     number and each deltaT within 1e-3 (measured: 26 steps, 9.8e-5, the
#     Courant numbers from the slightly different fluxes of 1.).
#  6. Restart: from the t = 0.15 write (alphaPhi0.water read back, "restarting
#     alpha from the MULES flux") to 0.25 s gives the continuous run's fields
#     within 1e-10 (measured 2e-12 in U: the 16-digit writes).
#  7. Decomposed (scotch, 2 ranks, to 0.1 s; fields only, the point is
#     parked): the reconstructed fields equal
#     the serial run's as closely as interFoam's decomposed run equals its
#     serial one (the pressure solver's tolerance; both measured: alpha.water
#     2.6e-6, U 6.8e-5, p_rgh 1.0e-5): each within 1.5 x interFoam's own
#     serial-decomposed difference and 1e-3.
#  8. foamRun -solver mpmFoam (to 0.05 s) writes mpmFoam's alpha.water, U,
#     p_rgh and p at 0.05 s, byte for byte.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

base=$(damBreakCase damBreak) || exit 1
ifoam="$SCRATCH/interFoam"
cp -r "$base" "$ifoam"
runApps "$ifoam" interFoam || { echo "FAIL: interFoam"; tail -20 "$ifoam/log.interFoam"; exit 1; }

# mpmFoam's VOF fluid (vofMpmCase: fluidModel VOF, one point parked in the
# air, oneWay)
mfoam=$(vofMpmCase "$base" mpmFoam) || exit 1
(cd "$mfoam" && postProcess -func writeCellVolumes -time 0 > log.writeCellVolumes 2>&1) || { echo "FAIL: writeCellVolumes"; exit 1; }
runApps "$mfoam" mpmFoam || { echo "FAIL: mpmFoam VOF"; tail -30 "$mfoam/log.mpmFoam"; exit 1; }
nPoints=$(sed -n 's/^Writing \([0-9]*\) material points.*/\1/p' "$mfoam/log.mpmSetParticles" | tail -1)
check "one parked point (oneWay): the fluid alone" "n == 1" n="${nPoints:-0}"

# compare <case>: the largest difference from interFoam over the writes, per
# field, printed; "da du dp dpp" (alpha absolute, the others relative to
# interFoam's largest magnitude)
compare()
{
    "$PY" - "$ifoam" "$1" <<'PYEOF'
import sys
import numpy as np, mpmPost
ref, case = sys.argv[1], sys.argv[2]
worst = {}
for t in ["0.05", "0.1", "0.15", "0.2", "0.25"]:
    line = []
    for f in ["alpha.water", "U", "p_rgh", "p"]:
        a = np.asarray(mpmPost.read_internal_field(ref, t, f), float)
        b = np.asarray(mpmPost.read_internal_field(case, t, f), float)
        d = np.abs(a - b).max()
        if f != "alpha.water":
            d /= np.abs(a).max()
        worst[f] = max(worst.get(f, 0.0), d)
        line.append("%s %.3g" % (f, d))
    print("    t = %-4s: " % t + ", ".join(line), file=sys.stderr)
print(worst["alpha.water"], worst["U"], worst["p_rgh"], worst["p"])
PYEOF
}

echo "mpmFoam VOF against interFoam (alpha.water: max |difference|; U, p_rgh, p: max |difference| / max |interFoam's|):"
read -r da du dp dpp <<< "$(compare "$mfoam")"
check "alpha.water = interFoam's within 1e-3 at every write (max |diff| ${da:-nan})" "d <= 1e-3" d="${da:-nan}"
check "U = interFoam's within 1e-2 x max|U| at every write (${du:-nan})" "d <= 1e-2" d="${du:-nan}"
check "p_rgh = interFoam's within 1e-3 x max|p_rgh| at every write (${dp:-nan})" "d <= 1e-3" d="${dp:-nan}"
check "p = interFoam's within 1e-3 x max|p| at every write (${dpp:-nan})" "d <= 1e-3" d="${dpp:-nan}"

# The water volume at every step, against interFoam's
water=$("$PY" - "$ifoam/log.interFoam" "$mfoam/log.mpmFoam" "$mfoam" <<'PYEOF'
import re, sys
import numpy as np
ilog, mlog, case = sys.argv[1:4]
# interFoam: the last "Phase-1 volume fraction" of each time step
frac = []
for block in open(ilog).read().split("\nTime = ")[1:]:
    v = re.findall(r"Phase-1 volume fraction = (\S+)", block)
    if v: frac.append(float(v[-1]))
rel, bal, vol = [], [], []
for l in open(mlog):
    if l.startswith("VOF: water volume"):
        w = l.split()
        vol.append(float(w[7].rstrip(",")))
        rel.append(float(w[12].rstrip(",")))
        bal.append(float(w[24].rstrip(";")))
# the mesh's cells' volumes (postProcess -func writeCellVolumes) and the
# start's water volume from 0/alpha.water
from mpmPost import read_internal_field
import numpy as np
cellV = np.asarray(read_internal_field(case, "0", "V"), float)
Vmesh = cellV.sum()
W0 = (np.asarray(read_internal_field(case, "0", "alpha.water"), float)*cellV).sum()
V0 = vol[0]/(1 + rel[0])
n = min(len(frac), len(vol))
dif = max(abs(vol[i] - frac[i]*Vmesh)/W0 for i in range(n))
print("water volume (V - V0)/V0 at each of the %d steps (mpmFoam):" % len(rel), file=sys.stderr)
for i in range(0, len(rel), 5):
    print("    steps %3d-%3d: " % (i + 1, min(i + 5, len(rel))) + " ".join("%+.2e" % r for r in rel[i:i + 5]), file=sys.stderr)
print(len(rel), n, max(abs(b) for b in bal), dif, (frac[-1]*Vmesh - W0)/W0, abs(V0/W0 - 1))
PYEOF
)
read -r nSteps nCommon maxBal dWater iDrift dStart <<< "$water"
echo "  interFoam's own water volume change over the run: ${iDrift:-nan}"
check "a water volume line at each of the 250 steps ($nSteps)" "n == 250" n="${nSteps:-0}"
check "the logged start water volume is int alpha.water dV of 0/alpha.water (|ratio - 1| ${dStart:-nan})" "d <= 1e-13" d="${dStart:-nan}"
check "water volume balance (V - V0 + outflow)/V0 within 2e-6 at every step (max |.| ${maxBal:-nan})" "b <= 2e-6" b="${maxBal:-nan}"
check "water volume = interFoam's within 1e-7 of the start volume at every step ($nCommon steps, max ${dWater:-nan})" "d <= 1e-7 and n == 250" d="${dWater:-nan}" n="${nCommon:-0}"

minAF=$(grep "continuity error" "$mfoam/log.mpmFoam" | sed 's/.*min alpha.fluid \([^,]*\),.*/\1/' | sort -g | head -1)
check "min alpha.fluid 1 at every step: no grain in the fluid (${minAF:-nan})" "a == 1" a="${minAF:-nan}"
if grep -q "interface Courant Number max" "$mfoam/log.mpmFoam"; then
    echo "PASS: the log gives the interface Courant number"
else
    echo "FAIL: no interface Courant number in the log"; failures=$((failures + 1))
fi

# --- 5. the adjustable step (maxCo, maxAlphaCo), as interFoam's setDeltaT.H -----
adjust() { sed -i 's/^adjustTimeStep .*/adjustTimeStep  yes;/; s/^endTime .*/endTime 0.1;/' "$1/system/controlDict"; }
ia="$SCRATCH/interFoam.adjustable"; cp -r "$base" "$ia"; adjust "$ia"
ma=$(vofMpmCase "$base" mpmFoam.adjustable) || exit 1; adjust "$ma"
if runApps "$ia" interFoam && runApps "$ma" mpmFoam; then
    read -r nI nM dDt <<< "$("$PY" - "$ia/log.interFoam" "$ma/log.mpmFoam" <<'PYEOF'
import re, sys
a = [float(x) for x in re.findall(r"^deltaT = (\S+)", open(sys.argv[1]).read(), re.M)]
b = [float(x) for x in re.findall(r"^fluid: Courant Number max .* deltaT = (\S+)", open(sys.argv[2]).read(), re.M)]
n = min(len(a), len(b))
print(len(a), len(b), max(abs(a[i] - b[i])/a[i] for i in range(n)) if n else 1)
PYEOF
)"
    check "adjustable step: interFoam's steps ($nI and $nM steps, each deltaT within 1e-3: ${dDt:-nan})" "a == b and a > 10 and d <= 1e-3" a="${nI:-0}" b="${nM:-1}" d="${dDt:-nan}"
else
    echo "FAIL: the adjustable-step runs"; failures=$((failures + 1))
fi

# --- 6. restart from the t = 0.15 write -----------------------------------------
r="$SCRATCH/mpmFoam.restart"
cp -r "$mfoam" "$r"
rm -rf "$r/0.2" "$r/0.25" "$r/log.mpmFoam" "$r/postProcessing"
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$r/system/controlDict"
if runApps "$r" mpmFoam && grep -q "restarting alpha from the MULES flux" "$r/log.mpmFoam"; then
    dr=$("$PY" -c "
import numpy as np, mpmPost
print(max(np.abs(np.asarray(mpmPost.read_internal_field('$mfoam', '0.25', f), float) - np.asarray(mpmPost.read_internal_field('$r', '0.25', f), float)).max()/np.abs(np.asarray(mpmPost.read_internal_field('$mfoam', '0.25', f), float)).max() for f in ['alpha.water', 'U', 'p_rgh']))")
    check "restart from 0.15 s: the continuous run's fields at 0.25 s within 1e-10 (${dr:-nan})" "d <= 1e-10" d="${dr:-nan}"
else
    echo "FAIL: the restart"; tail -20 "$r/log.mpmFoam"; failures=$((failures + 1))
fi

# --- 7. decomposed, against serial, beside interFoam's own ----------------------
# decomposed <serial case> <name> <app>: the case to 0.1 s on 2 ranks, reconstructed
decomposed()
{
    local d="$SCRATCH/$2"
    cp -r "$1" "$d"
    rm -rf "$d"/0.[0-9]* "$d"/log.* "$d/postProcessing"
    sed -i 's/^endTime .*/endTime 0.1;/' "$d/system/controlDict"
    sed 's/^numberOfSubdomains .*/numberOfSubdomains 2;/' "$MPMFOAM_ROOT/etc/caseDicts/decomposeParDict" > "$d/system/decomposeParDict"
    (cd "$d" && decomposePar > log.decomposePar 2>&1 && mpirun -np 2 --oversubscribe "$3" -parallel > "log.$3" 2>&1 \
        && reconstructPar -time 0.1 > log.reconstructPar 2>&1) || return 1
    echo "$d"
}
# serialDiff <serial> <decomposed>: the largest difference at 0.1 s, per field
serialDiff()
{
    "$PY" -c "
import numpy as np, mpmPost
r = []
for f in ['alpha.water', 'U', 'p_rgh']:
    a = np.asarray(mpmPost.read_internal_field('$1', '0.1', f), float)
    b = np.asarray(mpmPost.read_internal_field('$2', '0.1', f), float)
    r.append(np.abs(a - b).max()/(1 if f == 'alpha.water' else np.abs(a).max()))
print(*r)"
}
if ip=$(decomposed "$ifoam" interFoam.decomposed interFoam) && mp=$(decomposed "$mfoam" mpmFoam.decomposed mpmFoam); then
    read -r ia iu ipr <<< "$(serialDiff "$ifoam" "$ip")"
    read -r ma mu mpr <<< "$(serialDiff "$mfoam" "$mp")"
    echo "  decomposed against serial at 0.1 s: interFoam alpha.water $ia, U $iu, p_rgh $ipr; mpmFoam alpha.water $ma, U $mu, p_rgh $mpr"
    check "decomposed mpmFoam VOF = its serial run as interFoam's decomposed run = its serial one (within 1.5 x and 1e-3)" \
        "ma <= max(1.5*ia, 1e-12) and mu <= max(1.5*iu, 1e-12) and mp <= max(1.5*ip, 1e-12) and max(ma, mu, mp) <= 1e-3" \
        ma="${ma:-nan}" ia="${ia:-nan}" mu="${mu:-nan}" iu="${iu:-nan}" mp="${mpr:-nan}" ip="${ipr:-nan}"
else
    echo "FAIL: the decomposed runs"; tail -20 "$SCRATCH"/*.decomposed/log.* 2>/dev/null | tail -30; failures=$((failures + 1))
fi

# --- 8. foamRun -solver mpmFoam ------------------------------------------------
fr="$SCRATCH/foamRun"
cp -r "$mfoam" "$fr"
rm -rf "$fr"/0.[0-9]* "$fr"/log.mpmFoam "$fr/postProcessing"
sed -i 's/^endTime .*/endTime 0.05;/' "$fr/system/controlDict"
if runIn "$fr" foamRun -solver mpmFoam > "$fr/log.foamRun" 2>&1; then
    same=0
    for f in alpha.water U p_rgh p; do cmp -s "$mfoam/0.05/$f" "$fr/0.05/$f" && same=$((same + 1)); done
    check "foamRun -solver mpmFoam: alpha.water, U, p_rgh, p at 0.05 s byte for byte mpmFoam's ($same of 4)" "n == 4" n="$same"
else
    echo "FAIL: foamRun -solver mpmFoam"; tail -20 "$fr/log.foamRun"; failures=$((failures + 1))
fi

# --- 2. sensitivity: one alpha corrector fewer must be seen -------------------
m1=$(vofMpmCase "$base" mpmFoam.nAlphaCorr1) || exit 1
sed -i 's/^\( *nAlphaCorr *\)2;/\11;/' "$m1/system/fvSolution"
grep -q "nAlphaCorr *1;" "$m1/system/fvSolution" || { echo "FAIL: could not set nAlphaCorr 1"; failures=$((failures + 1)); }
runApps "$m1" mpmFoam || { echo "FAIL: mpmFoam VOF nAlphaCorr 1"; tail -30 "$m1/log.mpmFoam"; failures=$((failures + 1)); }
echo "sensitivity: mpmFoam VOF with nAlphaCorr 1 against interFoam with 2:"
read -r da1 du1 dp1 dpp1 <<< "$(compare "$m1")"
check "nAlphaCorr 1 is told apart: alpha.water, U and p_rgh each beyond the tolerances of 1. (${da1:-nan}, ${du1:-nan}, ${dp1:-nan})" \
    "a > 1e-3 and u > 1e-2 and p > 1e-3" a="${da1:-0}" u="${du1:-0}" p="${dp1:-0}"

finish
