#!/bin/bash
#------------------------------------------------------------------------------
# Parallel: the neo-Hookean disk of gridCrossing (cubic B-splines, FLIP,
# USL) skidding at 2.5 m/s along the floor of a periodic 2 m box, decomposed
# in 3 x-slabs of 0.67 m (simple (3 1 1)) and run on 3 ranks
# (mpirun -np 3 --oversubscribe) for 4 s: the 0.5 m disk crosses processor
# boundaries every ~0.27 s, through the periodic one too. Checked:
#   - every logged step's total count, id sum and mass checksum equal the
#     seeded cloud's (exact migration), and points migrated more than 3x
#     their number;
#   - the shared checks on the reconstructed case, energy growth <= 1e-2 of
#     the available (as gridCrossing, serial: 3.4e-3);
#   - the decomposed end state equals the serial run's to 1e-10 relative
#     (halo sums in another order: round-off).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

prepare()
{
    cp -r "$MPMFOAM_ROOT/tests/cases/parallelCases/periodic2D" "$1"
    sed -i "s/^shapeFunction .*/shapeFunction cubicBSpline;/; s/^transfer .*/transfer PICFLIP; flipRatio 1;/; s/^stressUpdate .*/stressUpdate USL;/" "$(props "$1")"
    sed -i 's/endTime 1.5;/endTime 4;/; s/writeInterval 0.75;/writeInterval 1;/' "$1/system/controlDict"
    setUp "$1"
}
serial="$SCRATCH/serial"; par="$SCRATCH/np3"
prepare "$serial"; prepare "$par"
solve "$serial"
read -r count idSum checksum <<< "$(cloudTotals "$par")"
decomposeCase "$par" 3 simple "n (3 1 1);"
(cd "$par" && timeout 300 mpirun -np 3 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1)
(cd "$par" && reconstructPar > log.reconstructPar 2>&1) || { echo "FAIL: reconstructPar"; failures=$((failures + 1)); }
checkConservation "3 ranks" "$par/log.mpmFoam" "$count" "$idSum" "$checksum" 100
migrated=$(grep "^MPM: points per processor" "$par/log.mpmFoam" | tail -1 | sed 's/.*migrated \([0-9]*\).*/\1/')
check "points crossed processor boundaries: migrations > 3 x points" "m > 3*n" m="${migrated:-0}" n="$count"
checkRun "$par" --energy-growth 1e-2
out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$serial" "$par" 4 --fields U stress F)
worst=$(echo "$out" | awk '$1!="count" && $1!="ids" {if ($2 > m) m = $2} END {print m + 0}')
same=$(echo "$out" | awk '$1=="ids"{print $3}')
check "3 ranks vs serial at t = 4: same points, positions/U/stress/F within 1e-10" \
    "s == 1 and w <= 1e-10" s="${same:-0}" w="${worst:-1}"
finish
