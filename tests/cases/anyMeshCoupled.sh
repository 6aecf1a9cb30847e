#!/bin/bash
#------------------------------------------------------------------------------
# A fluid on a mesh that is not a uniform box (docs/geometry.md): the MPM
# lattice is its own and the exchange goes through the overlaps of the
# lattice cells with the fluid's cells, the same weights both ways.
#   1. Packed bed (multiphase/packedBed) on a fluid mesh of 40 cells graded
#      1:4 along the flow, lattice h = 2.5 mm: the pressure gradient inside
#      the bed equals Ergun's within 1 %, and the drop over the whole bed
#      equals the uniform 40-cell mesh's within 0.5 % (the smeared top edge
#      of the bed costs both the same O(h) deficit, packedBed.sh).
#   2. The grain volume the cells receive equals the points' to round-off
#      at every logged step (1e-12), in both cases; the overlaps cover every
#      lattice cell of the graded bed's box exactly (its 80 lattice cells,
#      |coverage - 1| <= 1e-12).
#   3. Settling suspension (multiphase/settlingSuspension) on 200 cells
#      graded 1:4 and 4:1, lattice h = 0.5 mm: the mean settling velocity of
#      the middle of the suspension (the points between its 30th and 70th
#      height percentiles, t = 0.25-0.6 s) equals Richardson-Zaki within
#      1 % (the Wen-Yu law's own steady value is 1.0043 of it) and the
#      uniform mesh's within 0.2 %.
#   4. The graded settling column on 2 ranks (simple, split along the
#      column: the lattice and the cells decomposed differently), HDF5
#      points, against serial with the pressure solver converged tight
#      (tolerance 1e-14): points (positions, U) within 1e-9 and the fluid's
#      U, p and alpha.solid within 2e-9 of the largest value
#      (parallelCoupled.sh: why not bitwise); the grain volume on the cells
#      exact at every logged step. Measured: the largest field difference
#      1.5e-9 of its field's largest value with the exact overlaps (1.0e-9
#      with the sampled ones before; U 7e-13 m/s of 7e-4 m/s, at the
#      column's top, p 4e-12, alpha.solid 3e-13; U was 8.3e-10 with the
#      gravity flux g & Sf, which the face gradient of g.x replaced:
#      round-off differences, not the decomposition's).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# grainVolume <case>: the largest |relative difference| of the logged
# "Grain volume: cells ..., points ..." lines, and their count
# --- packed bed ---------------------------------------------------------------
declare -A drop grad
for variant in uniform40 graded40; do
    c=$(copyTutorial multiphase/packedBed "bed-$variant")
    resizeColumn "$c" 0.2 40 0.1 > /dev/null
    if [ "$variant" = graded40 ]; then
        sed -i 's/simpleGrading (1 1 1)/simpleGrading (1 4 1)/' "$c/system/blockMeshDict"
        echo 'lattice { spacing 0.0025; }' >> "$(props "$c")"
    fi
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: packed bed $variant"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    (cd "$c" && postProcess -func writeCellCentres -latestTime > log.cellCentres 2>&1)
    (cd "$c" && "$PY" plotPackedBed.py --no-plot) | sed "s/^packedBed:/packedBed ($variant):/" | tee "$c/log.plot"
    grad[$variant]=$(sed -n 's/.*inside the bed .* ratio \([0-9.e+-]*\).*/\1/p' "$c/log.plot")
    drop[$variant]=$(sed -n 's/.*over the whole bed .* ratio \([0-9.e+-]*\).*/\1/p' "$c/log.plot")
    [ "$variant" = graded40 ] && bed="$c"
done
check "graded bed: Ergun gradient inside the bed within 1 % (${grad[graded40]:-nan})" "abs(r - 1) <= 0.01" r="${grad[graded40]:-nan}"
check "graded bed: whole-bed drop ${drop[graded40]:-nan} x Ergun L, as the uniform 40-cell mesh's ${drop[uniform40]:-nan} within 0.5 %" \
    "abs(g/u - 1) <= 0.005" g="${drop[graded40]:-nan}" u="${drop[uniform40]:-nan}"
if [ -n "${bed:-}" ]; then
    read -r dv nv <<< "$(grainVolume "$bed")"
    check "graded bed: grain volume on the cells = the points' at $nv logged steps (max $dv)" "d <= 1e-12 and n >= 50" d="$dv" n="$nv"
    # The overlaps are exact: every lattice cell inside the box is covered
    # to round-off (the tets sampled at h/2 before left most of them a few
    # % off, each point then renormalised over its stencil)
    read -r nf np <<< "$(sed -n 's/^ *lattice cells inside the mesh: \([0-9]*\) fully, \([0-9]*\) partly.*/\1 \2/p' "$bed/log.mpmFoam")"
    check "graded bed: every lattice cell covered by the box mesh to round-off (${nf:-?} fully, ${np:-?} partly)" \
        "f == 80 and p == 0" f="${nf:-0}" p="${np:--1}"
    coupledInvariants "$bed" 0.63
fi

# --- settling -------------------------------------------------------------------
declare -A ratio
for variant in uniform graded4 graded025; do
    c=$(copyTutorial multiphase/settlingSuspension "settling-$variant")
    case "$variant" in
        graded4)   sed -i 's/simpleGrading (1 1 1)/simpleGrading (1 4 1)/' "$c/system/blockMeshDict" ;;
        graded025) sed -i 's/simpleGrading (1 1 1)/simpleGrading (1 0.25 1)/' "$c/system/blockMeshDict" ;;
    esac
    [ "$variant" != uniform ] && echo 'lattice { spacing 0.0005; }' >> "$(props "$c")"
    runApps "$c" blockMesh mpmSetParticles mpmFoam \
        || { echo "FAIL: settling $variant"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    uRZ=$(cd "$c" && "$PY" plotSettling.py --no-plot 2>&1 | sed -n 's/.*Richardson-Zaki u = Ut alphaF^n = \([0-9.eE+-]*\) m\/s/\1/p')
    ratio[$variant]=$("$PY" - "$c" "$uRZ" <<'PYEOF'
import sys, numpy as np, mpmPost
case, uRZ = sys.argv[1], float(sys.argv[2])
vals = []
for t in mpmPost.times(case):
    if not 0.25 <= float(t) <= 0.6:
        continue
    y = mpmPost.read_positions(case, t)[:, 1]
    v = mpmPost.read_cloud_field(case, t, "U")[:, 1]
    lo, hi = np.percentile(y, 30), np.percentile(y, 70)
    vals.append(-v[(y > lo) & (y < hi)].mean())
print(np.mean(vals)/uRZ)
PYEOF
)
    echo "settling ($variant): middle of the suspension at ${ratio[$variant]} x Richardson-Zaki"
    if [ "$variant" != uniform ]; then
        read -r dv nv <<< "$(grainVolume "$c")"
        check "settling $variant: grain volume on the cells = the points' at $nv logged steps (max $dv)" "d <= 1e-12 and n >= 10" d="$dv" n="$nv"
    fi
done
for variant in graded4 graded025; do
    check "settling $variant: ${ratio[$variant]:-nan} x Richardson-Zaki, within 1 %, and within 0.2 % of the uniform mesh's ${ratio[uniform]:-nan}" \
        "abs(r - 1) <= 0.01 and abs(r/u - 1) <= 0.002" r="${ratio[$variant]:-nan}" u="${ratio[uniform]:-nan}"
done

# --- decomposed -------------------------------------------------------------------
tEnd=0.2
export OMP_NUM_THREADS=1
serial=$(gradedSettling settlingSerial "$tEnd")
(cd "$serial" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: serial"; tail -20 "$serial/log.mpmFoam"; failures=$((failures + 1)); }
par=$(gradedSettling settlingParallel "$tEnd")
decomposeCase "$par" 2 simple "n (1 2 1);"
(cd "$par" && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: decomposed"; tail -30 "$par/log.mpmFoam"; failures=$((failures + 1)); }
read -r ids w <<< "$(cloudDiff "$serial" "$par" "$tEnd" U)"
check "graded settling on 2 ranks: points within 1e-9 of serial ($w)" "i == 1 and w <= 1e-9" i="${ids:-0}" w="$w"
(cd "$par" && reconstructPar -latestTime -fields '(U p alpha.solid)' > log.reconstructPar 2>&1) \
    || { echo "FAIL: reconstructPar"; failures=$((failures + 1)); }
f=$(fluidDiff "$serial" "$par" "$tEnd")
check "graded settling on 2 ranks: fluid U, p, alpha.solid within 2e-9 of serial ($f)" "f <= 2e-9" f="${f:-1}"
read -r dv nv <<< "$(grainVolume "$par")"
check "graded settling on 2 ranks: grain volume on the cells = the points' at $nv logged steps (max $dv)" "d <= 1e-12 and n >= 10" d="$dv" n="$nv"
finish
