#include "virtualMassForce.H"
#include "fluidCoupling.H"
#include "choice.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(virtualMassForce, 0);
    addToRunTimeSelectionTable(solidForce, virtualMassForce, dictionary);
}

Foam::virtualMassForce::virtualMassForce
(
    fluidCoupling& coupling,
    const dictionary& couplingDict
)
:
    solidForce(coupling, couplingDict),
    Cvm_(readBounded(couplingDict, "Cvm", 0.5, 0, 10))
{
    const bool reaction = coupling.mode() != fluidCoupling::couplingMode::oneWay;
    coupling.fluid().enableVirtualMass(Cvm_, reaction);
    auto& c = coupling.mpm().system().coupling();
    const label nNodes = label(coupling.mpm().system().lattice().nNodes);
    for (auto& a : c.fluidAcceleration) a.assign(nNodes, 0.0);
    // One density (enableVirtualMass refuses a fluid of several)
    c.addedMassDensity = Cvm_*gMax(coupling.fluid().rho().primitiveField());
}

void Foam::virtualMassForce::correct()
{
    // DU/Dt of the fluid over its last step, frozen over the sub-cycles
    auto& c = coupling_.mpm().system().coupling();
    coupling_.cellsToLattice(coupling_.fluid().DUDt().primitiveField(), c.fluidAcceleration);
}

void Foam::virtualMassForce::afterSolids()
{
    if (coupling_.mode() == fluidCoupling::couplingMode::oneWay) return;
    // The fluid's share, -Cvm aS rho_f (DU/Dt - dUs/dt), with aS here even
    // in twoWayMomentum (where the fluid's own aF is 1)
    const fvMesh& mesh = coupling_.mesh();
    volScalarField::Internal alphaS
    (
        IOobject("alphaS.virtualMass", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    forAll(alphaS, celli) alphaS[celli] = coupling_.cappedAlphaSolid(celli);
    coupling_.fluid().setVirtualMassFraction(alphaS);
}
