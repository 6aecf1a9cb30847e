#include "openBoundaries.H"
#include "wallConditions.H"
#include "pointSeeder.H"
#include "knownKeywords.H"
#include "Time.H"
#include "surfaceWallShape.H"
#include "triSurface.H"
#include <limits>

namespace
{

using namespace Foam;

// The outward unit normal of a planar patch (its triangles, every
// processor's); an inlet that is not one plane stops with a message
vector planeNormal(const triSurface& s, const word& patch, const dictionary& d)
{
    vector sum(Zero);
    scalar area = 0;
    forAll(s, t)
    {
        sum += s[t].areaNormal(s.points());
        area += s[t].mag(s.points());
    }
    const vector n(sum/max(mag(sum), VSMALL));
    forAll(s, t)
    {
        const vector at(s[t].areaNormal(s.points()));
        if (mag(at) > 1e-9*area && (at/mag(at) & n) < 1 - 1e-6)
        {
            FatalIOErrorInFunction(d)
                << "The inlet " << patch << " is not one plane: its face at "
                << s[t].centre(s.points()) << " has the normal " << at/mag(at)
                << ", the patch " << n << " (an inlet off the lattice box's "
                << "sides must be planar)" << exit(FatalIOError);
        }
    }
    return n;
}

// Whether q lies in triangle (a, b, c), all given in the plane's 2D
// coordinates (u, v), edges included
bool inTriangle(const vector2D& q, const vector2D& a, const vector2D& b, const vector2D& c)
{
    auto cross = [](const vector2D& o, const vector2D& x, const vector2D& y)
    {
        return (x.x() - o.x())*(y.y() - o.y()) - (x.y() - o.y())*(y.x() - o.x());
    };
    const scalar d1 = cross(a, b, q), d2 = cross(b, c, q), d3 = cross(c, a, q);
    const scalar tol = 1e-12*(mag(b - a) + mag(c - a))*(mag(b - a) + mag(c - a));
    const bool neg = d1 < -tol || d2 < -tol || d3 < -tol;
    const bool pos = d1 > tol || d2 > tol || d3 > tol;
    return !(neg && pos);
}

} // namespace


Foam::List<Foam::point> Foam::openBoundaries::planeLayer
(
    const triSurface& surface,
    vector& inward,
    const Vector<label>& ppc,
    scalar& normalSpacing,
    const word& patch,
    const dictionary& d
) const
{
    // A point per sub-cell position, as seeding puts them, on a grid of the
    // patch's plane: along the lattice's axes where the plane is normal to
    // one (the positions the seeded material has), else along two in-plane
    // directions at h/n. The same list on every processor.
    const mpm::Lattice& L = lattice_.lattice();
    const pointField& pts = surface.points();
    const point mid(lattice_.cellCentre(0));   // unsolved axes: the mid-plane
    label a = 0;
    for (direction i = 1; i < 3; ++i) if (mag(inward[i]) > mag(inward[a])) a = i;
    const bool aligned = mag(inward[a]) > 1 - 1e-9;
    vector e[2];
    scalar step[2];
    label count[2];
    scalar start[2];
    point origin(Zero);
    if (aligned)
    {
        const scalar sgn = inward[a] > 0 ? 1 : -1;
        inward = Zero;
        inward[a] = sgn;
        normalSpacing = L.h/ppc[a];
        const label ax[2] = {min((a + 1) % 3, (a + 2) % 3), max((a + 1) % 3, (a + 2) % 3)};
        scalar plane = 0;
        for (const point& x : pts) plane += x[a]/pts.size();
        origin[a] = plane;
        for (int k = 0; k < 2; ++k)
        {
            e[k] = Zero;
            e[k][ax[k]] = 1;
            origin[ax[k]] = L.origin[ax[k]];
            if (L.solved[ax[k]])
            {
                step[k] = L.h/ppc[ax[k]];
                count[k] = L.nCells[ax[k]]*ppc[ax[k]];
                start[k] = 0.5*step[k];
            }
            else
            {
                step[k] = 0;
                count[k] = 1;
                start[k] = mid[ax[k]] - L.origin[ax[k]];
            }
        }
    }
    else
    {
        label n = -1;
        for (direction i = 0; i < 3; ++i)
        {
            if (!L.solved[i]) continue;
            if (n >= 0 && ppc[i] != n)
            {
                FatalIOErrorInFunction(d)
                    << "The inlet " << patch << " is not normal to an axis "
                    << "of the lattice: its pointsPerCell must be the same "
                    << "in every solved direction (it is " << ppc << ")"
                    << exit(FatalIOError);
            }
            n = ppc[i];
        }
        normalSpacing = L.h/n;
        label u = -1;
        for (direction i = 0; i < 3; ++i) if (!L.solved[i]) u = i;
        if (u >= 0)
        {
            // 2D: the plane holds the unsolved axis; one row at mid-plane
            e[1] = Zero;
            e[1][u] = 1;
            e[0] = e[1] ^ inward;
            e[0] /= mag(e[0]);
        }
        else
        {
            label k = 0;
            for (direction i = 1; i < 3; ++i) if (mag(inward[i]) < mag(inward[k])) k = i;
            vector axis(Zero);
            axis[k] = 1;
            e[0] = axis - (axis & inward)*inward;
            e[0] /= mag(e[0]);
            e[1] = inward ^ e[0];
        }
        origin = pts[0];
        for (int k = 0; k < 2; ++k)
        {
            if (u >= 0 && k == 1)
            {
                step[k] = 0;
                count[k] = 1;
                start[k] = (mid - origin) & e[k];
                continue;
            }
            scalar lo = GREAT, hi = -GREAT;
            for (const point& x : pts)
            {
                lo = min(lo, (x - origin) & e[k]);
                hi = max(hi, (x - origin) & e[k]);
            }
            step[k] = normalSpacing;
            count[k] = label(std::ceil((hi - lo)/step[k]));
            start[k] = lo + 0.5*step[k];
        }
    }
    // The triangles in the plane's coordinates
    auto uv = [&](const point& x)
    {
        return vector2D((x - origin) & e[0], (x - origin) & e[1]);
    };
    List<FixedList<vector2D, 3>> tri(surface.size());
    forAll(surface, t)
    {
        for (label i = 0; i < 3; ++i) tri[t][i] = uv(pts[surface[t][i]]);
    }
    DynamicList<point> layer;
    label beyond = 0;
    for (label j = 0; j < count[1]; ++j)
    for (label i = 0; i < count[0]; ++i)
    {
        const vector2D q(start[0] + i*step[0], start[1] + j*step[1]);
        bool inside = false;
        forAll(tri, t)
        {
            if (inTriangle(q, tri[t][0], tri[t][1], tri[t][2])) { inside = true; break; }
        }
        if (!inside) continue;
        const point x(origin + q.x()*e[0] + q.y()*e[1]);
        // The part of the patch beyond a lattice extent lets nothing in
        // (a hair inside the plane: its points sit on the lattice's side)
        if (!lattice_.insideLattice(x + 1e-6*L.h*inward)) { ++beyond; continue; }
        layer.append(x);
    }
    if (beyond)
    {
        Info<< "    " << patch << ": " << beyond << " points of a layer lie beyond"
            << " the lattice's extent and are left out" << nl;
    }
    if (layer.empty())
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch << " holds no point of a layer at the "
            << "lattice spacing " << L.h << " and pointsPerCell " << ppc
            << (beyond ? ": it lies beyond the lattice's extent" : ": it is"
                " smaller than the spacing between points") << exit(FatalIOError);
    }
    return List<point>(layer);
}

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

    // The patch is one side of the box (its normal is the entry direction,
    // a plane the layers are parallel to), or a plane off the box's sides
    // (a mesh that is not a uniform box: a level-set inlet)
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
    // Its faces off the box's sides (a mesh that is not a uniform box)
    const label patchi = mesh_.boundaryMesh().findPatchID(patch_[open]);
    label offFaces = 0;
    if (patchi >= 0 && !lattice_.cellsAreNodes())
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        forAll(pp, f) offFaces += latticeBoxSide(L, pp.faceCentres()[f]) < 0;
    }
    reduce(offFaces, sumOp<label>());
    const bool offBox = offFaces > 0;
    if (side >= 0 && offBox)
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch_[open] << " lies partly on a side of the "
            << "lattice's box and partly off it (" << offFaces << " faces): an "
            << "inlet must be one plane" << exit(FatalIOError);
    }
    if (side < 0 && !offBox)
    {
        FatalIOErrorInFunction(d)
            << "The inlet " << patch_[open] << " has no face on the box"
            << exit(FatalIOError);
    }
    const int a = side >= 0 ? side/2 : 0;
    const bool low = side % 2 == 0;
    in.inward = Zero;
    if (side >= 0) in.inward[a] = low ? 1 : -1;
    triSurface surface;
    if (offBox)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        surface = triangulate(mesh_, identity(pp.size(), pp.start()));
        in.inward = -planeNormal(surface, patch_[open], d);
    }
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

    DynamicList<point> layer;
    scalar offBoxSpacing = 0;
    if (offBox)
    {
        layer = planeLayer(surface, in.inward, ppc, offBoxSpacing, patch_[open], d);
    }
    else
    {
        // One layer: a point per sub-cell position of every face of the patch,
        // on the patch plane, in the order of the faces (lattice order), the
        // same on every processor.
        const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        const int lo = min(a1, a2), hi = max(a1, a2);
        const scalar plane = L.origin[a] + (low ? 0 : L.length(a));
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
    const scalar spacing = offBox ? offBoxSpacing : L.h/ppc[a];
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
