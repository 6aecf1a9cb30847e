#include "materialLibrary.H"
#include "IOstreams.H"
#include "knownKeywords.H"
#include "drag/dragLaw.hpp"
#include <cmath>
#include <sstream>

namespace
{

std::string validModelNames()
{
    return mpm::registryNames(mpm::availableLaws());
}

// "; did you mean 'druckerPrager'?" for a near miss (a difference of case
// alone included), or nothing
std::string modelSuggestion(const Foam::word& given)
{
    using namespace Foam;
    wordList names;
    std::istringstream is(validModelNames());
    for (std::string n; is >> n;)
    {
        if (!n.empty() && n.back() == ',') n.pop_back();
        names.append(word(n));
    }
    const word close(closestWord(given, names));
    return close.empty() ? "" : "; did you mean '" + close + "'?";
}

// The keywords of a material's drag sub-dictionary, checked here with the
// material's own (coupled or not, and in mpmSetParticles too) rather than
// only when a coupled run reads it. An unknown or missing drag model is
// reported by fluidCoupling, which lists the valid ones.
void checkDragKeywords(const Foam::dictionary& material, const std::string& name)
{
    using namespace Foam;
    const dictionary& dd = optionalSubDict(material, "drag");
    const word model(dd.getOrDefault<word>("model", word::null));
    if (const mpm::DragLawInfo* info = mpm::findDragLaw(model))
    {
        checkKeywords
        (
            dd, modelKeywords({"model"}, info->parameters),
            "drag of material " + name + " (model " + model + ")"
        );
    }
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
    checkAllSubDicts(mats, "materials (one sub-dictionary per material)");
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
                << "Unknown model '" << model << "' for material " << name
                << modelSuggestion(model).c_str() << nl
                << "Valid models: " << validModelNames().c_str()
                << exit(FatalIOError);
        }

        // The law knows its coefficients; drag is read by fluidCoupling
        // (coupled cases only) and checked there against the drag law.
        checkKeywords
        (
            d, modelKeywords({"model"}, info->parameters, {"drag"}),
            "material " + name + " (model " + model + ")"
        );
        checkDragKeywords(d, name);

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
                if (std::isnan(p.defaultValue))
                {
                    // One of alternatives (druckerPrager: phi or mu), left
                    // to the law: a NaN must not reach a comparison here,
                    // which traps under FOAM_SIGFPE
                    if (echo) Info<< "    " << key << " (not given) " << p.description.c_str() << nl;
                    continue;
                }
                c[p.name] = p.defaultValue;
                if (echo)
                {
                    Info<< "    " << key << " " << p.defaultValue
                        << " (default) " << p.description.c_str() << nl;
                }
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
            const std::string note = mpm::makeLaw(model, c)->note();
            if (echo && !note.empty()) Info<< "    " << note.c_str() << nl;
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
