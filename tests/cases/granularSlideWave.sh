#!/bin/bash
#------------------------------------------------------------------------------
# The granularSlideWave tutorial (2D: a block of dry sand, 0.30 x 0.06 m,
# 28.7 kg/m, released at 2.5 m/s down a 45 degree friction slope into still
# water h = 0.2 m, fluidModel VOF with the default alphaContinuity
# corrected, twoWay), reduced to 0.65 s: the first crest has then wholly
# passed the first three gauges (X = x/h = 2.5 - 3.5; the tutorial's
# largest first crest is at X = 2.5, its value the same to the printed
# digits) and the wave front has reached eight. Same mesh and lattice (1 cm)
# as the tutorial, serial, run by the tutorial's own ./Allrun as its
# README says (its plotGranularSlideWave.py measures and draws); 33 s
# measured alone.
#
#  1. The run completes (t = 0.65).
#  2. Grains: every write holds each seeded id once with its seeded mass,
#     the count and mass mpmSetParticles logged (723 points, 0.2874 kg);
#     alpha.fluid >= 1 - alphaMax; the fluid's continuity error in the log
#     <= 1e-6 (measured 1.6e-7 at most, 2.3e-7 over the tutorial's 1.5 s:
#     the p_rgh solver's tolerance 1e-7 on this non-orthogonal mesh).
#  3. Water: the volume balance (V - V0 + out)/V0 in the log within 1e-5 at
#     every logged step (measured 1.7e-7, 4.3e-7 over the tutorial's
#     1.5 s); alpha.water within [0, 1] to 1e-4 (measured -5.2e-6 to 1
#     here, -2.4e-5 to 1 + 7e-7 over the tutorial's 1.5 s: MULES's own
#     undershoot, of order 1e-5; 1e-4 leaves a factor 4 on the tutorial;
#     the tutorial with d = 4 mm reaches -2.6e-4 at t = 0.6 s and would
#     fail it, README). The alpha flux correction (alphaContinuity
#     corrected, docs/coupling.md) keeps it there; with `alphaContinuity
#     conservative;` added to the "alpha.water.*" entry of system/fvSolution
#     (the default before) this case gave 2.10 by 0.65 s (tried, one-off,
#     20 s: water piled up in the slide's deposit) and fails this check.
#     The still water reads eta = 0 at every gauge at the start: |eta| <=
#     1e-7 m at the first record, after the first fluid step (measured
#     8e-9 m at X = 2.5, 0 with conservative; the correction's potential
#     flux is weighted by alpha.fluid/rho, as the pressure equation, so the
#     light air makes room for the slide. With the weight alpha.fluid only,
#     an intermediate build, that flux ran from the slide, still in the
#     air, to the open top through the water too: 4.0e-6 m at X = 2.5
#     after the first step, 0.06 mm by the impact; this bound catches
#     it). A wrong gauge volume or level would read millimetres.
#  4. The slide moves as a Coulomb block on the slope until the front
#     reaches the water: V_s = V0 + g (sin a - mu cos a) t_i within 0.5 %
#     (measured V_s = 2.548 m/s at t_i = 12.5 ms against 2.548; without
#     the wall friction the gain would be 1.5 % more, without gravity the
#     loss 1.9 %).
#  5. Against Heller & Hager (2010): P = F S^(1/2) M^(1/4) cos(6/7 a)^(1/2)
#     from the measured V_s, s, m_s (F 1.82, S 0.304, M 0.718: P 0.817),
#     predicted a_M = (4/9) P^(4/5) h = 7.56 cm; the largest first crest
#     over the gauges is within +-30 % of it (measured 8.36 cm at X = 2.5,
#     ratio 1.106; +-30 %: the scatter band the README discusses; 1.03
#     with alphaContinuity conservative, 1.30 with d = 4 mm instead of
#     0.5 mm, README). A oneWay run (the water not seeing the slide) makes
#     no wave and fails this (tried before the alpha flux correction:
#     eta <= 2.2 mm at the first gauges by 0.65 s, no crest found).
#  6. The wave travels: its front (eta first >= h/20 = 1 cm) reaches the
#     gauges one after the other (8 of them by 0.65 s), at a speed within
#     15 % of the solitary wave's sqrt(g (h + a_M)) with the measured a_M
#     (measured 1.658 m/s, ratio 0.994; 0.991 over the tutorial's 12
#     gauges; 1.03 on 5 mm cells before the alpha flux correction). The
#     first crest itself is broad, ragged and still forming here (its
#     celerity over the tutorial's gauges is 0.88 of sqrt(g (h + a)),
#     README): not checked.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial multiphase/granularSlideWave slide)
rm -f "$c"/0/C "$c"/0/Cx "$c"/0/Cy "$c"/0/Cz "$c"/0/alpha.water
sed -i 's/^endTime .*/endTime         0.65;/' "$c/system/controlDict"
# The tutorial's own Allrun, as its README tells users to run it
(cd "$c" && MPMFOAM_PYTHON="$PY" ./Allrun > log.Allrun 2>&1) \
    || { echo "FAIL: Allrun"; tail -20 "$c/log.Allrun"; failures=$((failures + 1)); finish; }
grep -q "fluidModel VOF" "$c/log.mpmFoam" || { echo "FAIL: not the VOF fluid"; failures=$((failures + 1)); }
plog=$(ls "$c"/log.python* 2>/dev/null | head -1)     # runApplication's log of "$MPMFOAM_PYTHON"
[ -n "$plog" ] || { echo "FAIL: no plot log"; tail -20 "$c"/log.*; failures=$((failures + 1)); finish; }
out=$(cat "$plog")
echo "$out" | sed 's/^/    /'
summary=$(echo "$out" | sed -n 's/^SUMMARY //p')
val() { echo "$summary" | tr ' ' '\n' | sed -n "s/^$1=//p"; }

# 1.
check "ran to the end (t = 0.65)" "t == 0.65" t="$(val tEnd)"
# 2.
coupledInvariants "$c" 0.63 1e-6
check "the analysis saw every write's cloud complete (ids and masses)" "e == 1" e="$(val exact)"
# 3.
check "water volume balance within 1e-5 at every logged step ($(val balance))" "b <= 1e-5" b="$(val balance)"
check "alpha.water within [0, 1] to 1e-4 ($(val alphaMin) to $(val alphaMax))" "lo >= -1e-4 and hi <= 1 + 1e-4" lo="$(val alphaMin)" hi="$(val alphaMax)"
check "still water at the $(val nGauges) gauges at the start: |eta| <= 1e-7 m ($(val eta0))" "e <= 1e-7 and n == 12" e="$(val eta0)" n="$(val nGauges)"
# 4.
check "impact velocity = Coulomb block on the slope, V0 + g (sin a - mu cos a) t_i, within 0.5 % (V_s $(val Vs) at t_i $(val tImpact))" \
    "abs(v/(2.5 + 9.81*(0.70710678 - 0.45*0.70710678)*ti) - 1) <= 0.005" v="$(val Vs)" ti="$(val tImpact)"
# 5.
check "largest first crest within +-30 % of Heller & Hager's a_M = (4/9) P^(4/5) h (P $(val P): $(val aMmeas) m against $(val aMpred) m)" \
    "abs(r - 1) <= 0.3" r="$(val ratio)"
# 6.
check "the wave front reaches the gauges in order ($(val nFront) reached)" "o == 1 and n >= 6" o="$(val frontOrdered)" n="$(val nFront)"
check "at a speed within 15 % of sqrt(g (h + a_M)) ($(val cFront) m/s, ratio $(val cFrontRatio))" "abs(r - 1) <= 0.15" r="$(val cFrontRatio)"
finish
