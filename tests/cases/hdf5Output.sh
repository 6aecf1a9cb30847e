#!/bin/bash
#------------------------------------------------------------------------------
# pointOutput hdf5: one checkpoint file per write time for the whole run,
# an XDMF series for ParaView, and restarts on any number of processors.
# On the 3D elastic block of the parallel tests (1452 points, cubic
# B-splines, friction/slip/no-slip walls) and a coupled 2D case:
#   - the HDF5 run equals the OpenFOAM-format run of the same case (every
#     point field, 17 digits), and h5dump shows units on every dataset;
#   - ParaView's XDMF Reader (pvbatch) loads the last time: the point count,
#     the stress tensor of every point (component order) and the cell
#     fields alpha.solid and U.solid (cell order) equal the OpenFOAM output;
#   - a serial restart from the middle time is bitwise the uninterrupted
#     run; so is a 4-rank restart on the same decomposition;
#   - restarts on another number of ranks, re-decomposed, straight from the
#     file: 1 -> 3 (one rank never has a point) and 4 -> 2 ranks, within
#     1e-10 of the uninterrupted run (the halo sums in another order);
#   - materials are matched by name: a material inserted before the body's
#     in mpmProperties keeps its law; a renamed one is an error;
#   - a write that never completed (its .tmp left behind) is never read,
#     the error names the last complete time; startFrom latestTime on a
#     re-decomposed case (processors back at 0) refuses to restart from the
#     seeded points;
#   - coupled (underwater collapse): the fluid's U, p and alpha.fluid are in
#     the file and equal the time directory's fields; a restart (points from
#     the file, fluid from its time directory at 17 digits) is bitwise the
#     uninterrupted run.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/parallelCases"
compare() { "$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$@"; }
fields="U stress F C mass volume volume0 plasticStrain J material"
export OMP_NUM_THREADS=1

# prepare <dir> foam|hdf5
prepare()
{
    cp -r "$CASES/block3D" "$1"
    followMesh "$1"
    echo "pointOutput $2;" >> "$1/constant/mpmProperties"
    runApps "$1" blockMesh mpmSetParticles \
        || { echo "FAIL: setting up $1"; failures=$((failures + 1)); }
}
run() { (cd "$1" && shift && "$@" > log.run 2>&1) || { echo "FAIL: $* in $1"; tail -20 "$1/log.run"; failures=$((failures + 1)); }; }
startAt()
{
    foamDictionary -entry startFrom -set startTime "$1/system/controlDict" > /dev/null
    foamDictionary -entry startTime -set "$2" "$1/system/controlDict" > /dev/null
}

# worst <label> <a> <b> <time> <tolerance>: every point field within tol
within()
{
    local out worst same
    out=$(compare "$2" "$3" "$4" --fields $fields)
    same=$(echo "$out" | awk '$1=="ids"{print $3}')
    worst=$(echo "$out" | awk 'NR>2{if($2>m)m=$2}END{print m+0}')
    check "$1 (same points; worst relative difference over positions, $fields)" \
        "same == 1 and worst <= tol" same="${same:-0}" worst="${worst:-1}" tol="$5"
}

tEnd=0.8; tMid=0.4
foam="$SCRATCH/foam"; h5="$SCRATCH/hdf5"
prepare "$foam" foam
prepare "$h5" hdf5
run "$foam" mpmFoam
run "$h5" mpmFoam
grep -q "Material point output: hdf5" "$h5/log.run" || { echo "FAIL: hdf5 not selected"; failures=$((failures + 1)); }
n=$(ls "$h5"/HDF5/materialPoints_*.h5 2>/dev/null | wc -l)
check "one HDF5 file per write time (2), no lagrangian directories" \
    "n == 2 and lag == 0" n="$n" lag="$(ls -d "$h5"/[1-9]*/lagrangian "$h5"/0.[1-9]*/lagrangian 2>/dev/null | wc -l)"
within "HDF5 checkpoint equals the OpenFOAM-format cloud" "$foam" "$h5" "$tEnd" 1e-15

# Self-describing: units and a description on every point dataset
missing=0
for d in position $fields pointId; do
    h5dump -a "/materialPoints/$d/units" "$h5/HDF5/materialPoints_$tEnd.h5" > /dev/null 2>&1 || missing=$((missing + 1))
    h5dump -a "/materialPoints/$d/description" "$h5/HDF5/materialPoints_$tEnd.h5" > /dev/null 2>&1 || missing=$((missing + 1))
done
units=$(h5dump -a /materialPoints/stress/units "$h5/HDF5/materialPoints_$tEnd.h5" | grep -o '"Pa"')
check "h5dump: units and description on every point dataset, stress in Pa" \
    "missing == 0 and ok == 1" missing="$missing" ok="$([ "$units" = '"Pa"' ] && echo 1 || echo 0)"

# ParaView (XDMF Reader) against the OpenFOAM output of the same run
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
    xvfb-run -a pvbatch "$MPMFOAM_ROOT/tests/cases/hdf5/readXdmf.py" "$h5/materialPoints.xmf" "$SCRATCH/xdmf.npz" 2>&1 | grep "^XDMF" | sed 's/^/    /'
    read -r nT nP dS dA dU t0 stable <<< "$("$PY" - "$foam" "$tEnd" "$SCRATCH/xdmf.npz" <<'PYEOF'
import sys
import numpy as np, mpmPost
case, t, npz = sys.argv[1], sys.argv[2], sys.argv[3]
x = np.load(npz)
ids = mpmPost.read_cloud_field(case, t, "pointId").astype(int)
s = mpmPost.read_cloud_field(case, t, "stress")[np.argsort(ids)]     # xx xy xz yy yz zz
full = s[:, [0, 1, 2, 1, 3, 4, 2, 4, 5]]
pv = x["stress"][np.argsort(x["pointId"])]
dS = np.abs(pv - full).max()/np.abs(full).max()
a = mpmPost.read_internal_field(case, t, "alpha.solid")   # blockMesh: x fastest, as VTK
u = mpmPost.read_internal_field(case, t, "U.solid")
dA = np.abs(x["alpha.solid"] - a).max()/np.abs(a).max()
dU = np.abs(x["U.solid"] - u).max()/np.abs(u).max()
stable = int(all(n == "materialPoints,lattice" for n in x["blockNames"]))
print(len(x["times"]), x["nPoints"], dS, dA, dU, x["times"][0], stable)
PYEOF
)"
    check "ParaView's XDMF Reader: the seeded start and 2 writes, every point at the last" \
        "nT == 3 and nP == 1452" nT="${nT:-0}" nP="${nP:-0}"
    check "ParaView's XDMF series starts at t = 0 and names its blocks materialPoints and lattice at every time (issue 28, item 2)" \
        "t0 == 0 and s == 1" t0="${t0:-1}" s="${stable:-0}"
    check "ParaView's stress tensors equal OpenFOAM's symmTensor (component order)" \
        "d <= 1e-15" d="${dS:-1}"
    check "ParaView's alpha.solid and U.solid equal the volFields (cell order)" \
        "a <= 1e-15 and u <= 1e-15" a="${dA:-1}" u="${dU:-1}"
else
    echo "FAIL: pvbatch or xvfb-run missing"; failures=$((failures + 1))
fi

echo "=== restarts"
# Serial, from the middle checkpoint: bitwise
restart="$SCRATCH/restart"
cp -r "$h5" "$restart"
rm -rf "$restart/$tEnd" "$restart/HDF5/materialPoints_$tEnd.h5"
run "$restart" mpmFoam
grep -q "Reading the material points of .*materialPoints_$tMid.h5" "$restart/log.run" \
    || { echo "FAIL: the restart did not read the checkpoint"; failures=$((failures + 1)); }
within "serial restart from the HDF5 checkpoint equals the uninterrupted run bitwise" "$h5" "$restart" "$tEnd" 0

# Materials by name: insert one before the body's
renamed="$SCRATCH/insertedMaterial"
cp -r "$h5" "$renamed"
rm -rf "$renamed/$tEnd" "$renamed/HDF5/materialPoints_$tEnd.h5"
sed -i 's/materials { rubber/materials { stone { model linearElastic; rho 2500; E 1e7; nu 0.2; } rubber/' "$renamed/constant/mpmProperties"
run "$renamed" mpmFoam
fields="U stress F C mass volume" within "a material inserted before the body's in mpmProperties: the points keep their law (by name)" "$h5" "$renamed" "$tEnd" 0
sed -i 's/ rubber { model/ gum { model/' "$renamed/constant/mpmProperties"
rm -rf "$renamed/$tEnd" "$renamed/HDF5/materialPoints_$tEnd.h5"
expectFailure "a checkpoint's material missing from mpmProperties" \
    "has material 'rubber', which constant/mpmProperties does not define" runIn "$renamed" mpmFoam

# Parallel: 4 ranks; restart on 4 (same decomposition), 2 and 3
par4="$SCRATCH/par4"
prepare "$par4" hdf5
decomposeCase "$par4" 4 scotch
run "$par4" mpirun -np 4 mpmFoam -parallel
n=$(ls "$par4"/HDF5/materialPoints_*.h5 2>/dev/null | wc -l)
check "4 ranks write one file per write time" "n == 2" n="$n"
within "4 ranks (collective MPI-IO) against serial" "$h5" "$par4" "$tEnd" 1e-10

same4="$SCRATCH/same4"
cp -r "$par4" "$same4"
rm -rf "$same4"/processor*/"$tEnd" "$same4/HDF5/materialPoints_$tEnd.h5"
run "$same4" mpirun -np 4 mpmFoam -parallel
within "4 -> 4 ranks, same decomposition, latestTime: bitwise the uninterrupted run" "$par4" "$same4" "$tEnd" 0

to2="$SCRATCH/from4to2"
cp -r "$par4" "$to2"
rm -rf "$to2/HDF5/materialPoints_$tEnd.h5"
decomposeCase "$to2" 2 scotch
expectFailure "latestTime on a re-decomposed case (processors at 0, a checkpoint at $tMid)" \
    "startFrom latestTime gives time 0, but there is a later HDF5 checkpoint at time $tMid" \
    bash -c "cd '$to2' && mpirun -np 2 mpmFoam -parallel"
startAt "$to2" "$tMid"
run "$to2" mpirun -np 2 mpmFoam -parallel
within "4 -> 2 ranks, re-decomposed, restarted from the file, against the uninterrupted 4-rank run" "$par4" "$to2" "$tEnd" 1e-10
within "4 -> 2 ranks against serial" "$h5" "$to2" "$tEnd" 1e-10

# 1 -> 3: rank 2 owns the slab x > 13/14, where no point is at the restart
# (t = 0.4) nor at the end (t = 0.8, the write): it reads and writes with no
# points
to3="$SCRATCH/from1to3"
cp -r "$h5" "$to3"
rm -rf "$to3/$tEnd" "$to3/HDF5/materialPoints_$tEnd.h5"
manualSlices "$to3" "0 if i < 7 else (1 if i < 13 else 2)"
decomposeCase "$to3" 3 manual 'dataFile "cellDecomposition";'
startAt "$to3" "$tMid"
run "$to3" mpirun -np 3 mpmFoam -parallel
within "1 -> 3 ranks, restarted from the serial file, against the uninterrupted serial run" "$h5" "$to3" "$tEnd" 1e-10
first=$(grep "^MPM: points per processor" "$to3/log.run" | head -1 | grep -c "min 0,")
last=$(grep "^MPM: points per processor" "$to3/log.run" | tail -1 | grep -c "min 0,")
check "1 -> 3: a rank without points at the read and at the write took part in both" \
    "first == 1 and last == 1" first="$first" last="$last"

# A write that never completed: only the .tmp of the last time exists
killed="$SCRATCH/killedWrite"
cp -r "$h5" "$killed"
mv "$killed/HDF5/materialPoints_$tEnd.h5" "$killed/HDF5/materialPoints_$tEnd.h5.tmp"
truncate -s 1000 "$killed/HDF5/materialPoints_$tEnd.h5.tmp"
expectFailure "an interrupted write is never read; the error names the last complete time" \
    "No HDF5 checkpoint for time $tEnd.*|The last complete checkpoint is time $tMid" runIn "$killed" mpmFoam
msg=$(cd "$killed" && mpmFoam 2>&1)
echo "$msg" | grep -q "The last complete checkpoint is time $tMid: set 'startFrom startTime; startTime $tMid;'" \
    && echo "PASS: the advice names time $tMid and the controlDict entries" \
    || { echo "FAIL: no advice naming the last complete checkpoint"; echo "$msg" | tail -8; failures=$((failures + 1)); }
startAt "$killed" "$tMid"
run "$killed" mpmFoam
within "continuing from the last complete checkpoint equals the uninterrupted run" "$h5" "$killed" "$tEnd" 0

echo "=== coupled (underwater granular collapse)"
coupled=$(copyTutorial multiphase/underwaterGranularCollapse coupled)
followMesh "$coupled"
sed -i "s/^endTime .*/endTime 0.04;/; s/^writeInterval .*/writeInterval 0.02;/; s/^writePrecision .*/writePrecision 17;/" "$coupled/system/controlDict"
grep -q "^writePrecision" "$coupled/system/controlDict" || echo "writePrecision 17;" >> "$coupled/system/controlDict"
sed -i 's/tolerance 1e-10; relTol 0.01;/tolerance 1e-14; relTol 0;/; s/tolerance 1e-10; relTol 0;/tolerance 1e-14; relTol 0;/' "$coupled/system/fvSolution"
echo "pointOutput hdf5;" >> "$coupled/constant/mpmProperties"
runApps "$coupled" blockMesh mpmSetParticles
run "$coupled" mpmFoam
read -r nf dmax <<< "$("$PY" - "$coupled" 0.04 <<'PYEOF'
import sys
import h5py, numpy as np, mpmPost
case, t = sys.argv[1], sys.argv[2]
worst, n = 0.0, 0
with h5py.File("%s/HDF5/materialPoints_%s.h5" % (case, t), "r") as h5:
    for f in ("U", "p", "alpha.fluid", "alpha.solid", "U.solid"):
        if "lattice/" + f not in h5:
            continue
        n += 1
        a = h5["lattice/" + f][...]
        a = a.reshape(-1, 3) if a.ndim == 4 else a.reshape(-1)
        b = mpmPost.read_internal_field(case, t, f)
        worst = max(worst, np.abs(a - b.reshape(a.shape)).max()/max(np.abs(b).max(), 1e-300))
print(n, worst)
PYEOF
)"
check "coupled: the fluid's U, p, alpha.fluid and the solid's fields in the file equal the volFields" \
    "n == 5 and d <= 1e-15" n="${nf:-0}" d="${dmax:-1}"
crestart="$SCRATCH/coupledRestart"
cp -r "$coupled" "$crestart"
rm -rf "$crestart/0.04" "$crestart/HDF5/materialPoints_0.04.h5"
run "$crestart" mpmFoam
within "coupled restart from the HDF5 checkpoint (fluid from its 17-digit time directory) equals the uninterrupted run bitwise" "$coupled" "$crestart" 0.04 0

finish
