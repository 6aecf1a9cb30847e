#include "dragForce.H"
#include "fluidCoupling.H"
#include "floatingPointTraps.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "common/modelRegistry.hpp"

namespace Foam
{
    defineTypeNameAndDebug(dragForce, 0);
    addToRunTimeSelectionTable(solidForce, dragForce, dictionary);
}

Foam::dragForce::dragForce(fluidCoupling& coupling, const dictionary& couplingDict)
:
    solidForce(coupling, couplingDict)
{
    readLaws(coupling.mpm().dict());
}

void Foam::dragForce::readLaws(const dictionary& mpmDict)
{
    const dictionary& mats = mpmDict.subDict("materials");
    const wordList& names = coupling_.mpm().materials().names();
    const scalar h = coupling_.mpm().system().lattice().h;
    dragLaws_.assign(names.size(), nullptr);
    // (model, coefficients) of each distinct law, to share its instance
    std::vector<std::pair<word, mpm::Coefficients>> specs;
    std::vector<std::shared_ptr<const mpm::DragLaw>> laws;
    forAll(names, i)
    {
        const dictionary& md = mats.subDict(names[i]);
        if (!md.found("drag", keyType::LITERAL))
        {
            Info<< "    material " << names[i] << ": no drag" << nl;
            continue;
        }
        const dictionary& dd = optionalSubDict(md, "drag");
        if (!dd.found("model"))
        {
            FatalIOErrorInFunction(dd)
                << "Missing keyword model in drag of material " << names[i] << nl
                << "Valid drag models: " << mpm::registryNames(mpm::availableDragLaws()).c_str()
                << exit(FatalIOError);
        }
        const word model(dd.get<word>("model"));
        // Its keywords are checked with the material's (materialLibrary).
        mpm::Coefficients coeffs;
        for (const entry& e : dd)
        {
            if (e.keyword() != "model") coeffs[e.keyword()] = dd.get<scalar>(e.keyword());
        }
        std::size_t k = 0;
        while (k < specs.size() && !(specs[k].first == model && specs[k].second == coeffs)) ++k;
        if (k == specs.size())
        {
            try
            {
                laws.emplace_back(mpm::makeDragLaw(model, coeffs));
            }
            catch (const std::exception& ex)
            {
                FatalIOErrorInFunction(dd)
                    << "Drag of material " << names[i] << ": " << ex.what()
                    << exit(FatalIOError);
            }
            specs.emplace_back(model, coeffs);
        }
        dragLaws_[i] = laws[k];
        const mpm::DragLaw& law = *laws[k];
        Info<< "    material " << names[i] << ": drag " << model << ", d "
            << law.d() << ", alphaFMin " << law.alphaFMin() << nl;
        if (law.d() > h)
        {
            WarningInFunction
                << "Grain diameter d = " << law.d() << " of material "
                << names[i] << " is larger than the cell size h = " << h
                << " (d/h = " << law.d()/h << "): volume averaging assumes "
                << "grains much smaller than cells" << endl;
        }
    }
    if (laws.empty())
    {
        FatalIOErrorInFunction(mats)
            << "drag is in coupling forces, but no material has a drag "
            << "sub-dictionary { model ...; d ...; }" << nl
            << "Valid drag models: " << mpm::registryNames(mpm::availableDragLaws()).c_str()
            << exit(FatalIOError);
    }
    singleDragLaw_ = true;
    for (const auto& l : dragLaws_) singleDragLaw_ = singleDragLaw_ && l == dragLaws_[0];
    if (!singleDragLaw_)
    {
        Info<< "    beta per cell: the materials' laws weighted by their "
            << "share of the grain volume" << nl;
    }
}

void Foam::dragForce::correct()
{
    mpm::MpmSystem& s = coupling_.mpm().system();
    const labelList& node = coupling_.mpm().lattice().cellNode();
    const fluidPhase& fluid = coupling_.fluid();
    const volVectorField& U = fluid.U();
    // The local density and viscosity (the VOF fluid's mixture; uniform for
    // the single fluid)
    const volScalarField& rho = fluid.rho();
    const volScalarField mu(fluid.mu());
    volScalarField& beta = coupling_.fluid().beta();
    if (!singleDragLaw_) s.materialGrainVolume(materialVolume_);
    // The traps are held off: an extreme but in-range parameter (a grain
    // diameter of 1e-200 m) overflows here, and is reported below, with
    // what to check, rather than as a SIGFPE
    const floatingPointTrapsOff noTraps;
    forAll(node, celli)
    {
        const label I = node[celli];
        const scalar volume = coupling_.grid().volume[I];
        const scalar alphaS = coupling_.cappedAlphaSolid(celli);
        beta[celli] = 0;
        if (alphaS <= 0) continue;
        const scalar slip = mag(U[celli] - coupling_.solidVelocity(celli));
        if (singleDragLaw_)
        {
            beta[celli] = dragLaws_[0]->beta(1 - alphaS, slip, rho[celli], mu[celli]);
            continue;
        }
        forAll(dragLaws_, m)
        {
            const scalar share = materialVolume_[m][I]/volume;
            if (dragLaws_[m] && share > 0)
            {
                beta[celli] += share*dragLaws_[m]->beta(1 - alphaS, slip, rho[celli], mu[celli]);
            }
        }
    }
    checkFinite();
}

void Foam::dragForce::checkFinite() const
{
    const volScalarField& beta = coupling_.fluid().beta();
    const fvMesh& mesh = coupling_.mesh();
    label bad = -1;
    forAll(beta, celli)
    {
        if (!std::isfinite(beta[celli])) { bad = celli; break; }
    }
    if (returnReduce(bad >= 0, orOp<bool>()))
    {
        FatalErrorInFunction
            << "Stopping at time " << mesh.time().timeName() << ": the drag"
            << " coefficient beta is not finite";
        if (bad >= 0)
        {
            FatalError
                << " in cell " << bad << " at " << mesh.C()[bad]
                << " (alpha.solid " << coupling_.cappedAlphaSolid(bad) << ")";
        }
        FatalError
            << "." << nl << "A drag parameter (the grain diameter d, in the "
            << "drag sub-dictionaries of constant/mpmProperties materials) or "
            << "the fluid's nu and rho (constant/transportProperties) give an "
            << "overflow: check their values and units (d in m)."
            << exit(FatalError);
    }
}

void Foam::dragForce::addTo(solidForceTerms& t) const
{
    const volScalarField& beta = coupling_.fluid().beta();
    const volVectorField& U = coupling_.fluid().U();
    const scalarField& V = coupling_.mesh().V();
    forAll(beta, celli)
    {
        const scalar KDrag = beta[celli]*V[celli];
        if (KDrag <= 0) continue;
        if (coupling_.frozenFluid())
        {
            t.K[celli] += KDrag;
            t.KU[celli] += KDrag*U[celli];
            continue;
        }
        // d(force)/dv with the slip's response
        const scalar K = KDrag/coupling_.fluidFraction(celli);
        t.K[celli] += K;
        t.KU[celli] += KDrag*U[celli] + (K - KDrag)*coupling_.solidVelocity(celli);
    }
}

void Foam::dragForce::afterSolids()
{
    if (coupling_.mode() == fluidCoupling::couplingMode::oneWay)
    {
        coupling_.fluid().beta().primitiveFieldRef() = 0;
    }
}
