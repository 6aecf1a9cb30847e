#include "fluidCoupling.H"
#include "choice.H"
#include "knownKeywords.H"
#include "uniformDimensionedFields.H"
#include "step/stepTimers.hpp"
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

const char* responseName(Foam::fluidCoupling::fluidResponse r)
{
    return r == Foam::fluidCoupling::fluidResponse::frozen ? "frozen" : "linearised";
}

bool parseResponse(const std::string& s, Foam::fluidCoupling::fluidResponse& r)
{
    using R = Foam::fluidCoupling::fluidResponse;
    for (auto c : {R::linearised, R::frozen})
    {
        if (s == responseName(c)) { r = c; return true; }
    }
    return false;
}

// A uniform box's cells write node arrays at their own nodes (each node by
// one cell at most, write()); decomposed, a cell's node may be another
// rank's (a balance by points): the arrays are zero elsewhere, so the sum
// into the owners moves each value there, and the copy sends the owners'
// values to every copy
template<class Write>
void writeAtOwners
(
    mpm::MpmSystem& s, const std::vector<mpm::Real*>& arrays, std::size_t n, Write&& write
)
{
    const bool moved = Foam::Pstream::parRun();
    if (moved) for (mpm::Real* a : arrays) std::fill(a, a + n, 0.0);
    write();
    if (!moved) return;
    s.sumToOwners(arrays);
    s.copyToHalo(arrays);
}

} // namespace

Foam::fluidCoupling::fluidCoupling(const fvMesh& mesh, mpmModel& mpm, fluidPhase& fluid)
:
    mesh_(mesh),
    mpm_(mpm),
    fluid_(fluid),
    g_("g", dimAcceleration, Zero),
    terms_(mesh.nCells())
{
    const dictionary& mpmDict = mpm.dict();
    overlaps_ = !mpm.lattice().cellsAreNodes();
    // A rebalance makes the node arrays again: between fluid steps, not
    // inside the solids' sub-cycles (advanceSolids)
    mpm.rebalanceBetweenFluidSteps();
    prepareExchange();
    if (!mpmDict.isDict("coupling"))
    {
        FatalIOErrorInFunction(mpmDict)
            << "The case has a fluid (constant/transportProperties, 0/U) but "
            << "mpmProperties has no coupling { mode ...; forces (...); }" << nl
            << "Valid modes: oneWay twoWayMomentum twoWay; valid forces: "
            << spaceSeparated(solidForce::names()).c_str() << exit(FatalIOError);
    }
    const dictionary& d = mpmDict.subDict("coupling");
    Info<< "Fluid coupling:" << nl;
    if (overlaps_ && !Pstream::parRun()) reportCoverage();
    mode_ = readChoice(d, "mode", parseMode, modeName, "oneWay twoWayMomentum twoWay", couplingMode::twoWay);
    // frozen: the scheme before the linearised response, unstable for
    // lifted beds (docs/stabilityAnalysis.md section 7b); an analysis aid
    response_ = readChoice(d, "fluidResponse", parseResponse, responseName, "linearised frozen", fluidResponse::linearised);
    forceNames_ = d.get<wordList>("forces");
    // Each force's own keywords are known only once it is selected
    wordList known({"mode", "forces", "alphaMax", "subCycles", "fluidResponse", "timeStepAdvice"});
    checkSelection(forceNames_, solidForce::names(), d, "force", "forces");
    Info<< "    forces " << forceNames_ << " (others are not computed)" << nl;
    // Below 1: the fluid keeps a share of every cell (alpha.fluid >= 1 -
    // alphaMax divides the pressure equation and the drag)
    alphaMax_ = readBounded(d, "alphaMax", 0.63, numberRange{0, 1, false, false});
    // Off by default: the analysis costs seconds with hundreds of
    // sub-cycles (docs/stabilityAnalysis.md section 7b.7)
    timeStepAdvice_ = d.getOrDefault<bool>("timeStepAdvice", false);
    Info<< "    timeStepAdvice " << (timeStepAdvice_ ? "yes" : "no") << nl;
    const entry* sc = d.findEntry("subCycles", keyType::LITERAL);
    if (sc && !(sc->stream()[0].isWord() && sc->stream()[0].wordToken() == "auto"))
    {
        subCycles_ = label(readBounded(d, "subCycles", 1, 1, 1e6));
    }
    else
    {
        Info<< "    subCycles auto (from the MPM stable time step)" << nl;
    }

    mpm_.system().coupling().addedMassDensity = 0;
    // Grains are incompressible: alpha.solid counts their volume m/rho.
    mpm_.system().setConstantGrainVolume(true);
    // Neither phase has gravity unless the gravity force sets it
    mpm_.system().setGravity({0, 0, 0});

    forces_.setSize(forceNames_.size());
    forceTime_.setSize(forceNames_.size(), Zero);
    forAll(forceNames_, i)
    {
        forces_.set(i, solidForce::New(forceNames_[i], *this, d));
        known.append(forces_[i].keywords());
    }
    checkKeywords(d, known, "coupling");
    if (!forceNames_.found("gravity")) Info<< "    no gravity (not in forces)" << nl;
    Info<< endl;
    mapSolids();                    // alpha.solid from the grain volumes
}

void Foam::fluidCoupling::prepareExchange()
{
    mpmModel& mpm = mpm_;
    // Coupling arrays on the padded lattice; zero on ghosts.
    mpm.system().coupling().resize(mpm.system().lattice().nNodes);
    if (!overlaps_) return;
    // Decomposed, a rank's cells overlap copies of the exchange halo: the
    // coverage is summed into the owners and sent back
    const std::vector<double>& local = mpm.lattice().coverage();
    coverage_.assign(local.begin(), local.end());
    mpm.system().sumToOwners({coverage_.data()});
    mpm.system().copyToHalo({coverage_.data()});
    mpm.system().setCoverage(coverage_);
    // Each node's sum of its overlaps' fractions (the mesh does not
    // move): the denominators of the cells' averages onto the nodes
    overlapWeight_.assign(coverage_.size(), 0.0);
    forAll(mesh_.cells(), celli)
    {
        mpm.lattice().forEachOverlap(celli, [&](label I, scalar T) { overlapWeight_[I] += T; });
    }
    mpm.system().sumToOwners({overlapWeight_.data()});
    mpm.system().copyToHalo({overlapWeight_.data()});
}

void Foam::fluidCoupling::reportCoverage() const
{
    // The overlaps are exact: a lattice cell inside the mesh is covered
    // to round-off, and its points keep their plain P2G grain volume
    label full = 0, part = 0;
    const mpm::Lattice& L = mpm_.system().lattice();
    for (int k = 0; k < L.nCells[2]; ++k)
    for (int j = 0; j < L.nCells[1]; ++j)
    for (int i = 0; i < L.nCells[0]; ++i)
    {
        const scalar c = coverage_[std::size_t(L.realNode(i, j, k))];
        if (mag(c - 1) <= mpm::MpmSystem::fullCoverage) ++full;
        else if (c > 0) ++part;
    }
    Info<< "    lattice cells inside the mesh: " << full << " fully, "
        << part << " partly (coverage within " << mpm::MpmSystem::fullCoverage
        << " of 1: fully)" << nl;
}

void Foam::fluidCoupling::mapSolids()
{
    mpm::MpmSystem& s = mpm_.system();
    {
        mpm::ScopedTimer timer(p2gTime_);
        s.mapToGrid(overlaps_ ? &nodeGrainVolume_ : nullptr);
    }
    mpm::ScopedTimer timer(mapsTime_);
    grid_ = s.sampleGrid();
    if (overlaps_)
    {
        s.spreadGrainVolume(nodeGrainVolume_);
        s.sumToOwners({nodeGrainVolume_.data()});
        s.copyToHalo({nodeGrainVolume_.data()});
    }
    updateFluidFraction();
}

const Foam::solidForce* Foam::fluidCoupling::findForce(const word& name) const
{
    const label i = forceNames_.find(name);
    return i < 0 ? nullptr : &forces_[i];
}

void Foam::fluidCoupling::setGravity(const vector& g)
{
    g_.value() = g;
    mpm_.system().setGravity({g.x(), g.y(), g.z()});
}

Foam::vector Foam::fluidCoupling::solidVelocity(label celli) const
{
    const auto& v = grid_.velocity;
    if (overlaps_) return overlapAverage(celli, v);
    const label I = mpm_.lattice().cellNode()[celli];
    return vector(v[0][I], v[1][I], v[2][I]);
}

Foam::vector Foam::fluidCoupling::overlapAverage
(
    label celli, const std::array<const mpm::Real*, 3>& a
) const
{
    vector u(Zero);
    mpm_.lattice().forEachOverlap(celli, [&](label I, scalar T)
    {
        u += T*vector(a[0][I], a[1][I], a[2][I]);
    });
    return u;
}

void Foam::fluidCoupling::cellsToLattice
(
    const vectorField& f, std::array<std::vector<mpm::Real>, 3>& out
) const
{
    if (overlaps_)
    {
        cellsToNodes(f, out);
        return;
    }
    const labelList& node = mpm_.lattice().cellNode();
    writeAtOwners(mpm_.system(), {out[0].data(), out[1].data(), out[2].data()}, out[0].size(), [&]
    {
        forAll(node, celli)
        {
            for (int k = 0; k < 3; ++k) out[k][node[celli]] = f[celli][k];
        }
    });
}

void Foam::fluidCoupling::cellsToNodes
(
    const vectorField& f, std::array<std::vector<mpm::Real>, 3>& out
) const
{
    for (auto& a : out) std::fill(a.begin(), a.end(), 0.0);
    forAll(f, celli)
    {
        mpm_.lattice().forEachOverlap(celli, [&](label I, scalar T)
        {
            for (int k = 0; k < 3; ++k) out[k][I] += T*f[celli][k];
        });
    }
    // Decomposed: every rank's cells' share, then the average on every copy
    mpm::MpmSystem& s = mpm_.system();
    s.sumToOwners({out[0].data(), out[1].data(), out[2].data()});
    for (std::size_t I = 0; I < overlapWeight_.size(); ++I)
    {
        if (overlapWeight_[I] > 0) for (auto& a : out) a[I] /= overlapWeight_[I];
    }
    s.copyToHalo({out[0].data(), out[1].data(), out[2].data()});
}

Foam::List<Foam::Tuple2<Foam::word, Foam::scalar>> Foam::fluidCoupling::costs() const
{
    List<Tuple2<word, scalar>> c(forces_.size() + 1);
    forAll(forces_, i)
    {
        c[i] = Tuple2<word, scalar>("force " + forceNames_[i], forceTime_[i]);
    }
    c.last() = Tuple2<word, scalar>("coupling P2G", p2gTime_);
    c.append(Tuple2<word, scalar>("coupling maps", mapsTime_));
    c.append(Tuple2<word, scalar>("coupling solid flux", solidFluxTime_));
    return c;
}

Foam::scalar Foam::fluidCoupling::alphaSolid(label celli) const
{
    if (overlaps_)
    {
        // The grain volume of each overlapped lattice cell, spread evenly
        // over it: the cell's share is its overlap
        scalar a = 0;
        mpm_.lattice().forEachOverlap(celli, [&](label I, scalar T)
        {
            a += T*nodeGrainVolume_[I];
        });
        return a/mpm_.lattice().cellVolume();
    }
    return grid_.volume[mpm_.lattice().cellNode()[celli]]/mesh_.V()[celli];
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
        // fluidFraction(celli), from the alpha.solid just computed
        aF[celli] = volumeCoupled() ? 1 - min(alphaS, alphaMax_) : 1;
    }
    alphaF.correctBoundaryConditions();
    if (overlaps_ && mpm_.logThisStep())
    {
        // The cells receive the points' grain volume exactly (before the
        // cap at alphaMax): the exchange's conservation, in the log
        scalar cells = 0, points = 0;
        forAll(node, celli) cells += alphaSolid(celli)*mesh_.V()[celli];
        const mpm::Particles& P = mpm_.system().particles();
        for (mpm::Index p = 0; p < P.size(); ++p)
        {
            points += P.mass[p]/mpm_.system().material(P.material[p]).rho0();
        }
        reduce(cells, sumOp<scalar>());
        reduce(points, sumOp<scalar>());
        Info<< "Grain volume: cells " << cells << ", points " << points
            << ", relative difference " << (points > 0 ? cells/points - 1 : 0) << nl;
    }
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

void Foam::fluidCoupling::termsToLattice()
{
    auto& c = mpm_.system().coupling();
    const labelList& node = mpm_.lattice().cellNode();
    const volVectorField& U = fluid_.U();
    if (overlaps_)
    {
        // K_I = sum_c T_cI K_c and K_I U_I = sum_c T_cI (K U)_c: the drag
        // the nodes receive is what the cells give, with the cells' solid
        // velocity the same overlap average (solidVelocity); the force per
        // solid volume F is an overlap average. U enters the MPM only as
        // K U, so it is zero where K is. One pass over the overlaps, one
        // halo sum, one copy.
        auto& a = nodeSums_;
        for (auto& v : a) v.assign(c.K.size(), 0.0);
        forAll(node, celli)
        {
            const scalar K = terms_.K[celli];
            const vector& KU = terms_.KU[celli];
            const vector& F = terms_.F[celli];
            mpm_.lattice().forEachOverlap(celli, [&](label I, scalar T)
            {
                a[0][I] += T*K;
                for (int k = 0; k < 3; ++k)
                {
                    a[1 + k][I] += T*KU[k];
                    a[4 + k][I] += T*F[k];
                }
            });
        }
        std::vector<mpm::Real*> all;
        for (auto& v : a) all.push_back(v.data());
        mpm::MpmSystem& s = mpm_.system();
        s.sumToOwners(all);
        for (std::size_t I = 0; I < c.K.size(); ++I)
        {
            const scalar w = overlapWeight_[I], K = a[0][I];
            c.K[I] = K;
            for (int k = 0; k < 3; ++k)
            {
                c.U[k][I] = K > 0 ? a[1 + k][I]/K : 0;
                c.F[k][I] = w > 0 ? a[4 + k][I]/w : 0;
            }
        }
        s.copyToHalo
        ({
            c.K.data(), c.U[0].data(), c.U[1].data(), c.U[2].data(),
            c.F[0].data(), c.F[1].data(), c.F[2].data()
        });
        return;
    }
    const std::vector<mpm::Real*> all
    {
        c.K.data(), c.U[0].data(), c.U[1].data(), c.U[2].data(),
        c.F[0].data(), c.F[1].data(), c.F[2].data()
    };
    writeAtOwners(mpm_.system(), all, c.K.size(), [&]
    {
        forAll(node, celli)
        {
            const label I = node[celli];
            const scalar K = terms_.K[celli];
            c.K[I] = K;
            for (int k = 0; k < 3; ++k)
            {
                c.U[k][I] = K > 0 ? terms_.KU[celli][k]/K : U[celli][k];
                c.F[k][I] = terms_.F[celli][k];
            }
        }
    });
}

void Foam::fluidCoupling::advanceSolids(scalar dt)
{
    // The points out of balance: the lattice partitioned again, its node
    // arrays made again, the solids mapped on it
    if (mpm_.rebalance())
    {
        prepareExchange();
        mapSolids();
    }
    mpm::MpmSystem& s = mpm_.system();
    auto& c = s.coupling();

    // The forces' terms from the state at the start of the step: the
    // lattice already holds it (mapped at the end of the previous step, or
    // by the constructor), so no P2G is repeated here. Every force updates
    // before any adds (the pressure response uses the drag's beta).
    forAll(forces_, i)
    {
        mpm::ScopedTimer timer(forceTime_[i]);
        forces_[i].correct();
    }
    terms_.reset();
    forAll(forces_, i)
    {
        mpm::ScopedTimer timer(forceTime_[i]);
        forces_[i].addTo(terms_);
    }
    {
        mpm::ScopedTimer timer(mapsTime_);
        termsToLattice();
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
    mapSolids();
    tmp<volVectorField> tUs;
    {
        mpm::ScopedTimer timer(mapsTime_);
        tUs = tmp<volVectorField>::New(fluid_.Us());
        volVectorField& Us = tUs.ref();
        const labelList& node = mpm_.lattice().cellNode();
        // A cell may overlap a halo copy that no point of this rank reached:
        // the owners' integrals, on every copy
        if (overlaps_ || Pstream::parRun())
        {
            s.copyToHalo({c.velocityIntegral[0].data(), c.velocityIntegral[1].data(), c.velocityIntegral[2].data()});
        }
        forAll(node, celli)
        {
            if (overlaps_)
            {
                // The overlap average, as the drag was given to the nodes
                Us[celli] = overlapAverage
                (
                    celli,
                    {c.velocityIntegral[0].data(), c.velocityIntegral[1].data(), c.velocityIntegral[2].data()}
                )/c.time;
                continue;
            }
            const label I = node[celli];
            for (int k = 0; k < 3; ++k) Us[celli][k] = c.velocityIntegral[k][I]/c.time;
        }
        Us.correctBoundaryConditions();
    }
    {
        mpm::ScopedTimer timer(solidFluxTime_);
        fluid_.setSolid(tUs(), capped_);
    }
    forAll(forces_, i)
    {
        mpm::ScopedTimer timer(forceTime_[i]);
        forces_[i].afterSolids();
    }
    fluid_.beta().correctBoundaryConditions();
}
