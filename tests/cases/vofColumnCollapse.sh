#!/bin/bash
#------------------------------------------------------------------------------
# Against experiment: the collapse of a water column (fluidModel VOF, no
# grain in the fluid), Martin & Moyce (1952), "An experimental study of the
# collapse of liquid columns on a rigid horizontal plane", Phil. Trans. R.
# Soc. A 244, 312-324: the column a wide and n^2 a = 2a high, a = 2.25 in
# (0.05715 m), the surge front z(t) on the floor as Z = z/a against
# T = t sqrt(2 g/a). The data: their Figure 3 (n^2 = 2, a = 2.25 in) as
# digitised in PySPH (github.com/pypr/pysph, pysph/examples/db_exp_data.py,
# mm_data_2), below.
#
# 2D, a tank 15a x 2.5a of cubic cells a/16 (240 x 40), interFoam's
# damBreak fields, schemes and solvers (tests/cases/vofDamBreakCase) and
# its adjustable step (maxCo 0.5, maxAlphaCo 0.5), to t = 0.5 s (T = 9.3);
# front: where alpha.water crosses 0.5 along the floor's cells, at each
# 0.01 s write, interpolated to the data's T. interFoam runs the same case.
#
#  1. mpmFoam's front equals interFoam's within 1 % of Z at every data
#     point (measured 6.9e-6): what follows is the VOF model's, not the
#     coupling's.
#  2. Against the experiment: the computed front leads the data, by 3-5 %
#     once T >= 4.4 (checked within 8 %; measured 5.4 % at most) and by
#     9-18 % earlier (T < 4.4: checked ahead of the data and within 25 %).
#     The early lead is beyond the experiment's scatter (the two column
#     sizes of their Figure 3, a = 1.125 and 2.25 in, differ by up to about
#     9 % at the same T): this simulation, 2D, releases the column at once
#     and resolves it with 16 cells; the lead is reported, not tuned away.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

a=0.05715
c="$SCRATCH/column"
cp -r "$_caseTestDir/vofDamBreakCase" "$c"
cp "$c/0/alpha.water.orig" "$c/0/alpha.water"
"$PY" - "$c" "$a" <<'PYEOF'
import sys
c, a = sys.argv[1], float(sys.argv[2])
h = a/16; nx, ny = 240, 40
open(c + "/system/blockMeshDict", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
// Martin & Moyce (1952): a column a x 2a (n^2 = 2), a = 2.25 in, in a 15a x 2.5a tank; cubic cells a/16
vertices ( (0 0 0) ({nx*h} 0 0) ({nx*h} {ny*h} 0) (0 {ny*h} 0) (0 0 {h}) ({nx*h} 0 {h}) ({nx*h} {ny*h} {h}) (0 {ny*h} {h}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
boundary
(
    leftWall {{ type wall; faces ((0 4 7 3)); }}
    rightWall {{ type wall; faces ((2 6 5 1)); }}
    lowerWall {{ type wall; faces ((1 5 4 0)); }}
    atmosphere {{ type patch; faces ((3 7 6 2)); }}
    defaultFaces {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
""")
open(c + "/system/setFieldsDict", "w").write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object setFieldsDict; }}
defaultFieldValues ( volScalarFieldValue alpha.water 0 );
regions ( boxToCell {{ box (-1 -1 -1) ({a} {2*a} 1); fieldValues ( volScalarFieldValue alpha.water 1 ); }} );
""")
PYEOF
sed -i 's/^adjustTimeStep .*/adjustTimeStep  yes;/; s/^maxCo .*/maxCo           0.5;/; s/^maxAlphaCo .*/maxAlphaCo      0.5;/;
        s/^endTime .*/endTime         0.5;/; s/^deltaT .*/deltaT          1e-4;/;
        s/^writeControl .*/writeControl    adjustableRunTime;/; s/^writeInterval .*/writeInterval   0.01;/' "$c/system/controlDict"
runApps "$c" blockMesh setFields || { echo "FAIL: set-up"; tail -20 "$c"/log.*; exit 1; }
ic="$SCRATCH/column.interFoam"
cp -r "$c" "$ic"
m=$(vofMpmCase "$c" column.mpmFoam "(0.8322 0.1314 0)" "(0.85725 0.142875 0.0036)") || exit 1   # one lattice cell (0.0146)
runApps "$ic" interFoam || { echo "FAIL: interFoam"; tail -20 "$ic/log.interFoam"; exit 1; }
runApps "$m" mpmFoam || { echo "FAIL: mpmFoam"; tail -20 "$m/log.mpmFoam"; exit 1; }

res=$("$PY" - "$m" "$ic" "$a" <<'PYEOF'
import sys
import numpy as np, mpmPost
m, ic, a = sys.argv[1], sys.argv[2], float(sys.argv[3])
g, nx = 9.81, 240
h = a/16
# Martin & Moyce (1952) Fig. 3, n^2 = 2, a = 2.25 in: T = t sqrt(2g/a), Z = z/a
# (PySPH, pysph/examples/db_exp_data.py, mm_data_2)
mm = np.array([[0.832, 1.217], [1.219, 1.474], [1.997, 2.292], [2.547, 2.995], [3.345, 4.134],
               [4.034, 4.944], [4.418, 5.881], [5.091, 6.980], [5.685, 7.945], [6.306, 8.966],
               [6.822, 9.986], [7.439, 10.963], [8.031, 11.977], [8.633, 13.005], [9.237, 13.970]])
def front(case):
    T, Z = [], []
    for t in mpmPost.field_times(case, "alpha.water"):
        row = np.asarray(mpmPost.read_internal_field(case, t, "alpha.water"), float)[:nx]   # the floor's cells
        i = np.flatnonzero(row >= 0.5)
        if not len(i): continue
        i = i.max()
        x = (i + 0.5)*h + (h*(row[i] - 0.5)/(row[i] - row[i + 1]) if i + 1 < nx else 0)
        T.append(float(t)*np.sqrt(2*g/a)); Z.append(x/a)
    return np.interp(mm[:, 0], T, Z)
zm, zi = front(m), front(ic)
r = zm/mm[:, 1]
for k in range(len(mm)):
    print("    T %.3f: Martin & Moyce Z %.3f, mpmFoam %.3f (ratio %.3f), interFoam %.3f" % (mm[k, 0], mm[k, 1], zm[k], r[k], zi[k]), file=sys.stderr)
late = mm[:, 0] >= 4.4
print((np.abs(zm - zi)/zi).max(), np.abs(r[late] - 1).max(), r[~late].min(), r[~late].max())
PYEOF
)
read -r dI dLate rMin rMax <<< "$res"
check "the front = interFoam's within 1 % at every data point (${dI:-nan})" "d <= 0.01" d="${dI:-nan}"
check "the front = Martin & Moyce's within 8 % for T >= 4.4 (max |ratio - 1| ${dLate:-nan})" "d <= 0.08" d="${dLate:-nan}"
check "for T < 4.4 it leads the data, by less than 25 % (ratio ${rMin:-nan} to ${rMax:-nan})" "lo >= 1 and hi <= 1.25" lo="${rMin:-nan}" hi="${rMax:-nan}"
finish
