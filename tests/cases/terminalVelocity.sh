#!/bin/bash
#------------------------------------------------------------------------------
# Verification: terminal velocity of a dilute grain population (coupling).
#
# Case tests/cases/terminalVelocityCase: a 1D vertical water column (0.1 m,
# 100 cells, bottom wall, open top with p = 0), a cloud of `dilute` glass
# grains (rho_s 2500, alpha.solid 1e-4) in 0.05 < y < 0.07, drag
# SchillerNaumann, forces (drag pressureGradient gravity).
#
# The reference is computed here, independently of the solver: the
# Schiller-Naumann terminal velocity solves
#     18 mu/d^2 (1 + 0.15 Re^0.687) Ut = (rho_s - rho_f) g,  Re = rho_f Ut d/mu
# (fixed-point iteration, a contraction since the exponent 0.687 < 1).
# Ut measured = -(grains' centre-of-mass velocity, summary.dat Ucm_y, averaged
# over the last third of the run) + the fluid velocity the grains see
# (alpha.solid-weighted mean of U_y at the last write; ~0 in one-way).
#
#  1. oneWay, d = 0.2 mm (Re_p = 4.6, tau = 5.6 ms, fluid step 1 ms, run
#     0.15 s = 27 tau): |Ut/Ut_SN - 1| <= 1 %; the fluid stays at rest.
#  2. twoWay, same grains: |Ut/Ut_SN - 1| <= 1 % (model A reduces the slip by
#     alpha.fluid = 1 - 1e-4, invisible at 1 %), and the return flow: in a
#     1D column closed at the bottom the mixture flux is zero, so inside the
#     cloud the water rises at U_f = -alpha.s U_s / alpha.f (~alpha.s Ut =
#     2.3e-6 m/s). Checked within 1 % on the cloud's interior cells (plateau
#     of alpha.solid, 3 cells away from its smeared edges).
#  3. Stiff: d = 8.5 um, tau = rho_s d^2/(18 mu) = 1.0e-5 s = 1e-3 x the fluid
#     step 0.01 s, and one MPM step per fluid step (subCycles 1): stable (no
#     NaN, |Ucm| bounded), equilibrium slip = Stokes Ut (Re_p = 5e-4; the SN
#     correction is 0.08 %) within 1 %.
#  4. Drag per material (oneWay, the d = 0.2 mm column): three clouds far
#     apart, `fine` grains (d = 0.1 mm) at the top, `coarse` (0.2 mm) in the
#     middle, and both materials mixed half and half at the bottom. Each
#     pure cloud falls at its own Schiller-Naumann Ut within 1 %. The mixed
#     cloud shares one grid velocity; with beta = sum_m (aS_m/aS) beta_m it
#     falls at u solving sum_m phi_m beta_m(u)/aS u = sum_m phi_m (rho_s -
#     rho_f) g, here (f_fine(u) + f_coarse(u)) u = 2 (rho_s - rho_f) g with
#     f = 18 mu/d^2 (1 + 0.15 Re^0.687): within 1 %. Using one law for all
#     would put a pure cloud 3x off; summing without the shares, the mixture
#     2x.
#  5. Virtual mass, settling from rest (oneWay, d = 0.2 mm, fluid step 5e-5 s
#     = tau/110, 0.03 s): the grains' velocity history against the ODE
#     (rho_s + Cvm rho_f) dv/dt = -(rho_s - rho_f) g - 18 mu/d^2 (1 + 0.15
#     Re^0.687) v, integrated here by RK4, within 1 % of Ut at every step,
#     for Cvm = 0.5 and without virtual mass (Cvm = 0); the two histories
#     differ by > 5 % of Ut, so a missing added mass fails.
#  6. Virtual mass, accelerating fluid (oneWay, no drag, no gravity: forces
#     (pressureGradient virtualMass)): the inflow ramps at A = 1 m/s^2, the
#     1D column accelerates uniformly, grad p = -A. Heavy grains then
#     accelerate at (1 + Cvm) rho_f A/(rho_s + Cvm rho_f): 0.5 A with
#     Cvm = 0.5, 0.4 A without (buoyancy alone). Slope of Ucm_y over the
#     second half of 0.1 s within 1 %.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

caseSrc="$MPMFOAM_ROOT/tests/cases/terminalVelocityCase"
rhoS=2500; rhoF=1000; mu=1e-3; g=9.81

# Ut_SN <d> : Schiller-Naumann terminal velocity by fixed-point iteration
utSN()
{
    "$PY" -c "
rs, rf, mu, g, d = $rhoS, $rhoF, $mu, $g, $1
ust = (rs - rf)*g*d*d/(18*mu)
u = ust
for i in range(500):
    u = ust/(1 + 0.15*(rf*u*d/mu)**0.687)
print('%.15g %.15g %.15g' % (u, ust, rf*u*d/mu))"
}

# newCase <name> <mode> <d> <deltaT> <endTime> <subCycles>
newCase()
{
    local c="$SCRATCH/$1"
    cp -r "$caseSrc" "$c"
    sed -i "s/^\( *mode  *\)[A-Za-z]*;/\1$2;/; s/\(model SchillerNaumann; d\) [^;]*;/\1 $3;/; s/^\( *subCycles *\).*/\1$6;/" \
        "$c/constant/mpmProperties"
    sed -i "s/^deltaT .*/deltaT          $4;/; s/^endTime .*/endTime         $5;/; s/^writeInterval .*/writeInterval   $5;/" \
        "$c/system/controlDict"
    echo "$c"
}

runCase()   # case -> 0 on success
{
    runApps "$1" blockMesh mpmSetParticles mpmFoam
}

# measure <case> <endTime> -> "UcmY Ufluid spread UfReturn UfExpected"
measure()
{
    "$PY" - "$1" "$2" <<'PYEOF'
import sys
import numpy as np
import mpmPost
case, tEnd = sys.argv[1], float(sys.argv[2])
s = mpmPost.read_summary(case)
late = s["time"] >= 2*tEnd/3
uy = s["Uy"][late]
t = mpmPost.field_times(case, "U")[-1]
a = mpmPost.read_internal_field(case, t, "alpha.solid")
U = mpmPost.read_internal_field(case, t, "U")[:, 1]
Us = mpmPost.read_internal_field(case, t, "U.solid")[:, 1]
w = a/a.sum()
Uf = (w*U).sum()
# Interior of the cloud: alpha.solid on its plateau, 3 cells from the edges
plateau = np.flatnonzero(a >= (1 - 1e-4)*a.max())
inner = plateau[3:-3]
ret = U[inner].mean()
exp = (-a*Us/(1 - a))[inner].mean()
print(uy.mean(), Uf, (uy.max() - uy.min())/abs(uy.mean()), ret, exp)
PYEOF
}

# 1 and 2: d = 0.2 mm, one-way and two-way
read -r ut ust re <<< "$(utSN 2e-4)"
echo "d = 0.2 mm: Schiller-Naumann Ut = $ut m/s (Stokes $ust, Re_p $re)"
for mode in oneWay twoWay; do
    c=$(newCase "$mode" "$mode" 2e-4 1e-3 0.15 auto)
    runCase "$c" || { echo "FAIL: $mode run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    read -r ucm uf spread ret exp <<< "$(measure "$c" 0.15)"
    echo "$mode: Ucm_y $ucm, fluid U_y seen by the grains $uf, Ucm spread over the last third $spread"
    check "$mode: steady (Ucm_y varies < 1e-4 over the last third)" "s < 1e-4" s="$spread"
    check "$mode: Ut = Uf - Ucm_y within 1 % of Schiller-Naumann" "abs((uf - u)/ut - 1) <= 0.01" u="$ucm" uf="$uf" ut="$ut"
    if [ "$mode" = oneWay ]; then
        check "oneWay: fluid at rest (|U_f| < 1e-6 Ut)" "abs(uf) < 1e-6*ut" uf="$uf" ut="$ut"
    else
        echo "twoWay: return flow inside the cloud $ret m/s, -alpha.s U_s/alpha.f = $exp m/s"
        check "twoWay: return flow U_f = -alpha.s U_s/alpha.f within 1 %" "abs(r/e - 1) <= 0.01" r="$ret" e="$exp"
    fi
done

# 3. Stiff drag: tau = 1e-3 fluid step, one MPM step per fluid step
read -r ut ust re <<< "$(utSN 8.5e-6)"
tau=$("$PY" -c "print($rhoS*8.5e-6**2/(18*$mu))")
echo "d = 8.5 um: tau $tau s (fluid step 0.01 s), Stokes Ut $ust, Schiller-Naumann $ut (Re_p $re)"
c=$(newCase stiff oneWay 8.5e-6 1e-2 0.2 1)
if ! runCase "$c"; then
    if grep -q "subCycles" "$c/log.mpmFoam"; then
        echo "FAIL: 'subCycles 1;' (a number, as documented in fluidCoupling.H) is rejected:"
        grep -m1 -B1 -A2 "FATAL" "$c/log.mpmFoam"
        failures=$((failures + 1))
        echo "      rerunning with subCycles auto (one sub-cycle here too: dilute grains have no wave speed)"
        sed -i "s/^\( *subCycles *\).*/\1auto;/" "$c/constant/mpmProperties"
        (cd "$c" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: stiff run"; tail -20 "$c/log.mpmFoam"; finish; }
    else
        echo "FAIL: stiff run"; tail -20 "$c/log.mpmFoam"; finish
    fi
fi
nsub=$(grep "sub-cycles of deltaT" "$c/log.mpmFoam" | awk '{print $2}' | sort -gu | tail -1)
check "stiff: one MPM step per fluid step" "n == 1" n="$nsub"
read -r ucm uf spread ret exp <<< "$(measure "$c" 0.2)"
maxU=$("$PY" -c "import mpmPost; print(mpmPost.read_summary('$c')['maxU'].max())")
echo "stiff: Ucm_y $ucm, max |U| over the run $maxU"
check "stiff: stable (max |U| <= 1.01 Ut_Stokes at every step)" "m <= 1.01*ust" m="$maxU" ust="$ust"
check "stiff: equilibrium slip = Stokes Ut within 1 %" "abs((uf - u)/ust - 1) <= 0.01" u="$ucm" uf="$uf" ust="$ust"

# 4. Drag per material
c=$(newCase perMaterial oneWay 2e-4 1e-3 0.15 auto)
"$PY" - "$c" <<'PYEOF'
import re, sys
c = sys.argv[1]
p = c + "/constant/mpmProperties"
s = open(p).read()
s = re.sub(r"materials\s*\{.*\n\}\s*\n(?=walls)", """materials
{
    fine   { model dilute; rho 2500; drag { model SchillerNaumann; d 1e-4; } }
    coarse { model dilute; rho 2500; drag { model SchillerNaumann; d 2e-4; } }
}

""", s, flags=re.S)
open(p, "w").write(s)
box = "type box; min (0 %g 0); max (0.001 %g 0.001); material %s; pointsPerCell 2; solidFraction %g;"
open(c + "/system/mpmSetParticlesDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    fine      { %s }
    coarse    { %s }
    mixFine   { %s }
    mixCoarse { %s overlap add; }
}
""" % (box % (0.08, 0.09, "fine", 1e-4), box % (0.05, 0.06, "coarse", 1e-4),
       box % (0.02, 0.03, "fine", 5e-5), box % (0.02, 0.03, "coarse", 5e-5)))
PYEOF
if runCase "$c"; then
    read -r uFine uCoarse uMix mixSpread <<< "$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
import mpmPost
c = sys.argv[1]
t = mpmPost.times(c)[-1]
y = mpmPost.read_positions(c, t)[:, 1]
v = mpmPost.read_cloud_field(c, t, "U")[:, 1]
m = mpmPost.read_cloud_field(c, t, "material")
top, mid, low = y > 0.07, (y > 0.04) & (y < 0.07), y < 0.04
print(v[top].mean(), v[mid].mean(), v[low].mean(), np.ptp(v[low])/abs(v[low].mean()))
PYEOF
)"
    read -r utF ustF reF <<< "$(utSN 1e-4)"
    read -r utC ustC reC <<< "$(utSN 2e-4)"
    uMixRef=$("$PY" -c "
rs, rf, mu, g = $rhoS, $rhoF, $mu, $g
f = lambda u, d: 18*mu/d**2*(1 + 0.15*(rf*u*d/mu)**0.687)
lo, hi = 0.0, 1.0
for i in range(200):
    u = 0.5*(lo + hi)
    lo, hi = (u, hi) if (f(u, 1e-4) + f(u, 2e-4))*u < 2*(rs - rf)*g else (lo, u)
print('%.15g' % u)")
    echo "perMaterial: fine $uFine (SN $utF), coarse $uCoarse (SN $utC), mixed $uMix (reference $uMixRef, spread $mixSpread)"
    check "perMaterial: fine cloud at its own Ut within 1 %" "abs(-u/ut - 1) <= 0.01" u="$uFine" ut="$utF"
    check "perMaterial: coarse cloud at its own Ut within 1 %" "abs(-u/ut - 1) <= 0.01" u="$uCoarse" ut="$utC"
    check "perMaterial: mixed cloud at the volume-share-weighted Ut within 1 %" "abs(-u/r - 1) <= 0.01" u="$uMix" r="$uMixRef"
else
    echo "FAIL: perMaterial run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1))
fi

# setForces <case> <forces...> [Cvm]: the coupling's force list (and Cvm)
setForces()
{
    sed -i "s/^\( *forces *\).*/\1($2);/" "$1/constant/mpmProperties"
    [ -n "${3:-}" ] && sed -i "s/^\( *forces *.*\)$/\1\n    Cvm         $3;/" "$1/constant/mpmProperties"
    return 0
}

# 5. Virtual mass: settling from rest against the ODE
declare -A vmHist
for cvm in 0.5 0; do
    c=$(newCase "vmSettle$cvm" oneWay 2e-4 5e-5 0.03 auto)
    if [ "$cvm" = 0 ]; then setForces "$c" "drag pressureGradient gravity"
    else setForces "$c" "drag pressureGradient gravity virtualMass" "$cvm"; fi
    runCase "$c" || { echo "FAIL: vmSettle$cvm run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    read -r err ut <<< "$("$PY" - "$c" "$cvm" $rhoS $rhoF $mu $g <<'PYEOF'
import sys
import numpy as np
import mpmPost
c, cvm, rs, rf, mu, g = sys.argv[1], *map(float, sys.argv[2:])
d = 2e-4
s = mpmPost.read_summary(c)
t, v = s["time"], s["Uy"]
def rhs(u):
    Re = rf*abs(u)*d/mu
    return (-(rs - rf)*g - 18*mu/d**2*(1 + 0.15*Re**0.687)*u)/(rs + cvm*rf)
# RK4 with 100 sub-steps per output interval
ref, u, tt = [], 0.0, 0.0
for tn in t:
    h = (tn - tt)/100
    for i in range(100):
        k1 = rhs(u); k2 = rhs(u + h*k1/2); k3 = rhs(u + h*k2/2); k4 = rhs(u + h*k3)
        u += h*(k1 + 2*k2 + 2*k3 + k4)/6
    tt = tn
    ref.append(u)
ref = np.array(ref)
ut = abs(ref[-1])
np.savetxt(c + "/history.dat", np.c_[t, v])
print(np.abs(v - ref).max()/ut, ut)
PYEOF
)"
    echo "vmSettle Cvm $cvm: max |v - v_ODE| = $err Ut (Ut $ut)"
    check "virtual mass Cvm $cvm: settling history = ODE within 1 % of Ut" "e <= 0.01" e="$err"
    vmHist[$cvm]="$c/history.dat"
done
if [ -n "${vmHist[0.5]:-}" ] && [ -n "${vmHist[0]:-}" ]; then
    diffVm=$("$PY" -c "
import numpy as np
a = np.loadtxt('${vmHist[0.5]}'); b = np.loadtxt('${vmHist[0]}')
print(np.abs(a[:, 1] - b[:, 1]).max()/abs(b[-1, 1]))")
    echo "vmSettle: Cvm 0.5 vs none differ by up to $diffVm Ut"
    check "virtual mass changes the settling history (> 5 % of Ut)" "x > 0.05" x="$diffVm"
fi

# 6. Virtual mass: heavy grains in a uniformly accelerating fluid
for cvm in 0.5 0; do
    c=$(newCase "vmAccel$cvm" oneWay 2e-4 1e-3 0.1 auto)
    if [ "$cvm" = 0 ]; then setForces "$c" "pressureGradient"
    else setForces "$c" "pressureGradient virtualMass" "$cvm"; fi
    "$PY" - "$c" <<'PYEOF'
import re, sys
c = sys.argv[1]
u = open(c + "/0/U").read()
u = re.sub(r"bottom\s*\{[^}]*\}", "bottom { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (0 1 0))); value uniform (0 0 0); }", u)
open(c + "/0/U", "w").write(u)
p = open(c + "/0/p").read()
p = re.sub(r"internalField\s+nonuniform List<scalar> \d+\s*\([^)]*\)\s*;", "internalField uniform 0;", p)
open(c + "/0/p", "w").write(p)
PYEOF
    runCase "$c" || { echo "FAIL: vmAccel$cvm run"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    ratio=$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
import mpmPost
s = mpmPost.read_summary(sys.argv[1])
late = s["time"] >= 0.05
print(np.polyfit(s["time"][late], s["Uy"][late], 1)[0]/1.0)
PYEOF
)
    expect=$("$PY" -c "print((1 + $cvm)*$rhoF/($rhoS + $cvm*$rhoF))")
    echo "vmAccel Cvm $cvm: a_s/a_f = $ratio (expected $expect)"
    check "virtual mass Cvm $cvm: a_s/a_f = (1 + Cvm) rho_f/(rho_s + Cvm rho_f) within 1 %" "abs(r/e - 1) <= 0.01" r="$ratio" e="$expect"
done
finish
