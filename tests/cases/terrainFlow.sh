#!/bin/bash
#------------------------------------------------------------------------------
# The terrainFlow tutorial (sand down an STL valley, decomposed, HDF5 output)
# through its own Allrun, shortened to t = 0.4 s: checkTerrain.py finds no
# point below the terrain beyond the concave-surface bound, and the count,
# ids and mass equal the seeded cloud's at every write time. Then its
# ./Allclean leaves nothing of the run.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/terrainFlow terrainFlow)
sed -i 's/^endTime .*/endTime 0.4;/' "$c/system/controlDict"
"$c/Allrun" > "$c/log.Allrun" 2>&1 || { echo "FAIL: Allrun"; tail -30 "$c/log.Allrun"; exit 1; }
log="$c/log.python3.checkTerrain"
grep -q "^nothing leaked: True" "$log"
check "terrainFlow: nothing leaked ($(grep '^lowest point' "$log"))" "r == 0" r=$?
read -r left <<< "$(sed -n 's/^Obstacle terrain: left out \([0-9]*\) points inside it/\1/p' "$c/log.mpmSetParticles")"
check "terrainFlow: seeding left out the points inside the terrain ($left)" "n > 1000" n="${left:-0}"
n=$(ls "$c"/HDF5/materialPoints_*.h5 | wc -l)
check "terrainFlow: one HDF5 file per write time ($n)" "n == 4" n="$n"
[ -f "$c/terrainFlow.png" ]
check "terrainFlow: the picture is written" "r == 0" r=$?
# ./Allclean, as its README says, leaves the set-up only
"$c/Allclean" > /dev/null 2>&1
left=$(cd "$c" && ls -d HDF5 processor* [0-9]*.[0-9]* materialPoints.xmf log.* terrainFlow.png uniform \
    constant/triSurface/terrain.stl constant/polyMesh 2>/dev/null | wc -l)
check "terrainFlow: ./Allclean removes every output ($left left)" "n == 0" n="$left"
finish
