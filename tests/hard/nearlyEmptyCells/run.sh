#!/bin/bash
#------------------------------------------------------------------------------
# Nearly empty cells: the vibrating bar (tutorials/mpm/axialBar: 25 cells,
# 2 points per cell, CBS, here FLIP 1, USL, lumped mass) seeded with the
# sub-cell pattern shifted (mpmSetParticlesDict offset) so that its free end
# point sits 2 - eps cells from the next node: that node's mass is
# m_p eps^3/6, a fraction r of a typical node's (rho h). Runs with r = 1e-12
# (below the core's mass tolerance, 1e-10 of the mean point mass: the node
# gets no velocity) and r = 1e-9 (above it: its velocity is a ratio of tiny
# numbers), for 2 periods of the first mode, velocity amplitude a = 1e-5
# (the end moves 1.6e-5, < 0.1 eps, so the node stays that light).
#   - the set-up: alpha.solid of that node's cell over a full cell's is r
#     within a factor 2;
#   - no velocity spike: max |U| over every logged step <= 1.01 a (the
#     mode's amplitude; an exact solution never exceeds it);
#   - the shared checks, energy growth <= 1e-2 of E0.
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

a=1e-5
for r in 1e-12 1e-9; do
    c=$(copyTutorial mpm/axialBar "r$r")
    # m_p = rho h / 2 = 0.5, typical node mass rho h = 1: r = eps^3/12
    eps=$("$PY" -c "print((12*$r)**(1/3))")
    s=$("$PY" -c "print($eps - 0.25)")
    sed -i "s/^        pointsPerCell 2;/        pointsPerCell 2;\n        offset        ($s 0 0);/; s/amplitude  (0.1 0 0);/amplitude  ($a 0 0);/" "$c/system/mpmSetParticlesDict"
    sed -i 's/^massMatrix .*/massMatrix      lumped;/; s/^flipRatio .*/flipRatio       1;/; s/^logInterval .*/logInterval     1;/' "$(props "$c")"
    sed -i 's/^endTime .*/endTime         20;/; s/^writeInterval .*/writeInterval   1;/' "$c/system/controlDict"
    setUp "$c"
    solve "$c"
    checkRun "$c" --energy-growth 1e-2
    # the end node's cell: x in (26, 27), cell 26; a full cell: 12
    ratio=$("$PY" -c "
import mpmPost
a = mpmPost.read_internal_field('$c', '1', 'alpha.solid')
print(a[26]/a[12])")
    check "r = $r: the end node's alpha.solid / a full cell's = r within a factor 2 (eps $eps)" \
        "r/2 <= q <= 2*r" q="${ratio:-0}" r="$r"
    umax=$(sed -n 's/^MPM: step .*, max |U| \([^ ]*\)$/\1/p' "$c/log.mpmFoam" | sort -g | tail -1)
    check "r = $r: no velocity spike, max |U| <= 1.01 a over every step" "u <= 1.01*a" u="${umax:-1}" a="$a"
done
finish
