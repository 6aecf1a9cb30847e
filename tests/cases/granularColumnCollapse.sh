#!/bin/bash
#------------------------------------------------------------------------------
# Case test: tutorials/mpm/granularColumnCollapse (2D Drucker-Prager sand
# column, a = h0/a0 = 2, collapsing on a friction floor).
#
# Runs blockMesh, mpmSetParticles, mpmFoam (full length, t = 1 s) and
# plotProfile.py --no-plot on a copy in a temporary directory and checks:
#   - mass: sum of the point masses, first vs last write, |dm|/m <= 1e-12
#   - every point inside the mesh bounding box
#   - collapse: final max point height < 0.8 h0, runout L_f - a0 > a0
#   - rest: final max |U| (summary.dat) < 0.02 sqrt(g h0)
#   - plasticity: max equivalent plastic strain > 0.1
#   - runout (L_f - a0)/a0 (front: 99.9 % of the mass behind it, plotProfile.py)
#     within [1.6, 3.6]: the empirical 2D laws give
#     1.2 a = 2.4 (a < 1.8) and 1.9 a^(2/3) = 3.0 (a > 2.8) at a = 2, with a
#     material-dependent scatter of the prefactors of some 20 %; the band is
#     2/3 of the lower law to 1.2 x the upper one. It rejects a frictionless
#     floor (the deposit reaches the right wall, ratio ~4) and a column
#     without plasticity (no collapse, ratio ~0).
#
# Env: MPM_CASE_SRC  case to copy instead of the tutorial (for checking that
#                    the test catches broken variants);
#      RUNOUT_BAND=0 report the runout without checking the band (a law
#                    known not to match Lube's law at this resolution);
#      KEEP_CASE=1   keep the temporary directory.
# Exit status non-zero on any failure. Takes ~20-40 s.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)"
root="$(cd "$here/../.." && pwd -P)"
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . "$root/etc/bashrc" || { echo "FAIL: cannot source $root/etc/bashrc"; exit 1; }
fi
src="${MPM_CASE_SRC:-$root/tutorials/mpm/granularColumnCollapse}"
py="${MPMFOAM_PYTHON:-/usr/bin/python3}"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/granularColumnCollapse.XXXXXX")" || exit 1
if [ "${KEEP_CASE:-0}" = 1 ]; then
    echo "case kept in $tmp"
else
    trap 'rm -rf "$tmp"' EXIT
fi
cp -r "$src"/. "$tmp"/
cd "$tmp" || exit 1
./Allclean >/dev/null 2>&1
rm -rf log.* [0-9]* postProcessing

for app in blockMesh mpmSetParticles mpmFoam; do
    if ! $app > log.$app 2>&1; then
        echo "FAIL: $app failed:"; tail -20 log.$app; exit 1
    fi
done
PYTHONPATH="$root/etc/python${PYTHONPATH:+:$PYTHONPATH}" "$py" plotProfile.py --no-plot \
    > log.plotProfile 2>&1 || { echo "FAIL: plotProfile.py"; cat log.plotProfile; exit 1; }
cat log.plotProfile

PYTHONPATH="$root/etc/python${PYTHONPATH:+:$PYTHONPATH}" "$py" - <<'EOF'
import os
import re
import sys

import numpy as np

import mpmPost

A0, H0, G = 0.2, 0.4, 9.81
fails = []


def check(ok, what):
    print("  %-4s %s" % ("ok" if ok else "FAIL", what))
    if not ok:
        fails.append(what)


ts = mpmPost.times(".")
t0, t1 = ts[0], ts[-1]
print("Checks (first time %s, last time %s):" % (t0, t1))

# Mass conservation
m0 = mpmPost.read_cloud_field(".", t0, "mass")
m1 = mpmPost.read_cloud_field(".", t1, "mass")
dm = abs(m1.sum() - m0.sum())/m0.sum()
check(len(m1) == len(m0) and dm <= 1e-12,
      "mass: %d -> %d points, total %.12g -> %.12g kg, |dm|/m = %.3g <= 1e-12"
      % (len(m0), len(m1), m0.sum(), m1.sum(), dm))

# Points inside the mesh bounding box
with open("constant/polyMesh/points") as f:
    txt = f.read()
body = txt[txt.index("}", txt.index("FoamFile")) + 1:]
num = r"([-+0-9.eE]+)"
pts = np.array(re.findall(r"\(\s*" + num + r"\s+" + num + r"\s+" + num + r"\s*\)", body), dtype=float)
lo, hi = pts.min(axis=0), pts.max(axis=0)
x0 = mpmPost.read_positions(".", t0)
x1 = mpmPost.read_positions(".", t1)
out = np.sum(np.any((x1 < lo) | (x1 > hi), axis=1))
check(out == 0, "points outside the box %s-%s at t = %s: %d" % (lo, hi, t1, out))

# Collapse and runout
dp = float(np.min(np.diff(np.unique(np.round(x0[:, 0], 10)))))
sys.path.insert(0, ".")
from plotProfile import mass_front   # the tutorial's front definition
Lf = mass_front(x1, m1)
ymax = x1[:, 1].max()
runout = (Lf - A0)/A0
check(ymax < 0.8*H0, "collapsed: final max point height %.4f m < 0.8 h0 = %.3f m" % (ymax, 0.8*H0))
check(Lf - A0 > A0, "spread: runout L_f - a0 = %.4f m > a0 = %.2f m" % (Lf - A0, A0))
a = H0/A0
band = "runout (L_f - a0)/a0 = %.3f in [1.6, 3.6] (empirical 1.2a = %.2f, 1.9a^(2/3) = %.2f)" \
    % (runout, 1.2*a, 1.9*a**(2/3))
if os.environ.get("RUNOUT_BAND", "1") == "1":
    check(1.6 <= runout <= 3.6, band)
else:
    print("  info %s: not checked (RUNOUT_BAND=0)" % band)
print("       final height H_f/a0 = %.3f (empirical ~a^(2/5) = %.2f; not checked)"
      % ((ymax + dp/2)/A0, a**0.4))

# At rest
s = mpmPost.read_summary(".")
uref = np.sqrt(G*H0)
check(s["maxU"][-1] < 0.02*uref,
      "at rest: final max |U| = %.3g m/s < 0.02 sqrt(g h0) = %.3g m/s (t = %g s)"
      % (s["maxU"][-1], 0.02*uref, s["time"][-1]))

# Plasticity
try:
    ep = mpmPost.read_cloud_field(".", t1, "plasticStrain")
    epmax = float(np.max(ep))
except (OSError, ValueError):
    epmax = 0.0
check(epmax > 0.1, "plastic flow: max equivalent plastic strain %.3g > 0.1" % epmax)

if fails:
    print("granularColumnCollapse: %d check(s) FAILED" % len(fails))
    sys.exit(1)
print("granularColumnCollapse: all checks passed")
EOF
