#include "compressionCheck.H"
#include "PstreamReduceOps.H"

void Foam::stopIfInverted
(
    const mpm::MpmSystem::InvertedPoints& local,
    const wordList& materialNames,
    label step,
    const Time& runTime,
    const std::string& advice
)
{
    const label nBad = returnReduce(label(local.count), sumOp<label>());
    if (nBad == 0) return;

    // The named point: the lowest id; its values from the rank holding it
    const label id = local.count > 0 ? label(local.id) : labelMax;
    const label firstId = returnReduce(id, minOp<label>());
    const bool mine = id == firstId;
    const label material = returnReduce(mine ? label(local.material) : label(-1), maxOp<label>());
    const scalar J = returnReduce(mine ? local.J : -GREAT, maxOp<scalar>());
    const scalar volume = returnReduce(mine ? local.volume : -GREAT, maxOp<scalar>());

    FatalErrorInFunction
        << "Stopping at time " << runTime.timeName() << ", step " << step
        << ": material point id " << firstId << " (material "
        << (material >= 0 && material < materialNames.size()
            ? materialNames[material] : word("?")) << ") is compressed to "
        << "zero volume or below: J = " << J << ", volume = " << volume
        << " (" << nBad << " such points)." << nl
        << "Nothing was written for this time. Such a state has no physical"
        << " meaning; an explicit step reaches it when a point moves more"
        << " than a cell's width relative to its neighbours in one step"
        << " (a hard impact on a wall or between bodies). Reduce the time"
        << " step (timeStep { type adaptive; courant 0.5; } or a smaller"
        << " controlDict deltaT), or the impact velocity; a finer mesh with"
        << " more points per cell also helps. The last written time can be"
        << " restarted with the new settings." << advice.c_str()
        << exit(FatalError);
}
