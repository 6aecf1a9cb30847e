#include "fluidCoupling.H"
#include "choice.H"
#include "knownKeywords.H"
#include "uniformDimensionedFields.H"
#include "Tuple2.H"
#include "floatingPointTraps.H"
#include <cmath>

namespace
{

const char* modeName(Foam::fluidCoupling::couplingMode m)
{
    switch (m)
    {
        case Foam::fluidCoupling::couplingMode::oneWay: return "oneWay";
        case Foam::fluidCoupling::couplingMode::twoWayMomentum: return "twoWayMomentum";
        default: return "twoWay";
    }
}

bool parseMode(const std::string& s, Foam::fluidCoupling::couplingMode& m)
{
    using M = Foam::fluidCoupling::couplingMode;
    for (auto c : {M::oneWay, M::twoWayMomentum, M::twoWay})
    {
        if (s == modeName(c)) { m = c; return true; }
    }
    return false;
}

} // namespace

Foam::fluidCoupling::fluidCoupling(const fvMesh& mesh, mpmModel& mpm, fluidPhase& fluid)
:
    mesh_(mesh),
    mpm_(mpm),
    fluid_(fluid),
    g_("g", dimAcceleration, Zero)
{
    const dictionary& mpmDict = mpm.dict();
    if (!mpmDict.isDict("coupling"))
    {
        FatalIOErrorInFunction(mpmDict)
            << "The case has a fluid (constant/transportProperties, 0/U) but "
            << "mpmProperties has no coupling { mode ...; forces (...); }" << nl
            << "Valid modes: oneWay twoWayMomentum twoWay; valid forces: "
            << "drag pressureGradient gravity virtualMass" << exit(FatalIOError);
    }
    const dictionary& d = mpmDict.subDict("coupling");
    checkKeywords(d, {"mode", "forces", "alphaMax", "subCycles", "Cvm"}, "coupling");
    Info<< "Fluid coupling:" << nl;
    mode_ = readChoice(d, "mode", parseMode, modeName, "oneWay twoWayMomentum twoWay", couplingMode::twoWay);

    const wordList forces(d.get<wordList>("forces"));
    for (const word& f : forces)
    {
        if (f == "drag") drag_ = true;
        else if (f == "pressureGradient") pressureGradient_ = true;
        else if (f == "gravity") gravity_ = true;
        else if (f == "virtualMass") virtualMass_ = true;
        else
        {
            FatalIOErrorInFunction(d)
                << "Unknown force '" << f << "' in forces" << nl
                << "Valid forces: drag pressureGradient gravity virtualMass"
                << exit(FatalIOError);
        }
    }
    Info<< "    forces " << forces << " (others are not computed)" << nl;
    // Below 1: the fluid keeps a share of every cell (alpha.fluid >= 1 -
    // alphaMax divides the pressure equation and the drag)
    alphaMax_ = readBounded(d, "alphaMax", 0.63, numberRange{0, 1, false, false});
    const entry* sc = d.findEntry("subCycles", keyType::LITERAL);
    if (sc && !(sc->stream()[0].isWord() && sc->stream()[0].wordToken() == "auto"))
    {
        subCycles_ = label(readBounded(d, "subCycles", 1, 1, 1e6));
    }
    else
    {
        Info<< "    subCycles auto (from the MPM stable time step)" << nl;
    }

    if (virtualMass_)
    {
        // Added mass of a sphere: 0.5 (Auton, Hunt & Prud'homme 1988)
        Cvm_ = readBounded(d, "Cvm", 0.5, 0, 10);
        fluid_.enableVirtualMass(Cvm_, mode_ != couplingMode::oneWay);
    }
    if (drag_) readDrag(mpmDict);

    // Gravity: from constant/g, for both phases, only if listed.
    // Grains are incompressible: alpha.solid counts their volume m/rho.
    mpm_.system().setConstantGrainVolume(true);
    if (gravity_)
    {
        const uniformDimensionedVectorField g
        (
            IOobject("g", mesh.time().constant(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE)
        );
        g_.value() = g.value();
    }
    else
    {
        mpm_.system().setGravity({0, 0, 0});
        Info<< "    no gravity (not in forces)" << nl;
    }

    // Coupling arrays on the padded lattice; zero on ghosts.
    auto& c = mpm_.system().coupling();
    const label nNodes = label(mpm_.system().lattice().nNodes);
    c.K.assign(nNodes, 0.0);
    for (int k = 0; k < 3; ++k)
    {
        c.U[k].assign(nNodes, 0.0);
        c.F[k].assign(nNodes, 0.0);
        c.velocityIntegral[k].assign(nNodes, 0.0);
        if (virtualMass_) c.fluidAcceleration[k].assign(nNodes, 0.0);
    }
    c.addedMassDensity = virtualMass_ ? Cvm_*fluid_.rho().value() : 0;
    Info<< endl;
    mpm_.system().mapToGrid();      // alpha.solid from the grain volumes
    updateFluidFraction();
}

void Foam::fluidCoupling::readDrag(const dictionary& mpmDict)
{
    const dictionary& mats = mpmDict.subDict("materials");
    const wordList& names = mpm_.materials().names();
    const scalar h = mpm_.system().lattice().h;
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

Foam::scalar Foam::fluidCoupling::alphaSolid(label celli) const
{
    return mpm_.system().grid().volume[mpm_.lattice().cellNode()[celli]]/mesh_.V()[celli];
}

void Foam::fluidCoupling::updateBeta()
{
    mpm::MpmSystem& s = mpm_.system();
    const labelList& node = mpm_.lattice().cellNode();
    const volVectorField& U = fluid_.U();
    const scalar rhoF = fluid_.rho().value();
    const volScalarField mu(fluid_.mu());
    volScalarField& beta = fluid_.beta();
    if (!singleDragLaw_) s.materialGrainVolume(materialVolume_);
    // The traps are held off: an extreme but in-range parameter (a grain
    // diameter of 1e-200 m) overflows here, and is reported below, with
    // what to check, rather than as a SIGFPE
    const floatingPointTrapsOff noTraps;
    forAll(node, celli)
    {
        const label I = node[celli];
        const scalar volume = s.grid().volume[I];
        const scalar alphaS = cappedAlphaSolid(celli);
        beta[celli] = 0;
        if (alphaS <= 0) continue;
        const vector Us(s.grid().velocity[0][I], s.grid().velocity[1][I], s.grid().velocity[2][I]);
        const scalar slip = mag(U[celli] - Us);
        if (singleDragLaw_)
        {
            beta[celli] = dragLaws_[0]->beta(1 - alphaS, slip, rhoF, mu[celli]);
            continue;
        }
        forAll(dragLaws_, m)
        {
            const scalar share = materialVolume_[m][I]/volume;
            if (dragLaws_[m] && share > 0)
            {
                beta[celli] += share*dragLaws_[m]->beta(1 - alphaS, slip, rhoF, mu[celli]);
            }
        }
    }
    label bad = -1;
    forAll(beta, celli)
    {
        if (!std::isfinite(beta[celli])) { bad = celli; break; }
    }
    if (returnReduce(bad >= 0, orOp<bool>()))
    {
        FatalErrorInFunction
            << "Stopping at time " << mesh_.time().timeName() << ": the drag"
            << " coefficient beta is not finite";
        if (bad >= 0)
        {
            FatalError
                << " in cell " << bad << " at " << mesh_.C()[bad]
                << " (alpha.solid " << cappedAlphaSolid(bad) << ")";
        }
        FatalError
            << "." << nl << "A drag parameter (the grain diameter d, in the "
            << "drag sub-dictionaries of constant/mpmProperties materials) or "
            << "the fluid's nu and rho (constant/transportProperties) give an "
            << "overflow: check their values and units (d in m)."
            << exit(FatalError);
    }
}

void Foam::fluidCoupling::updateFluidFraction()
{
    const labelList& node = mpm_.lattice().cellNode();
    volScalarField& alphaF = fluid_.alpha();
    // primitiveFieldRef() keeps the previous fluid fraction as the old time
    // (d(alphaF)/dt); writing through operator[] alone would not.
    scalarField& aF = alphaF.primitiveFieldRef();
    label capped = 0;
    capped_.setSize(mesh_.nCells());
    capped_ = false;
    scalar maxAlphaS = 0;
    label maxCell = -1;
    forAll(node, celli)
    {
        const scalar alphaS = alphaSolid(celli);
        if (alphaS > maxAlphaS) { maxAlphaS = alphaS; maxCell = celli; }
        if (alphaS > alphaMax_) { ++capped; capped_[celli] = true; }
        aF[celli] = mode_ == couplingMode::twoWay ? 1 - min(alphaS, alphaMax_) : 1.0;
    }
    alphaF.correctBoundaryConditions();
    // Over all processors: the count, the largest alpha.solid and where,
    // and the first maxListed capped cells (each rank's first ones, in
    // processor order).
    const label maxListed = 10;
    const label cappedAll = returnReduce(capped, sumOp<label>());
    if (cappedAll)
    {
        const scalar maxAll = returnReduce(maxAlphaS, maxOp<scalar>());
        vector where(maxCell >= 0 && maxAlphaS == maxAll ? mesh_.C()[maxCell] : vector::uniform(-GREAT));
        reduce(where, maxOp<vector>());
        List<List<Tuple2<point, scalar>>> listed(Pstream::nProcs());
        auto& mine = listed[Pstream::myProcNo()];
        forAll(capped_, celli)
        {
            if (!capped_[celli]) continue;
            if (mine.size() == maxListed) break;
            mine.append(Tuple2<point, scalar>(mesh_.C()[celli], alphaSolid(celli)));
        }
        Pstream::gatherList(listed);
        Info<< "alphaMax " << alphaMax_ << " reached at time "
            << mesh_.time().timeName() << " in " << cappedAll << " cells; max "
            << "alpha.solid " << maxAll << " at " << where << nl
            << "    capped cells (centre alpha.solid):";
        label shown = 0;
        for (const auto& l : listed)
        {
            for (const auto& c : l)
            {
                if (shown == maxListed) break;
                Info<< ' ' << c.first() << ' ' << c.second();
                ++shown;
            }
        }
        if (cappedAll > shown) Info<< " ... and " << cappedAll - shown << " more";
        Info<< nl;
    }
}

void Foam::fluidCoupling::advanceSolids(scalar dt)
{
    mpm::MpmSystem& s = mpm_.system();
    auto& c = s.coupling();
    const labelList& node = mpm_.lattice().cellNode();
    const volVectorField& U = fluid_.U();
    const scalar rhoF = fluid_.rho().value();

    // Drag coefficient per cell from the state at the start of the step: the
    // lattice already holds it (mapped at the end of the previous step, or
    // by the constructor), so no P2G is repeated here.
    volScalarField& beta = fluid_.beta();
    if (drag_) updateBeta();
    const volVectorField gradp(fluid_.gradp());
    // The fluid's response to the solids, taken implicitly (a linearised
    // partial elimination). Over the fluid step U and grad p are frozen,
    // but a change dv of the solid velocity would change both:
    //  * twoWay: the mixture flux aS v + aF U is divergence-free and set by
    //    the last pressure solve; holding it, rather than U, fixed gives
    //    dU = -(aS/aF) dv, so the slip changes by -dv/aF;
    //  * with buoyancy: the fluid's grad p carries the drag reaction,
    //    aF grad p ~ -beta (U - Us)/rho, so the grains' force
    //    -aS rho grad p changes by (aS/aF) beta d(slip).
    // With both, d(force)/dv = -beta V/aF^2, which is K below, and
    //   K U_c = beta V U + (K - beta V) v0
    // (v0: solid velocity at the start of the step) leaves the steady state
    // unchanged, where v = v0. Freezing U alone made the next fluid step
    // undo the grains' motion with gain -aS/aF: lifting beds (aS ~ 0.5)
    // oscillated every fluid step (docs/coupling.md).
    const bool volumeCoupled = mode_ == couplingMode::twoWay;
    const bool pressureResponse = pressureGradient_ && mode_ != couplingMode::oneWay;
    forAll(node, celli)
    {
        const label I = node[celli];
        const scalar V = mesh_.V()[celli];
        const scalar KDrag = drag_ ? beta[celli]*V : 0;
        const scalar aS = cappedAlphaSolid(celli);
        const scalar aF = volumeCoupled ? 1 - aS : 1;
        const scalar slipPerDv = volumeCoupled ? 1/aF : 1;
        const scalar K = KDrag*slipPerDv*(1 + (pressureResponse ? aS/aF : 0));
        c.K[I] = K;
        for (int k = 0; k < 3; ++k)
        {
            const scalar v0 = s.grid().velocity[k][I];
            c.U[k][I] = K > 0 ? (KDrag*U[celli][k] + (K - KDrag)*v0)/K : U[celli][k];
            c.F[k][I] = pressureGradient_ ? -rhoF*gradp[celli][k] : 0;
        }
    }

    if (virtualMass_)
    {
        // DU/Dt of the fluid over its last step, frozen over the sub-cycles
        const volVectorField& DUDt = fluid_.DUDt();
        forAll(node, celli)
        {
            for (int k = 0; k < 3; ++k) c.fluidAcceleration[k][node[celli]] = DUDt[celli][k];
        }
    }

    // Sub-cycle the solids over the fluid step
    label n = subCycles_;
    if (n == 0)
    {
        const scalar dtMpm = mpm_.deltaT();
        n = max(label(1), label(std::ceil(dt/dtMpm - 1e-9)));
    }
    else
    {
        mpm_.warnIfAboveCourantLimit(dt/n, "coupling subCycles");
    }
    lastSubCycles_ = n;
    c.resetIntegral();
    for (label i = 0; i < n; ++i) mpm_.evolve(dt/n);

    // Hand the solid state to the fluid
    s.mapToGrid();
    updateFluidFraction();
    volVectorField Us(fluid_.Us());
    forAll(node, celli)
    {
        const label I = node[celli];
        for (int k = 0; k < 3; ++k) Us[celli][k] = c.velocityIntegral[k][I]/c.time;
        if (mode_ == couplingMode::oneWay) beta[celli] = 0;
    }
    Us.correctBoundaryConditions();
    beta.correctBoundaryConditions();
    fluid_.setSolid(Us, capped_);
    if (virtualMass_ && mode_ != couplingMode::oneWay)
    {
        // The fluid's share, -Cvm aS rho_f (DU/Dt - dUs/dt), with aS here
        // even in twoWayMomentum (where the fluid's own aF is 1)
        volScalarField::Internal alphaS
        (
            IOobject("alphaS.virtualMass", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedScalar(dimless, Zero)
        );
        forAll(node, celli)
        {
            alphaS[celli] = cappedAlphaSolid(celli);
        }
        fluid_.setVirtualMassFraction(alphaS);
    }
}
