#include "choice.H"

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
    const bool given = dict.found(keyword);
    const scalar v = given ? dict.get<scalar>(keyword) : deflt;
    if (!std::isfinite(v) || v < minValue || v > maxValue)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword " << keyword << " = " << v << " is out of range ["
            << minValue << ", " << maxValue << "]"
            << exit(FatalIOError);
    }
    if (echo)
    {
        Info<< "    " << keyword << " " << v << (given ? "" : " (default)") << nl;
    }
    return v;
}
