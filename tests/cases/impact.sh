#!/bin/bash
#------------------------------------------------------------------------------
# Extreme compression: an elastic disk (wave speed ~1 m/s) thrown at a wall at
# 20 m/s, with a fixed step just above the Courant limit (warned about, not
# an error). Points are crushed through themselves (J < 0) without a NaN;
# the run must stop naming the step, the point and its material, with exit
# code != 0, and no time on disk may hold J <= 0 or volume <= 0.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/elasticDisks impact)
cat > "$c/system/mpmSetParticlesDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    disk
    {
        type          cylinder;
        point1        (0.2 0.5 -1);
        point2        (0.2 0.5  2);
        radius        0.2;
        material      disk;
        pointsPerCell (2 2 1);
        velocity      { type uniform; value (-20 0 0); }
    }
}
DEOF
sed -i 's/type        adaptive;/type        fixed;/' "$(props "$c")"
sed -i 's/^deltaT .*/deltaT 0.0025;/; s/^endTime .*/endTime 0.1;/; s/^writeInterval .*/writeInterval 0.01;/' "$c/system/controlDict"
runApps "$c" blockMesh mpmSetParticles || { echo "FAIL: set-up"; exit 1; }

expectFailure "impact: a point at J <= 0 stops the run with step, point and material" \
    "Stopping at time [0-9.e-]+, step [0-9]+: material point id [0-9]+ \(material disk\) is compressed to zero volume or below: J = -" \
    runIn "$c" mpmFoam
expectFailure "impact: the message says what to do" "Reduce the time step" runIn "$c" mpmFoam

# Nothing non-physical on disk: every written J and volume > 0
read -r nTimes minJ minV <<< "$("$PY" - "$c" <<'PYEOF'
import sys, mpmPost
c = sys.argv[1]
ts = [t for t in mpmPost.times(c) if t != "0"]
J = min(mpmPost.read_cloud_field(c, t, "J").min() for t in ts) if ts else 1
V = min(mpmPost.read_cloud_field(c, t, "volume").min() for t in ts) if ts else 1
print(len(ts), J, V)
PYEOF
)"
check "impact: no J <= 0 or volume <= 0 written (times written: $nTimes)" "J > 0 and V > 0" J="$minJ" V="$minV"
finish
