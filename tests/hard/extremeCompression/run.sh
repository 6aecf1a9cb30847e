#!/bin/bash
#------------------------------------------------------------------------------
# Extreme compression, J -> 0: an elastic disk (linearElastic, P-wave speed
# 1.16 m/s; tutorials/mpm/elasticDisks) thrown at a slip wall at 20 m/s,
# 17 x its wave speed, so that points are crushed through themselves:
#   - fixed step 2.5e-3 (Courant ~1.06, below the analysed limit of CBS/USF/
#     FLIP, 2.7, so not warned about): the run must stop with the message
#     naming the step, the point, its material and what to change;
#   - adaptive step (courant 0.2): handled (runs to the end, energy growth
#     <= 5e-2 of the available, as in highSpeedImpact) or stopped the same
#     way;
#   - in both, nothing written has J <= 0 or volume <= 0, and the shared
#     checks hold up to the stop.
#------------------------------------------------------------------------------
. "$(dirname "$0")/../hardFunctions"

for mode in fixed adaptive; do
    c=$(copyTutorial mpm/elasticDisks "$mode")
    cat > "$c/system/mpmSetParticlesDict" <<'DEOF'
FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }
regions
{
    disk
    {
        type cylinder; point1 (0.2 0.5 -1); point2 (0.2 0.5 2); radius 0.2;
        material disk; pointsPerCell (2 2 1);
        velocity { type uniform; value (-20 0 0); }
    }
}
DEOF
    [ "$mode" = fixed ] && sed -i 's/type        adaptive;/type        fixed;/' "$(props "$c")"
    sed -i 's/^deltaT .*/deltaT 0.0025;/; s/^endTime .*/endTime 0.1;/; s/^writeInterval .*/writeInterval 0.01;/' "$c/system/controlDict"
    sed -i 's/^logInterval .*/logInterval     1;/' "$(props "$c")"
    setUp "$c"
    solve "$c"
    if [ "$mode" = fixed ] || grep -q "FOAM FATAL" "$c/log.mpmFoam"; then
        checkRun "$c" --expect-stop "Stopping at time [0-9.e-]+, step [0-9]+: material point id [0-9]+ \(material disk\) is compressed to zero volume or below: J = -.*Reduce the time step"
    else
        checkRun "$c" --energy-growth 5e-2
    fi
    checkNothingInverted "$c" "$mode"
done
finish
