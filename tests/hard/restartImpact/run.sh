#!/bin/bash
#------------------------------------------------------------------------------
# Restart in the middle of a violent event: the neo-Hookean disk of
# highSpeedImpact hitting the slip wall at 0.5 c (FLIP, USF, adaptive step),
# written at full precision (writePrecision 17). A run stopped at the write
# time in the middle of the contact (t = 0.345 s: contact from 0.17 s to
# ~0.5 s) and continued to the end must equal the uninterrupted run:
# positions, U, stress and F within 1e-12 relative (compareClouds.py), and
# the same number of steps; both runs pass the shared checks (energy growth
# <= 5e-2 of the available, as in highSpeedImpact).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c_p=$("$PY" -c "E, rho, nu = 1000., 1000., 0.3; print((E*(1 - nu)/((1 + nu)*(1 - 2*nu))/rho)**0.5)")
v=$("$PY" -c "print(0.5*$c_p)")
tEnd=$("$PY" -c "print(4*0.1/$v)")
tMid=$("$PY" -c "print($tEnd/2)")
ref=$(copyTutorial mpm/elasticDisks uninterrupted)
cat > "$ref/system/mpmSetParticlesDict" <<DEOF
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    disk
    {
        type cylinder; point1 (0.1 0.5 -1); point2 (0.1 0.5 2); radius 0.2;
        material disk; pointsPerCell (2 2 1);
        velocity { type uniform; value (-$v 0 0); }
    }
}
DEOF
sed -i "s/^endTime .*/endTime         $tEnd;/; s/^writeInterval .*/writeInterval   $tMid;/; s/^writePrecision .*/writePrecision  17;/; s/^timePrecision .*/timePrecision   12;/" "$ref/system/controlDict"
sed -i 's/model   linearElastic;/model   neoHookean;/' "$(props "$ref")"
setUp "$ref"
restarted="$SCRATCH/restarted"
cp -r "$ref" "$restarted"
solve "$ref"
checkRun "$ref" --energy-growth 5e-2

# The interrupted run: to tMid, then on to tEnd from what it wrote
sed -i "s/^endTime .*/endTime         $tMid;/" "$restarted/system/controlDict"
solve "$restarted" log.first
sed -i "s/^endTime .*/endTime         $tEnd;/" "$restarted/system/controlDict"
solve "$restarted"
first=$(grep -m1 "^Time = " "$restarted/log.mpmFoam" | awk '{print $3}')
check "the restart starts after the middle write time $tMid" "t > $tMid" t="${first:-0}"
checkRun "$restarted" --energy-growth 5e-2

lastTime() { ls -d "$1"/[0-9]* | xargs -n1 basename | sort -g | tail -1; }
tLast=$(lastTime "$ref"); tLastRes=$(lastTime "$restarted")
# The end time is summed from another start (tMid + steps): its name may
# differ in the last digit; compare the two end states
check "both runs end at the same time (round-off)" "abs(a - b) <= 1e-11" a="$tLast" b="$tLastRes"
[ "$tLastRes" != "$tLast" ] && mv "$restarted/$tLastRes" "$restarted/$tLast"
out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$ref" "$restarted" "$tLast" --fields U stress F)
echo "$out" | sed 's/^/    restarted vs uninterrupted: /'
worst=$(echo "$out" | awk 'NR>0 && $1!="count" && $1!="ids" {if ($2 > m) m = $2} END {print m + 0}')
same=$(echo "$out" | awk '$1=="ids"{print $3}')
steps() { sed -n 's/^MPM: step \([0-9]*\),.*/\1/p' "$1" | tail -1; }
nRef=$(steps "$ref/log.mpmFoam"); nRes=$(( $(steps "$restarted/log.first") + $(steps "$restarted/log.mpmFoam") ))
check "restart mid-impact: same points, positions/U/stress/F within 1e-12 of the uninterrupted run" \
    "s == 1 and w <= 1e-12" s="${same:-0}" w="${worst:-1}"
check "restart mid-impact: the same number of steps" "a == b" a="$nRef" b="$nRes"
finish
