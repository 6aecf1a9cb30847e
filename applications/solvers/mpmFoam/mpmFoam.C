/*---------------------------------------------------------------------------*\
Application
    mpmFoam

Group
    grpLagrangianSolvers

Description
    Material Point Method solver for solid and granular material, with the
    finite-volume mesh as the background lattice (pure-MPM mode: no fluid).

    Reads constant/mpmProperties, constant/g and the material points of the
    start time (lagrangian/materialPoints, seeded by mpmSetParticles).
    Writes the points and the lattice fields alpha.solid and U.solid.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmModel.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Material Point Method solver (solid and granular material)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    mpmModel mpm(mesh);

    mpm.report(Info);   // state at the start time

    Info<< "\nStarting time loop\n" << endl;

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
    Info<< "End\n" << endl;

    return 0;
}
