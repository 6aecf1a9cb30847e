#include "foamMaterialPoints.H"
#include "materialPointsIO.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(foamMaterialPoints, 0);
    addToRunTimeSelectionTable(materialPointsFormat, foamMaterialPoints, mesh);
}

void Foam::foamMaterialPoints::read(mpm::Particles& points)
{
    readMaterialPoints(mesh_, points, materialNames_);
}

void Foam::foamMaterialPoints::write(const mpm::Particles& points)
{
    writeMaterialPoints(mesh_, lattice_, points, materialNames_);
}
