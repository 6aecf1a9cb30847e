#!/bin/bash
#------------------------------------------------------------------------------
# A mesh that is not a uniform box (docs/geometry.md): the MPM lattice is then
# its own, and the mesh's wall patches off the lattice box's sides are
# level-set walls.
#   * A graded mesh of the elasticDisks box with lattice { spacing 0.05; }
#     gives the uniform mesh's run to round-off (the same lattice, walls and
#     points): positions at every written time, and the seeded ids.
#   * A rotated mesh: a 3 x 1 m box turned by 25 degrees, its floor a
#     friction wall (mu = 0.3) as a level set, vertical gravity. An elastic
#     block on it slides at g (sin 25 - mu cos 25) within 2 %, and no point
#     ever leaves the mesh; seeding leaves out the points of a region that
#     reach past the mesh and logs how many.
#   * Decomposed, on 2 ranks with HDF5 point output, the rotated incline gives
#     the serial positions to 1e-10; with the lagrangian cloud, seeded
#     decomposed (decomposePar, mpmSetParticles -parallel): the seeded
#     points equal the serial seeding's and the reconstructed final cloud
#     the serial run's to 1e-10.
#   * An outlet off the lattice box's sides: the rotated incline, frictionless,
#     its downhill end an outlet patch: the block slides out through it,
#     every point and its mass is booked as leaving there (the open
#     boundaries' balance exact), and none crosses the floor meanwhile.
#   * snappyHexMesh around an STL pier (tests/cases/snappyPierCase: hex and
#     polyhedral cells, the pier a wall patch, the box's faces snapped off
#     the lattice's sides): an elastic block thrown at the pier at 3 m/s
#     (1/4 of its wave speed) bounces off it; no point comes closer to the
#     axis than the snapped surface (radius 0.1 m, its 48-facet STL
#     inscribed circle 0.0998 m), none is lost.
#   * A sand bed at rest around a snappyHexMesh pier in a channel
#     (tests/cases/pierBedCase), the box's faces on the lattice's sides
#     (spacing 0.01: they stay mirrored walls, the pier alone a level set)
#     and off them (0.0101: every patch a level set). For 0.01 s under
#     gravity no point beyond two cells of the pier moves more than 0.2 mm
#     (the bed's own settling: 6e-5 m), none within them more than
#     h^2/R = 4 mm (the tangent planes of a convex obstacle push points
#     outside it out by up to ~h^2/(2R): 1.4 and 2.7 mm measured). Before
#     the fix the first run crashed, and the second pushed points 4.7 cm:
#     the box's ghost nodes, outside the mesh hence inside its patches'
#     level set, gave planes to the points beside the mirrored faces.
#   * A lattice spacing too coarse for the mesh and one that is not positive
#     stop with a message; so does one that does not divide a periodic
#     length, naming spacings that do (the one it names runs); without a
#     spacing, the default is rounded to divide it. (A fluid on such a
#     mesh: anyMeshCoupled.sh.)
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

# --- graded against uniform --------------------------------------------------
u=$(copyTutorial mpm/elasticDisks uniform)
sed -i 's/^endTime .*/endTime 1.5;/; s/^writePrecision .*/writePrecision 17;/' "$u/system/controlDict"
g=$(copyTutorial mpm/elasticDisks graded)
cp "$u/system/controlDict" "$g/system/"
# Three blocks in x, graded towards the middle: 28 cells, not uniform
"$PY" - "$g/system/blockMeshDict" <<'PYEOF'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"blocks \(.*?\);", "blocks ( hex (0 1 2 3 4 5 6 7) ($nCells $nCells 1) simpleGrading (((0.3 0.4 2) (0.4 0.2 1) (0.3 0.4 0.5)) 1 1) );", s, flags=re.S)
open(p, "w").write(s)
PYEOF
printf 'lattice { spacing 0.05; }\n' >> "$(props "$g")"
runApps "$u" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: uniform run"; exit 1; }
runApps "$g" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: graded run"; tail -30 "$g/log.mpmFoam"; exit 1; }
grep -qE "MPM lattice: its own, spacing 0.05[0-9]* \(lattice spacing\)" "$g/log.mpmFoam"
check "graded mesh: the log says the lattice is its own, and why" "r == 0" r=$?
read -r d n <<< "$(samePositions "$u" "$g")"
check "graded mesh: positions equal the uniform mesh's at $n written times (max difference $d)" "d <= 1e-12 and n >= 4" d="$d" n="$n"

# --- a rotated mesh: an incline --------------------------------------------
r=$(copyTutorial mpm/elasticDisks rotated)
"$PY" - "$r" <<'PYEOF'
import math, sys
c = sys.argv[1]
th = math.radians(-25)
def rot(x, y):
    return (x*math.cos(th) - y*math.sin(th), x*math.sin(th) + y*math.cos(th))
v = [rot(0, 0), rot(3, 0), rot(3, 1), rot(0, 1)]
pts = " ".join("(%.12g %.12g %g)" % (x, y, z) for z in (0, 0.05) for x, y in v)
open(c + "/system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( %s );
blocks ( hex (0 1 2 3 4 5 6 7) (60 20 1) simpleGrading (1 1 1) );
boundary
(
    floor  { type wall; faces ( (0 1 5 4) ); }
    sides  { type wall; faces ( (0 4 7 3) (1 2 6 5) (3 7 6 2) ); }
    frontAndBack { type empty; faces ( (0 3 2 1) (4 5 6 7) ); }
);
""" % pts)
# The block: 0.4 x 0.2 m along the floor from 0.3 m, a rotated box; and a
# strip along the floor that reaches past the mesh's far end
e1 = rot(1, 0)
o = rot(0.3, 0)
open(c + "/system/mpmSetParticlesDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    block
    {
        type rotatedBox; span (0.4 0.2 1); origin (%.12g %.12g -0.5);
        e1 (%.12g %.12g 0); e3 (0 0 1);
        material disk; pointsPerCell (2 2 1);
    }
}
""" % (o[0], o[1], e1[0], e1[1]))
PYEOF
cat > "$(props "$r")" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }
shapeFunction   cubicBSpline;
transfer        APIC;
logInterval     20;
timeStep { type adaptive; courant 0.3; }
materials { disk { model linearElastic; rho 1000; E 1e6; nu 0.3; } }
walls
{
    floor { type friction; frictionCoefficient 0.3; }
    sides { type slip; }
}
EOF
setGravity "$r"
sed -i 's/^endTime .*/endTime 0.5;/; s/^writeInterval .*/writeInterval 0.1;/' "$r/system/controlDict"
runApps "$r" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: rotated run"; tail -30 "$r/log.mpmFoam"; exit 1; }
read -r acc out nt <<< "$("$PY" - "$r" <<'PYEOF'
import math, sys, numpy as np, mpmPost
c = sys.argv[1]
th = math.radians(25)
s = mpmPost.read_summary(c)
t, u = s["time"], s["Ux"]*math.cos(th) - s["Uy"]*math.sin(th)   # along the floor, downhill
k = (t >= 0.05) & (t <= 0.5)
a = np.polyfit(t[k], u[k], 1)[0]
# Points outside the rotated mesh at any written time: coordinates in the
# mesh's frame within [0, 3] x [0, 1]
worst, n = -1.0, 0
for tt in mpmPost.times(c):
    x = mpmPost.read_positions(c, tt)
    xm = x[:, 0]*math.cos(th) - x[:, 1]*math.sin(th)
    ym = x[:, 0]*math.sin(th) + x[:, 1]*math.cos(th)
    worst = max(worst, (-ym).max(), (xm - 3).max(), (-xm).max(), (ym - 1).max())
    n += 1
print(a/(9.81*(math.sin(th) - 0.3*math.cos(th))), worst, n)
PYEOF
)"
check "rotated mesh: the block slides at g (sin 25 - 0.3 cos 25) = 1.478 m/s2 (measured: $acc of it)" \
    "abs(a - 1) < 0.02" a="$acc"
check "rotated mesh: no point outside the mesh at $nt written times (furthest: $out m)" "o <= 1e-9 and n >= 5" o="$out" n="$nt"
grep -q "patch floor, 60 faces: friction" "$r/log.mpmFoam"
check "rotated mesh: the floor patch is a level-set friction wall in the log" "r == 0" r=$?

# An outlet at the incline's lower end, off the lattice box's sides
o=$(copyTutorial mpm/elasticDisks rotatedOutlet)
cp -r "$r/system" "$r/constant" "$o/"
rm -rf "$o/constant/polyMesh"
sed -i 's/    sides  { type wall; faces ( (0 4 7 3) (1 2 6 5) (3 7 6 2) ); }/    sides  { type wall; faces ( (0 4 7 3) (3 7 6 2) ); }\n    end    { type patch; faces ( (1 2 6 5) ); }/' "$o/system/blockMeshDict"
sed -i 's/    floor { type friction; frictionCoefficient 0.3; }/    floor { type slip; }\n    end   { type outlet; }/' "$(props "$o")"
sed -i 's/^endTime .*/endTime 1.6;/; s/^writeInterval .*/writeInterval 0.2;/' "$o/system/controlDict"
runApps "$o" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: outlet run"; tail -30 "$o/log.mpmFoam"; failures=$((failures + 1)); }
bal=$(grep "^    balance:" "$o/log.mpmFoam" | tail -1)
echo "    $bal"
read -r n0 out present merr <<< "$(echo "$bal" | sed -n 's/.*initial \([0-9]*\) .* out \([0-9]*\) .* present \([0-9]*\) .*mass error \([^;]*\);.*/\1 \2 \3 \4/p')"
check "outlet off the box: every point left through it ($out of $n0), the balance exact (mass error $merr)" \
    "o == n and p == 0 and n > 100 and abs(e) <= 1e-12" o="${out:--1}" n="${n0:-0}" p="${present:--1}" e="${merr:-1}"
grep -q "patch end, 20 faces: outlet" "$o/log.mpmFoam"
check "outlet off the box: a level-set outlet in the log" "r == 0" r=$?
below=$("$PY" - "$o" <<'PYEOF'
import math, sys, numpy as np, mpmPost
c = sys.argv[1]
th = math.radians(25)
worst = -1.0
for t in mpmPost.times(c):
    try:
        x = mpmPost.read_positions(c, t)
    except Exception:
        continue
    if len(x):
        worst = max(worst, (-(x[:, 0]*math.sin(th) + x[:, 1]*math.cos(th))).max())
print(worst)
PYEOF
)
check "outlet off the box: no point below the floor at any written time ($below)" "b <= 1e-9" b="$below"

# Seeding past the mesh's end: points outside the mesh are left out, counted
s=$(copyTutorial mpm/elasticDisks seedPast)
cp "$r/system/blockMeshDict" "$r/system/controlDict" "$s/system/"
cp "$(props "$r")" "$r/constant/g" "$s/constant/"
cat > "$s/system/mpmSetParticlesDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions { all { type box; min (0.05 -1.2 0); max (2.8 0.9 0.05); material disk; pointsPerCell (2 2 1); } }
EOF
runApps "$s" blockMesh mpmSetParticles || { echo "FAIL: seeding past the mesh"; tail -20 "$s/log.mpmSetParticles"; exit 1; }
left=$(sed -n 's/^ *left out \([0-9]*\) points outside the mesh/\1/p' "$s/log.mpmSetParticles")
read -r outside seeded <<< "$("$PY" - "$s" <<'PYEOF'
import math, sys, mpmPost
c = sys.argv[1]
th = math.radians(25)
x = mpmPost.read_positions(c, "0")
xm = x[:, 0]*math.cos(th) - x[:, 1]*math.sin(th)
ym = x[:, 0]*math.sin(th) + x[:, 1]*math.cos(th)
print(int(((xm < 0) | (xm > 3) | (ym < 0) | (ym > 1)).sum()), len(x))
PYEOF
)"
check "seeding: $left points outside the mesh left out, none written outside ($outside of $seeded)" \
    "left > 100 and outside == 0 and seeded > 1000" left="${left:-0}" outside="$outside" seeded="$seeded"

# --- snappyHexMesh ------------------------------------------------------------
sp="$SCRATCH/snappyPier"
cp -r "$MPMFOAM_ROOT/tests/cases/snappyPierCase" "$sp"
runApps "$sp" blockMesh || { echo "FAIL: blockMesh"; failures=$((failures + 1)); }
(cd "$sp" && snappyHexMesh -overwrite > log.snappyHexMesh 2>&1 && checkMesh > log.checkMesh 2>&1) \
    || { echo "FAIL: snappyHexMesh"; failures=$((failures + 1)); }
poly=$(sed -n 's/^ *polyhedra: *\([0-9]*\).*/\1/p' "$sp/log.checkMesh")
runApps "$sp" mpmSetParticles mpmFoam || { echo "FAIL: snappy pier run"; tail -20 "$sp/log.mpmFoam"; failures=$((failures + 1)); }
read -r rmin nmin nmax xhit xend <<< "$("$PY" - "$sp" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
r, n, xs = [], [], []
for t in mpmPost.times(c):
    x = mpmPost.read_positions(c, t)
    r.append(np.hypot(x[:, 0] - 0.6, x[:, 1] - 0.25).min())
    n.append(len(x))
    xs.append(x[:, 0].max())
print(min(r), min(n), max(n), max(xs), xs[-1])
PYEOF
)"
check "snappyHexMesh pier ($poly polyhedra): no point inside the pier (closest to its axis $rmin m)" \
    "p > 0 and r >= 0.0995" p="${poly:-0}" r="$rmin"
check "snappyHexMesh pier: the block reached the pier and bounced back (front $xhit, then $xend m), no point lost" \
    "h > 0.5 and e < h - 0.1 and a == b" h="$xhit" e="$xend" a="$nmin" b="$nmax"

# --- a bed at rest around a snappy pier: mirrored box faces beside a level set
for spacing in 0.01 0.0101; do
    pb="$SCRATCH/pierBed$spacing"
    cp -r "$MPMFOAM_ROOT/tests/cases/pierBedCase" "$pb"
    sed -i "s/spacing 0.01;/spacing $spacing;/" "$pb/constant/mpmProperties"
    runApps "$pb" blockMesh || { echo "FAIL: blockMesh"; failures=$((failures + 1)); }
    (cd "$pb" && snappyHexMesh -overwrite > log.snappyHexMesh 2>&1) || { echo "FAIL: snappyHexMesh"; failures=$((failures + 1)); }
    runApps "$pb" mpmSetParticles mpmFoam || { echo "FAIL: pier bed run ($spacing)"; tail -20 "$pb/log.mpmFoam"; failures=$((failures + 1)); }
    echo "pier bed, lattice spacing $spacing: $(grep -c "^    patch " "$pb/log.mpmFoam") patches as level sets"
    read -r far near same last <<< "$("$PY" - "$pb" <<'PYEOF'
import sys, numpy as np, mpmPost
c = sys.argv[1]
def byId(t):
    ids = mpmPost.read_cloud_field(c, t, "pointId").reshape(-1)
    o = np.argsort(ids)
    return ids[o], mpmPost.read_positions(c, t)[o]
i0, x0 = byId("0")
r = np.hypot(x0[:, 0] - 0.17, x0[:, 1] - 0.125)
far = near = 0.0
same = 1
for t in mpmPost.times(c)[1:]:
    i1, x1 = byId(t)
    if not np.array_equal(i0, i1):
        same = 0
        break
    d = np.abs(x1 - x0).max(axis=1)
    far, near = max(far, d[r > 0.045].max()), max(near, d[r <= 0.045].max())
print(far, near, same, mpmPost.times(c)[-1])
PYEOF
)"
    echo "    largest displacement: $far m beyond two cells of the pier, $near m within them (last time $last)"
    check "pier bed ($spacing): ran to t = 0.01 with every point" "t == 0.01 and s == 1" t="${last:-0}" s="${same:-0}"
    check "pier bed ($spacing): the bed away from the pier stays at rest (<= 0.2 mm)" "f <= 2e-4" f="${far:-1}"
    check "pier bed ($spacing): points beside the pier move <= h^2/R = 4 mm" "n <= 4e-3" n="${near:-1}"
done

# --- decomposed: the lattice's own decomposition ---------------------------
# The rotated incline with HDF5 point output, serial and on 2 ranks (scotch
# splits the mesh's cells; a lattice cell goes to the rank whose cell holds
# its centre): the same positions at the end
h=$(copyTutorial mpm/elasticDisks rotatedH5)
cp -r "$r/constant" "$r/system" "$h/"
cp -r "$r/0" "$h/"
rm -rf "$h"/0/lagrangian "$h"/0/uniform
echo "pointOutput hdf5;" >> "$(props "$h")"
sed -i 's/^endTime .*/endTime 0.2;/' "$h/system/controlDict"
hp=$(copyTutorial mpm/elasticDisks rotatedH5par)
cp -r "$h/constant" "$h/system" "$h/0" "$hp/"
runApps "$h" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: serial HDF5 run"; tail -20 "$h/log.mpmFoam"; failures=$((failures + 1)); }
runApps "$hp" blockMesh mpmSetParticles || { echo "FAIL: seeding"; failures=$((failures + 1)); }
decomposeCase "$hp" 2 scotch
(cd "$hp" && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: decomposed run"; tail -30 "$hp/log.mpmFoam"; failures=$((failures + 1)); }
read -r dmax np <<< "$("$PY" - "$h" "$hp" <<'PYEOF'
import sys, h5py, numpy as np
def final(c):
    with h5py.File(c + "/HDF5/materialPoints_0.2.h5", "r") as f:
        ids = f["materialPoints/pointId"][...].reshape(-1)
        return ids[np.argsort(ids)], f["materialPoints/position"][...][np.argsort(ids)]
ia, xa = final(sys.argv[1])
ib, xb = final(sys.argv[2])
print(np.abs(xa - xb).max() if np.array_equal(ia, ib) else 1e9, len(ia))
PYEOF
)"
check "2 ranks on the rotated mesh: final positions of $np points equal the serial run's (max difference $dmax)" \
    "d <= 1e-10" d="${dmax:-1}"
grep -q "MPM lattice decomposition: lattice cells per processor 2(" "$hp/log.mpmFoam"
check "the log gives the lattice's decomposition" "r == 0" r=$?
# The lagrangian cloud (pointOutput foam) on 2 ranks, seeded decomposed:
# decomposePar, then mpmSetParticles -parallel, then mpmFoam -parallel. A
# point lives on the rank of its lattice cell and is written on the rank of
# its mesh cell (cloud/meshCellSearch.H). The seeded cloud and the final one
# equal the serial run's, and reconstructPar gathers them.
f=$(copyTutorial mpm/elasticDisks rotatedFoamPar)
cp -r "$r/constant" "$r/system" "$f/"
rm -rf "$f/constant/polyMesh"
runApps "$f" blockMesh || { echo "FAIL: mesh"; failures=$((failures + 1)); }
# Split the block in two (blockMesh's 60 x 20 cells, x fastest: the cells
# below 0.5 m along the floor on processor 0), so that lattice cells, not
# rotated with the mesh, straddle the processors' boundary
"$PY" - "$f/constant/cellDecomposition" <<'PYEOF'
import sys
cells = [0 if i < 10 else 1 for j in range(20) for i in range(60)]
open(sys.argv[1], "w").write(
    "FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }\n"
    + "%d\n(\n%s\n)\n" % (len(cells), "\n".join(map(str, cells))))
PYEOF
decomposeCase "$f" 2 manual 'dataFile "cellDecomposition";'
(cd "$f" && mpirun -np 2 --oversubscribe mpmSetParticles -parallel > log.mpmSetParticles 2>&1) \
    || { echo "FAIL: decomposed seeding"; tail -20 "$f/log.mpmSetParticles"; failures=$((failures + 1)); }
seeded=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$r" "$f" 0 --fields U mass)
echo "$seeded" | sed 's/^/    seeded: /'
check "decomposed seeding on a mesh that is not a box: the serial seeding's points (same ids, positions and masses)" \
    "i == 1 and p == 0 and m == 0" i="$(echo "$seeded" | awk '$1=="ids"{print $3}')" \
    p="$(echo "$seeded" | awk '$1=="positions"{print $2}')" m="$(echo "$seeded" | awk '$1=="mass"{print $2}')"
nSerial=$(sed -n 's/^Writing \([0-9]*\) material points.*/\1/p' "$r/log.mpmSetParticles")
nPar=$(sed -n 's/^Writing \([0-9]*\) material points.*/\1/p' "$f/log.mpmSetParticles")
check "decomposed seeding: the logged count is the serial one ($nPar, $nSerial)" "a == b" a="${nPar:-0}" b="${nSerial:--1}"
nMoved=$(sed -n 's/^Material points: \([0-9]*\) written by the processor of their mesh cell.*/\1/p' "$f/log.mpmSetParticles" | tail -1)
check "decomposed seeding: points of one rank's lattice cells written by another rank ($nMoved)" "n > 0" n="${nMoved:-0}"
(cd "$f" && mpirun -np 2 --oversubscribe mpmFoam -parallel > log.mpmFoam 2>&1) \
    || { echo "FAIL: decomposed run, cloud output"; tail -30 "$f/log.mpmFoam"; failures=$((failures + 1)); }
(cd "$f" && reconstructPar -latestTime > log.reconstructPar 2>&1) \
    || { echo "FAIL: reconstructPar"; tail -20 "$f/log.reconstructPar"; failures=$((failures + 1)); }
final=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$r" "$f" 0.5 --fields U)
echo "$final" | sed 's/^/    final: /'
check "decomposed run with cloud output: the reconstructed cloud at 0.5 equals the serial run's (positions within 1e-10)" \
    "i == 1 and p <= 1e-10" i="$(echo "$final" | awk '$1=="ids"{print $3}')" p="$(echo "$final" | awk '$1=="positions"{print $2}')"
c=$(copyTutorial mpm/elasticDisks coarse)
cp "$g/system/blockMeshDict" "$c/system/"
printf 'lattice { spacing 2; }\n' >> "$(props "$c")"
runIn "$c" blockMesh > /dev/null 2>&1
expectFailure "lattice spacing too coarse for the mesh" \
    "at least 2 are needed for the ghost layers.*give a smaller lattice spacing" runIn "$c" mpmSetParticles
c=$(copyTutorial mpm/elasticDisks negative)
printf 'lattice { spacing -0.05; }\n' >> "$(props "$c")"
runIn "$c" blockMesh > /dev/null 2>&1
expectFailure "lattice spacing not positive" "Keyword spacing = -0.05 is out of range \(0, inf\)" runIn "$c" mpmSetParticles

# A periodic (cyclic) direction on a graded mesh: a spacing that does not
# divide the period names spacings that do, and the one it names runs
p=$(copyTutorial mpm/inclinedPlaneFlow periodic)
sed -i 's/simpleGrading (1 1 1)/simpleGrading (1 2 1)/' "$p/system/blockMeshDict"
sed -i 's/^endTime .*/endTime 0.002;/' "$p/system/controlDict"
printf 'lattice { spacing 0.0006; }\n' >> "$(props "$p")"
runApps "$p" blockMesh mpmSetParticles || { echo "FAIL: periodic set-up"; failures=$((failures + 1)); }
expectFailure "a spacing that does not divide the periodic length" \
    "The mesh is 0.002 long in direction 0: give a lattice spacing that divides it, e.g. lattice \{ spacing 0.0005; \} \(4 cells\) or 0.000666666+7 \(3 cells\)" \
    runIn "$p" mpmFoam
sed -i 's/^lattice .*/lattice { spacing 0.0006666666667; }/' "$(props "$p")"
rm -rf "$p"/0.0*
runApps "$p" mpmFoam
grep -q "downslope periodic" "$p/log.mpmFoam"
check "the spacing it names runs, the cyclic pair periodic" "r == 0" r=$?
# Without a spacing, the default (the mean cell size, here 0.000559 with 12
# rows) is rounded to divide the period, and said so
q=$(copyTutorial mpm/inclinedPlaneFlow periodicDefault)
sed -i 's/simpleGrading (1 1 1)/simpleGrading (1 2 1)/; s/^ny .*/ny      12;/' "$q/system/blockMeshDict"
sed -i 's/^endTime .*/endTime 0.002;/' "$q/system/controlDict"
runApps "$q" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: periodic default run"; tail -20 "$q/log.mpmFoam"; failures=$((failures + 1)); }
grep -qE "default spacing 0.00055[0-9]* rounded to 0.0005 to divide the periodic length 0.002 \(patch upslope, 4 cells\)" "$q/log.mpmFoam" \
    && grep -q "downslope periodic" "$q/log.mpmFoam"
check "no spacing on a periodic graded mesh: the default rounded to divide the period (0.0005), the run periodic" "r == 0" r=$?
finish
