#!/bin/bash
#------------------------------------------------------------------------------
# Verification: two colliding elastic disks (Sulsky, Chen & Schreyer 1994),
# the tutorial as shipped (r = 0.2 at (0.2,0.2) and (0.8,0.8), v = +-(0.1,0.1),
# E = 1000, nu = 0.3, rho = 1000, h = 0.05, 2x2 points per cell, cubic
# B-splines, pure FLIP, USF), run to t = 3.5: contact from t ~ 1.16, maximum
# compression at t ~ 1.92, rebound complete by t ~ 2.7. About 1 s of CPU.
#
# Measured (this commit): KE0 = 2.6 exactly = seeded mass (416 points) x
# |v|^2 / 2, +3.45 % over the continuum disks; min KE 7.0 % of KE0; max
# elastic energy 75 % of KE0; total-energy drift 18.5 % at maximum
# compression, 0.48 % after the rebound; |Ucm| <= 9e-17.
#
#  1. Mass-correct seeding: KE0 = 0.5 m |v|^2 with m = rho x (number of
#     sub-lattice points inside the disks, counted here independently) x
#     (h/2)^2 x thickness, to 1e-9; the point count matches the seeder log.
#     Against the continuum disks (2 x pi r^2) the seeded area is 3.45 %
#     too large (208 lattice points per disk for pi 8^2 = 201.06: 8 points
#     per radius), so that comparison is held to 4 %, not 1 %; 1 % would
#     need 4x4 points per cell (+0.96 %) and prove nothing more.
#  2. Free flight: before the disks' stencils meet, KE stays KE0 to 1e-10
#     (a uniform velocity field makes no strain: partition of unity; walls
#     not felt: on the bare unit square, where each disk is tangent to two
#     mirror walls and held by its image, KE falls by 92 % in free flight
#     and this check, the drift (12.7 %) and the contact time all fail).
#  3. Energy after the rebound: max |E - E0| / E0 for t >= 2 t(KE min) -
#     t(contact) below 3 % (measured 0.48 %). Catches energy creation or
#     loss by the scheme: a sign error in the internal force makes the
#     contact unstable (energy grows without bound); a PIC share or a
#     dissipative update fails too (measured: USL 18.6 %, flipRatio
#     0.99 15.6 %, APIC 40 %; passing: MUSL 1.5 %, quadraticBSpline
#     0.86 %, consistent mass 0.73 %, courant 0.1 0.76 %).
#     The maximum drift over the whole run, 8.0 % at maximum compression,
#     is the hypoelastic law's complementary energy sigma:C^-1:sigma/2 J,
#     exact only for small strains, applied at log-strains up to 0.6 in the
#     contact zone (J down to 0.53); held to 12 %.
#  4. The disks interact: min KE < 70 % of KE0 and max elastic energy
#     > 10 % of KE0 (missing stress or no grid contact: they pass through
#     each other with KE = KE0 and no strain; with E = 1e-3 the run gives
#     min KE 99.99 % and elastic 1e-5 of KE0, and checks 3-4 fail).
#  5. Symmetry: total momentum is zero initially and MPM conserves it to
#     round-off when no wall is felt, so max |Ucm| < 1e-8 |v0| (measured
#     6e-16 |v0|): eight orders above round-off, far below what a lost
#     point (1/416 of the momentum of one disk) or a one-sided force would
#     leave.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

c=$(copyTutorial mpm/elasticDisks shipped)
rm -f "$c"/*.png
start=$(date +%s)
(cd "$c" && ./Allrun > log.Allrun 2>&1) || { echo "FAIL: Allrun"; cat "$c/log.Allrun"; failures=$((failures + 1)); finish; }
for l in log.blockMesh log.mpmSetParticles log.mpmFoam log.python3; do
    grep -q "^End\|wrote elasticDisks.png" "$c/$l" || { echo "FAIL: $l did not finish"; tail -20 "$c/$l"; failures=$((failures + 1)); }
done
[ -f "$c/elasticDisks.png" ] || { echo "FAIL: no elasticDisks.png"; failures=$((failures + 1)); }
echo "elasticDisks: Allrun took $(( $(date +%s) - start )) s"
[ "$failures" -eq 0 ] || finish

# The tutorial's own figures (name = value)
(cd "$c" && "$PY" plotEnergy.py --no-plot) | tee "$c/figures.txt"
fig() { sed -n "s/^elasticDisks: $1 = //p" "$c/figures.txt"; }

# Independent count of the seeded points and the free-flight KE
read -r nExpected keSeeded keFreeDev tFree <<< "$("$PY" - "$c" <<'PYEOF'
import sys
import numpy as np
case = sys.argv[1]
sys.path.insert(0, case)
import mpmPost
import plotEnergy as pe
h, thick = pe.block_mesh_extent(case)
x0 = -0.2                                   # mesh origin (blockMeshDict)
n = int(round(1.4/h))
s = x0 + (np.arange(2*n) + 0.5)*h/2         # 2x2 sub-lattice coordinates
X, Y = np.meshgrid(s, s)
N = sum(int(((X - cx)**2 + (Y - cy)**2 < pe.R**2).sum()) for cx, cy in pe.CENTRES)
m = N*pe.RHO*(h/2)**2*thick
ke_seeded = 0.5*m*float(pe.V0 @ pe.V0)
# Free flight: before the supports of the two disks can share a node. The
# cubic B-spline stencil is a square of half-width 2h, so along the diagonal
# line of centres each disk reaches 2h sqrt(2) beyond its edge.
gap = np.linalg.norm(pe.CENTRES[1] - pe.CENTRES[0]) - 2*pe.R
t_free = (gap - 4*np.sqrt(2)*h)/(2*np.linalg.norm(pe.V0))
S = mpmPost.read_summary(case)
sel = S["time"] <= t_free
dev = np.abs(S["kineticEnergy"][sel]/S["kineticEnergy"][0] - 1).max()
print(N, repr(ke_seeded), repr(dev), repr(t_free))
PYEOF
)"
nSeeded=$(sed -n 's/^ *\([0-9]*\) points of material disk.*/\1/p' "$c/log.mpmSetParticles" | paste -sd+ | bc)
echo "elasticDisks: seeded points $nSeeded (log), $nExpected (counted); KE0 of the seeded mass $keSeeded"

# 1. Mass-correct seeding
check "seeded point count matches the 2x2 sub-lattice inside the disks" "n == ne" n="$nSeeded" ne="$nExpected"
check "KE0 = 0.5 m_seeded |v|^2 to 1e-9" "abs(ke/ks - 1) < 1e-9" ke="$(fig KE0)" ks="$keSeeded"
check "KE0 within 4 % of the continuum 2 x rho pi r^2 |v|^2 / 2 (lattice area +3.45 %)" \
    "abs(err) < 0.04" err="$(fig KE0_error)"
# 2. Free flight
check "KE constant to 1e-10 in free flight (t <= $tFree)" "dev < 1e-10" dev="$keFreeDev"
# 3. Energy conservation
check "total-energy drift after the rebound < 3 %" "d < 0.03" d="$(fig drift_after_rebound)"
check "total-energy drift over the run < 12 % (complementary energy at large strain)" "d < 0.12" d="$(fig drift_max)"
check "the run reached the rebound phase" "tend > ta + 0.5" tend="$(fig t_end)" ta="$(fig t_after_rebound)"
# 4. Interaction
check "min KE < 70 % of KE0" "r < 0.7" r="$(fig KE_min_ratio)"
check "max elastic energy > 10 % of KE0" "r > 0.1" r="$(fig El_max_ratio)"
check "first contact after free flight, before continuum touch + 0.1" \
    "tf < tc < tcc + 0.1" tc="$(fig t_contact)" tf="$tFree" tcc="$(fig t_contact_continuum)"
# 5. Symmetry
check "max |Ucm| < 1e-8 |v0|" "u < 1e-8*v0" u="$(fig Ucm_max)" v0=0.14142135623730951

seededPoints "$c" "elasticDisks: "
finish
