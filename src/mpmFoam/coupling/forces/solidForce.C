#include "solidForce.H"

namespace Foam
{
    defineTypeNameAndDebug(solidForce, 0);
    defineRunTimeSelectionTable(solidForce, dictionary);
}

Foam::wordList Foam::solidForce::names()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}

std::string Foam::solidForce::namesString()
{
    std::string s;
    for (const word& n : names()) s += (s.empty() ? "" : " ") + n;
    return s;
}

void Foam::solidForce::checkName(const word& name, const dictionary& dict)
{
    if (!dictionaryConstructorTablePtr_->found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown force '" << name << "' in forces" << nl
            << "Valid forces: " << namesString().c_str()
            << exit(FatalIOError);
    }
}

Foam::autoPtr<Foam::solidForce> Foam::solidForce::New
(
    const word& name,
    fluidCoupling& coupling,
    const dictionary& couplingDict
)
{
    checkName(name, couplingDict);
    return dictionaryConstructorTablePtr_->cfind(name)()(coupling, couplingDict);
}
