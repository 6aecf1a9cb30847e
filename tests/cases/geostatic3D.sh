#!/bin/bash
#------------------------------------------------------------------------------
# 3D verification: an elastic block (1 x 1 x 1 m, 10^3 cells, 8 points per
# cell) settles under gravity between slip walls (uniaxial strain). At rest
#     sigma_zz(z) = -rho g (H - z),   sigma_xx = sigma_yy = nu/(1-nu) sigma_zz.
# Checks the mean sigma_zz of the points against that line (3 %) and the
# lateral ratio (5 %), i.e. gravity, slip walls, 3D stencils and the stress
# update together. The block still rings in its first mode (period 4H/c =
# 0.116 s; PIC damps the low modes slowly), so the stress is averaged over
# the writes of the last period (every 0.01 s from 0.48 to 0.6 s).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c="$SCRATCH/geostatic"
mkdir -p "$c/system" "$c/constant"
cp "$MPMFOAM_ROOT/tutorials/mpm/axialBar/system/"{fvSchemes,fvSolution} "$c/system/"
cat > "$c/system/blockMeshDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1.2) (1 0 1.2) (1 1 1.2) (0 1 1.2) );
blocks ( hex (0 1 2 3 4 5 6 7) (10 10 12) simpleGrading (1 1 1) );
boundary
(
    floor { type wall; faces ( (0 3 2 1) ); }
    sides { type wall; faces ( (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (4 5 6 7) ); }
);
DEOF
cat > "$c/system/controlDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application mpmFoam; startFrom latestTime; startTime 0; stopAt endTime; endTime 0.6;
deltaT 1e-3; writeControl adjustableRunTime; writeInterval 0.01; writeFormat ascii;
writePrecision 10; timeFormat general; timePrecision 6; runTimeModifiable false;
DEOF
cat > "$c/system/mpmSetParticlesDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions { block { type box; min (0 0 0); max (1 1 1); material soil; pointsPerCell 2; } }
DEOF
setGravity "$c" "(0 0 -10)"
cat > "$c/constant/mpmProperties" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }
shapeFunction quadraticBSpline; transfer PICFLIP; flipRatio 0; stressUpdate USL;
logInterval 200;
timeStep { type adaptive; courant 0.5; }
materials { soil { model linearElastic; rho 1000; E 1e6; nu 0.25; } }
walls { floor { type slip; } sides { type slip; } }
DEOF
runApps "$c" blockMesh mpmSetParticles mpmFoam \
    || { echo "FAIL: run"; tail -20 "$c/log.mpmFoam"; exit 1; }
grep -A7 "MPM summary" "$c/log.mpmFoam"
read -r err ratio < <("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
import mpmPost
case = sys.argv[1]
ts = [t for t in mpmPost.times(case) if float(t) >= 0.48 - 1e-9]
x = np.mean([mpmPost.read_positions(case, t) for t in ts], axis=0)
s = np.mean([mpmPost.read_cloud_field(case, t, "stress") for t in ts], axis=0)   # xx xy xz yy yz zz
rho, g, nu = 1000.0, 10.0, 0.25
H = x[:, 2].max() + 0.25*0.1                          # top of the points' domain
exact = -rho*g*(H - x[:, 2])
inner = x[:, 2] < H - 0.2                            # away from the free top
err = np.abs(s[inner, 5] - exact[inner]).mean()/np.abs(exact[inner]).mean()
ratio = (s[inner, 0].sum() + s[inner, 3].sum())/(2*s[inner, 5].sum())/(nu/(1 - nu))
print(err, ratio)
PYEOF
)
echo "geostatic 3D: mean |sigma_zz - rho g (H - z)| / mean |rho g (H - z)| = $err; lateral ratio / (nu/(1-nu)) = $ratio"
check "vertical stress follows rho g (H - z) within 3 %" "e <= 0.03" e="$err"
check "lateral stress ratio nu/(1-nu) within 5 %" "abs(r - 1) <= 0.05" r="$ratio"
seededPoints "$c" "geostatic 3D: "
finish
