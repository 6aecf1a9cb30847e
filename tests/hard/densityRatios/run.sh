#!/bin/bash
#------------------------------------------------------------------------------
# Density ratios: dilute grains (alpha.solid 1e-4, Schiller-Naumann drag,
# forces drag pressureGradient gravity, twoWay) settling from rest in the
# 1D column of tests/cases/terminalVelocityCase (0.1 m, 1 mm cells, fluid
# step 1 ms), at the two ends of the density ratio:
#   - 1.05: near-buoyant grains in water (rho_s 1050, d 0.2 mm): the net
#     weight is 5 % of the weight, so buoyancy (the pressure gradient) and
#     gravity nearly cancel and an error in either dominates;
#   - 2000: sand in air (rho_s 2400, rho_f 1.2, nu 1.5e-5, d 50 um).
# Bounds: the grains' settling velocity over the last third of the run
# within 1 % of the Schiller-Naumann terminal velocity (computed here; the
# runs last > 10 relaxation times); the shared checks with alphaMax 0.63;
# kinetic + potential energy of the grains grows by <= 1e-3 of the available
# (drag and buoyancy only take energy from grains falling through a fluid at
# rest; the return flow is 1e-4 of the settling speed).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"
g=9.81

# name rhoS rhoF nuF d endTime
for setup in "ratio1.05 1050 1000 1e-6 2e-4 0.1" "ratio2000 2400 1.2 1.5e-5 5e-5 0.15"; do
    read -r name rhoS rhoF nu d tEnd <<< "$setup"
    c="$SCRATCH/$name"
    cp -r "$MPMFOAM_ROOT/tests/cases/terminalVelocityCase" "$c"
    sed -i "s/^\( *mode  *\)[A-Za-z]*;/\1twoWay;/; s/\(model SchillerNaumann; d\) [^;]*;/\1 $d;/; s/^\( *rho  *\)2500;/\1$rhoS;/" "$(props "$c")"
    sed -i "s/^nu .*/nu              $nu;/; s/^rho .*/rho             $rhoF;/" "$c/constant/transportProperties"
    sed -i "s/^endTime .*/endTime         $tEnd;/; s/^writeInterval .*/writeInterval   $("$PY" -c "print($tEnd/2)");/" "$c/system/controlDict"
    setUp "$c"
    solve "$c"
    read -r ut tau <<< "$("$PY" -c "
rs, rf, mu, g, d = $rhoS, $rhoF, $rhoF*$nu, $g, $d
ust = (rs - rf)*g*d*d/(18*mu)
u = ust
for i in range(500):
    u = ust/(1 + 0.15*(rf*u*d/mu)**0.687)
print(u, rs*d*d/(18*mu))")"
    ucm=$("$PY" -c "
import mpmPost
s = mpmPost.read_summary('$c'); late = s['time'] >= 2*$tEnd/3
print(-s['Uy'][late].mean())")
    echo "    $name: tau $tau s, run $tEnd s; Schiller-Naumann Ut $ut m/s, measured $ucm m/s"
    check "$name: settling velocity within 1 % of Schiller-Naumann" "abs(u/ut - 1) <= 0.01" u="${ucm:-0}" ut="$ut"
    checkRun "$c" --alpha-max 0.63 --energy-growth 1e-3
done
finish
