#!/bin/bash
#------------------------------------------------------------------------------
# Bad input gets a clear error naming the file/keyword and the valid choices,
# never a crash, a hang or silently written NaN. Each case breaks one thing
# in a copy of the axialBar tutorial and asserts the message.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseTestFunctions"

seededCopy mpm/axialBar

c=$(freshCopy unknownModel)
sed -i 's/model   linearElastic;/model   linearElastik;/' "$(props "$c")"
expectFailure "unknown model" "Unknown model 'linearElastik'" runIn "$c" mpmFoam
expectFailure "unknown model lists valid models" "Valid models: linearElastic, neoHookean, newtonianFluid, druckerPrager, muIRheology, dilute" runIn "$c" mpmFoam
expectFailure "unknown model names the file" "constant/mpmProperties" runIn "$c" mpmFoam
expectFailure "unknown model suggests the closest" "Unknown model 'linearElastik' for material bar; did you mean 'linearElastic'\\?" runIn "$c" mpmFoam

c=$(freshCopy modelCase)
sed -i 's/model   linearElastic;/model   LinearElastic;/' "$(props "$c")"
expectFailure "a model differing only in case is suggested" "Unknown model 'LinearElastic' for material bar; did you mean 'linearElastic'\\?" runIn "$c" mpmFoam

c=$(freshCopy missingCoefficient)
sed -i '/^        E       100;/d' "$(props "$c")"
expectFailure "missing coefficient" "Missing coefficient E for material bar \(model linearElastic\).*valid range \(0, inf\)" runIn "$c" mpmFoam

c=$(freshCopy negativeCoefficient)
sed -i 's/^        E       100;/        E       -100;/' "$(props "$c")"
expectFailure "negative coefficient" "Coefficient E = -100 of material bar \(model linearElastic\) is out of range \(0, inf\)" runIn "$c" mpmFoam

c=$(freshCopy poissonRange)
sed -i 's/^        nu      0;/        nu      0.6;/' "$(props "$c")"
expectFailure "Poisson ratio out of range" "Coefficient nu = 0.6 .* out of range \[0, 0.5\)" runIn "$c" mpmFoam

c=$(freshCopy unknownShape)
sed -i 's/^shapeFunction .*/shapeFunction   cubic;/' "$(props "$c")"
expectFailure "unknown shape function" "Unknown shapeFunction 'cubic'" runIn "$c" mpmFoam
expectFailure "shape function choices" "Valid shapeFunction choices: linearHat quadraticBSpline cubicBSpline" runIn "$c" mpmFoam

c=$(freshCopy shapeCase)
sed -i 's/^shapeFunction .*/shapeFunction   CubicBSpline;/' "$(props "$c")"
expectFailure "a choice differing only in case is suggested" "Unknown shapeFunction 'CubicBSpline'; did you mean 'cubicBSpline'\\?" runIn "$c" mpmFoam

c=$(freshCopy unknownBackend)
echo "backend gpu;" >> "$(props "$c")"
expectFailure "unknown backend" "Unknown backend 'gpu'" runIn "$c" mpmFoam
expectFailure "backend choices" "Valid backend choices: serial openmp cuda" runIn "$c" mpmFoam

# cuda from a build without CUDA, or on a machine without a GPU: the reason,
# before anything is seeded or written
c=$(freshCopy cudaUnavailable)
echo "backend cuda;" >> "$(props "$c")"
expectFailure "cuda unavailable: the reason" "backend cuda cannot run: (this build has no CUDA back-end|.*GPU)" runIn "$c" mpmFoam
expectFailure "cuda unavailable: the usable back-ends" "Valid backends here: serial openmp" runIn "$c" mpmFoam

c=$(freshCopy unknownWall)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type sticky; }/' "$(props "$c")"
expectFailure "unknown wall type" "Valid type choices: noSlip slip friction periodic" runIn "$c" mpmFoam

c=$(freshCopy frictionWithoutCoefficient)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type friction; }/' "$(props "$c")"
expectFailure "friction wall without coefficient" "Missing keyword frictionCoefficient for the friction wall fixedEnd" runIn "$c" mpmFoam

# A friction coefficient on a wall of another type would be ignored
c=$(freshCopy coefficientOnSlipWall)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type slip; frictionCoefficient 0.3; }/' "$(props "$c")"
expectFailure "friction coefficient on a slip wall" "The wall fixedEnd is slip: frictionCoefficient needs type friction" runIn "$c" mpmFoam

# Strict dictionaries: an unknown keyword (here a misspelling) is an error
# naming the file, the keyword and the closest valid one, never ignored.
c=$(freshCopy misspeltTopLevel)
sed -i 's/^logInterval /logInteval  /' "$(props "$c")"
expectFailure "misspelt mpmProperties keyword: did you mean" "Unknown keyword 'logInteval' in mpmProperties; did you mean 'logInterval'\?" runIn "$c" mpmFoam
expectFailure "misspelt mpmProperties keyword: file and line" "file: .*constant/mpmProperties at line [0-9]+" runIn "$c" mpmFoam
expectFailure "misspelt mpmProperties keyword: valid keywords" "Valid keywords: shapeFunction transfer flipRatio .* timeStep lattice materials walls obstacles coupling pointOutput" runIn "$c" mpmFoam

c=$(freshCopy unknownTopLevel)
sed -i 's/^logInterval .*/colour blue;/' "$(props "$c")"
expectFailure "unknown keyword, nothing close: no suggestion" "Unknown keyword 'colour' in mpmProperties$" runIn "$c" mpmFoam

c=$(freshCopy misspeltTimeStep)
sed -i 's/courant     0.1;/courrant    0.1;/' "$(props "$c")"
expectFailure "misspelt timeStep keyword" "Unknown keyword 'courrant' in timeStep; did you mean 'courant'\?" runIn "$c" mpmFoam
expectFailure "misspelt timeStep keyword names the file" "file: .*constant/mpmProperties.timeStep at line" runIn "$c" mpmFoam

c=$(freshCopy timeStepNotDict)
sed -i '/^timeStep/,/^}/d' "$(props "$c")"
echo "timeStep fixed;" >> "$(props "$c")"
expectFailure "timeStep that is not a dictionary" "Keyword timeStep must be a sub-dictionary timeStep \{ ... \}" runIn "$c" mpmFoam

c=$(freshCopy misspeltCoefficient)
sed -i 's/^        nu      0;/        Nu      0;/' "$(props "$c")"
expectFailure "misspelt material coefficient" "Unknown keyword 'Nu' in material bar \(model linearElastic\); did you mean 'nu'\?" runIn "$c" mpmFoam
expectFailure "misspelt coefficient lists the law's keywords" "Valid keywords: model rho E nu drag" runIn "$c" mpmFoam
expectFailure "misspelt coefficient names the file (seeding too)" "file: .*constant/mpmProperties.materials.bar at line" runIn "$c" mpmSetParticles

c=$(freshCopy misspeltDruckerPrager)
sed -i 's/model   linearElastic;/model   druckerPrager; phi 30; pis 5;/' "$(props "$c")"
expectFailure "misspelt optional coefficient of another law" "Unknown keyword 'pis' in material bar \(model druckerPrager\); did you mean 'psi'\?" runIn "$c" mpmFoam

c=$(freshCopy materialNotDict)
sed -i '/^materials$/,/^{/ s/^{/{\n    steel linearElastic;/' "$(props "$c")"
expectFailure "material that is not a dictionary" "Entry 'steel' of materials \(one sub-dictionary per material\) is not a dictionary" runIn "$c" mpmFoam

c=$(freshCopy misspeltWallKeyword)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd { type friction; frictionCoeficient 0.5; }/' "$(props "$c")"
expectFailure "misspelt wall keyword" "Unknown keyword 'frictionCoeficient' in wall fixedEnd; did you mean 'frictionCoefficient'\?" runIn "$c" mpmFoam

c=$(freshCopy wallNamesNoPatch)
sed -i 's/fixedEnd { type noSlip; }/fixedEnds { type slip; }/' "$(props "$c")"
expectFailure "walls entry naming no patch" "walls entry 'fixedEnds' matches no patch of the mesh; did you mean 'fixedEnd'\?" runIn "$c" mpmFoam
expectFailure "walls entry naming no patch lists the patches" "Patches of the mesh: fixedEnd farEnd sides" runIn "$c" mpmFoam

c=$(freshCopy wallRegexNoPatch)
sed -i 's/fixedEnd { type noSlip; }/"(left|right)" { type slip; }/' "$(props "$c")"
expectFailure "walls regex matching no patch" "walls entry '\(left\|right\)' matches no patch of the mesh$" runIn "$c" mpmFoam

c=$(freshCopy wallNotDict)
sed -i 's/fixedEnd { type noSlip; }/fixedEnd slip;/' "$(props "$c")"
expectFailure "walls entry that is not a dictionary" "Entry 'fixedEnd' of walls \(one sub-dictionary per patch\) is not a dictionary" runIn "$c" mpmFoam

# What OpenFOAM expands (#include, regular-expression keywords that match a
# valid keyword) and the FoamFile header are not unknown keywords.
c=$(freshCopy includeAndRegex)
sed -i 's/^logInterval .*/#include "logControls"/; s/^        E       100;/        "(E|Young)" 100;/' "$(props "$c")"
echo 'logInterval 100;' > "$c/constant/logControls"
sed -i 's/^endTime .*/endTime 0.5;/' "$c/system/controlDict"
if out=$(runIn "$c" mpmFoam 2>&1) && echo "$out" | grep -q "logInterval 100$"; then
    echo "PASS: #include and a matching regular-expression keyword are accepted"
else
    echo "FAIL: #include or a regular-expression keyword rejected"; echo "$out" | tail -20; failures=$((failures + 1))
fi

c=$(freshCopy misspeltRegionKeyword)
sed -i 's/pointsPerCell 2;/pointsPerCell 2;\n        ofset         (0.1 0 0);/' "$c/system/mpmSetParticlesDict"
expectFailure "misspelt region keyword" "Unknown keyword 'ofset' in region bar \(type box\); did you mean 'offset'\?" runIn "$c" mpmSetParticles
expectFailure "misspelt region keyword names the file" "file: .*system/mpmSetParticlesDict.regions.bar at line" runIn "$c" mpmSetParticles

c=$(freshCopy misspeltVelocityKeyword)
sed -i 's/type       sine;/type       sine;\n            phse       0.5;/' "$c/system/mpmSetParticlesDict"
expectFailure "misspelt velocity keyword" "Unknown keyword 'phse' in velocity \(type sine\); did you mean 'phase'\?" runIn "$c" mpmSetParticles

c=$(freshCopy misspeltSeedTopLevel)
sed -i 's/^regions$/Regions/' "$c/system/mpmSetParticlesDict"
expectFailure "misspelt mpmSetParticlesDict keyword" "Unknown keyword 'Regions' in mpmSetParticlesDict; did you mean 'regions'\?" runIn "$c" mpmSetParticles

# A graded mesh runs on a lattice of its own (tests/cases/anyMesh.sh); a
# lattice spacing that is not a number is refused
c=$(freshCopy latticeSpacingWord)
printf 'lattice { spacing fine; }\n' >> "$(props "$c")"
expectFailure "lattice spacing not a number" "spacing" runIn "$c" mpmFoam
c=$(freshCopy latticeUnknownKeyword)
printf 'lattice { spacin 0.1; }\n' >> "$(props "$c")"
expectFailure "misspelt lattice keyword" "Unknown keyword 'spacin' in lattice; did you mean 'spacing'\\?" runIn "$c" mpmFoam

c=$(freshCopy seededOutside)
sed -i 's/max           (25 1 1);/max           (40 1 1);/' "$c/system/mpmSetParticlesDict"
expectFailure "region outside the mesh" "reaches outside the mesh .*points would be seeded outside the mesh" runIn "$c" mpmSetParticles

c=$(freshCopy notSeeded)
rm -rf "$c/0/lagrangian"
expectFailure "no material points" "No material points in" runIn "$c" mpmFoam

expectFailure "no material points: what to do" "Seed them with mpmSetParticles" runIn "$c" mpmFoam

# A zero or negative fixed step would never advance the time (a hang with
# writeControl timeStep, a division by zero with adjustableRunTime).
c=$(freshCopy zeroFixedStep)
sed -i 's/type        adaptive;/type        fixed;/' "$(props "$c")"
sed -i 's/^deltaT .*/deltaT          0;/' "$c/system/controlDict"
expectFailure "zero fixed time step" "Keyword deltaT = 0 is out of range \(0, inf\) \(the fixed MPM step, timeStep \{ type fixed; \}\)" runIn "$c" mpmFoam
expectFailure "zero fixed time step names controlDict" "file: .*system/controlDict" runIn "$c" mpmFoam
sed -i 's/^deltaT .*/deltaT          -0.01;/; s/^writeControl .*/writeControl timeStep;/; s/^writeInterval .*/writeInterval 10;/' "$c/system/controlDict"
expectFailure "negative fixed time step (writeControl timeStep)" "Keyword deltaT = -0.01 is out of range \(0, inf\)" runIn "$c" mpmFoam

# mpmSetParticles in a case that has run (startFrom latestTime selects the
# run's last time) would replace that time's points: refused unless asked.
c=$(freshCopy seedAfterRun)
sed -i 's/^endTime .*/endTime 1;/; s/^writeInterval .*/writeInterval 1;/' "$c/system/controlDict"
runIn "$c" mpmFoam > "$c/log.mpmFoam" 2>&1
sum1=$(cksum < "$c/1/lagrangian/materialPoints/U")
expectFailure "mpmSetParticles over a run's results" "Time 1 holds the results of a run \(after controlDict startTime 0; mpmFoam fields alpha.solid U.solid\)" runIn "$c" mpmSetParticles
expectFailure "mpmSetParticles over a run's results: what to do" "remove the later times \(foamListTimes -rm\).*mpmSetParticles -overwrite" runIn "$c" mpmSetParticles
check "mpmSetParticles refused: the run's points are untouched" "same == 1" same="$([ "$sum1" = "$(cksum < "$c/1/lagrangian/materialPoints/U")" ] && echo 1 || echo 0)"
if runIn "$c" mpmSetParticles -overwrite > "$c/log.overwrite" 2>&1 && [ "$sum1" != "$(cksum < "$c/1/lagrangian/materialPoints/U")" ]; then
    echo "PASS: mpmSetParticles -overwrite replaces the points"
else
    echo "FAIL: mpmSetParticles -overwrite"; tail -5 "$c/log.overwrite"; failures=$((failures + 1))
fi

c=$(freshCopy nanDuringRun)
# A fixed step ten times the stability limit: the bar blows up to inf/NaN.
sed -i 's/type        adaptive;/type        fixed;/' "$(props "$c")"
sed -i 's/^deltaT .*/deltaT          1;/; s/^writeInterval .*/writeInterval   1;/; s/^endTime .*/endTime 100000;/' "$c/system/controlDict"
# It stops at the first non-physical state: a point crushed through itself
# (J <= 0, compressionCheck) or, failing that, a non-finite value (the core).
expectFailure "blow-up names step and point" "non-finite .* at step [0-9]+ in material point id [0-9]+|step [0-9]+: material point id [0-9]+ \(material bar\) is compressed to zero volume or below" runIn "$c" mpmFoam
expectFailure "a fixed step above Courant 1 is warned about first" "The MPM step .* set by timeStep fixed .* gives Courant number [0-9.e+]+ > 1" runIn "$c" mpmFoam
bad=$(grep -rliE "\bnan\b|\binf\b" "$c"/[0-9]*/lagrangian "$c"/[0-9]*/*.solid 2>/dev/null | head -3)
if [ -z "$bad" ]; then echo "PASS: no NaN/inf written"; else echo "FAIL: NaN written in $bad"; failures=$((failures + 1)); fi


# Decomposed (2 ranks): an input error is printed once, as a serial run
# prints it, with the file and its lines (the master's copy); no rank's copy
# with "[1]" in front, none naming "IOstream" for a file (errorsOnce.H)
expectOncePar()
{
    local what="$1" pattern="$2"; shift 2
    local out rc copies
    out="$("$@" 2>&1)"; rc=$?
    copies=$(echo "$out" | grep -cE -- "$pattern")
    if [ $rc -eq 0 ]; then
        echo "FAIL: $what: succeeded, expected an error"; failures=$((failures + 1))
    elif [ "$copies" -ne 1 ] || echo "$out" | grep -qE "^\[[0-9]+\]|IOstream"; then
        echo "FAIL: $what: printed $copies times, or by rank"; echo "$out" | tail -30; failures=$((failures + 1))
    elif ! echo "$out" | grep -qE "^file: .*constant/mpmProperties.materials.bar from line [0-9]+ to line [0-9]+"; then
        echo "FAIL: $what: no file and lines"; echo "$out" | tail -30; failures=$((failures + 1))
    else
        echo "PASS: $what: once, $(echo "$out" | grep -E -m1 "^file: " | sed 's/^ *//')"
    fi
}
c=$(freshCopy decomposedError)
decomposeCase "$c" 2 scotch
sed -i 's/model   linearElastic;/model   linearElastik;/' "$(props "$c")"
expectOncePar "decomposed mpmFoam: the error once" "Unknown model 'linearElastik'" \
    runIn "$c" mpirun -np 2 mpmFoam -parallel
expectOncePar "decomposed foamRun -solver mpmFoam: the error once" "Unknown model 'linearElastik'" \
    runIn "$c" mpirun -np 2 foamRun -solver mpmFoam -parallel
expectOncePar "mpmSetParticles -parallel: the error once" "Unknown model 'linearElastik'" \
    runIn "$c" mpirun -np 2 mpmSetParticles -parallel -overwrite

finish
