#include "solverModule.H"

void Foam::runSolverModule(Time& runTime, solverModule& module)
{
    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        module.preSolve();

        const scalar deltaT = module.maxDeltaT();
        if (deltaT < VGREAT)
        {
            runTime.setDeltaT(deltaT);   // adjusted to land on write times
        }
        ++runTime;

        while (module.loop())
        {
            module.moveMesh();
            module.prePredictor();
            module.momentumPredictor();
            module.thermophysicalPredictor();
            module.pressureCorrector();
            module.postCorrector();
        }

        module.postSolve();
        runTime.write();
        module.postWrite();
    }

    module.end();
}
