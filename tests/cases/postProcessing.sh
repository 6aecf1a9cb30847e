#!/bin/bash
#------------------------------------------------------------------------------
# What users do after a run: the material points must be readable by
# ParaView's built-in OpenFOAM reader (pvbatch) and foamToVTK, and survive
# decomposePar / reconstructPar (decomposed runs themselves: parallel.sh).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/granularColumnCollapse post)
sed -i "s/^endTime .*/endTime         0.05;/; s/^writeInterval .*/writeInterval   0.05;/" "$c/system/controlDict"
runApps "$c" blockMesh mpmSetParticles mpmFoam \
    || { echo "FAIL: run"; tail -20 "$c/log.mpmFoam"; exit 1; }
last=$(cd "$c" && ls -d [0-9]* | sort -g | tail -1)
n=$(sed -n 's/^Material points: \([0-9]*\).*/\1/p' "$c/log.mpmFoam")
echo "run: $n material points, last time $last"

# foamToVTK: the cloud as VTK polydata with the point fields
(cd "$c" && foamToVTK -latestTime > log.foamToVTK 2>&1)
vtk=$(find "$c/VTK" -path "*materialPoints*" \( -name "*.vtp" -o -name "*.vtk" \) | head -1)
if [ -n "$vtk" ]; then
    nv=$("$PY" - "$vtk" <<'PYEOF'
import re, sys
t = open(sys.argv[1], errors="replace").read()
m = re.search(r"NumberOfPoints=[\"'](\d+)", t) or re.search(r"POINTS\s+(\d+)", t)
print(m.group(1) if m else -1)
PYEOF
)
    check "foamToVTK writes every material point" "nv == n" nv="$nv" n="$n"
    grep -q "plasticStrain" "$vtk" && echo "PASS: foamToVTK carries plasticStrain" || { echo "FAIL: no plasticStrain in $vtk"; failures=$((failures + 1)); }
else
    echo "FAIL: foamToVTK wrote no materialPoints file"; failures=$((failures + 1))
fi

# ParaView's built-in reader (what paraFoam shows)
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
    touch "$c/case.foam"
    cat > "$c/readCloud.py" <<'PYEOF'
import sys
from paraview.simple import OpenFOAMReader, MergeBlocks, servermanager
r = OpenFOAMReader(FileName=sys.argv[1])
r.MeshRegions = ["lagrangian/materialPoints"]
r.Lagrangianpositionswithoutextradata = 1
r.UpdatePipeline(max(r.TimestepValues))
d = servermanager.Fetch(MergeBlocks(Input=r))
names = [d.GetPointData().GetArrayName(i) for i in range(d.GetPointData().GetNumberOfArrays())]
print("POINTS", d.GetNumberOfPoints(), "ARRAYS", " ".join(sorted(names)))
PYEOF
    out=$(cd "$c" && xvfb-run -a pvbatch readCloud.py "$c/case.foam" 2>&1 | grep "^POINTS")
    echo "pvbatch: $out"
    np=$(echo "$out" | awk '{print $2}')
    check "ParaView's OpenFOAM reader shows every material point" "np == n" np="${np:--1}" n="$n"
    echo "$out" | grep -q " stress" && echo "PASS: ParaView reads the stress field" || { echo "FAIL: stress not read"; failures=$((failures + 1)); }
else
    echo "FAIL: pvbatch/xvfb-run missing"; failures=$((failures + 1))
fi

# decomposePar / reconstructPar keep the cloud
cat > "$c/system/decomposeParDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method          scotch;
DEOF
(cd "$c" && decomposePar -latestTime > log.decomposePar 2>&1)
nd=$("$PY" -c "
import glob, os, mpmPost
ps = [p for p in glob.glob('$c/processor*') if os.path.isfile(p + '/$last/lagrangian/materialPoints/mass')]
print(sum(len(mpmPost.read_cloud_field(p, '$last', 'mass')) for p in ps))")
check "decomposePar distributes every point over the processors" "nd == n" nd="$nd" n="$n"
mv "$c/$last" "$c/$last.orig"
(cd "$c" && reconstructPar -latestTime > log.reconstructPar 2>&1)
d=$("$PY" -c "
import mpmPost, numpy as np
a = mpmPost.read_cloud_field('$c', '$last.orig', 'mass'); b = mpmPost.read_cloud_field('$c', '$last', 'mass')
print(abs(a.sum() - b.sum())/a.sum() if len(a) == len(b) else 1)")
check "reconstructPar restores the cloud (total mass)" "d <= 1e-12" d="$d"

# mpmPost.richardson, which the tutorials' convergence tables print
# (granularColumnCollapse/plotRunout.py, siloDischarge/plotDischarge.py):
# f(h) = 1 + C h^p on halved grids must give back p and the limit 1; a
# second-order term (f = 1 + h + 3 h^2) must leave the true limit inside
# the band; oscillating or growing changes must give no extrapolation.
r=$("$PY" -c "
import mpmPost
out = []
for p in (1.0, 2.0, 0.7):
    r = mpmPost.richardson([1 + 0.3*h**p for h in (0.4, 0.2, 0.1)])
    out += [abs(r['p'] - p), abs(r['limit'] - 1)]
r = mpmPost.richardson([1 + h + 3*h*h for h in (0.2, 0.1, 0.05, 0.025)])
inside = r['band'][0] <= 1 <= r['band'][1] and r['p_previous'] is not None
print(max(out), int(inside), mpmPost.richardson([1, 2, 1.5])['status'], mpmPost.richardson([1, 1.1, 1.3])['status'])")
read -r err inside osc div <<< "$r"
echo "richardson: $r"
check "richardson recovers the order and limit of f = 1 + C h^p (p = 1, 2, 0.7)" "e <= 1e-9" e="$err"
check "richardson's band holds the limit of f = 1 + h + 3 h^2" "i == 1" i="$inside"
[ "$osc $div" = "oscillating diverging" ] && echo "PASS: richardson refuses oscillating and growing changes" \
    || { echo "FAIL: richardson status '$osc $div'"; failures=$((failures + 1)); }

finish
