#include "choice.H"
#include "knownKeywords.H"
#include <sstream>
#include <cctype>
#include <cmath>

bool Foam::numberRange::contains(scalar v) const
{
    return std::isfinite(v)
        && (minIncluded ? v >= min : v > min)
        && (maxIncluded ? v <= max : v < max);
}

Foam::Ostream& Foam::operator<<(Ostream& os, const numberRange& r)
{
    // GREAT and labelMax stand for "no upper limit"
    os  << (r.minIncluded ? "[" : "(") << r.min << ", ";
    if (r.max >= GREAT) os << "inf)";
    else os << r.max << (r.maxIncluded ? "]" : ")");
    return os;
}

void Foam::checkInRange
(
    const dictionary& dict,
    const word& keyword,
    scalar v,
    const numberRange& range,
    const std::string& what
)
{
    if (!range.contains(v))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << keyword << " = " << v << " is out of range "
            << range << what.c_str()
            << exit(FatalIOError);
    }
}

Foam::scalar Foam::readBounded
(
    const dictionary& dict,
    const word& keyword,
    scalar deflt,
    const numberRange& range,
    bool echo
)
{
    const bool given = dict.found(keyword);
    const scalar v = given ? dict.get<scalar>(keyword) : deflt;
    checkInRange(dict, keyword, v, range);
    if (echo)
    {
        Info<< "    " << keyword << " " << v << (given ? "" : " (default)") << nl;
    }
    return v;
}

Foam::scalar Foam::readBounded
(
    const dictionary& dict,
    const word& keyword,
    scalar deflt,
    scalar minValue,
    scalar maxValue,
    bool echo
)
{
    return readBounded(dict, keyword, deflt, numberRange{minValue, maxValue}, echo);
}

std::string Foam::spaceSeparated(const wordList& words)
{
    std::string s;
    for (const word& w : words) s += (s.empty() ? "" : " ") + w;
    return s;
}

void Foam::checkSelection
(
    const wordList& selected,
    const wordList& valid,
    const dictionary& dict,
    const word& what,
    const word& keyword
)
{
    forAll(selected, i)
    {
        if (!valid.found(selected[i]))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown " << what << " '" << selected[i] << "' in "
                << keyword << nl << "Valid " << what << "s: "
                << spaceSeparated(valid).c_str() << exit(FatalIOError);
        }
        if (selected.find(selected[i]) != i)
        {
            std::string What(what);
            What[0] = std::toupper(What[0]);
            FatalIOErrorInFunction(dict)
                << What.c_str() << " '" << selected[i] << "' listed twice in "
                << keyword << " " << selected << exit(FatalIOError);
        }
    }
}


std::string Foam::choiceSuggestion(const word& given, const char* validNames)
{
    wordList names;
    std::istringstream is(validNames);
    for (std::string n; is >> n;) names.append(word(n));
    const word close(closestWord(given, names));
    return close.empty() ? "" : "; did you mean '" + close + "'?";
}
