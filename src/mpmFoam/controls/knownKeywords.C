#include "knownKeywords.H"
#include "IOstreams.H"
#include "DynamicList.H"
#include <algorithm>
#include <cctype>

namespace
{

using namespace Foam;

std::string lower(const std::string& s)
{
    std::string l(s);
    for (char& c : l) c = char(std::tolower(static_cast<unsigned char>(c)));
    return l;
}

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of neighbours ("pis" for "psi") each count one.
label editDistance(const std::string& a, const std::string& b)
{
    const size_t n = a.size(), m = b.size();
    std::vector<std::vector<label>> d(n + 1, std::vector<label>(m + 1, 0));
    for (size_t i = 0; i <= n; ++i) d[i][0] = label(i);
    for (size_t j = 0; j <= m; ++j) d[0][j] = label(j);
    for (size_t i = 1; i <= n; ++i)
    {
        for (size_t j = 1; j <= m; ++j)
        {
            const label cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
            {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

bool alwaysAllowed(const word& key)
{
    return key == "FoamFile" || key[0] == '#' || key[0] == '$';
}

} // namespace

Foam::word Foam::closestWord(const word& given, const wordList& candidates)
{
    // Close: a case-only difference, or at most a third of the candidate's
    // letters changed (one for short words) without changing all of them,
    // so that "x" does not suggest "c".
    const std::string g(lower(given));
    word best;
    label bestDistance = labelMax;
    for (const word& c : candidates)
    {
        const label d = editDistance(g, lower(c));
        const label allowed = max(label(1), label(c.size())/3);
        if (d <= allowed && d < label(c.size()) && d < bestDistance)
        {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

void Foam::checkKeywords
(
    const dictionary& dict,
    const wordList& known,
    const std::string& what
)
{
    const entry* first = nullptr;
    OStringStream unknown;
    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if (alwaysAllowed(key)) continue;
        bool ok = false;
        for (const word& k : known) ok = ok || key.match(k);
        if (ok) continue;
        if (!first) first = &e;
        unknown << "Unknown keyword '" << key.c_str() << "' in " << what.c_str();
        const word close(key.isPattern() ? word::null : closestWord(key, known));
        if (!close.empty()) unknown << "; did you mean '" << close << "'?";
        unknown << nl;
    }
    if (first)
    {
        OStringStream valid;
        for (const word& k : known) valid << ' ' << k;
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), first->startLineNumber(), first->endLineNumber()
        )   << unknown.str().c_str()
            << "Valid keywords:" << valid.str().c_str() << nl
            << "Annotated examples of every keyword: etc/caseDicts"
            << exit(FatalIOError);
    }
}

Foam::wordList Foam::modelKeywords
(
    std::initializer_list<word> before,
    const std::vector<mpm::Parameter>& parameters,
    std::initializer_list<word> after
)
{
    DynamicList<word> keys(before);
    for (const mpm::Parameter& p : parameters) keys.append(word(p.name));
    for (const word& k : after) keys.append(k);
    return wordList(std::move(keys));
}

const Foam::dictionary& Foam::optionalSubDict
(
    const dictionary& dict,
    const word& keyword
)
{
    const entry* e = dict.findEntry(keyword, keyType::LITERAL);
    if (e && !e->isDict())
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), e->startLineNumber(), e->endLineNumber()
        )   << "Keyword " << keyword << " must be a sub-dictionary "
            << keyword << " { ... }" << exit(FatalIOError);
    }
    return e ? e->dict() : dictionary::null;
}

void Foam::checkAllSubDicts(const dictionary& dict, const std::string& what)
{
    for (const entry& e : dict)
    {
        if (e.isDict() || alwaysAllowed(e.keyword())) continue;
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            dict.name(), e.startLineNumber(), e.endLineNumber()
        )   << "Entry '" << e.keyword().c_str() << "' of " << what.c_str()
            << " is not a dictionary: write " << e.keyword().c_str()
            << " { ... }" << exit(FatalIOError);
    }
}
