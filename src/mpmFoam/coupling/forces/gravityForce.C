#include "gravityForce.H"
#include "fluidCoupling.H"
#include "uniformDimensionedFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(gravityForce, 0);
    addToRunTimeSelectionTable(solidForce, gravityForce, dictionary);
}

Foam::gravityForce::gravityForce(fluidCoupling& coupling, const dictionary& couplingDict)
:
    solidForce(coupling, couplingDict)
{
    const fvMesh& mesh = coupling.mesh();
    const uniformDimensionedVectorField g
    (
        IOobject("g", mesh.time().constant(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    coupling.setGravity(g.value());
}
