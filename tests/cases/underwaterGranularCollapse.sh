#!/bin/bash
#------------------------------------------------------------------------------
# Underwater granular collapse (two-way coupled, Drucker-Prager sand in
# water): the run completes without blow-up and comes to rest, the column
# collapses, solid mass is conserved, the fluid keeps continuity and never
# sees more than alphaMax of solid. The runout is compared with the dry case
# (printed, not asserted: there is no reference for this set-up; README).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial multiphase/underwaterGranularCollapse wet)
d=$(copyTutorial mpm/granularColumnCollapse dry)
runApps "$c" blockMesh mpmSetParticles mpmFoam \
    || { echo "FAIL: underwater run"; tail -20 "$c/log.mpmFoam"; exit 1; }
runApps "$d" blockMesh mpmSetParticles mpmFoam \
    || { echo "FAIL: dry run"; exit 1; }
(cd "$c" && "$PY" plotUnderwater.py . "$d" --no-plot) | tee "$c/log.plot"
ratio=$(sed -n 's/.*runout ratio = \([0-9.]*\).*/\1/p' "$c/log.plot")
read -r ke kemax hmax lf <<< "$("$PY" -c "
import mpmPost
s = mpmPost.read_summary('$c'); x = mpmPost.read_positions('$c', mpmPost.times('$c')[-1])
print(s['kineticEnergy'][-1], s['kineticEnergy'].max(), x[:, 1].max(), x[:, 0].max())")"
echo "underwater/dry runout ratio $ratio"
check "at rest: final kinetic energy < 1e-3 of its peak" "ke < 1e-3*kemax" ke="$ke" kemax="$kemax"
check "collapsed: top below 0.8 h0 and front beyond 2 a0" "h < 0.32 and l > 0.4" h="$hmax" l="$lf"
coupledInvariants "$c" 0.63
finish
