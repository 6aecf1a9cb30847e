#!/bin/bash
#------------------------------------------------------------------------------
# Points leaving through an outlet: the quasi-2D silo of
# tutorials/mpm/siloDischarge (coarse, as tests/cases/siloDischarge.sh: 0.6 m
# wide, filled to 0.8 m, cells of 0.02 m, a 0.2 m slot in the floor, an
# outlet), Drucker-Prager sand, 1 s: 2278 of 4800 points leave, the rest
# flows at up to ~2 m/s past the slot's corners. Checked (shared checker):
#   - the count and mass at every write time: seeded - removed, from the
#     solver's ledger (postProcessing/openBoundaries/*/massBalance.dat),
#     exact (the cloud's summed mass to 1e-12: measured 1.1e-13); each
#     remaining point keeps its seeded mass;
#   - energy: the flow only dissipates, and removal takes the leaving
#     points' energy with them: growth <= 1e-3 of the available;
#   - no NaN/inf, the run completes; points did leave (removed > 10 % of
#     the seeded).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c=$(copyTutorial mpm/siloDischarge silo)
rm -rf "$c/runs"
(
    cd "$c" || exit 1
    "$PY" -m slotMesh --width 0.6 --height 0.84 --slot 0.2 --cell 0.02
    foamDictionary -entry endTime -set 1 system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 0.25 system/controlDict > /dev/null
    foamDictionary -entry writeFormat -set ascii system/controlDict > /dev/null   # checkRun reads ASCII
    foamDictionary -entry regions.fill.max -set "(0.6 0.8 0.02)" system/mpmSetParticlesDict > /dev/null
)
setUp "$c"
solve "$c"
checkRun "$c" --energy-growth 1e-3
removed=$(figure "$c" removed --energy-growth 1e30)
seeded=$(figure "$c" points --energy-growth 1e30)
check "points left through the outlet: removed > 10 % of the seeded" "r > 0.1*n" r="${removed:-0}" n="${seeded:-1}"
finish
