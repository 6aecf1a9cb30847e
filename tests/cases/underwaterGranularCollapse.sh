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
(cd "$c" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1) \
    || { echo "FAIL: underwater run"; tail -20 "$c/log.mpmFoam"; exit 1; }
(cd "$d" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1) \
    || { echo "FAIL: dry run"; exit 1; }
(cd "$c" && "$PY" plotUnderwater.py . "$d" --no-plot) | tee "$c/log.plot"
ratio=$(sed -n 's/.*runout ratio = \([0-9.]*\).*/\1/p' "$c/log.plot")
read -r ke kemax m0 m1 amin hmax lf <<< "$("$PY" -c "
import mpmPost, numpy as np
s = mpmPost.read_summary('$c'); ts = mpmPost.times('$c')
m0 = mpmPost.read_cloud_field('$c', ts[0], 'mass').sum(); m1 = mpmPost.read_cloud_field('$c', ts[-1], 'mass').sum()
a = min(mpmPost.read_internal_field('$c', t, 'alpha.fluid').min() for t in mpmPost.field_times('$c', 'alpha.fluid'))
x = mpmPost.read_positions('$c', ts[-1])
print(s['kineticEnergy'][-1], s['kineticEnergy'].max(), m0, m1, a, x[:, 1].max(), x[:, 0].max())")"
cont=$(grep "continuity error" "$c/log.mpmFoam" | awk '{print $4}' | tr -d , | sort -g | tail -1)
echo "underwater/dry runout ratio $ratio"
check "at rest: final kinetic energy < 1e-3 of its peak" "ke < 1e-3*kemax" ke="$ke" kemax="$kemax"
check "collapsed: top below 0.8 h0 and front beyond 2 a0" "h < 0.32 and l > 0.4" h="$hmax" l="$lf"
check "solid mass conserved" "abs(m1 - m0) <= 1e-12*m0" m0="$m0" m1="$m1"
check "alpha.fluid >= 1 - alphaMax" "a >= 1 - 0.63 - 1e-12" a="$amin"
check "fluid continuity error at solver tolerance" "e <= 1e-10" e="$cont"
finish
