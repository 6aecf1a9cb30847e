// Command-line helpers shared by the pure-MPM and the coupled analyses.
#pragma once
#include "types.hpp"
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace mpm {
namespace cli {

[[noreturn]] inline void fail(const std::string& msg)
{
    std::cerr << "mpmStabilityAnalysis: " << msg << "\n";
    std::exit(1);
}

inline std::vector<std::string> splitList(const std::string& s, char sep = ',')
{
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, sep)) if (!item.empty()) out.push_back(item);
    return out;
}

inline Real toReal(const std::string& s)
{
    try { std::size_t n = 0; const Real x = std::stod(s, &n); if (n == s.size()) return x; }
    catch (const std::exception&) {}
    fail("not a number: '" + s + "'");
}

inline std::vector<Real> realList(const std::string& s)
{
    std::vector<Real> out;
    for (const std::string& x : splitList(s)) out.push_back(toReal(x));
    return out;
}

// Walks the command line option by option for both analyses' parsers:
// `--help`/`-h` prints the usage and exits; value() takes the word after the
// current option, or fails naming it.
class Arguments
{
public:
    Arguments(int argc, char** argv, void (*usage)()) : argc_(argc), argv_(argv), usage_(usage) {}

    // Advances to the next option; false past the last one.
    bool next()
    {
        if (++i_ >= argc_) return false;
        option_ = argv_[i_];
        if (option_ == "--help" || option_ == "-h") { usage_(); std::exit(0); }
        return true;
    }
    const std::string& option() const { return option_; }
    std::string value()
    {
        if (i_ + 1 >= argc_) fail("missing value after " + option_);
        return argv_[++i_];
    }

private:
    int argc_;
    char** argv_;
    void (*usage_)();
    int i_ = 0;
    std::string option_;
};

} // namespace cli
} // namespace mpm
