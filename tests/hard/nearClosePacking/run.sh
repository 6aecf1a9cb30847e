#!/bin/bash
#------------------------------------------------------------------------------
# Near close packing: the sand bed of tutorials/multiphase/jetScour (2D
# tank 0.3 x 0.2 m, water jet 1.5 m/s through a 3 cm slot, twoWay,
# Drucker-Prager sand with Gidaspow drag) seeded at solid fraction 0.64,
# 0.01 above alphaMax 0.63, for 0.4 s, while the jet scours it. (Seeded at
# 0.62 the bed never went above 0.6203: the jet loosens it, so the cap is
# exercised by an over-packed bed.) The fluid must see the bed capped at
# alphaMax everywhere, in every step's equations and written field, and
# stay stable in a bed with 37 % fluid. Bounds:
#   - 1 - alpha.fluid <= alphaMax in every written field (the cap), and the
#     raw lattice alpha.solid does exceed alphaMax (measured 0.6403; the
#     capped cells are logged: 13 lines);
#   - the shared checks; energy: the grains' kinetic + stored + potential
#     energy grows by at most the jet's mechanical energy inflow rho U^3 A t
#     (kinetic 1/2 rho U^2 plus at most the stagnation pressure, through
#     A = 0.03 m x 5 mm over 0.4 s: 0.20 J; measured: no growth at all,
#     the bed settles).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c=$(copyTutorial multiphase/jetScour bed)
sed -i 's/solidFraction 0.6;/solidFraction 0.64;/' "$c/system/mpmSetParticlesDict"
sed -i 's/^endTime .*/endTime         0.4;/; s/^writeInterval .*/writeInterval   0.1;/' "$c/system/controlDict"
setUp "$c"
solve "$c"
jet=$("$PY" -c "print(1000*1.5**3*0.03*0.005*0.4)")
checkRun "$c" --alpha-max 0.63 --energy-growth 0 --energy-source "$jet"
raw=$(figure "$c" alphaSolidRaw --alpha-max 0.63)
check "the bed was pushed past close packing: raw alpha.solid max > alphaMax 0.63" "r > 0.63" r="${raw:-0}"
finish
