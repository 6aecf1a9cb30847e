#include "completeTimes.H"
#include "OFstream.H"
#include "OSspecific.H"

namespace
{

Foam::fileName marker(const Foam::fileName& timePath)
{
    return timePath/"uniform"/"mpmComplete";
}

} // namespace

void Foam::markTimeComplete(const Time& runTime)
{
    mkDir(runTime.timePath()/"uniform");
    OFstream os(marker(runTime.timePath()));
    os  << "// Every field of time " << runTime.timeName() << " was written"
        << " completely (mpmFoam reads only times with this marker)" << nl;
}

void Foam::checkTimeComplete(const Time& runTime)
{
    // No directory: nothing half-written (an HDF5 checkpoint, complete by
    // its rename, restarted on processors that never wrote this time)
    const bool complete = returnReduce
    (
        !isDir(runTime.timePath()) || isFile(marker(runTime.timePath())),
        andOp<bool>()
    );
    if (complete) return;

    // The earlier times of the case, and the last complete one among them
    const scalar tol = 1e-9*max(runTime.deltaTValue(), SMALL);
    bool earlier = false;
    word lastComplete;
    for (const instant& t : runTime.times())
    {
        if (t.name() == runTime.constant() || t.value() >= runTime.value() - tol) continue;
        earlier = true;
        const fileName tp(runTime.path()/t.name());
        if (returnReduce(isFile(marker(tp)), andOp<bool>())) lastComplete = t.name();
    }
    // The first time: the seeded points (mpmSetParticles before markers)
    if (!earlier) return;

    const fileName dir(runTime.timePath());
    FatalErrorInFunction
        << "Time " << runTime.timeName() << " is incomplete: "
        << marker(dir) << " is missing. mpmFoam writes it after every field"
        << " of a write time, so the run that wrote " << runTime.timeName()
        << " stopped during the write (killed, time limit, disk full)." << nl
        << "Delete it (foamListTimes -time " << runTime.timeName() << " -rm";
    if (Pstream::parRun()) FatalError << " -processor";
    FatalError
        << ") and restart: startFrom latestTime then continues from ";
    if (lastComplete.size())
    {
        FatalError << "time " << lastComplete << ", the last complete one.";
    }
    else
    {
        FatalError << "the earlier time.";
    }
    FatalError
        << nl << "If time " << runTime.timeName() << " was written completely by"
        << " an mpmFoam older than this marker, create it instead: touch "
        << marker(dir) << exit(FatalError);
}
