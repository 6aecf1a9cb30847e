#include "mpmModel.H"
#include "choice.H"
#include "wallConditions.H"
#include "obstacles.H"
#include "Time.H"
#include "clockTime.H"
#include "floatingPointTraps.H"
#include "compressionCheck.H"
#include <sstream>
#include "completeTimes.H"
#include "meshCellSearch.H"
#include "knownKeywords.H"
#include <omp.h>
#include <cstring>

Foam::mpmModel::mpmModel(const fvMesh& mesh)
:
    mesh_(mesh),
    dict_
    (
        IOobject("mpmProperties", mesh.time().constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    ),
    lattice_(mesh, dict_),
    materials_(dict_),
    controls_(mesh, dict_),
    balance_(optionalSubDict(dict_, "lattice")),
    alphaSolid_
    (
        IOobject("alpha.solid", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh, dimensionedScalar(dimless, Zero)
    ),
    Usolid_
    (
        IOobject("U.solid", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh, dimensionedVector(dimVelocity, Zero)
    )
{
    // Before anything of the start time is read: a half-written time would
    // fail with a parse error, or give points whose fields disagree
    checkTimeComplete(mesh.time());
    lattice_.report(Info);
    reportCourantLimit();
    suspendPoolThreadTraps();
    wordList conditionPatch;
    std::vector<mpm::LevelSetWall> patchWalls;
    const mpm::BoundarySpec walls(readWallConditions(mesh, lattice_, dict_, conditionPatch, patchWalls));
    system_.setup(lattice_.lattice(), walls, controls_.step, decompose(walls));
    setLevelSetWalls(std::move(patchWalls));
    for (label m = 0; m < materials_.size(); ++m)
    {
        system_.materials().push_back(materials_.create(m));
    }

    pointFormat_ = materialPointsFormat::New(dict_, mesh, lattice_, comm_, materials_.names());
    {
        const clockTime timer;
        pointFormat_->read(system_.particles());
        Info<< "Read the material points in "
            << returnReduce(timer.elapsedTime(), maxOp<scalar>()) << " s" << nl;
    }
    const mpm::Particles& P = system_.particles();
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        if (P.material[p] < 0 || P.material[p] >= materials_.size())
        {
            FatalErrorInFunction
                << "Material point " << P.id[p] << " has material index "
                << P.material[p] << " but mpmProperties defines "
                << materials_.size() << " materials " << materials_.names()
                << exit(FatalError);
        }
    }
    checkPointsOutsideObstacles();
    const label outside = returnReduce(label(system_.countOutside()), sumOp<label>());
    if (outside)
    {
        FatalErrorInFunction
            << outside << " material points lie outside the mesh"
            << exit(FatalError);
    }
    // decomposePar places a point by its tracked cell; the lattice owner of
    // a point on a processor face may be the other rank.
    try
    {
        system_.migrate();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    // The lattice's owners by points from the start, whatever the mesh's
    // decomposition
    rebalance(true);
    open_.reset
    (
        new openBoundaries(mesh, lattice_, dict_, materials_, walls, conditionPatch, system_)
    );
    Info<< "Material points: " << returnReduce(label(P.size()), sumOp<label>())
        << ", OpenMP threads: " << omp_get_max_threads();
    if (Pstream::parRun()) Info<< " per processor, processors: " << Pstream::nProcs();
    {
        // What actually runs: a loop shorter than threadMinLoopSize stays on
        // one thread, so a small case uses one whatever OMP_NUM_THREADS says
        const label most = returnReduce(label(P.size()), maxOp<label>());
        const bool openmp = controls_.step.backend == mpm::Backend::openmp;
        if (!openmp)
        {
            Info<< " (backend " << mpm::backendName(controls_.step.backend)
                << ": its point and node loops do not use them)";
        }
        else if (omp_get_max_threads() > 1 && most < label(mpm::MpmSystem::parallelThreshold))
        {
            Info<< " (the point loops run on one thread: " << most
                << " points, below threadMinLoopSize "
                << label(mpm::MpmSystem::parallelThreshold) << ")";
        }
    }
    Info<< nl;
    {
        // A friction wall rougher than the material holds it only as hard
        // as the material's own friction (MpmSystem::computeFrictionCap):
        // box walls, mesh patches off the box and obstacles alike
        const scalar most = system_.largestWallFriction();
        const scalar cap = most > 0 ? system_.computeFrictionCap() : GREAT;
        if (most > cap)
        {
            Info<< "Friction walls: coefficients above " << cap << ", the largest friction the"
                << " material mobilises in simple shear, act as " << cap << ": the material next"
                << " to the wall yields first (docs/druckerPrager.md)" << nl;
        }
    }
    // The step's phases, as every back-end runs them (step/stepPlan.hpp)
    Info<< "Step plan: " << system_.plan().describe().c_str() << nl;
    reportBalance(Info);
    Info<< endl;
    system_.mapToGrid();
    updateFields();
    // The series of the point output starts at the start time
    pointFormat_->writeStart(system_.particles());
    readDiagnostics();
}

void Foam::mpmModel::readDiagnostics()
{
    diagnosticNames_ = dict_.getOrDefault<wordList>("diagnostics", wordList({"summary"}));
    Info<< "Diagnostics: " << diagnosticNames_
        << (dict_.found("diagnostics") ? "" : " (default)") << nl << endl;
    diagnostics_.setSize(diagnosticNames_.size());
    diagnosticTime_.setSize(diagnosticNames_.size(), Zero);
    checkSelection(diagnosticNames_, mpmDiagnostic::names(), dict_, "diagnostic", "diagnostics");
    forAll(diagnosticNames_, i)
    {
        diagnostics_.set(i, mpmDiagnostic::New(diagnosticNames_[i], *this, dict_));
    }
}

std::shared_ptr<const mpm::Subdomain> Foam::mpmModel::decompose
(
    const mpm::BoundarySpec& walls
)
{
    if (!Pstream::parRun()) return nullptr;
    auto sd = std::make_shared<mpm::Subdomain>();
    const int reach = mpm::MpmSystem::stencilReach(controls_.step.shape);
    try
    {
        // The box holds every lattice cell this rank's mesh cells overlap,
        // owned here or not (the exchange halo)
        sd->build
        (
            lattice_.lattice(), lattice_.ownedLatticeCells(), reach,
            mpm::Boundary::periodicAxes(lattice_.lattice(), walls), comm_,
            lattice_.overlappedCells()
        );
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    lattice_.attach(sd);
    const label halo = label(sd->haloNodes());
    Info<< "Decomposed lattice: " << Pstream::nProcs() << " processors, halo "
        << reach << " node layers; halo nodes per processor: max "
        << returnReduce(halo, maxOp<label>()) << ", total "
        << returnReduce(halo, sumOp<label>()) << "; halo neighbours: max "
        << returnReduce(label(sd->neighbourCount()), maxOp<label>()) << nl;
    return sd;
}

bool Foam::mpmModel::rebalance(bool start)
{
    if (!Pstream::parRun() || !balance_.enabled()) return false;
    const label n = label(system_.particles().size());
    const scalar before = latticeBalance::imbalance(n);
    // The start within 1.05 keeps its owners: a new partition would move
    // points for nothing (scotch's split need not be the mesh's)
    const scalar most = start ? min(startImbalance, balance_.maxImbalance()) : balance_.maxImbalance();
    if (before <= most)
    {
        if (start)
        {
            Info<< "MPM load balance at time " << mesh_.time().timeName()
                << ": points per processor max/mean " << before << " -> " << before
                << "; within " << most << ": the owners that follow the mesh kept" << nl;
        }
        return false;
    }
    const clockTime timer;
    labelList owners(balance_.owners(lattice_, system_.particles(), lattice_.meshOwners()));
    label cellsMoved = 0;
    forAll(owners, c) cellsMoved += owners[c] != lattice_.latticeOwners()[c];
    // The same owners (the points cannot be split finer): nothing to make
    // again
    label pointsMoved = 0;
    if (cellsMoved)
    {
        lattice_.setOwners(std::move(owners));
        system_.changeSubdomain(decompose(system_.boundary().spec()));
        pointsMoved = toLatticeOwners(lattice_, system_.particles());
    }
    const scalar after = latticeBalance::imbalance(label(system_.particles().size()));
    const scalar cost = returnReduce(timer.elapsedTime(), maxOp<scalar>());
    balanceTime_ += cost;
    ++rebalances_;
    Info<< "MPM load balance at time " << mesh_.time().timeName()
        << ": points per processor max/mean " << before << " -> " << after
        << "; moved " << pointsMoved << " points and " << cellsMoved
        << " lattice cells; " << cost << " s" << nl;
    return cellsMoved > 0;
}

void Foam::mpmModel::reportBalance(Ostream& os) const
{
    if (!Pstream::parRun()) return;
    const mpm::Particles& P = system_.particles();
    const label n = label(P.size());
    const label total = returnReduce(n, sumOp<label>());
    // Exact whatever the distribution of the points, so migration can be
    // checked step by step: the sum of the ids and a checksum of the mass
    // bit patterns (sum mod 2^61 - 1, combined in rank order).
    const std::uint64_t prime = (std::uint64_t(1) << 61) - 1;
    std::uint64_t massSum = 0;
    std::int64_t idSum = 0;
    for (label p = 0; p < n; ++p)
    {
        std::uint64_t bits;
        std::memcpy(&bits, &P.mass[p], sizeof bits);
        massSum = (massSum + bits % prime) % prime;
        idSum += P.id[p];
    }
    std::vector<std::int64_t> all;
    comm_.allGather({std::int64_t(massSum)}, all);
    massSum = 0;
    for (const std::int64_t s : all) massSum = (massSum + std::uint64_t(s)) % prime;
    idSum = comm_.sum(idSum);
    os  << "MPM: points per processor min " << returnReduce(n, minOp<label>())
        << ", mean " << scalar(total)/Pstream::nProcs() << ", max "
        << returnReduce(n, maxOp<label>()) << "; total " << total
        << ", id sum " << std::to_string(idSum).c_str()
        << ", mass checksum " << std::to_string(massSum).c_str()
        << "; migrated "
        << std::to_string(comm_.sum(std::int64_t(system_.migratedCount()))).c_str()
        << nl;
}

const Foam::stableCourant& Foam::mpmModel::analysedLimit() const
{
    if (!courantLimitKnown_)
    {
        courantLimit_ = analysedCourantLimit(controls_.step);
        courantLimitKnown_ = true;
        if (courantLimit_.limit > 0)
        {
            Info<< "Stable Courant number " << courantLimit_.limit << " ("
                << courantLimit_.description.c_str() << ")" << nl;
        }
        else
        {
            Info<< "Stable Courant number: not analysed ("
                << courantLimit_.description.c_str() << "); steps are "
                << "checked against 1" << nl;
        }
    }
    return courantLimit_;
}

Foam::scalar Foam::mpmModel::courantLimit() const
{
    const scalar limit = analysedLimit().limit;
    return limit > 0 ? limit : 1;
}

void Foam::mpmModel::reportCourantLimit() const
{
    if (controls_.adaptive && controls_.courant <= belowEveryAnalysedCourant)
    {
        Info<< "Stable Courant number: not needed (timeStep courant "
            << controls_.courant << " is below " << belowEveryAnalysedCourant
            << ", under every analysed limit; a fixed step above it is checked)"
            << nl;
        return;
    }
    analysedLimit();   // logs it
    if (controls_.adaptive && controls_.courant > courantLimit())
    {
        WarningInFunction
            << "timeStep courant " << controls_.courant << " is above the "
            << "stable Courant number " << courantLimit() << " of this "
            << "algorithm (" << courantLimit_.description.c_str() << "): "
            << "use timeStep { courant " << 0.5*courantLimit() << "; }"
            << endl;
    }
}

void Foam::mpmModel::warnIfAboveCourantLimit(scalar dt, const char* source) const
{
    const scalar Co = courantNumber(dt);
    // Below every analysed limit: no need to know this algorithm's
    if (Co <= belowEveryAnalysedCourant || Co <= courantLimit()) return;
    // Kept for the stop message, should the run then fail
    maxCourantAboveLimit_ = max(maxCourantAboveLimit_, Co);
    if (courantWarned_) return;
    // Once per run: the explicit update is unstable above the analysed
    // limit (docs/stabilityAnalysis.md); the run itself will tell.
    courantWarned_ = true;
    WarningInFunction
        << "The MPM step " << dt << " set by " << source << " gives "
        << "Courant number " << Co << " > " << courantLimit()
        << ", the stable limit of this algorithm ("
        << courantLimit_.description.c_str() << "), at time "
        << mesh_.time().timeName() << " (signal speed "
        << system_.maxSignalSpeed() << ", h " << lattice_.lattice().h
        << "). Explicit MPM is unstable above it: use a step <= "
        << dt*courantLimit()/Co << ", or timeStep { type adaptive; courant "
        << 0.5*courantLimit() << "; } (docs/stabilityAnalysis.md)." << endl;
}

Foam::scalar Foam::mpmModel::deltaT() const
{
    if (!controls_.adaptive)
    {
        warnIfAboveCourantLimit(mesh_.time().deltaTValue(), "timeStep fixed (controlDict deltaT)");
        return mesh_.time().deltaTValue();
    }
    // No point left anywhere (all gone through an outlet): nothing limits
    // the step; take controlDict's deltaT rather than an infinite one
    if (returnReduce(label(system_.pointCount()), sumOp<label>()) == 0)
    {
        return min(mesh_.time().deltaTValue(), controls_.maxDeltaT);
    }
    const floatingPointTrapsOff noTraps;
    const scalar dt = min(system_.stableDeltaT(controls_.courant), controls_.maxDeltaT);
    if (!std::isfinite(dt) || dt <= 0)
    {
        FatalErrorInFunction
            << "Stopping at time " << mesh_.time().timeName()
            << ": the stable time step is " << dt << " (signal speed "
            << system_.maxSignalSpeed() << "); the material points' velocity"
            << " or stress is no longer finite" << exit(FatalError);
    }
    return dt;
}

std::string Foam::mpmModel::stopAdvice() const
{
    std::ostringstream os;
    if (maxCourantAboveLimit_ > 0)   // the limit is then known
    {
        os  << "\nThe step's Courant number reached " << maxCourantAboveLimit_
            << ", above the stable limit " << courantLimit() << " of this "
            << "algorithm (" << courantLimit_.description << ").";
    }
    if (controls_.step.shape == mpm::ShapeKind::linearHat)
    {
        os  << "\nWith linear hats the internal force jumps whenever a point "
            << "crosses a cell face (grid-crossing error), which a hard case "
            << "turns into an instability: shapeFunction cubicBSpline (or "
            << "quadraticBSpline) avoids it.";
    }
    return os.str();
}

Foam::scalar Foam::mpmModel::courantNumber(scalar dt) const
{
    const floatingPointTrapsOff noTraps;
    return system_.maxSignalSpeed()*dt/lattice_.lattice().h;
}

void Foam::mpmModel::evolve(scalar dt)
{
    if (balanceInEvolve_) rebalance();
    try
    {
        const floatingPointTrapsOff noTraps;
        if (wallsMove_)
        {
            // Where the moving walls are at the step's start, and their
            // mean velocity over it
            moveWalls(wallTime_, wallTime_ + dt);
        }
        wallTime_ += dt;
        system_.step(dt);
        if (!deviceReported_ && controls_.step.backend == mpm::Backend::cuda)
        {
            // After the first step: the fluid coupling is set up by then
            const std::string why = system_.residentUnsupported();
            Info<< "cuda: " << (why.empty()
                ? std::string("points and grid resident on the device")
                : "host-assisted step (the resident one does not cover " + why + ")").c_str() << endl;
            deviceReported_ = true;
        }
    }
    catch (const mpm::NonFiniteError& e)
    {
        // The core knows a material by its index: name it
        std::string what(e.what());
        if (e.material >= 0 && e.material < materials_.size())
        {
            what = e.base + " (material " + materials_.names()[e.material] + ")";
        }
        FatalErrorInFunction
            << "Stopping at time " << mesh_.time().timeName() << ": "
            << what.c_str() << nl
            << "Nothing was written for this time. Reduce the time step "
            << "(timeStep courant) or check the material coefficients."
            << stopAdvice().c_str() << exit(FatalError);
    }
    catch (const std::runtime_error& e)
    {
        // A point moved beyond its processor's halo (decomposed runs)
        FatalErrorInFunction
            << "Stopping at time " << mesh_.time().timeName() << ": "
            << e.what() << nl << "Nothing was written for this time."
            << exit(FatalError);
    }
    stopIfInverted
    (
        system_.inverted(), materials_.names(), label(system_.stepCount()),
        mesh_.time(), stopAdvice()
    );
    // The inlets' layers that entered during the step (after the points
    // moved and those beyond an open face left)
    open_->inject(system_, dt);
    ++steps_;
}

void Foam::mpmModel::updateFields()
{
    const mpm::MpmSystem::GridSample g = system_.sampleGrid();
    const labelList& node = lattice_.cellNode();
    if (!lattice_.cellsAreNodes())
    {
        // Any other mesh: the lattice cells a cell overlaps, by their
        // overlaps (the exchange's weights, meshLattice::forEachOverlap):
        // the solid volume spread evenly over each lattice cell, the
        // velocity mass-weighted. Decomposed, an overlapped lattice cell
        // may be another rank's: sampleGrid's copy holds the owner's values.
        const scalar VL = lattice_.cellVolume();
        forAll(node, celli)
        {
            scalar vol = 0, m = 0;
            vector p(Zero);
            lattice_.forEachOverlap(celli, [&](label I, scalar T)
            {
                vol += T*g.volume[I];
                m += T*g.mass[I];
                p += T*g.mass[I]*vector(g.velocity[0][I], g.velocity[1][I], g.velocity[2][I]);
            });
            alphaSolid_[celli] = vol/VL;
            Usolid_[celli] = m > 0 ? p/m : vector::zero;
        }
        alphaSolid_.correctBoundaryConditions();
        Usolid_.correctBoundaryConditions();
        return;
    }
    forAll(node, celli)
    {
        const label I = node[celli];
        alphaSolid_[celli] = g.volume[I]/mesh_.cellVolumes()[celli];
        Usolid_[celli] = vector(g.velocity[0][I], g.velocity[1][I], g.velocity[2][I]);
    }
    alphaSolid_.correctBoundaryConditions();
    Usolid_.correctBoundaryConditions();
}

void Foam::mpmModel::write()
{
    if (!mesh_.time().writeTime()) return;
    const clockTime timer;
    // The step leaves the lattice at the start-of-step positions; map again
    // so fields and points describe the same instant.
    system_.mapToGrid();
    updateFields();
    pointFormat_->write(system_.particles());
    const scalar seconds = returnReduce(timer.elapsedTime(), maxOp<scalar>());
    ioTime_ += seconds;
    Info<< "Wrote " << returnReduce(label(system_.particles().size()), sumOp<label>())
        << " material points and the lattice fields in " << seconds << " s" << nl;
}

bool Foam::mpmModel::logThisStep() const
{
    return steps_ % controls_.logInterval == 0;
}

void Foam::mpmModel::setLevelSetWalls(std::vector<mpm::LevelSetWall> walls)
{
    const label nFixed = label(walls.size());
    PtrList<Function1<vector>> obstacleVelocity;
    for (mpm::LevelSetWall& w : readObstacles(mesh_, dict_, true, &obstacleVelocity))
    {
        walls.push_back(std::move(w));
    }
    if (walls.empty()) return;
    wallVelocity_.setSize(label(walls.size()));
    forAll(obstacleVelocity, i)
    {
        if (obstacleVelocity.set(i))
        {
            wallVelocity_.set(nFixed + i, obstacleVelocity.release(i));
            wallsMove_ = true;
        }
    }
    // The shapes see a 2D case's mid-plane along its unsolved axis
    const point mid(lattice_.cellCentre(0));
    try
    {
        system_.setLevelSetWalls(std::move(walls), {mid.x(), mid.y(), mid.z()});
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(dict_) << e.what() << exit(FatalIOError);
    }
    Info<< "    lattice nodes inside level-set walls and obstacles: "
        << returnReduce(label(system_.levelSetWalls().nodesInside()), sumOp<label>())
        << (Pstream::parRun() ? " (summed over the processors' boxes)" : "") << nl;
    // Moving obstacles start where they are at the start time (a restart)
    wallTime_ = mesh_.time().value();
    if (wallsMove_) moveWalls(wallTime_, wallTime_);
}

void Foam::mpmModel::moveWalls(scalar t0, scalar t1)
{
    const label n = wallVelocity_.size();
    std::vector<std::array<mpm::Real, 3>> d(n, {0, 0, 0}), v(n, {0, 0, 0});
    forAll(wallVelocity_, w)
    {
        if (!wallVelocity_.set(w)) continue;
        const Function1<vector>& f = wallVelocity_[w];
        // (No integral over an empty interval: v1912's table writes out
        // of bounds for integrate(x, x) at its first sample)
        const vector disp(t0 > 0 ? f.integrate(0, t0) : vector::zero);
        const vector vel(t1 > t0 ? vector(f.integrate(t0, t1)/(t1 - t0)) : f.value(t0));
        for (direction a = 0; a < 3; ++a) { d[w][a] = disp[a]; v[w][a] = vel[a]; }
    }
    system_.moveLevelSetWalls(d, v);
}

void Foam::mpmModel::checkPointsOutsideObstacles() const
{
    const mpm::LevelSetWalls& ls = system_.levelSetWalls();
    if (ls.empty()) return;
    // A run keeps every point outside the closest-point planes of the
    // nodes; a concave wall (an STL's hollow) can leave a point a hair
    // inside the exact surface, so a restart allows a quarter cell.
    const scalar depth = 0.25*lattice_.lattice().h;
    const mpm::Particles& P = system_.particles();
    List<label> inside(ls.walls().size(), Zero);
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        const mpm::Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        int w = -1;
        if (ls.distance(x, &w) < -depth) ++inside[w];
    }
    Pstream::listCombineGather(inside, plusEqOp<label>());
    Pstream::listCombineScatter(inside);
    std::string which;
    forAll(inside, w)
    {
        if (inside[w] == 0) continue;
        which += " " + std::to_string(inside[w]) + " in " + ls.walls()[w].name;
    }
    if (!which.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "Material points lie inside obstacles:" << which.c_str() << nl
            << "Seed again with mpmSetParticles (it leaves out points inside"
            << " obstacles and outside the mesh), or move the obstacle."
            << exit(FatalIOError);
    }
}

void Foam::mpmModel::report(Ostream& os)
{
    forAll(diagnostics_, i)
    {
        mpm::ScopedTimer timer(diagnosticTime_[i]);
        diagnostics_[i].report(os);
    }
    reportBalance(os);
    open_->report(system_, os);
    if (!system_.levelSetWalls().empty())
    {
        os  << "Obstacles: points put back on their surface so far "
            << returnReduce(label(system_.levelSetContainedCount()), sumOp<label>()) << nl;
    }
}

void Foam::mpmModel::summary
(
    Ostream& os,
    const List<Tuple2<word, scalar>>& effects
) const
{
    // The slowest rank's time of each phase: what the run waited for.
    mpm::StepTimers t = system_.timers();
    for (double* x : {&t.p2g, &t.nodal, &t.g2p, &t.constitutive, &t.migration, &t.halo,
                      &t.haloIn.p2g, &t.haloIn.nodal, &t.haloIn.g2p, &t.haloIn.constitutive})
    {
        reduce(*x, maxOp<double>());
    }
    const scalar io = returnReduce(ioTime_, maxOp<scalar>());
    // The rebalances' partition, new box lattices and point moves (already
    // the slowest rank's)
    const scalar balance = balanceTime_;
    // Each selected effect by name: the diagnostics, then the others'
    List<Tuple2<word, scalar>> named(diagnostics_.size());
    forAll(diagnostics_, i)
    {
        named[i] = Tuple2<word, scalar>("diagnostic " + diagnosticNames_[i], diagnosticTime_[i]);
    }
    named.append(effects);
    scalar total = t.total() + io + balance;
    for (auto& e : named)
    {
        reduce(e.second(), maxOp<scalar>());
        total += e.second();
    }
    const label nPoints = returnReduce(label(system_.pointCount()), sumOp<label>());
    auto line = [&](const std::string& name, scalar s)
    {
        os  << "    " << name.c_str() << tab << s << " s" << tab
            << (total > 0 ? 100*s/total : 0) << " %" << nl;
    };
    os  << nl << "MPM summary: " << nPoints
        << " material points, " << steps_ << " steps";
    if (steps_ > 0 && t.total() > 0)
    {
        os  << ", " << nPoints*scalar(steps_)/t.total()/1e6
            << " M point-steps/s";
    }
    if (Pstream::parRun()) os << ", " << Pstream::nProcs() << " processors";
    os  << nl << "  Cost breakdown:" << nl;
    // Decomposed: each phase's halo time (its waits for the other ranks
    // included) under the phase it is part of
    auto phase = [&](const std::string& name, scalar s, scalar halo)
    {
        line(name, s);
        if (Pstream::parRun() && halo > 0) line("  of which halo", halo);
    };
    phase("P2G          ", t.p2g, t.haloIn.p2g);
    phase("nodal update ", t.nodal, t.haloIn.nodal);
    phase("G2P          ", t.g2p, t.haloIn.g2p);
    phase("constitutive ", t.constitutive, t.haloIn.constitutive);
    if (Pstream::parRun()) line("migration    ", t.migration);
    if (rebalances_ > 0)
    {
        line("load balance ", balance);
        os  << "        (" << rebalances_ << " partitions by points)" << nl;
    }
    line("I/O          ", io);
    for (const auto& e : named) line(e.first(), e.second());
    // 3D without APIC: which P2G loop the first steps' timing chose (this
    // rank's; the results are the same bits either way)
    const mpm::P2gRowChoice& rowChoice = system_.p2gRowChoice();
    if (rowChoice.decided() && rowChoice.trialSeconds(true) > 0 && rowChoice.trialSeconds(false) > 0)
    {
        os  << "  P2G loop chosen by timing " << mpm::P2gRowChoice::trialSteps
            << " trial steps: " << (rowChoice.chosenRows() ? "node rows" : "node by node")
            << " (rows " << rowChoice.trialSeconds(true) << " s, node by node "
            << rowChoice.trialSeconds(false) << " s)" << nl;
    }
    os  << endl;
}
