#!/bin/bash
#------------------------------------------------------------------------------
# The spectral analysis against the real axial bar (fixed end, free end; not
# the periodic lattice it assumes). PIC (alpha = 0), cubic B-spline, lumped
# mass, USL, CFL 0.5, 2 points per cell, at 25 and 100 cells.
#
# Measured: per-step decay of the total energy E_n = E_0 |G|^(2n) of the
# first mode. Predicted: |G| of the analysis at kh = pi h / (2 L), offsets
# 0.25, 0.75. The damping rates 1 - |G| agree to 0.03 % (25 cells) and
# 0.005 % (100 cells); the rest is the ends (the mode is a quarter sine, not
# a periodic Fourier mode) and the higher modes the initial field excites.
# Asserted: within 1 %, which a wrong alpha, shape or CFL misses by far.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"
tool="$MPMFOAM_BUILD/applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"

for n in 25 100; do
    c=$(copyTutorial mpm/axialBar damping$n)
    h=$("$PY" -c "print(25/$n)"); dt=$("$PY" -c "print(0.5*$h/10)")
    sed -i "s/^nCells .*/nCells  $((n*6/5));/" "$c/system/blockMeshDict"
    sed -i "s/^deltaT .*/deltaT          $dt;/" "$c/system/controlDict"
    sed -i "s/^flipRatio .*/flipRatio       0;/; s/^massMatrix .*/massMatrix      lumped;/; s/type        adaptive;/type        fixed;/" \
        "$c/constant/mpmProperties"
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: run $c"; failures=$((failures + 1)); continue; }
    "$tool" --model wave --shape CBS --alpha 0 --scheme USL --offsets 0.25,0.75 --CFL 0.5 --nk $((2*n)) \
        --csv "$c/G.csv" > /dev/null
    read -r measured predicted < <("$PY" - "$c" "$dt" "$h" <<'PYEOF'
import csv, math, sys
import mpmPost
case, dt, h = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
s = mpmPost.read_summary(case)
E = s["kineticEnergy"] + s["elasticEnergy"]
steps = round(s["time"][-1]/dt)
measured = (E[-1]/E[0])**(1/(2*steps))
kh = math.pi/(2*25)*h
rows = [r for r in csv.DictReader(open(case + "/G.csv")) if abs(float(r["kh"]) - kh) < 1e-9]
print(measured, float(rows[0]["absG"]))
PYEOF
)
    echo "axialBar $n cells, PIC CBS USL CFL 0.5: per-step |G| measured $measured, predicted $predicted"
    echo "    damping rate 1-|G|: measured $("$PY" -c "print(1-$measured)"), predicted $("$PY" -c "print(1-$predicted)")"
    check "bar damping at $n cells matches the analysis within 1 %" \
        "abs((1 - m) - (1 - p)) <= 0.01*(1 - p)" m="$measured" p="$predicted"
done
finish
