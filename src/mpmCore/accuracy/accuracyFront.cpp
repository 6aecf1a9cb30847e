#include "accuracyFront.hpp"
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace mpm {
namespace accuracy {

namespace {

// One CSV record (RFC 4180 quoting: "a, b" and "" inside quotes).
std::vector<std::string> splitRecord(const std::string& line)
{
    std::vector<std::string> out(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i)
    {
        const char c = line[i];
        if (quoted)
        {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') { out.back() += '"'; ++i; }
            else if (c == '"') quoted = false;
            else out.back() += c;
        }
        else if (c == '"') quoted = true;
        else if (c == ',') out.emplace_back();
        else if (c != '\r') out.back() += c;
    }
    return out;
}

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::optional<double> toNumber(const std::string& s)
{
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return x;
}

std::vector<std::string> tokens(const std::string& s)
{
    std::string spaced;
    for (char c : s)
    {
        if (c == '(' || c == ')' || c == ';') { spaced += ' '; spaced += c; spaced += ' '; }
        else spaced += c;
    }
    std::istringstream is(spaced);
    std::vector<std::string> out;
    for (std::string t; is >> t;) if (t != ";") out.push_back(t);
    return out;
}

double numberOr(const std::map<std::string, std::string>& row, const char* key)
{
    const auto it = row.find(key);
    const auto x = it == row.end() ? std::nullopt : toNumber(it->second);
    return x ? *x : std::nan("");
}

} // namespace

AccuracyFront parseAccuracyFront(const std::string& text)
{
    AccuracyFront f;
    std::istringstream is(text);
    std::vector<std::string> names;
    for (std::string line; std::getline(is, line);)
    {
        if (trim(line).empty()) continue;
        if (line[0] == '#')
        {
            const std::string h = trim(line.substr(1));
            if (h.rfind("error:", 0) == 0) f.errorName = trim(h.substr(6));
            if (h.rfind("parameters:", 0) == 0)
            {
                std::istringstream ps(h.substr(11));
                for (std::string p; ps >> p;) f.parameters.push_back(p);
            }
            continue;
        }
        const std::vector<std::string> cells = splitRecord(line);
        if (names.empty())
        {
            names = cells;
            for (const char* need : {"error", "solverTime", "status"})
            {
                bool found = false;
                for (const auto& n : names) found = found || n == need;
                if (!found)
                {
                    throw std::runtime_error(std::string("no '") + need + "' column in the header row");
                }
            }
            for (const auto& n : names)
            {
                if (n.find(':') != std::string::npos) f.entryColumns.push_back(n);
            }
            continue;
        }
        if (cells.size() != names.size())
        {
            throw std::runtime_error("a row has " + std::to_string(cells.size())
                                     + " fields, the header " + std::to_string(names.size()));
        }
        FrontRun r;
        for (size_t i = 0; i < names.size(); ++i) r.columns[names[i]] = cells[i];
        r.error = numberOr(r.columns, "error");
        r.solverTime = numberOr(r.columns, "solverTime");
        const auto fragile = r.columns.find("fragile");
        r.fragile = fragile != r.columns.end() && fragile->second == "1";
        const auto ref = r.columns.find("reference");
        r.usable = r.columns["status"] == "ok" && std::isfinite(r.error) && std::isfinite(r.solverTime)
                   && (ref == r.columns.end() || ref->second.empty() || ref->second == "0");
        f.runs.push_back(std::move(r));
    }
    if (names.empty()) throw std::runtime_error("no header row");
    return f;
}

bool sameValue(const std::string& a, const std::string& b)
{
    const auto ta = tokens(a), tb = tokens(b);
    if (ta.size() != tb.size()) return false;
    for (size_t i = 0; i < ta.size(); ++i)
    {
        const auto x = toNumber(ta[i]), y = toNumber(tb[i]);
        if (x && y)
        {
            if (std::abs(*x - *y) > 1e-6*std::max(std::abs(*x), std::abs(*y))) return false;
        }
        else if (ta[i] != tb[i])
        {
            return false;
        }
    }
    return true;
}

Expected expectedError(const AccuracyFront& f, const EntryLookup& lookup)
{
    Expected e;
    std::map<std::string, std::optional<std::string>> caseValues;
    for (const auto& col : f.entryColumns)
    {
        const auto colon = col.find(':');
        caseValues[col] = lookup(col.substr(0, colon), col.substr(colon + 1));
    }
    for (const auto& r : f.runs)
    {
        if (!r.usable) continue;
        ++e.usableRuns;
        if (e.run) continue;
        bool all = !f.entryColumns.empty();
        for (const auto& col : f.entryColumns)
        {
            const auto& v = caseValues[col];
            all = all && v && sameValue(*v, r.columns.at(col));
        }
        if (all) e.run = &r;
    }
    if (!e.run) return e;
    e.onFront = true;
    for (const auto& q : f.runs)
    {
        if (!q.usable || &q == e.run) continue;
        const bool dominates = q.solverTime <= e.run->solverTime && q.error <= e.run->error
            && (q.solverTime < e.run->solverTime || q.error < e.run->error);
        if (dominates)
        {
            e.onFront = false;
            if (!e.cheaperAsGood || q.solverTime < e.cheaperAsGood->solverTime) e.cheaperAsGood = &q;
        }
    }
    return e;
}

std::string describe(const AccuracyFront& f, const FrontRun& r)
{
    std::string s;
    for (const auto& p : f.parameters)
    {
        const auto it = r.columns.find(p);
        if (it == r.columns.end()) continue;
        s += (s.empty() ? "" : ", ") + p + " " + it->second;
    }
    return s;
}

} // namespace accuracy
} // namespace mpm
