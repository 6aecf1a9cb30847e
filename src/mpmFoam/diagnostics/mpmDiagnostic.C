#include "mpmDiagnostic.H"
#include "mpmModel.H"
#include "Time.H"
#include "choice.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmDiagnostic, 0);
    defineRunTimeSelectionTable(mpmDiagnostic, dictionary);
}

Foam::wordList Foam::mpmDiagnostic::names()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}

Foam::autoPtr<Foam::mpmDiagnostic> Foam::mpmDiagnostic::New
(
    const word& name,
    const mpmModel& mpm,
    const dictionary& mpmDict
)
{
    checkSelection(wordList({name}), names(), mpmDict, "diagnostic", "diagnostics");
    return dictionaryConstructorTablePtr_->cfind(name)()(mpm, mpmDict);
}

Foam::OFstream& Foam::mpmDiagnostic::file
(
    const word& name,
    const string& header,
    const word& fileNameInDir
)
{
    if (!file_.valid())
    {
        const Time& runTime = mpm_.mesh().time();
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/name
           /runTime.timeName(runTime.startTime().value())
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/(fileNameInDir.empty() ? word(name + ".dat") : fileNameInDir)));
        file_() << header.c_str();
        file_().precision(12);
    }
    return file_();
}
