#!/bin/bash
#------------------------------------------------------------------------------
# Outlet with a fluid (coupled, twoWay): the terminal-velocity column
# (tests/cases/terminalVelocityCase: 1D water column, dilute 0.2 mm glass
# grains, Schiller-Naumann drag) with its bottom an outlet for the grains
# (the fluid's bottom stays a wall) and the cloud just above it
# (0.002 < y < 0.012 m, 40 points). The grains settle at Ut ~ 2.3 cm/s and
# leave through the bottom within the run. Checked:
#   - the balance, initial - removed = present, on every fluid step (count
#     exact, mass to round-off), and every grain gone at the end;
#   - the cloud settles as one (uniform velocity): at each written time the
#     points in the column have all moved the same distance s, to 1e-3 of s
#     (measured 4.8e-5: the twoWay return flow, alpha_s Ut/alpha_f ~ 1e-4
#     Ut, varies across the cloud), and the points removed are exactly
#     those with y0 < s. Beyond the outlet the drag per unit solid volume
#     continues from the cells inside (zero gradient); without it grains
#     within two cells of the outlet fell freely (spread 7.5 %);
#   - the same on 2 processors (simple (1 2 1)): the same counts on every
#     step, the cloud equal to serial to 1e-10 at t = 0.2.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

export OMP_NUM_THREADS=1
c="$SCRATCH/coupledOutlet"
cp -r "$MPMFOAM_ROOT/tests/cases/terminalVelocityCase" "$c"
sed -i 's/bottom { type noSlip; }/bottom { type outlet; }/; s/mode        oneWay;/mode        twoWay;/' "$c/constant/mpmProperties"
sed -i 's/min           (0 0.05 0);/min (0 0.002 0);/; s/max           (0.001 0.07 0.001);/max (0.001 0.012 0.001);/; s/pointsPerCell 2;/pointsPerCell 4;/' \
    "$c/system/mpmSetParticlesDict"
sed -i 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/writeInterval 0.1;/' "$c/system/controlDict"
p="$SCRATCH/coupledOutletParallel"
cp -r "$c" "$p"
runApps "$c" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: coupled outlet run"; tail -20 "$c/log.mpmFoam"; exit 1; }

res=$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np, mpmPost
c = sys.argv[1]
x0 = mpmPost.read_positions(c, "0")[:, 1]
id0 = mpmPost.read_cloud_field(c, "0", "pointId").astype(int)
y0 = dict(zip(id0, x0))
out = mpmPost.read_open_boundary(c, "bottom")
bal = mpmPost.read_open_boundary(c, "massBalance")
spread, badCount, checked = 0.0, 0, 0
for t in mpmPost.times(c)[1:]:
    ids = np.atleast_1d(mpmPost.read_cloud_field(c, t, "pointId")).astype(int)
    row = np.argmin(np.abs(out["time"] - float(t)))
    if len(ids) == 0:
        continue
    y = np.atleast_2d(mpmPost.read_positions(c, t))[:, 1]
    d = np.array([y0[i] for i in ids]) - y
    s = d.mean()
    spread = max(spread, (d.max() - d.min())/s)
    badCount += int((x0 < s).sum() != out["removedPoints"][row])
    checked += 1
bc = int((bal["presentPoints"] != bal["initialPoints"] - bal["removedPoints"]).sum())
bm = np.abs(bal["massError"]).max()/bal["initialMass"][0]
print(len(x0), checked, spread, badCount, bc, bm, int(bal["presentPoints"][-1]), len(bal["time"]))
PYEOF
)
read -r n0 checked spread badCount bc bm last rows <<< "$res"
check "coupled: balance closes on every fluid step ($rows rows), all $n0 grains gone at the end" \
    "rows >= 600 and bc == 0 and bm <= 1e-13 and last == 0" rows="$rows" bc="$bc" bm="$bm" last="$last"
check "coupled: the cloud settles as one through the outlet (spread of displacements / s at $checked written times)" \
    "checked >= 3 and spread <= 1e-3" checked="$checked" spread="$spread"
check "coupled: the points removed are those with y0 < s at every written time" "bad == 0" bad="$badCount"

# 2 processors against serial
runApps "$p" blockMesh mpmSetParticles || { echo "FAIL: parallel set-up"; exit 1; }
decomposeCase "$p" 2 simple "n (1 2 1);"
(cd "$p" && mpirun -np 2 mpmFoam -parallel > log.mpmFoam 2>&1) || { echo "FAIL: mpirun -np 2 (coupled)"; tail -20 "$p/log.mpmFoam"; exit 1; }
bad=$("$PY" - "$c" "$p" <<'PYEOF'
import sys
import numpy as np, mpmPost
a, b = (mpmPost.read_open_boundary(x, "massBalance") for x in sys.argv[1:3])
print(int(len(a["time"]) != len(b["time"]) or (a["presentPoints"] != b["presentPoints"]).any()
          or (a["removedPoints"] != b["removedPoints"]).any()))
PYEOF
)
check "coupled, 2 processors: the same counts as serial on every step" "bad == 0" bad="$bad"
out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$c" "$p" 0.2 --fields U)
pos=$(echo "$out" | awk '$1=="positions"{print $2}'); same=$(echo "$out" | awk '$1=="ids"{print $3}')
check "coupled, 2 processors: cloud at t = 0.2 equals serial (ids, positions)" \
    "same == 1 and pos <= 1e-10" same="${same:-0}" pos="${pos:-1}"

finish
