#!/bin/bash
#------------------------------------------------------------------------------
# Fixed bed: water through a bed of 1 mm beads (alpha.solid 0.6) resting on
# a porous plate. The pressure gradient inside the bed must equal Ergun's
# within 1 % (the drop over the whole bed is printed: the bed's top edge is
# smoothed over ~2 cells by the B-splines, which lowers it ~5 % at 40 cells).
# Also: solid mass conserved, fluid continuity at solver tolerance, and the
# fluid fraction never below 1 - alphaMax.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial multiphase/packedBed bed)
(cd "$c" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 && mpmFoam > log.mpmFoam 2>&1) \
    || { echo "FAIL: run"; tail -20 "$c/log.mpmFoam"; exit 1; }
(cd "$c" && "$PY" plotPackedBed.py --no-plot) | tee "$c/log.plot"
ratio=$(sed -n 's/.*inside the bed .* ratio \([0-9.e+-]*\).*/\1/p' "$c/log.plot")
check "Ergun gradient inside the bed within 1 %" "abs(r - 1) <= 0.01" r="$ratio"

coupledInvariants "$c" 0.63
finish
