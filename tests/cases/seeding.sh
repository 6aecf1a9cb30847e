#!/bin/bash
#------------------------------------------------------------------------------
# mpmSetParticles fills searchableSurface regions: a sphere, a cylinder and a
# cube given as an STL (triSurfaceMesh) in a 3D box of 20^3 cells, 2 points
# per cell and direction. The seeded volume (sum of point volumes) must match
# the region's volume: exactly for the lattice-aligned STL cube, within the
# sub-lattice resolution (2 %) for the curved ones. Also the initial velocity
# and stress keywords reach the points.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c="$SCRATCH/seeding"
mkdir -p "$c/system" "$c/constant/triSurface"
cp "$MPMFOAM_ROOT/tutorials/mpm/axialBar/system/"{fvSchemes,fvSolution,controlDict} "$c/system/"
cat > "$c/system/blockMeshDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1) );
blocks ( hex (0 1 2 3 4 5 6 7) (20 20 20) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ( (0 3 2 1) (4 5 6 7) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) ); } );
DEOF
cat > "$c/constant/mpmProperties" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }
materials { m { model linearElastic; rho 1000; E 1e6; nu 0.3; } n { model linearElastic; rho 2000; E 1e6; nu 0.3; } }
DEOF
"$PY" - "$c/constant/triSurface/cube.stl" <<'PYEOF'
import sys
import numpy as np
import mpmPost
lo, hi = 0.55, 0.95
centre = np.full(3, 0.5*(lo + hi))
tris = []
for axis in range(3):
    for side in (lo, hi):
        a, b = [d for d in range(3) if d != axis]
        corners = []
        for u, w in ((lo, lo), (hi, lo), (hi, hi), (lo, hi)):
            p = np.zeros(3); p[axis] = side; p[a] = u; p[b] = w
            corners.append(p)
        for t in ((0, 1, 2), (0, 2, 3)):
            tri = [corners[i] for i in t]
            n = np.cross(tri[1] - tri[0], tri[2] - tri[0])
            if np.dot(n, tri[0] - centre) < 0:      # orient outwards
                tri = [tri[0], tri[2], tri[1]]
            tris.append(tri)
mpmPost.write_stl(sys.argv[1], tris, "cube")
PYEOF
seedCase()   # region entries -> total seeded volume printed by the python check
{
    cat > "$c/system/mpmSetParticlesDict" <<DEOF
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions { r { $1 material m; pointsPerCell 2; velocity { type uniform; value (1 2 3); } stress (-5 0 0 -5 0 -5); } }
DEOF
    rm -rf "$c/0"
    (cd "$c" && mpmSetParticles > log.mpmSetParticles.$2 2>&1) || { echo "FAIL: seeding $2"; tail -20 "$c/log.mpmSetParticles.$2"; }
    "$PY" -c "
import mpmPost, numpy as np
v = mpmPost.read_cloud_field('$c', '0', 'volume'); U = mpmPost.read_cloud_field('$c', '0', 'U'); s = mpmPost.read_cloud_field('$c', '0', 'stress')
ok = np.allclose(U, [1, 2, 3]) and np.allclose(s[:, 0], -5) and np.allclose(s[:, 5], -5)
print(v.sum(), 1 if ok else 0)"
}
runApps "$c" blockMesh || { echo "FAIL: blockMesh"; exit 1; }

read -r vol ok < <(seedCase "type sphere; centre (0.3 0.3 0.3); radius 0.2;" sphere)
check "sphere: seeded volume 4/3 pi r^3 within 2 %" "abs(v/(4/3*3.141592653589793*0.2**3) - 1) <= 0.02" v="$vol"
check "sphere: initial velocity and stress on every point" "ok == 1" ok="$ok"
read -r vol ok < <(seedCase "type cylinder; point1 (0.5 0.5 0.1); point2 (0.5 0.5 0.9); radius 0.25;" cylinder)
check "cylinder: seeded volume pi r^2 L within 2 %" "abs(v/(3.141592653589793*0.25**2*0.8) - 1) <= 0.02" v="$vol"
read -r vol ok < <(seedCase "type stl; file cube.stl;" stl)
check "STL cube: seeded volume exact" "abs(v/0.4**3 - 1) <= 1e-9" v="$vol"

# Overlapping regions: the later region wins, the earlier one's points in the
# overlap are removed. Box a (material m, rho 1000) of 0.125 m^3, box b
# (material n, rho 2000) of 0.125 m^3 over half of it: 0.0625*1000 +
# 0.125*2000 = 312.5 kg (375 if the overlap were seeded twice).
cat > "$c/system/mpmSetParticlesDict" <<DEOF
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    a { type box; min (0 0 0); max (0.5 0.5 0.5); material m; pointsPerCell 2; }
    b { type box; min (0.25 0 0); max (0.75 0.5 0.5); material n; pointsPerCell 2; }
}
DEOF
rm -rf "$c/0"
(cd "$c" && mpmSetParticles > log.mpmSetParticles.overlap 2>&1) || { echo "FAIL: seeding overlap"; tail -20 "$c/log.mpmSetParticles.overlap"; }
read -r mass n nIds <<< "$("$PY" -c "
import mpmPost
m = mpmPost.read_cloud_field('$c', '0', 'mass'); ids = mpmPost.read_cloud_field('$c', '0', 'pointId')
print(m.sum(), len(m), len(set(ids.astype(int).tolist())))")"
check "overlapping regions: the mass in the overlap is not doubled (312.5 kg, not 375)" "abs(mass - 312.5) <= 1e-9*312.5" mass="$mass"
check "overlapping regions: 8000 + 8000 - 4000 points, ids unique" "n == 12000 and ids == n" n="$n" ids="$nIds"
log="$c/log.mpmSetParticles.overlap"
if grep -q "replaces 4000 points (mass 62.5) of earlier regions where they overlap" "$log" \
    && grep -q "region a: 4000 points, mass 62.5" "$log" && grep -q "region b: 8000 points, mass 250" "$log" \
    && grep -q "material n: 8000 points, mass 250" "$log"; then
    echo "PASS: overlapping regions: the log gives what was replaced, and count and mass per region and material"
else
    echo "FAIL: overlap not reported in the log"; tail -12 "$log"; failures=$((failures + 1))
fi
# overlap add: a mixture, the earlier points are kept (0.125*1000 + 0.125*2000)
sed -i 's/material n; pointsPerCell 2; }/material n; pointsPerCell 2; overlap add; }/' "$c/system/mpmSetParticlesDict"
rm -rf "$c/0"
(cd "$c" && mpmSetParticles > log.mpmSetParticles.add 2>&1) || { echo "FAIL: seeding overlap add"; tail -20 "$c/log.mpmSetParticles.add"; }
mass=$("$PY" -c "import mpmPost; print(mpmPost.read_cloud_field('$c', '0', 'mass').sum())")
check "overlap add: a mixture keeps both regions' points (375 kg)" "abs(mass - 375) <= 1e-9*375" mass="$mass"
sed -i 's/overlap add;/overlap replaec;/' "$c/system/mpmSetParticlesDict"
rm -rf "$c/0"
expectFailure "unknown overlap rule" "Unknown overlap 'replaec'.*|Valid overlap choices: replace add" runIn "$c" mpmSetParticles
finish
