#include "solverModule.H"

namespace Foam
{
    defineTypeNameAndDebug(solverModule, 0);
    defineRunTimeSelectionTable(solverModule, fvMesh);
}

Foam::solverModule::solverModule(fvMesh& mesh)
:
    mesh(mesh),
    runTime(mesh.time())
{}

Foam::autoPtr<Foam::solverModule> Foam::solverModule::New
(
    const word& name,
    fvMesh& mesh
)
{
    Info<< "Selecting solver module " << name << endl;

    // The table exists only once a module library has registered in it:
    // make an empty one so that an unknown name gets the message below.
    constructfvMeshConstructorTables();

    const auto cstrIter = fvMeshConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalErrorInFunction
            << "Unknown solver module " << name << nl
            << "    (modules register when their library is loaded: foamRun"
            << " opens lib" << name << ".so; others with -lib or the"
            << " controlDict libs entry)" << nl << nl
            << "Valid solver modules are :" << nl
            << fvMeshConstructorTablePtr_->sortedToc()
            << exit(FatalError);
    }
    return autoPtr<solverModule>(cstrIter()(mesh));
}

bool Foam::solverModule::loop()
{
    // One pass per step: true on the first call of a step, false on the
    // second, which also re-arms it for the next step.
    passDone_ = !passDone_;
    return passDone_;
}
