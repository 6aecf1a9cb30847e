#include "foamMaterialPoints.H"
#include "materialPointsIO.H"
#include "meshCellSearch.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(foamMaterialPoints, 0);
    addToRunTimeSelectionTable(materialPointsFormat, foamMaterialPoints, mesh);
}

void Foam::foamMaterialPoints::read(mpm::Particles& points)
{
    readMaterialPoints(mesh_, points, materialNames_);
    // Written per processor's mesh cells; run per lattice owner, which on
    // a lattice of its own need not be the same processor
    if (!lattice_.ownersAreMeshRanks()) toLatticeOwners(lattice_, points);
}

void Foam::foamMaterialPoints::write(const mpm::Particles& points)
{
    writeMaterialPoints(mesh_, lattice_, points, materialNames_);
}
