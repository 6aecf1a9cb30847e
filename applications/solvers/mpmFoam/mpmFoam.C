/*---------------------------------------------------------------------------*\
Application
    mpmFoam

Group
    grpLagrangianSolvers

Description
    Material Point Method solver for solid and granular material, with the
    finite-volume mesh as the background lattice.

    Pure MPM: reads constant/mpmProperties, constant/g and the material
    points of the start time (lagrangian/materialPoints, seeded by
    mpmSetParticles); writes the points and the lattice fields alpha.solid
    and U.solid.

    With a fluid (constant/transportProperties, 0/U, 0/p): a volume-averaged
    incompressible fluid is solved with PIMPLE and coupled to the solids by
    drag, buoyancy and the fluid fraction (mpmProperties::coupling); the
    solids sub-cycle within each fluid step. Without a fluid no fluid
    equation is constructed or solved.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmModel.H"
#include "fluidPhase.H"
#include "fluidCoupling.H"
#include "pimpleControl.H"
#include "clockTime.H"

namespace Foam
{

void pureMpm(Time& runTime, mpmModel& mpm)
{
    while (runTime.run())
    {
        const scalar dt = mpm.deltaT();
        runTime.setDeltaT(dt);   // adjusted to land on write times
        ++runTime;

        const scalar dtUsed = runTime.deltaTValue();
        const bool log = mpm.logThisStep();
        if (log)
        {
            Info<< "Courant Number max: " << mpm.courantNumber(dtUsed)
                << " deltaT = " << dtUsed << nl
                << "Time = " << runTime.timeName() << nl << endl;
        }

        mpm.evolve(dtUsed);
        mpm.write();
        runTime.write();

        if (log || runTime.writeTime())
        {
            mpm.report(Info);
            runTime.printExecutionTime(Info);
        }
    }
    mpm.summary(Info);
}

void coupled(Time& runTime, fvMesh& mesh, mpmModel& mpm)
{
    pimpleControl pimple(mesh);
    fluidPhase fluid(mesh, pimple);
    fluidCoupling coupling(mesh, mpm, fluid);
    scalar fluidTime = 0;

    while (runTime.run())
    {
        ++runTime;
        const scalar dt = runTime.deltaTValue();
        Info<< "Time = " << runTime.timeName() << nl << endl;

        coupling.advanceSolids(dt);
        Info<< "MPM: " << coupling.lastSubCycles() << " sub-cycles of deltaT = "
            << dt/coupling.lastSubCycles() << ", Courant Number max "
            << mpm.courantNumber(dt/coupling.lastSubCycles()) << nl;

        const clockTime timer;
        fluid.solve(pimple, coupling.g());
        fluidTime += timer.elapsedTime();
        Info<< "fluid: continuity error " << fluid.continuityError()
            << ", min alpha.fluid " << gMin(fluid.alpha().primitiveField())
            << ", alpha transport error " << fluid.alphaTransportError() << nl;

        mpm.write();
        runTime.write();
        mpm.report(Info);
        runTime.printExecutionTime(Info);
    }
    mpm.summary(Info, fluidTime);
}

} // End namespace Foam

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Material Point Method solver (solid and granular material),"
        " optionally coupled to a volume-averaged fluid"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    mpmModel mpm(mesh);
    mpm.report(Info);   // state at the start time

    Info<< "\nStarting time loop\n" << endl;

    if (fluidPhase::present(mesh))
    {
        coupled(runTime, mesh, mpm);
    }
    else
    {
        pureMpm(runTime, mpm);
    }

    Info<< "End\n" << endl;
    return 0;
}
