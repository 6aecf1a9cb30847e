#include "accuracyFrontLog.H"
#include "accuracy/accuracyFront.hpp"
#include "IFstream.H"
#include "OSspecific.H"
#include "dictionary.H"
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace
{

using namespace Foam;

//- The case's value of entry (a/b scoped) in file, as its tokens
std::optional<std::string> lookupEntry
(
    const fileName& caseDir,
    std::map<std::string, dictionary>& cache,
    const std::string& file,
    const std::string& entryPath
)
{
    auto it = cache.find(file);
    if (it == cache.end())
    {
        const fileName path(caseDir/file);
        dictionary dict;
        if (isFile(path))
        {
            IFstream is(path);
            dict.read(is);
        }
        it = cache.emplace(file, dict).first;
    }
    const auto finder = it->second.csearchScoped(word(entryPath), keyType::LITERAL);
    if (!finder.found()) return std::nullopt;
    if (finder.isDict()) return std::nullopt;
    std::string value;
    for (const token& t : finder.ref().stream())
    {
        OStringStream os;
        os << t;
        value += (value.empty() ? "" : " ") + os.str();
    }
    return value;
}

} // namespace

void Foam::reportExpectedError(Ostream& os, const Time& runTime, const fileName& front)
{
    const fileName caseDir(runTime.rootPath()/runTime.globalCaseName());
    const fileName path(front.isAbsolute() ? front : caseDir/front);
    os  << "  Expected error: ";
    if (!isFile(path))
    {
        os  << "none (no accuracy front: " << front << " not found; "
            << "mpmAccuracyCost <case> --sweep <dictionary> measures one)" << endl;
        return;
    }
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    mpm::accuracy::AccuracyFront f;
    try
    {
        f = mpm::accuracy::parseAccuracyFront(text.str());
    }
    catch (const std::runtime_error& e)
    {
        os  << "none (" << front << " is not an accuracy front: " << e.what() << ")" << endl;
        return;
    }
    std::map<std::string, dictionary> cache;
    const auto expected = mpm::accuracy::expectedError
    (
        f,
        [&](const std::string& file, const std::string& entry)
        {
            return lookupEntry(caseDir, cache, file, entry);
        }
    );
    const std::string what(f.errorName.empty() ? "error" : f.errorName);
    if (!expected.run)
    {
        os  << "none measured for this configuration (" << front << ": "
            << expected.usableRuns << " usable runs, none with this case's "
            << f.entryColumns.size() << " swept entries)" << endl;
        return;
    }
    const auto& r = *expected.run;
    os  << r.error << " (" << what.c_str() << "), measured for this configuration ("
        << mpm::accuracy::describe(f, r).c_str() << ") in " << front
        << " at " << r.solverTime << " s solver time; ";
    if (r.fragile)
    {
        os  << "fragile (the same settings went unstable at another refinement of the sweep); ";
    }
    if (expected.onFront)
    {
        os  << "on the Pareto front" << endl;
    }
    else
    {
        const auto& q = *expected.cheaperAsGood;
        os  << "not on the Pareto front: " << mpm::accuracy::describe(f, q).c_str()
            << " measured " << q.error << " in " << q.solverTime << " s" << endl;
    }
}
