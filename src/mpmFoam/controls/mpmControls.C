#include "mpmControls.H"
#include "choice.H"
#include "knownKeywords.H"
#include "uniformDimensionedFields.H"
#include "Time.H"
#include "step/mpmSystem.hpp"

void Foam::checkStep(const Time& runTime, const std::string& what)
{
    checkInRange
    (
        runTime.controlDict(), "deltaT", runTime.deltaTValue(),
        numberRange{0, GREAT, false}, (" (" + what + ")").c_str()
    );
}

Foam::mpmControls::mpmControls(const fvMesh& mesh, const dictionary& d)
{
    // The top level of mpmProperties: these controls, the sub-dictionaries
    // read by materialLibrary, readWallConditions and fluidCoupling, and
    // the point output format read by mpmModel.
    checkKeywords
    (
        d,
        {
            "shapeFunction", "transfer", "flipRatio", "stressUpdate",
            "massMatrix", "consistentMassIterations", "freezePositions",
            "logInterval", "threadMinLoopSize", "timeStep",
            "lattice", "materials", "walls", "obstacles", "coupling", "pointOutput", "diagnostics",
            "accuracyFront", "backend"
        },
        "mpmProperties"
    );
    Info<< "MPM controls:" << nl;
    step.shape = readChoice
    (
        d, "shapeFunction", mpm::parseShape,
        [](mpm::ShapeKind k) { return mpm::shapeName(k); },
        mpm::validShapeNames(), mpm::ShapeKind::cubicBSpline
    );
    step.transfer = readChoice
    (
        d, "transfer", mpm::parseTransfer,
        [](mpm::Transfer t) { return mpm::transferName(t); },
        mpm::validTransferNames(), mpm::Transfer::picFlip
    );
    step.flipRatio = readBounded(d, "flipRatio", 0.99, 0, 1);
    step.stressUpdate = readChoice
    (
        d, "stressUpdate", mpm::parseStressUpdate,
        [](mpm::StressUpdate s) { return mpm::stressUpdateName(s); },
        mpm::validStressUpdateNames(), mpm::StressUpdate::USL
    );
    step.massMatrix = readChoice
    (
        d, "massMatrix", mpm::parseMassMatrix,
        [](mpm::MassMatrix m) { return mpm::massMatrixName(m); },
        mpm::validMassMatrixNames(), mpm::MassMatrix::lumped
    );
    if (step.massMatrix == mpm::MassMatrix::consistent)
    {
        step.consistentMassIterations =
            int(readBounded(d, "consistentMassIterations", 2, 1, 50));
    }
    step.backend = readChoice
    (
        d, "backend", mpm::parseBackend,
        [](mpm::Backend b) { return mpm::backendName(b); },
        mpm::validBackendNames(), mpm::Backend::openmp
    );
    {
        // A valid name this build or machine cannot run: say why here,
        // before any point is seeded or field read
        const std::string why = mpm::backendUnavailableReason(step.backend);
        if (!why.empty())
        {
            FatalIOErrorInFunction(d)
                << "backend " << mpm::backendName(step.backend)
                << " cannot run: " << why.c_str() << nl
                << "Valid backends here: serial openmp" << exit(FatalIOError);
        }
    }
    step.freezePositions = d.getOrDefault<bool>("freezePositions", false);
    Info<< "    freezePositions " << step.freezePositions << nl;
    logInterval = label(readBounded(d, "logInterval", 1, 1, labelMax));
    // The end-of-run log quotes the error this front measured for the case's
    // configuration (bin/mpmAccuracyCost writes it)
    accuracyFront = d.getOrDefault<fileName>("accuracyFront", accuracyFront);
    Info<< "    accuracyFront " << accuracyFront << nl;
    // Loops over fewer points or nodes run on one OpenMP thread: a parallel
    // region costs a scheduler time slice when cores are shared (MPI ranks
    // plus threads). Lower it to thread small cases (tests do).
    mpm::MpmSystem::parallelThreshold =
        mpm::Index(readBounded(d, "threadMinLoopSize", 50000, 1, labelMax));

    const dictionary& ts = optionalSubDict(d, "timeStep");
    checkKeywords(ts, {"type", "courant", "maxDeltaT"}, "timeStep");
    const word type(ts.getOrDefault<word>("type", "adaptive"));
    if (type != "adaptive" && type != "fixed")
    {
        FatalIOErrorInFunction(ts)
            << "Unknown timeStep type '" << type << "'" << nl
            << "Valid timeStep types: adaptive fixed" << exit(FatalIOError);
    }
    adaptive = type == "adaptive";
    Info<< "    timeStep " << type << nl;
    if (adaptive)
    {
        courant = readBounded(ts, "courant", 0.5, SMALL, 10);
        maxDeltaT = readBounded(ts, "maxDeltaT", GREAT, SMALL, GREAT);
    }
    else
    {
        // The fixed step is controlDict's deltaT: zero would never advance
        // the time (a hang, or a division by zero in the write control)
        checkStep(mesh.time(), "the fixed MPM step, timeStep { type fixed; }");
    }

    IOobject gIO("g", mesh.time().constant(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE);
    if (gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        const uniformDimensionedVectorField g(gIO);
        for (direction c = 0; c < 3; ++c) step.gravity[c] = g.value()[c];
        Info<< "    gravity " << g.value() << " (constant/g)" << nl;
    }
    else
    {
        Info<< "    gravity (0 0 0) (no constant/g)" << nl;
    }
}
