#include "mpmDiagnostic.H"
#include "mpmModel.H"
#include "Time.H"

namespace Foam
{
    defineTypeNameAndDebug(mpmDiagnostic, 0);
    defineRunTimeSelectionTable(mpmDiagnostic, dictionary);
}

Foam::autoPtr<Foam::mpmDiagnostic> Foam::mpmDiagnostic::New
(
    const word& name,
    const mpmModel& mpm,
    const dictionary& mpmDict
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        std::string valid;
        for (const word& n : dictionaryConstructorTablePtr_->sortedToc())
        {
            valid += (valid.empty() ? "" : " ") + n;
        }
        FatalIOErrorInFunction(mpmDict)
            << "Unknown diagnostic '" << name << "' in diagnostics" << nl
            << "Valid diagnostics: " << valid.c_str()
            << exit(FatalIOError);
    }
    return cstrIter()(mpm, mpmDict);
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
