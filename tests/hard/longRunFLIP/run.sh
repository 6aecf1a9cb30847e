#!/bin/bash
#------------------------------------------------------------------------------
# Long run: 1e5 fixed steps of the vibrating axial bar (tutorials/mpm/axialBar,
# 25 cells, 2 points per cell) with pure FLIP (flipRatio 1), lumped mass,
# CBS, USL, Courant 0.1: 100 periods of the first mode (T = 4L/c = 10).
# FLIP does not damp,
# so round-off and grid-crossing noise could pile up over 1e5 steps.
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

c=$(copyTutorial mpm/axialBar longRun)
sed -i 's/^massMatrix .*/massMatrix      lumped;/; s/^flipRatio .*/flipRatio       1;/; s/^logInterval .*/logInterval     100;/; s/type        adaptive;/type        fixed;/' "$(props "$c")"
# dt = 0.01: Courant c dt/h = 10 x 0.01 / 1 = 0.1; 1e5 steps = t 1000 = 100 periods
sed -i 's/^deltaT .*/deltaT          0.01;/; s/^endTime .*/endTime         1000;/; s/^writeInterval .*/writeInterval   250;/' "$c/system/controlDict"
setUp "$c"
solve "$c"
# Bounds (README): the measured total swings within a period (KE and the
# stored energy are read at staggered instants; 0.43 % at Courant 0.1), so
# max (E - E0) <= 5e-3 E0; the mean over the last 10 periods (100) is not
# above the mean over the first 10 (no growth over 1e5 steps).
checkRun "$c" --energy-growth 5e-3 --energy-window 100
steps=$(logLast "$c/log.mpmFoam" 's/^MPM: step \([0-9]*\),.*/\1/p')
check "longRunFLIP: 1e5 steps were taken" "n == 100000" n="${steps:-0}"
finish
