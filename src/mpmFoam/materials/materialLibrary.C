#include "materialLibrary.H"
#include "IOstreams.H"
#include <sstream>

namespace
{

std::string validModelNames()
{
    return mpm::registryNames(mpm::availableLaws());
}

} // namespace

Foam::materialLibrary::materialLibrary(const dictionary& mpmDict, bool echo)
{
    if (!mpmDict.isDict("materials"))
    {
        FatalIOErrorInFunction(mpmDict)
            << "Missing sub-dictionary materials { name { model ...; } }" << nl
            << "Valid models: " << validModelNames().c_str()
            << exit(FatalIOError);
    }
    const dictionary& mats = mpmDict.subDict("materials");
    for (const entry& e : mats)
    {
        if (!e.isDict()) continue;
        const dictionary& d = e.dict();
        const word name(e.keyword());
        if (!d.found("model"))
        {
            FatalIOErrorInFunction(d)
                << "Material " << name << " has no keyword model" << nl
                << "Valid models: " << validModelNames().c_str()
                << exit(FatalIOError);
        }
        const word model(d.get<word>("model"));
        const mpm::LawInfo* info = mpm::findLaw(model);
        if (!info)
        {
            FatalIOErrorInFunction(d)
                << "Unknown model '" << model << "' for material " << name << nl
                << "Valid models: " << validModelNames().c_str()
                << exit(FatalIOError);
        }

        if (echo) Info<< "Material " << name << ": " << model << " ("
            << info->summary.c_str() << ")" << nl;
        mpm::Coefficients c;
        for (const mpm::Parameter& p : info->parameters)
        {
            const word key(p.name);
            if (!d.found(key))
            {
                if (p.required)
                {
                    FatalIOErrorInFunction(d)
                        << "Missing coefficient " << key << " for material "
                        << name << " (model " << model << "): "
                        << p.description.c_str() << ", valid range "
                        << mpm::rangeText(p).c_str()
                        << exit(FatalIOError);
                }
                c[p.name] = p.defaultValue;
                if (echo) Info<< "    " << key << " " << p.defaultValue
                    << " (default) " << p.description.c_str() << nl;
                continue;
            }
            const scalar v = d.get<scalar>(key);
            if (!mpm::inRange(p, v))
            {
                FatalIOErrorInFunction(d)
                    << "Coefficient " << key << " = " << v << " of material "
                    << name << " (model " << model << ") is out of range "
                    << mpm::rangeText(p).c_str() << ": "
                    << p.description.c_str()
                    << exit(FatalIOError);
            }
            c[p.name] = v;
            if (echo) Info<< "    " << key << " " << v << "  "
                << p.description.c_str() << nl;
        }
        // Let the law check combinations (e.g. dilatancy <= friction).
        try
        {
            mpm::makeLaw(model, c);
        }
        catch (const std::exception& ex)
        {
            FatalIOErrorInFunction(d)
                << "Material " << name << ": " << ex.what()
                << exit(FatalIOError);
        }
        names_.append(name);
        models_.push_back(model);
        coeffs_.push_back(c);
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(mats)
            << "No materials defined" << nl
            << "Valid models: " << validModelNames().c_str()
            << exit(FatalIOError);
    }
}

Foam::label Foam::materialLibrary::index
(
    const word& name,
    const dictionary& context
) const
{
    const label i = names_.find(name);
    if (i < 0)
    {
        FatalIOErrorInFunction(context)
            << "Unknown material '" << name << "'" << nl
            << "Valid materials (from mpmProperties): " << names_
            << exit(FatalIOError);
    }
    return i;
}

std::unique_ptr<mpm::ConstitutiveLaw>
Foam::materialLibrary::create(label i) const
{
    return mpm::makeLaw(models_[i], coeffs_[i]);
}
