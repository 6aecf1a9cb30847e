#include "materialPointsFormat.H"

namespace Foam
{
    defineTypeNameAndDebug(materialPointsFormat, 0);
    defineRunTimeSelectionTable(materialPointsFormat, mesh);
}

Foam::materialPointsFormat::materialPointsFormat
(
    const fvMesh& mesh,
    const meshLattice& lattice,
    const mpm::Communicator& comm,
    const wordList& materialNames
)
:
    mesh_(mesh),
    lattice_(lattice),
    comm_(comm),
    materialNames_(materialNames)
{}

Foam::autoPtr<Foam::materialPointsFormat> Foam::materialPointsFormat::New
(
    const dictionary& mpmDict,
    const fvMesh& mesh,
    const meshLattice& lattice,
    const mpm::Communicator& comm,
    const wordList& materialNames
)
{
    const word type(mpmDict.lookupOrDefault<word>("pointOutput", "foam"));
    auto cstrIter = meshConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(mpmDict)
            << "Unknown pointOutput '" << type << "'" << nl
            << "Valid pointOutput choices: "
            << meshConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    Info<< "Material point output: " << type
        << (mpmDict.found("pointOutput") ? "" : " (default)") << nl;
    return cstrIter()(mesh, lattice, comm, materialNames);
}
