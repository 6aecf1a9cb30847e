// An accuracy front: the results CSV of bin/mpmAccuracyCost (one row per
// measured run of a sweep), read so that the solver can quote, at the end of
// a run, the error measured for its own configuration.
//
// The CSV: '#' header lines ("error: <name>", "parameters: <names>"), then a
// header row and one row per run. Besides the parameters, error, solverTime,
// status and reference, every run records the dictionary entries the sweep
// set, one column each, named "<file>:<entry/path>" (e.g.
// "constant/mpmProperties:timeStep/courant"). A case's configuration is the
// run whose every such entry equals the case's own value.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mpm {
namespace accuracy {

struct FrontRun
{
    std::map<std::string, std::string> columns;  // every column, as written
    double error = 0;
    double solverTime = 0;
    bool usable = false;       // status ok and not the reference run
    bool fragile = false;      // its family was unstable at another refinement
};

struct AccuracyFront
{
    std::string errorName;                 // "# error: ..." (may be empty)
    std::vector<std::string> parameters;   // "# parameters: ..."
    std::vector<std::string> entryColumns; // the "<file>:<entry>" columns
    std::vector<FrontRun> runs;
};

// Parse the CSV text; throws std::runtime_error naming the problem (no
// header row, no error/solverTime/status column, a row of the wrong width).
AccuracyFront parseAccuracyFront(const std::string& text);

// Equal dictionary values: the same tokens (parentheses split off), numbers
// equal to a relative 1e-6 (what a dictionary prints back).
bool sameValue(const std::string& a, const std::string& b);

// The case's value of an entry of one of its files, or nothing if absent.
using EntryLookup =
    std::function<std::optional<std::string>(const std::string& file, const std::string& entry)>;

struct Expected
{
    const FrontRun* run = nullptr;         // the matching usable run, if any
    bool onFront = false;                  // no usable run is cheaper-or-equal and more accurate-or-equal
    const FrontRun* cheaperAsGood = nullptr;  // the cheapest run that dominates it
    int usableRuns = 0;
};

// The run measured with the case's configuration (every entry column
// matches), whether it is on the Pareto front, and if not the cheapest run
// at least as accurate.
Expected expectedError(const AccuracyFront&, const EntryLookup&);

// A run's parameters as "name value, name value".
std::string describe(const AccuracyFront&, const FrontRun&);

} // namespace accuracy
} // namespace mpm
