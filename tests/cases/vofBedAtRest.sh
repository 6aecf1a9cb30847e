#!/bin/bash
#------------------------------------------------------------------------------
# A saturated sand bed under still water with air above (fluidModel VOF,
# twoWay, forces (drag pressureGradient gravity)): the consolidation
# tutorial (multiphase/consolidation: a 0.1 m layer, aS 0.6, linear elastic
# skeleton, Ergun drag of 0.1 mm grains, drained at its top, starting
# unstressed) with the column raised from 0.12 to 0.2 m (80 cells of 2.5 mm),
# water up to 0.12 m and air above, set with setFields (alpha.water, and
# p_rgh hydrostatic); the annotated VOF files, with the p_rgh tolerance of
# the tutorial's p (1e-10). The tutorial runs as shipped beside it (the
# single fluid, water to the top at 0.12 m). To 1.5 s (T = c_v t/H^2 = 2.4):
#
#  1. The bed's excess pore pressure u = p - p(y_ref) - rho_w g (y_ref - y)
#     (y_ref = 0.114 m, in the water above the bed) equals the single
#     fluid's at every write within 1e-3 gamma'H (measured 4.2e-4 with the
#     default alphaContinuity corrected; conservative 2.8e-4, bounded
#     4.7e-4): the air above changes nothing below the surface.
#  2. It follows Terzaghi's series solution (plotConsolidation.py's, same
#     cells y < H - 2h) within 3 % of gamma'H at every write with
#     0.04 <= T <= 1 (as consolidation.sh; measured 2.2 %, each form).
#  3. At the end the skeleton carries the buoyant weight: the points'
#     sigma'_yy = -gamma'(H - y) + u within 1.5 % of gamma'H (measured
#     0.79 %; conservative 0.79 %, bounded 0.83 %).
#  4. At rest: the pressure is hydrostatic, dp/dy = -rho g within 1e-5 of
#     rho g in the water above the bed and in the air (measured 6.8e-7;
#     conservative 5.9e-7, bounded 1.6e-6); the spurious velocity above the
#     bed is below 1e-5 m/s at the end (measured 2.2e-7 m/s, each form);
#     the surface (alpha.water = 0.5) stays at 0.12 m within h/10.
#  5. The water volume int alpha.water alpha.fluid dV, while the grains
#     move (the bed settles), balances at every step within 1e-7 (measured
#     5.6e-16; conservative 1.6e-8, the MULESCorr predictor's tolerance
#     1e-8). Inside the bed the projected alpha.fluid does not follow
#     the last pressure solve's flux exactly (the log's "alpha transport
#     error"). With alphaContinuity corrected (the default) the alpha
#     transport's flux is corrected to carry alpha.fluid's change (pcorr):
#     alpha.water within [0, 1] to 1e-9 (measured 1 exactly). Run here too,
#     each with 1.-4. and the balance: alphaContinuity conservative (no
#     correction, the water kept): alpha.water leaves 1 in the bed, checked
#     above 1 + 1e-4 (the residual the correction removes; measured
#     1.0017) and within 1.01; bounded (alpha.water takes the residual with
#     it, MPPICInterFoam's form): within [0, 1] to 1e-12.
#  6. The seeded grains: count, ids and mass in every written cloud.
#  7. HDF5 (pointOutput hdf5, to 0.1 s): the checkpoint holds alpha.water,
#     p_rgh and p with the lattice's fields; a restart from the 0.05 s
#     checkpoint (alphaPhi0.water read back) gives the continuous run's
#     fluid fields at 0.1 s within 1e-8, in the time directory and on the
#     checkpoint's lattice (measured 7.8e-10 in U: the fluid restarts from
#     the 12-digit ASCII fields), and the checkpoint's points within 1e-12
#     (measured 3.9e-13). ParaView (pvbatch, the XDMF Reader, as
#     hdf5Output.sh) reads alpha.water, p_rgh and p from the series and
#     gives the volFields at 0.1 s within 1e-10 (measured 5.0e-12: the
#     12-digit ASCII fields).
#  8. Decomposed (simple, 2 ranks split along the column, to 0.1 s), with
#     the alpha and p_rgh solvers converged tight (1e-15, 1e-14): the
#     reconstructed fields equal the serial run's, alpha.water within 1e-8
#     (measured 3.8e-10), p_rgh within 1e-8 of its largest value (2.1e-10),
#     U within 1e-10 m/s (4.2e-12 m/s of 1.5e-4 m/s), and the points'
#     velocity and stress within 1e-8 of their largest (1.9e-10, 8.7e-11).
#     At the annotated tolerances (1e-8, 1e-10) the same differences are
#     2.8e-6 in alpha.water and 2.2e-7 m/s in U (a one-off run): the
#     solvers' tolerance, as for interFoam (vofDamBreak.sh).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

single=$(copyTutorial multiphase/consolidation single)
runApps "$single" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: the single-fluid consolidation"; tail -20 "$single/log.mpmFoam"; exit 1; }

c=$(copyTutorial multiphase/consolidation vof)
rm -f "$c/0/p"
sed -i 's/^height .*/height  0.2;/; s/^nCells .*/nCells  80;/' "$c/system/blockMeshDict"
sed -i 's/^logInterval .*/logInterval     1;/' "$c/constant/mpmProperties"    # the water volume every step
cp "$MPMFOAM_ROOT/etc/caseDicts/coupled/VOF/transportProperties" "$c/constant/"
cp "$MPMFOAM_ROOT/etc/caseDicts/coupled/VOF/fvSchemes" "$MPMFOAM_ROOT/etc/caseDicts/coupled/VOF/fvSolution" "$c/system/"
sed -i 's/^\( *p_rgh  *{.*tolerance\) [^;]*; relTol [^;]*;/\1 1e-10; relTol 0.01;/' "$c/system/fvSolution"
grep -q "p_rgh .*tolerance 1e-10; relTol 0.01;" "$c/system/fvSolution" || { echo "FAIL: could not set the p_rgh tolerance"; failures=$((failures + 1)); }
cat > "$c/0/p_rgh" <<'EOF'
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions      [1 -1 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    top    { type totalPressure; p0 uniform 0; }
    bottom { type fixedFluxPressure; value uniform 0; }
    sides  { type empty; }
}
EOF
cat > "$c/0/alpha.water" <<'EOF'
FoamFile { version 2.0; format ascii; class volScalarField; object alpha.water; }
dimensions      [0 0 0 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    top    { type inletOutlet; inletValue uniform 0; value uniform 0; }
    bottom { type zeroGradient; }
    sides  { type empty; }
}
EOF
# Water to y = 0.12 m; p_rgh = p + rho g y is 0 in the air (p = 0 at the
# top) and (rho_w - rho_a) g 0.12 in the water: hydrostatic
cat > "$c/system/setFieldsDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object setFieldsDict; }
defaultFieldValues ( volScalarFieldValue alpha.water 0 volScalarFieldValue p_rgh 0 );
regions ( boxToCell { box (-1 -1 -1) (1 0.12 1); fieldValues ( volScalarFieldValue alpha.water 1 volScalarFieldValue p_rgh 1176.0228 ); } );
EOF
runApps "$c" blockMesh setFields mpmSetParticles mpmFoam || { echo "FAIL: the VOF bed"; tail -30 "$c/log.mpmFoam"; exit 1; }

# analyse <case> <label>: 1.-5. for a VOF run of the bed
analyse()
{
res=$("$PY" - "$single" "$1" <<'PYEOF'
import os, sys
import numpy as np
import mpmPost
single, vof = sys.argv[1], sys.argv[2]
sys.path.insert(0, single)
import plotConsolidation as pc          # the tutorial's Terzaghi solution
cs = pc.setup(single)                   # soil and water: the same in both
H, h, gH, g = cs["H"], cs["h"], cs["gammaP"]*cs["H"], cs["g"]
rhoW, rhoA = 1000.0, 1.0
iref = 45                               # y = 0.11375 m: water above the bed
def excess(p, y, rho):
    return rho*((p - p[iref]) - g*(y[iref] - y)) if rho else (p - p[iref]) - rhoW*g*(y[iref] - y)
dSingle = dTerz = 0.0
for t in [t for t in mpmPost.field_times(single, "p") if float(t) > 0]:
    ps = np.asarray(mpmPost.read_internal_field(single, t, "p"), float)
    pv = np.asarray(mpmPost.read_internal_field(vof, t, "p"), float)
    ys = (np.arange(len(ps)) + 0.5)*h
    yv = (np.arange(len(pv)) + 0.5)*h
    inner = yv < H - 2*h
    us = excess(ps, ys, rhoW)            # kinematic p of the single fluid
    uv = excess(pv, yv, None)            # p in Pa
    dSingle = max(dSingle, np.abs(uv[inner] - us[inner[:len(ys)]]).max()/gH)
    T = cs["cv"]*float(t)/H**2
    if 0.04 <= T <= 1:
        dTerz = max(dTerz, np.abs(uv[inner] - pc.terzaghi(cs, yv[inner], T)).max()/gH)
t = mpmPost.field_times(vof, "p")[-1]
pv = np.asarray(mpmPost.read_internal_field(vof, t, "p"), float)
y = (np.arange(len(pv)) + 0.5)*h
u = excess(pv, y, None)
xp = mpmPost.read_positions(vof, t)[:, 1]
syy = mpmPost.read_cloud_field(vof, t, "stress")[:, 3]
deep = xp < H - 3*h
dStress = np.abs(syy - (-cs["gammaP"]*(H - xp) + np.interp(xp, y, u)))[deep].max()/gH
water = (y > H + 3*h) & (y < 0.115)
air = y > 0.13
hydro = max(np.abs(np.diff(pv[water])/h + rhoW*g).max()/(rhoW*g), np.abs(np.diff(pv[air])/h + rhoA*g).max()/(rhoA*g))
U = np.asarray(mpmPost.read_internal_field(vof, t, "U"), float)
uMax = np.abs(U[y > H + 3*h]).max()
a = np.asarray(mpmPost.read_internal_field(vof, t, "alpha.water"), float)
i = np.flatnonzero((a[:-1] >= 0.5) & (a[1:] < 0.5))[-1]
ySurf = y[i] + h*(a[i] - 0.5)/(a[i] - a[i + 1])
print("  at t = %s: excess pore pressure against the single fluid %.3g gamma'H, against Terzaghi %.3g; "
      "effective stress %.3g gamma'H; hydrostatic %.3g; max |U| above the bed %.3g m/s; surface at %.6f m; "
      "alpha.water in [%.6g, %.6g]" % (t, dSingle, dTerz, dStress, hydro, uMax, ySurf, a.min(), a.max()), file=sys.stderr)
# alpha.water at every write
aAll = [np.asarray(mpmPost.read_internal_field(vof, tt, "alpha.water"), float) for tt in mpmPost.field_times(vof, "alpha.water")]
print(dSingle, dTerz, dStress, hydro, uMax, abs(ySurf - 0.12)/h, repr(min(x.min() for x in aAll)), repr(max(x.max() for x in aAll)))
PYEOF
)
read -r dSingle dTerz dStress hydro uMax dSurf aMin aMax <<< "$res"
check "$2: excess pore pressure = the single fluid's within 1e-3 gamma'H at every write (${dSingle:-nan})" "d <= 1e-3" d="${dSingle:-nan}"
check "$2: excess pore pressure = Terzaghi's within 3 % of gamma'H, 0.04 <= T <= 1 (${dTerz:-nan})" "d <= 0.03" d="${dTerz:-nan}"
check "$2: effective stress = -gamma'(H - y) + u within 1.5 % of gamma'H at the end (${dStress:-nan})" "d <= 0.015" d="${dStress:-nan}"
check "$2: hydrostatic in the water above the bed and in the air within 1e-5 (${hydro:-nan})" "d <= 1e-5" d="${hydro:-nan}"
check "$2: spurious velocity above the bed below 1e-5 m/s at the end (${uMax:-nan})" "u <= 1e-5" u="${uMax:-nan}"
check "$2: the surface stays at 0.12 m within h/10 (|dy|/h ${dSurf:-nan})" "d <= 0.1" d="${dSurf:-nan}"
if [ "$2" = bounded ]; then
    check "$2: alpha.water within [0, 1] to 1e-12 (${aMin:-nan}, ${aMax:-nan})" "a >= -1e-12 and b <= 1 + 1e-12" a="${aMin:-nan}" b="${aMax:-nan}"
elif [ "$2" = conservative ]; then
    check "$2: alpha.water over 1 + 1e-4 in the bed and within 1.01 (${aMin:-nan}, ${aMax:-nan}: the uncorrected residual)" "a >= -1e-12 and b > 1 + 1e-4 and b <= 1.01" a="${aMin:-nan}" b="${aMax:-nan}"
else
    check "$2: alpha.water within [0, 1] to 1e-9 (${aMin:-nan}, ${aMax:-nan})" "a >= -1e-12 and b <= 1 + 1e-9" a="${aMin:-nan}" b="${aMax:-nan}"
fi
bal=$(grep "^VOF: water volume" "$1/log.mpmFoam" | sed 's/.*balance (V - V0 + out)\/V0 \([^;]*\);.*/\1/' | "$PY" -c "import sys; v = [abs(float(x)) for x in sys.stdin]; print(max(v), len(v))")
read -r balMax nBal <<< "$bal"
check "$2: the water volume balances at every step ($nBal) within 1e-7 while the bed settles (${balMax:-nan})" "b <= 1e-7 and n == 1500" b="${balMax:-nan}" n="${nBal:-0}"
}

grep -q "alphaContinuity corrected" "$c/log.mpmFoam" || { echo "FAIL: the default is not alphaContinuity corrected"; failures=$((failures + 1)); }
analyse "$c" corrected
seededPoints "$c"

# alphaContinuity conservative and bounded: the same bed
for form in conservative bounded; do
    cb="$SCRATCH/vof.$form"
    cp -r "$c" "$cb"
    rm -rf "$cb"/0.[0-9]* "$cb"/[1-9]* "$cb"/log.mpmFoam "$cb/postProcessing"
    sed -i 's/^\( *nLimiterIter .*\)/\1\n        alphaContinuity '$form';/' "$cb/system/fvSolution"
    runApps "$cb" mpmFoam && grep -q "alphaContinuity $form" "$cb/log.mpmFoam" \
        || { echo "FAIL: the $form run"; tail -20 "$cb/log.mpmFoam"; failures=$((failures + 1)); }
    analyse "$cb" $form
done


# --- 7. HDF5 checkpoints and restart from one -----------------------------------
hc="$SCRATCH/vof.hdf5"
cp -r "$c" "$hc"
rm -rf "$hc"/0.[0-9]* "$hc"/[1-9]* "$hc"/log.mpmFoam "$hc/postProcessing"
echo "pointOutput     hdf5;" >> "$hc/constant/mpmProperties"
sed -i 's/^endTime .*/endTime         0.1;/; s/^writeInterval .*/writeInterval   0.05;/' "$hc/system/controlDict"
hr="$SCRATCH/vof.hdf5.restart"
if runApps "$hc" mpmFoam && cp -r "$hc" "$hr" && rm -rf "$hr/0.1" "$hr/HDF5/materialPoints_0.1.h5" "$hr/log.mpmFoam" \
    && runApps "$hr" mpmFoam && grep -q "restarting alpha from the MULES flux" "$hr/log.mpmFoam"; then
    read -r inFile dFluid dH5 <<< "$("$PY" - "$hc" "$hr" <<'PYEOF'
import sys
import numpy as np, h5py, mpmPost
a, b = sys.argv[1], sys.argv[2]
A = h5py.File(a + "/HDF5/materialPoints_0.1.h5", "r"); B = h5py.File(b + "/HDF5/materialPoints_0.1.h5", "r")
inFile = all(k in A["lattice"] for k in ("alpha.water", "p_rgh", "p"))
dFluid = max(np.abs(np.asarray(mpmPost.read_internal_field(a, "0.1", f), float) - np.asarray(mpmPost.read_internal_field(b, "0.1", f), float)).max()
             / np.abs(np.asarray(mpmPost.read_internal_field(a, "0.1", f), float)).max() for f in ("alpha.water", "p_rgh", "p", "U"))
names = []
A.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
dH5 = 0.0
for n in names:
    x, y = np.asarray(A[n][()]), np.asarray(B[n][()])
    if x.size and np.issubdtype(x.dtype, np.number):
        x, y = x.astype(float), y.astype(float)
        s = np.nanmax(np.abs(x))
        if s == 0: continue
        if n.startswith("materialPoints"): dH5 = max(dH5, np.nanmax(np.abs(x - y))/s)
        else: dFluid = max(dFluid, np.nanmax(np.abs(x - y))/s)   # the lattice's (fluid) fields
print(int(inFile), dFluid, dH5)
PYEOF
)"
    check "the HDF5 checkpoint holds alpha.water, p_rgh and p" "f == 1" f="${inFile:-0}"
    check "restart from the 0.05 s HDF5 checkpoint: the fluid at 0.1 s within 1e-8 (${dFluid:-nan}), the checkpoint's points within 1e-12 (${dH5:-nan})" \
        "f <= 1e-8 and h <= 1e-12" f="${dFluid:-nan}" h="${dH5:-nan}"
else
    echo "FAIL: the HDF5 runs"; tail -20 "$hr/log.mpmFoam" "$hc/log.mpmFoam" 2>/dev/null | tail -30; failures=$((failures + 1))
fi
# --- 8. decomposed against serial, solvers converged tight ---------------------
ds="$SCRATCH/vof.serialTight"
cp -r "$c" "$ds"
rm -rf "$ds"/0.[0-9]* "$ds"/[1-9]* "$ds"/log.mpmFoam "$ds/postProcessing"
sed -i 's/^endTime .*/endTime         0.1;/; s/^writeInterval .*/writeInterval   0.1;/' "$ds/system/controlDict"
sed -i 's/^\( *tolerance  *\)1e-8;/\11e-15;/; s/^\( *p_rgh  *{.*tolerance\) [^;]*; relTol [^;]*;/\1 1e-14; relTol 0;/' "$ds/system/fvSolution"
dp="$SCRATCH/vof.decomposed"
cp -r "$ds" "$dp"
cat > "$dp/system/decomposeParDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method simple;
coeffs { n (1 2 1); }
EOF
if runApps "$ds" mpmFoam && (cd "$dp" && decomposePar > log.decomposePar 2>&1 \
    && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1 && reconstructPar -time 0.1 > log.reconstructPar 2>&1); then
    read -r da dpr du dpu dps <<< "$("$PY" - "$ds" "$dp" <<'PYEOF'
import sys
import numpy as np, mpmPost
a, b = sys.argv[1], sys.argv[2]
f = lambda c, n: np.asarray(mpmPost.read_internal_field(c, "0.1", n), float)
da = np.abs(f(a, "alpha.water") - f(b, "alpha.water")).max()
dp = np.abs(f(a, "p_rgh") - f(b, "p_rgh")).max()/np.abs(f(a, "p_rgh")).max()
du = np.abs(f(a, "U") - f(b, "U")).max()
def cloud(c, n):
    return mpmPost.read_cloud_field(c, "0.1", n)[np.argsort(mpmPost.read_cloud_field(c, "0.1", "pointId"))]
dpu, dps = (np.abs(cloud(a, n) - cloud(b, n)).max()/np.abs(cloud(a, n)).max() for n in ("U", "stress"))
print(da, dp, du, dpu, dps)
PYEOF
)"
    check "decomposed = serial: alpha.water within 1e-8 (${da:-nan}), p_rgh within 1e-8 (${dpr:-nan}), U within 1e-10 m/s (${du:-nan}), the points' U and stress within 1e-8 (${dpu:-nan}, ${dps:-nan})" \
        "a <= 1e-8 and p <= 1e-8 and u <= 1e-10 and pu <= 1e-8 and ps <= 1e-8" a="${da:-nan}" p="${dpr:-nan}" u="${du:-nan}" pu="${dpu:-nan}" ps="${dps:-nan}"
else
    echo "FAIL: the decomposed bed"; tail -20 "$dp/log.mpmFoam" "$ds/log.mpmFoam" 2>/dev/null | tail -30; failures=$((failures + 1))
fi

# ParaView's XDMF Reader on the series
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
    xvfb-run -a pvbatch "$MPMFOAM_ROOT/tests/cases/hdf5/readXdmf.py" "$hc/materialPoints.xmf" "$SCRATCH/xdmf.npz" 2>&1 | grep "^XDMF" | sed 's/^/    /'
    dPv=$("$PY" - "$hc" "$SCRATCH/xdmf.npz" <<'PYEOF'
import sys
import numpy as np, mpmPost
case, npz = sys.argv[1], sys.argv[2]
x = np.load(npz)
d = 0.0
for f in ("alpha.water", "p_rgh", "p"):
    a = np.asarray(mpmPost.read_internal_field(case, "0.1", f), float)
    d = max(d, np.abs(x["cell:" + f] - a).max()/np.abs(a).max())
print(d)
PYEOF
)
    check "ParaView's XDMF Reader: alpha.water, p_rgh and p at 0.1 s = the volFields within 1e-10 (${dPv:-nan})" "d <= 1e-10" d="${dPv:-nan}"
else
    echo "FAIL: no pvbatch or xvfb-run for the ParaView check"; failures=$((failures + 1))
fi
finish
