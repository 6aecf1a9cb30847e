#include "pressureGradientForce.H"
#include "fluidCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(pressureGradientForce, 0);
    addToRunTimeSelectionTable(solidForce, pressureGradientForce, dictionary);
}

Foam::pressureGradientForce::pressureGradientForce
(
    fluidCoupling& coupling,
    const dictionary& couplingDict
)
:
    solidForce(coupling, couplingDict)
{}

void Foam::pressureGradientForce::correct()
{
    // [Pa/m]: rho grad p of the single fluid's kinematic p, the VOF
    // fluid's grad p
    gradp_ = coupling_.fluid().gradP()().primitiveField();
}

void Foam::pressureGradientForce::addTo(solidForceTerms& t) const
{
    forAll(gradp_, celli) t.F[celli] -= gradp_[celli];
    if (coupling_.mode() == fluidCoupling::couplingMode::oneWay || coupling_.frozenFluid()) return;

    const volScalarField& beta = coupling_.fluid().beta();
    const scalarField& V = coupling_.mesh().V();
    forAll(beta, celli)
    {
        const scalar KDrag = beta[celli]*V[celli];
        if (KDrag <= 0) continue;
        // (aS/aF) beta V times d(slip)/dv = 1/aF
        const scalar aF = coupling_.fluidFraction(celli);
        const scalar Kp = KDrag*coupling_.cappedAlphaSolid(celli)/(aF*aF);
        t.K[celli] += Kp;
        t.KU[celli] += Kp*coupling_.solidVelocity(celli);
    }
}
