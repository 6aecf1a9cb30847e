#!/bin/bash
#------------------------------------------------------------------------------
# Large deformation: a granular column of aspect ratio 8 (0.05 m wide, 0.4 m
# tall, Drucker-Prager sand of tutorials/mpm/granularColumnCollapse, a
# symmetry wall at x = 0) collapses over 1 s; points travel ~8 column
# widths and the column's height drops by ~4x. Checked:
#   - shared checks (tests/hard/checkRun.py); energy: kinetic + stored +
#     potential may not grow by more than 1e-3 of the energy available
#     (friction and plasticity only dissipate);
#   - the logged potential energy is -sum m g.y of the written cloud
#     (relative 1e-9 at every write time), so the energy check sees gravity;
#   - large deformation happened: the runout front moved > 3 column widths
#     and the top fell below half the initial height.
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c=$(copyTutorial mpm/granularColumnCollapse column)
sed -i 's/max           (0.2 0.4 0.01);/max           (0.05 0.4 0.01);/' "$c/system/mpmSetParticlesDict"
sed -i 's/^logInterval .*/logInterval     50;/' "$(props "$c")"
sed -i 's/^writeInterval .*/writeInterval   0.25;/' "$c/system/controlDict"
setUp "$c"
solve "$c"
checkRun "$c" --energy-growth 1e-3

read -r peErr front top <<< "$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np, mpmPost
c = sys.argv[1]
s = mpmPost.read_summary(c)
worst = 0.0
for t in mpmPost.times(c):
    x = mpmPost.read_positions(c, t)
    m = mpmPost.read_cloud_field(c, t, "mass")
    pe = (m*9.81*x[:, 1]).sum()
    k = np.argmin(np.abs(s["time"] - float(t)))
    worst = max(worst, abs(s["potentialEnergy"][k]/pe - 1))
x = mpmPost.read_positions(c, mpmPost.times(c)[-1])
print(worst, x[:, 0].max(), x[:, 1].max())
PYEOF
)"
check "logged potential energy = sum m g y of the written cloud" "e <= 1e-9" e="${peErr:-1}"
check "large deformation: runout front > 3 widths (0.15 m), top < 0.2 m" "f > 0.15 and t < 0.2" f="${front:-0}" t="${top:-1}"
finish
