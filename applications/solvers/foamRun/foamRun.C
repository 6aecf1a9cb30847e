/*---------------------------------------------------------------------------*\
Application
    foamRun

Description
    Loads and runs a solver module, with the command line of OpenFOAM
    Foundation's foamRun (v11+): the module is named by the controlDict entry
    `solver NAME;` or, overriding it, by `-solver NAME`. foamRun opens
    lib<NAME>.so (runTime.libs(): v1912 has no global libs) and selects the
    module NAME from the solverModule table (src/solverModule); more
    libraries with -lib or the controlDict libs entry. -parallel works as in
    any solver.

Usage
    foamRun -solver mpmFoam [-parallel]
    foamRun                         (with `solver mpmFoam;` in controlDict)
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "columnFvMesh.H"   // createMesh.H needs it (-dry-run)
#include "solverModule.H"
#include "errorsOnce.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Loads and runs the solver module named by the controlDict solver"
        " entry or the -solver option"
    );
    argList::addOption
    (
        "solver",
        "name",
        "Solver module (overrides the controlDict solver entry)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    word solverName
    (
        runTime.controlDict().lookupOrDefault<word>("solver", word::null)
    );
    args.readIfPresent("solver", solverName);

    if (solverName.empty())
    {
        args.printUsage();
        FatalErrorIn(args.executable())
            << "solver not specified in the controlDict or on the command-line"
            << exit(FatalError);
    }

    // Before the mesh, as Foundation does: the library may bring boundary
    // conditions. A missing library only warns; New then says the name is
    // unknown and lists the modules that did register.
    runTime.libs().open("lib" + solverName + ".so");

    #include "createMesh.H"

    // An input error is printed once in a decomposed run (errorsOnce.H)
    reportErrorsOnce([&]()
    {
        autoPtr<solverModule> module(solverModule::New(solverName, mesh));
        runSolverModule(runTime, module());
    });

    Info<< "End\n" << endl;
    return 0;
}
