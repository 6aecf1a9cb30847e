#include "solidForce.H"
#include "choice.H"

namespace Foam
{
    defineTypeNameAndDebug(solidForce, 0);
    defineRunTimeSelectionTable(solidForce, dictionary);
}

Foam::wordList Foam::solidForce::names()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}

Foam::autoPtr<Foam::solidForce> Foam::solidForce::New
(
    const word& name,
    fluidCoupling& coupling,
    const dictionary& couplingDict
)
{
    checkSelection(wordList({name}), names(), couplingDict, "force", "forces");
    return dictionaryConstructorTablePtr_->cfind(name)()(coupling, couplingDict);
}
