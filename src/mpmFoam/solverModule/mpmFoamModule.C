#include "mpmFoamModule.H"
#include "addToRunTimeSelectionTable.H"
#include "clockTime.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmFoamModule, 0);
    addToRunTimeSelectionTable(solverModule, mpmFoamModule, fvMesh);
}

Foam::mpmFoamModule::mpmFoamModule(fvMesh& mesh)
:
    solverModule(mesh),
    mpm_(mesh)
{
    mpm_.report(Info);   // state at the start time

    if (fluidPhase::present(mesh))
    {
        pimple_.reset(new pimpleControl(mesh));
        fluid_.reset(new fluidPhase(mesh, pimple_()));
        coupling_.reset(new fluidCoupling(mesh, mpm_, fluid_()));
    }
}

Foam::scalar Foam::mpmFoamModule::maxDeltaT() const
{
    // Coupled: the fluid takes the controlDict deltaT and the solids
    // sub-cycle within it, so the step is not limited here.
    return coupled() ? VGREAT : mpm_.deltaT();
}

void Foam::mpmFoamModule::prePredictor()
{
    const scalar dt = runTime.deltaTValue();

    if (!coupled())
    {
        // The step header, every logInterval steps only
        logStep_ = mpm_.logThisStep();
        if (logStep_)
        {
            Info<< "Courant Number max: " << mpm_.courantNumber(dt)
                << " deltaT = " << dt << nl
                << "Time = " << runTime.timeName() << nl << endl;
        }
        return;
    }

    // Coupled: the solids first, over the whole fluid step (explicit
    // coupling: the fluid then sees their new fraction and velocity)
    Info<< "Time = " << runTime.timeName() << nl << endl;

    coupling_->advanceSolids(dt);
    const label nSub = coupling_->lastSubCycles();
    Info<< "MPM: " << nSub << " sub-cycles of deltaT = " << dt/nSub
        << ", Courant Number max " << mpm_.courantNumber(dt/nSub) << nl;
}

void Foam::mpmFoamModule::momentumPredictor()
{
    // Pure MPM: the whole MPM step (P2G, nodal momentum, G2P, stresses)
    if (!coupled())
    {
        mpm_.evolve(runTime.deltaTValue());
    }
}

void Foam::mpmFoamModule::pressureCorrector()
{
    if (!coupled()) return;

    // The fluid's whole PIMPLE loop: fluidPhase::solve loops itself
    const clockTime timer;
    fluid_->solve(pimple_(), coupling_->g());
    fluidTime_ += timer.elapsedTime();
    Info<< "fluid: continuity error " << fluid_->continuityError()
        << ", min alpha.fluid " << gMin(fluid_->alpha().primitiveField())
        << ", alpha transport error " << fluid_->alphaTransportError() << nl;
}

void Foam::mpmFoamModule::postSolve()
{
    mpm_.write();   // points and lattice fields, at write times only
}

void Foam::mpmFoamModule::postWrite()
{
    if (coupled() || logStep_ || runTime.writeTime())
    {
        mpm_.report(Info);
        runTime.printExecutionTime(Info);
    }
}

void Foam::mpmFoamModule::end()
{
    if (coupled())
    {
        mpm_.summary(Info, fluidTime_);
    }
    else
    {
        mpm_.summary(Info);
    }
}
