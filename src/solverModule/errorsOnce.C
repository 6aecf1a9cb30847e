#include "errorsOnce.H"
#include "error.H"
#include "Pstream.H"
#include "OSspecific.H"

namespace
{

// Print err as a serial run does, on the master without "[0] " in front
template<class Error>
void printAndExit(const Error& err, const unsigned waitSeconds)
{
    using namespace Foam;

    const bool parallel = Pstream::parRun();
    if (parallel && !Pstream::master())
    {
        // The master has the same error and will abort the job; if it
        // does not within the wait, the error is this rank's own
        Foam::sleep(waitSeconds);
        Perr<< nl << err << nl << "\nFOAM parallel run exiting\n" << endl;
        Pstream::exit(1);
    }

    const string prefix = Perr.prefix();
    Perr.prefix() = "";
    Perr<< nl << err << nl
        << (parallel ? "\nFOAM parallel run exiting\n" : "\nFOAM exiting\n")
        << endl;
    Perr.prefix() = prefix;

    if (parallel)
    {
        Pstream::exit(1);
    }
    std::exit(1);
}

} // End anonymous namespace


void Foam::reportErrorsOnce
(
    const std::function<void()>& body,
    const unsigned waitSeconds
)
{
    const bool wasThrowing = FatalError.throwExceptions();
    const bool ioWasThrowing = FatalIOError.throwExceptions();

    try
    {
        body();
    }
    catch (const IOerror& err)   // before error: IOerror derives from it
    {
        printAndExit(err, waitSeconds);
    }
    catch (const error& err)
    {
        printAndExit(err, waitSeconds);
    }

    FatalError.throwExceptions(wasThrowing);
    FatalIOError.throwExceptions(ioWasThrowing);
}
