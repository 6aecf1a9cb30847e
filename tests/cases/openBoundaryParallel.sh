#!/bin/bash
#------------------------------------------------------------------------------
# Open boundaries on 2 processors against serial: the outlet free fall and
# the inlet-to-outlet stream (tests/cases/openBoundaryCases), each
# decomposed across the flow (simple (1 2 1): the inlet on one processor,
# the outlet on the other, the material crossing between them) and along it
# (simple (2 1 1): every inlet layer and the outlet split between the two).
# Checked against the serial run:
#   - on every step, the points injected, removed per patch and present are
#     the same numbers (summed over processors), the masses within 1e-12;
#   - the balance closes on every step (count exact, mass to round-off);
#   - the clouds (ids, positions, velocities) equal serial to 1e-10 at a
#     written time with points in the domain.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

CASES="$MPMFOAM_ROOT/tests/cases/openBoundaryCases"
export OMP_NUM_THREADS=1

# tables <serial> <parallel> <patches...>: rows, differing counts, max mass difference
tables()
{
    "$PY" - "$@" <<'PYEOF'
import sys
import numpy as np, mpmPost
a, b, patches = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = badCount = 0
dm = 0.0
for name in patches + ["massBalance"]:
    s, p = mpmPost.read_open_boundary(a, name), mpmPost.read_open_boundary(b, name)
    if len(s["time"]) != len(p["time"]):
        badCount += 1; continue
    rows += len(s["time"])
    for k in s:
        if "Points" in k or k == "clamped":
            badCount += int((s[k] != p[k]).sum())
        elif "Mass" in k and k != "massError":
            dm = max(dm, np.abs(s[k] - p[k]).max()/max(np.abs(s[k]).max(), 1e-300))
bal = mpmPost.read_open_boundary(b, "massBalance")
bc = int((bal["presentPoints"] != bal["initialPoints"] + bal["injectedPoints"] - bal["removedPoints"]).sum())
bm = np.abs(bal["massError"]).max()/bal["initialMass"][0]
print(rows, badCount, dm, bc, bm)
PYEOF
}

for spec in "outletFall 0.16 bottom" "inletStream 0.6 top bottom"; do
    read -r case tCompare patches <<< "$spec"
    echo "=== $case"
    serial="$SCRATCH/$case.serial"
    cp -r "$CASES/$case" "$serial"
    runApps "$serial" blockMesh mpmSetParticles mpmFoam || { echo "FAIL: serial $case"; failures=$((failures + 1)); continue; }
    for split in "1 2 1" "2 1 1"; do
        par="$SCRATCH/$case.${split// /}"
        cp -r "$CASES/$case" "$par"
        runApps "$par" blockMesh mpmSetParticles \
            || { echo "FAIL: setting up $par"; failures=$((failures + 1)); continue; }
        decomposeCase "$par" 2 simple "n ($split);"
        (cd "$par" && mpirun -np 2 mpmFoam -parallel > log.mpmFoam 2>&1) \
            || { echo "FAIL: mpirun -np 2 mpmFoam ($case, $split)"; tail -20 "$par/log.mpmFoam"; failures=$((failures + 1)); continue; }
        read -r rows bad dm bc bm <<< "$(tables "$serial" "$par" $patches)"
        check "$case ($split): counts per patch and in the balance equal serial on every step ($rows rows)" \
            "rows > 500 and bad == 0" rows="$rows" bad="$bad"
        check "$case ($split): masses within 1e-12 of serial" "dm <= 1e-12" dm="$dm"
        check "$case ($split): balance closes on every step" "bc == 0 and bm <= 1e-13" bc="$bc" bm="$bm"
        out=$("$PY" "$MPMFOAM_ROOT/etc/python/compareClouds.py" "$serial" "$par" "$tCompare" --fields U)
        pos=$(echo "$out" | awk '$1=="positions"{print $2}')
        u=$(echo "$out" | awk '$1=="U"{print $2}')
        same=$(echo "$out" | awk '$1=="ids"{print $3}')
        n=$(echo "$out" | awk '$1=="count"{print $2}')
        check "$case ($split): cloud at t = $tCompare equals serial ($n points: ids, positions, U)" \
            "same == 1 and n > 0 and max(pos, u) <= 1e-10" same="${same:-0}" n="${n:-0}" pos="${pos:-1}" u="${u:-1}"
    done
done

finish
