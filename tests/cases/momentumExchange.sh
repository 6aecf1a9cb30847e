#!/bin/bash
#------------------------------------------------------------------------------
# Momentum exchange between the grains and the fluid (case
# tests/cases/periodicSuspensionCase): a 1D periodic water column, no walls,
# no gravity, forces (drag pressureGradient), twoWay. A slab of grains
# (alpha.solid 0.1, d = 0.2 mm, WenYu; relaxation time ~4 ms) is thrown up
# at 0.05 m/s; the water starts with the return flow that makes the mixture
# flux aS Us + aF U zero everywhere (a consistent incompressible state). Nothing
# acts from outside, so the mixture momentum
#     P = sum_points m v + rho_f sum_cells aF U V
# keeps its initial value, and both phases end at the common velocity P/M.
#
#  1. The grains and the water end at one velocity: at t = 0.2 s the grains'
#     mean velocity equals the water's within 2 % (measured 1.0 % with a
#     fluid step of 2e-3 s, 0.6 % with 5e-4 s). What is left is at the
#     slab's two edges, where alpha.solid drops from 0.1 to 0 over ~2 cells:
#     the cell-centred water velocity there carries a +-25 % dipole (it is
#     reconstructed from the momentum equation, as in DPMFoam; the face
#     fluxes are consistent), and the edge grains feel it.
#  2. Conservation. The exchange is split over the fluid step (the grains
#     sub-cycle against the fluid state of the step's start, the fluid sees
#     their mean; docs/coupling.md), so P is not conserved exactly: the
#     largest |P - P0|/P0 over the writes is 5.5 % with a fluid step of
#     2e-3 s (half a relaxation time) and 1.9 % with 5e-4 s. Most of it is
#     gained in the first fluid steps of the transient (O(dt): +5.5 %,
#     +2.9 %, +1.6 %, +0.9 % for 2e-3 ... 2.5e-4 s), the rest is a slow
#     drift from the edges above. Asserted: <= 7 % and <= 2.5 %, and the
#     error shrinks at least 2x for the 4x smaller step (measured 2.9x).
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

caseSrc="$MPMFOAM_ROOT/tests/cases/periodicSuspensionCase"
declare -A err
for dt in 2e-3 5e-4; do
    c="$SCRATCH/dt$dt"
    cp -r "$caseSrc" "$c"
    sed -i "s/^deltaT .*/deltaT          $dt;/" "$c/system/controlDict"
    runApps "$c" blockMesh mpmSetParticles \
        || { echo "FAIL: set-up ($dt)"; failures=$((failures + 1)); continue; }
    # The water's initial return flow U = -aS v0/(1 - aS), with aS the cubic
    # B-spline projection of the grain volumes (as the solver projects it)
    "$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
import mpmPost
c = sys.argv[1]
h, n, rho, v0 = 0.002, 50, 2500.0, 0.05
y = mpmPost.read_positions(c, "0")[:, 1]
m = mpmPost.read_cloud_field(c, "0", "mass")
def cbs(r):
    r = np.abs(r)
    return np.where(r < 1, 2/3 - r**2 + r**3/2, np.where(r < 2, (2 - r)**3/6, 0.0))
centres = (np.arange(n) + 0.5)*h
d = (y[:, None] - centres[None, :])/h
d = (d + n/2) % n - n/2                      # periodic distance in cells
aS = (cbs(d)*(m/rho)[:, None]).sum(axis=0)/h**3
U = -aS*v0/(1 - aS)
body = "\n".join("(0 %.15g 0)" % u for u in U)
p = c + "/0/U"
s = open(p).read().replace("internalField   uniform (0 0 0);",
                           "internalField   nonuniform List<vector> %d\n(\n%s\n);" % (n, body))
open(p, "w").write(s)
PYEOF
    (cd "$c" && mpmFoam > log.mpmFoam 2>&1) || { echo "FAIL: run ($dt)"; tail -20 "$c/log.mpmFoam"; failures=$((failures + 1)); continue; }
    read -r e slip <<< "$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
import mpmPost
c = sys.argv[1]
V, rhoF = 0.002**3, 1000.0
def momentum(t, aF):
    m = mpmPost.read_cloud_field(c, t, "mass")
    v = mpmPost.read_cloud_field(c, t, "U")[:, 1]
    U = mpmPost.read_internal_field(c, t, "U")[:, 1]
    return (m*v).sum() + rhoF*(aF*U*V).sum(), v.mean(), U
ts = mpmPost.times(c)
U0 = mpmPost.read_internal_field(c, "0", "U")[:, 1]
aS0 = -U0/(0.05 - U0)                        # from U0 = -aS v0/(1 - aS)
P0, _, _ = momentum("0", 1 - aS0)
errs = []
for t in ts[1:]:
    P, vs, U = momentum(t, mpmPost.read_internal_field(c, t, "alpha.fluid"))
    errs.append(abs(P - P0)/P0)
print(max(errs), abs(vs - U.mean())/abs(U.mean()))
PYEOF
)"
    echo "momentumExchange dt $dt: max |P - P0|/P0 = $e, final slip/velocity = $slip"
    check "dt $dt: grains and water end at one velocity (within 2 %)" "s <= 0.02" s="$slip"
    err[$dt]=$e
done
check "dt 2e-3: mixture momentum within 7 %" "e <= 0.07" e="${err[2e-3]:-nan}"
check "dt 5e-4: mixture momentum within 2.5 %" "e <= 0.025" e="${err[5e-4]:-nan}"
check "momentum error shrinks >= 2x for a 4x smaller fluid step" "a >= 2*b" a="${err[2e-3]:-nan}" b="${err[5e-4]:-nan}"
finish
