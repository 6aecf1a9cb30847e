#include "openBoundaries.H"
#include "wallConditions.H"
#include "pointSeeder.H"
#include "knownKeywords.H"
#include "Time.H"
#include <limits>

void Foam::openBoundaries::readInlet
(
    const label open,
    const dictionary& d,
    const materialLibrary& materials,
    const mpm::BoundarySpec& spec
)
{
    const mpm::Lattice& L = lattice_.lattice();
    const label c = condition_[open];
    inletInjection in;
    in.open = open;

    // The patch must be one side of the box: its normal is the entry
    // direction (a plane the layers are parallel to).
    int side = -1;
    for (int s = 0; s < 6; ++s)
    {
        bool here = false;
        for (const int fc : spec.faceCondition[s]) here = here || fc == c;
        if (!here) continue;
        if (side >= 0)
        {
            FatalIOErrorInFunction(d)
                << "The inlet " << patch_[open] << " lies on two sides of "
                << "the box: an inlet must be one plane (one side)"
                << exit(FatalIOError);
        }
        side = s;
    }
    if (side < 0)
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch_[open] << " has no face on the box"
            << exit(FatalIOError);
    }
    const int a = side/2;
    const bool low = side % 2 == 0;
    in.inward = Zero;
    in.inward[a] = low ? 1 : -1;
    const auto& U = spec.conditions[c].velocity;
    in.velocity = vector(U[0], U[1], U[2]);
    in.normalSpeed = in.velocity & in.inward;
    if (in.normalSpeed <= 0)
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch_[open] << " velocity " << in.velocity
            << " does not point into the domain (its component along the "
            << "inward normal " << in.inward << " is " << in.normalSpeed
            << "; it must be > 0)" << exit(FatalIOError);
    }

    if (!d.found("material"))
    {
        FatalIOErrorInFunction(d)
            << "Missing keyword material for the inlet " << patch_[open]
            << " (a material of mpmProperties::materials)"
            << exit(FatalIOError);
    }
    in.material = materials.index(d.get<word>("material"), d);
    in.rho = materials.rho(in.material);
    const Vector<label> ppc(readPointsPerCell(d, L));

    const bool mass = d.found("massFlowRate"), volume = d.found("volumeFlowRate");
    if (mass == volume)
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch_[open] << " needs exactly one of "
            << "massFlowRate [kg/s] and volumeFlowRate [m3/s] (a Function1 "
            << "of time, e.g. massFlowRate constant 2;)" << exit(FatalIOError);
    }
    in.massRate = mass;
    in.rate = Function1<scalar>::New(mass ? "massFlowRate" : "volumeFlowRate", d);

    // One layer: a point per sub-cell position of every face of the patch,
    // on the patch plane, in the order of the faces (lattice order), the
    // same on every processor.
    const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
    const int lo = min(a1, a2), hi = max(a1, a2);
    const scalar plane = L.origin[a] + (low ? 0 : L.length(a));
    DynamicList<point> layer;
    const auto& faces = spec.faceCondition[side];
    for (size_t f = 0; f < faces.size(); ++f)
    {
        if (faces[f] != c) continue;
        int r[3];
        r[lo] = int(f % size_t(L.nCells[lo]));
        r[hi] = int(f/size_t(L.nCells[lo]));
        r[a] = low ? 0 : L.nCells[a] - 1;
        const point cc(lattice_.cellCentre(label(L.cellIndex(r[0], r[1], r[2]))));
        for (label qh = 0; qh < ppc[hi]; ++qh)
        for (label ql = 0; ql < ppc[lo]; ++ql)
        {
            point x(cc);
            x[a] = plane;
            if (L.solved[lo]) x[lo] += ((ql + 0.5)/ppc[lo] - 0.5)*L.h;
            if (L.solved[hi]) x[hi] += ((qh + 0.5)/ppc[hi] - 0.5)*L.h;
            layer.append(x);
        }
    }
    in.layer = layer;
    // The same numbers on every processor (each rank's lattice spacing is
    // its own cells', equal to round-off only): every rank then decides
    // alike when a layer enters and gives its points the same mass.
    in.pointVolume = returnReduce
    (
        lattice_.cellVolume()/(ppc.x()*ppc.y()*ppc.z()), maxOp<scalar>()
    );
    in.pointMass = in.rho*in.pointVolume;
    in.layerVolume = in.layer.size()*in.pointVolume;
    const scalar spacing = L.h/ppc[a];
    const scalar area = in.layerVolume/spacing;
    Info<< "    " << patch_[open] << " inlet: material "
        << materials.names()[in.material] << ", " << ppc << " points per "
        << "cell, velocity " << in.velocity << nl
        << "        " << (in.massRate ? "massFlowRate" : "volumeFlowRate")
        << " (" << in.rate->type() << "); a layer of " << in.layer.size()
        << " points (mass " << in.layer.size()*in.pointMass << ") per "
        << in.layerVolume << " m3 of material; full density at "
        << in.rho*in.normalSpeed*area << " kg/s (rho U_n A, A = " << area
        << " m2)" << nl;
    inlets_.push_back(std::move(in));
}


Foam::openBoundaries::openBoundaries
(
    const fvMesh& mesh,
    const meshLattice& lattice,
    const dictionary& mpmDict,
    const materialLibrary& materials,
    const mpm::BoundarySpec& spec,
    const wordList& conditionPatch,
    const mpm::MpmSystem& system
)
:
    mesh_(mesh),
    lattice_(lattice),
    time_(mesh.time().value()),
    lastTime_(mesh.time().value())
{
    DynamicList<word> names;
    DynamicList<label> conditions;
    DynamicList<mpm::WallType> types;
    for (size_t c = 0; c < spec.conditions.size(); ++c)
    {
        if (!mpm::isOpen(spec.conditions[c].type)) continue;
        names.append(conditionPatch[c]);
        conditions.append(label(c));
        types.append(spec.conditions[c].type);
    }
    patch_ = names;
    condition_ = conditions;
    type_ = types;
    injectedCount_.setSize(patch_.size(), 0);
    injectedMass_.setSize(patch_.size(), 0);
    lastIn_.setSize(patch_.size(), 0);
    lastOut_.setSize(patch_.size(), 0);
    if (!active()) return;

    Info<< "Open boundaries:" << nl;
    const dictionary& walls = optionalSubDict(mpmDict, "walls");
    forAll(patch_, o)
    {
        if (type_[o] == mpm::WallType::outlet)
        {
            Info<< "    " << patch_[o] << " outlet: points crossing it leave"
                << nl;
            continue;
        }
        const entry* e = walls.findEntry(patch_[o], keyType::REGEX);
        readInlet(label(o), e->dict(), materials, spec);
    }

    const mpm::Particles& P = system.particles();
    scalar m = 0;
    std::int64_t maxId = -1;
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        m += P.mass[p];
        maxId = std::max(maxId, P.id[p]);
    }
    initialCount_ = returnReduce(label(P.size()), sumOp<label>());
    initialMass_ = returnReduce(m, sumOp<scalar>());
    // New points are numbered after every existing one
    nextId_ = system.subdomain() ? system.subdomain()->comm().max(maxId) + 1 : maxId + 1;
    Info<< "    initial points " << initialCount_ << ", mass " << initialMass_
        << nl << endl;
}


void Foam::openBoundaries::inject(mpm::MpmSystem& system, const scalar dt)
{
    if (!active()) return;
    const scalar t0 = time_, t1 = time_ + dt;
    time_ = t1;
    const mpm::Lattice& L = lattice_.lattice();
    mpm::Particles& P = system.particles();
    for (inletInjection& in : inlets_)
    {
        scalar dV = in.rate->integrate(t0, t1);
        if (in.massRate) dV /= in.rho;
        if (dV < 0)
        {
            FatalErrorInFunction
                << "The flow rate of the inlet " << patch_[in.open]
                << " is negative between times " << t0 << " and " << t1
                << " (" << in.rate->name() << " integral " << dV
                << "): an inlet only lets material in" << exit(FatalError);
        }
        const scalar V0 = in.volumeIn, V1 = V0 + dV;
        in.volumeIn = V1;
        // A layer enters when the integral reaches its mid-volume. A rate
        // that fills whole layers in whole steps (full density) reaches it
        // exactly: a relative 1e-9 keeps round-off from moving the step.
        const scalar tol = 1e-9*in.layerVolume;
        while ((in.layers + 0.5)*in.layerVolume <= V1 + tol)
        {
            // The instant the layer's mid-volume entered, and how far the
            // material entering then has moved in since
            const scalar target = (in.layers + 0.5)*in.layerVolume;
            const scalar tk = V1 > V0 ? min(t0 + dt*(target - V0)/(V1 - V0), t1) : t1;
            const scalar depth = max(in.normalSpeed*(t1 - tk), 1e-6*L.h);
            forAll(in.layer, k)
            {
                const point x(in.layer[k] + depth*in.inward);
                label ijk[3];
                lattice_.indicesOf(x, ijk);
                if (!lattice_.ownsLatticeCell(ijk[0], ijk[1], ijk[2])) continue;   // another processor's
                const mpm::Index p = P.add
                (
                    {x.x(), x.y(), x.z()},
                    {in.velocity.x(), in.velocity.y(), in.velocity.z()},
                    in.pointMass, in.pointVolume, int(in.material)
                );
                P.id[p] = nextId_ + k;
            }
            nextId_ += in.layer.size();
            ++in.layers;
            injectedCount_[in.open] += in.layer.size();
            injectedMass_[in.open] += in.layer.size()*in.pointMass;
        }
    }
}


void Foam::openBoundaries::openFiles()
{
    const Time& runTime = mesh_.time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"openBoundaries"
       /runTime.timeName(runTime.startTime().value())
    );
    mkDir(dir);
    forAll(patch_, o)
    {
        files_.append(new OFstream(dir/(patch_[o] + ".dat")));
        files_[o]
            << "# " << patch_[o] << " (" << mpm::wallTypeName(type_[o])
            << "): points and mass since the start of the run; the rates"
            << " over the interval since the previous row" << nl
            << "# time injectedPoints injectedMass removedPoints removedMass"
            << " massRateIn massRateOut" << nl;
        files_[o].precision(12);
    }
    balanceFile_.reset(new OFstream(dir/"massBalance.dat"));
    balanceFile_()
        << "# initial + injected - removed = present, points and mass; "
        << "massError = presentMass - (initialMass + injectedMass - "
        << "removedMass); clamped: points put back inside a wall" << nl
        << "# time initialPoints initialMass injectedPoints injectedMass "
        << "removedPoints removedMass presentPoints presentMass massError "
        << "clamped" << nl;
    balanceFile_().precision(15);
}


void Foam::openBoundaries::report(const mpm::MpmSystem& system, Ostream& os)
{
    if (!active()) return;
    const mpm::Particles& P = system.particles();
    scalar present = 0;
    for (mpm::Index p = 0; p < P.size(); ++p) present += P.mass[p];
    reduce(present, sumOp<scalar>());
    const label nPresent = returnReduce(label(P.size()), sumOp<label>());
    const label clamped = returnReduce(label(system.clampedCount()), sumOp<label>());

    labelList outCount(patch_.size());
    scalarField outMass(patch_.size());
    forAll(patch_, o)
    {
        outCount[o] = returnReduce(label(system.removedCount()[condition_[o]]), sumOp<label>());
        outMass[o] = returnReduce(scalar(system.removedMass()[condition_[o]]), sumOp<scalar>());
    }
    const scalar t = mesh_.time().value();
    const scalar interval = t - lastTime_;
    const label inTotal = sum(injectedCount_), outTotal = sum(outCount);
    const scalar inMass = sum(injectedMass_), outMassTotal = sum(outMass);
    const scalar massError = present - (initialMass_ + inMass - outMassTotal);

    os  << "Open boundaries: points (mass) since the start" << nl;
    scalarField rateIn(patch_.size(), 0), rateOut(patch_.size(), 0);
    forAll(patch_, o)
    {
        if (interval > 0)
        {
            rateIn[o] = (injectedMass_[o] - lastIn_[o])/interval;
            rateOut[o] = (outMass[o] - lastOut_[o])/interval;
        }
        os  << "    " << patch_[o] << ": ";
        if (type_[o] == mpm::WallType::inlet)
        {
            os  << "in " << injectedCount_[o] << " (" << injectedMass_[o]
                << "), rate in " << rateIn[o] << " kg/s; ";
        }
        os  << "out " << outCount[o] << " (" << outMass[o] << "), rate out "
            << rateOut[o] << " kg/s" << nl;
    }
    os  << "    balance: initial " << initialCount_ << " (" << initialMass_
        << ") + in " << inTotal << " (" << inMass << ") - out " << outTotal
        << " (" << outMassTotal << ") = " << initialCount_ + inTotal - outTotal
        << "; present " << nPresent << " (" << present << "), mass error "
        << massError << "; clamped at walls " << clamped << nl;
    if (nPresent != initialCount_ + inTotal - outTotal)
    {
        WarningInFunction
            << "Point count " << nPresent << " differs from the balance "
            << initialCount_ + inTotal - outTotal << endl;
    }
    if (clamped > 0 && clampWarned_ == 0)
    {
        // A point that would have crossed a wall was put back inside it: no
        // loss, but a step too large for the material's speed there, or a
        // wall next to an open face (the material turning the corner).
        // Once per run; the count goes on in the balance line and file.
        WarningInFunction
            << clamped << " material points crossed a wall "
            << "and were put back inside it by time " << mesh_.time().timeName()
            << ": the step is too large for their speed near the wall, or "
            << "they turn the corner of a wall and an open patch. Counted "
            << "on ('clamped at walls' in the log, massBalance.dat)" << endl;
        clampWarned_ = clamped;
    }
    lastIn_ = injectedMass_;
    lastOut_ = outMass;
    lastTime_ = t;

    if (!Pstream::master()) return;
    if (!balanceFile_.valid()) openFiles();
    forAll(patch_, o)
    {
        files_[o]
            << t << ' ' << injectedCount_[o] << ' ' << injectedMass_[o] << ' '
            << outCount[o] << ' ' << outMass[o] << ' ' << rateIn[o] << ' '
            << rateOut[o] << endl;
    }
    balanceFile_()
        << t << ' ' << initialCount_ << ' ' << initialMass_ << ' ' << inTotal
        << ' ' << inMass << ' ' << outTotal << ' ' << outMassTotal << ' '
        << nPresent << ' ' << present << ' ' << massError << ' ' << clamped
        << endl;
}
