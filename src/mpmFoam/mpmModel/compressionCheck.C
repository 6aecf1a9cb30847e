#include "compressionCheck.H"
#include "PstreamReduceOps.H"

void Foam::stopIfInverted
(
    const mpm::Particles& P,
    const wordList& materialNames,
    label step,
    const Time& runTime
)
{
    label nBad = 0;
    label id = labelMax;
    label material = -1;
    scalar J = 0, volume = 0;
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        const scalar Jp = P.J(p);
        // NaN is the non-finite check's (the core's); not counted here
        if (!(Jp <= 0) && !(P.volume[p] <= 0)) continue;
        ++nBad;
        if (label(P.id[p]) < id)
        {
            id = label(P.id[p]);
            material = P.material[p];
            J = Jp;
            volume = P.volume[p];
        }
    }
    if (returnReduce(nBad, sumOp<label>()) == 0) return;

    // The named point: the lowest id; its values from the rank holding it
    const label firstId = returnReduce(id, minOp<label>());
    const bool mine = id == firstId;
    material = returnReduce(mine ? material : label(-1), maxOp<label>());
    J = returnReduce(mine ? J : -GREAT, maxOp<scalar>());
    volume = returnReduce(mine ? volume : -GREAT, maxOp<scalar>());
    nBad = returnReduce(nBad, sumOp<label>());

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
        << " restarted with the new settings."
        << exit(FatalError);
}
