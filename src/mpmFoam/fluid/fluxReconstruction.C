#include "fluxReconstruction.H"
#include "fvcSurfaceIntegrate.H"
#include "extrapolatedCalculatedFvPatchFields.H"

Foam::fluxReconstruction::fluxReconstruction(const fvMesh& mesh)
:
    mesh_(mesh),
    nf_(mesh.Sf()/mesh.magSf()),
    invNS_
    (
        IOobject("fluxReconstruction.invNS", mesh.time().timeName(), mesh),
        mesh,
        dimensionedTensor(dimless/dimArea, Zero)
    )
{
    // Named, so inv() does not work in place on a temporary either
    const volTensorField NS(fvc::surfaceSum(nf_*mesh.Sf()));
    invNS_ = inv(NS);
}

Foam::tmp<Foam::volVectorField>
Foam::fluxReconstruction::operator()(const surfaceScalarField& phi) const
{
    const volVectorField b(fvc::surfaceSum(nf_*phi));
    tmp<volVectorField> tU
    (
        new volVectorField
        (
            IOobject("reconstruct(" + phi.name() + ')', phi.instance(), mesh_),
            mesh_,
            b.dimensions()/dimArea,
            extrapolatedCalculatedFvPatchField<vector>::typeName
        )
    );
    // Both operands named: the product gets storage of its own
    tU.ref().primitiveFieldRef() = (invNS_.primitiveField() & b.primitiveField());
    tU.ref().correctBoundaryConditions();
    return tU;
}
