#include "meshLattice.H"
#include "cellModel.H"
#include "boundBox.H"
#include "Pair.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "choice.H"
#include "wallConditions.H"
#include "knownKeywords.H"
#include "OStringStream.H"
#include <map>

Foam::meshLattice::meshLattice(const fvMesh& mesh, const dictionary& mpmDict)
:
    mesh_(mesh)
{
    build(mpmDict);
}

bool Foam::meshLattice::uniformBox(vector& h0, std::string& why) const
{
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    const cellShapeList& shapes = mesh_.cellShapes();
    const pointField& pts = mesh_.points();
    OStringStream os;
    // This rank's cells: hexes, axis-aligned boxes, all of one size
    vector hMin(vector::uniform(GREAT)), hMax(vector::uniform(-GREAT));
    forAll(shapes, celli)
    {
        const point& c = mesh_.cellCentres()[celli];
        if (shapes[celli].model() != hex)
        {
            os << "cell " << celli << " at " << c << " is a "
               << shapes[celli].model().name();
            break;
        }
        const boundBox cb(pointField(pts, shapes[celli]), false);
        const vector span = cb.span();
        const scalar boxVol = span.x()*span.y()*span.z();
        if (mag(boxVol - mesh_.cellVolumes()[celli]) > 1e-6*boxVol)
        {
            os << "cell " << celli << " at " << c << " is not an axis-aligned box";
            break;
        }
        hMin = min(hMin, span);
        hMax = max(hMax, span);
        // The spacing is this rank's first cell's, as it always was (the
        // cells' spans differ in the last bit)
        if (celli == 0) h0 = span;
    }
    reduce(hMin, minOp<vector>());
    reduce(hMax, maxOp<vector>());
    // The first rank with a reason gives it
    List<string> reasons(Pstream::nProcs());
    reasons[Pstream::myProcNo()] = os.str();
    Pstream::gatherList(reasons);
    Pstream::scatterList(reasons);
    for (const string& r : reasons)
    {
        if (r.empty()) continue;
        why = r;
        return false;
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (mag(hMax[d] - hMin[d]) > 1e-6*mag(hMin[d]))
        {
            why = "its cells are graded (sizes from " + Foam::name(hMin)
                + " to " + Foam::name(hMax) + ")";
            return false;
        }
    }
    const Vector<label>& solD = mesh_.solutionD();
    scalar h = -1;
    for (direction d = 0; d < 3; ++d)
    {
        if (solD[d] < 0) continue;
        if (h < 0) h = h0[d];
        if (mag(h0[d] - h) > 1e-6*h)
        {
            why = "its cells are not cubic (" + Foam::name(h0) + ")";
            return false;
        }
    }
    const boundBox bb(pts, true);
    label n = 1;
    for (direction d = 0; d < 3; ++d)
    {
        if (solD[d] < 0) continue;
        n *= label(std::round(bb.span()[d]/h));
    }
    if (n != returnReduce(mesh_.nCells(), sumOp<label>()))
    {
        why = "it does not fill its bounding box " + Foam::name(bb.min())
            + " " + Foam::name(bb.max()) + " with cells";
        return false;
    }
    return true;
}

void Foam::meshLattice::build(const dictionary& mpmDict)
{
    const label empty = returnReduce
    (
        mesh_.nCells() == 0 ? Pstream::myProcNo() : labelMax, minOp<label>()
    );
    if (empty != labelMax)
    {
        FatalErrorInFunction
            << "Processor " << empty << " has no cells: decompose for fewer"
            << " processors, or give every processor cells (method scotch"
            << " or hierarchical)" << exit(FatalError);
    }
    const dictionary& ld = optionalSubDict(mpmDict, "lattice");
    checkKeywords(ld, {"spacing", "extent", "extentWall", "balance", "maxImbalance", "migrationRatio"}, "lattice");
    vector h0(Zero);
    std::string notBox;
    const bool box = uniformBox(h0, notBox);
    const Vector<label>& solD = mesh_.solutionD();
    scalar hBox = -1;
    for (direction d = 0; d < 3 && hBox < 0; ++d) if (solD[d] > 0) hBox = h0[d];
    if (hBox < 0)
    {
        FatalErrorInFunction << "Mesh has no solved direction" << exit(FatalError);
    }
    const bool given = ld.found("spacing");
    scalar h =
        given ? readBounded(ld, "spacing", 0, numberRange{0, GREAT, false}, false)
      : meanCellSize();
    if (!given && !box) h = dividePeriods(h);
    const bool extent = ld.found("extent");
    if (!extent && ld.found("extentWall"))
    {
        FatalIOErrorInFunction(ld)
            << "extentWall without extent: the wall is the lattice extent's "
            << "side inside the mesh (lattice { extent ((x0 y0 z0) (x1 y1 z1)); "
            << "extentWall { type slip; } })" << exit(FatalIOError);
    }
    if (box && !extent && (!given || mag(h - hBox) <= 1e-6*hBox))
    {
        buildFromCells(h0);
        return;
    }
    const std::string why
    (
        extent ? std::string("lattice extent given")
      : box
      ? "lattice spacing " + Foam::name(h) + " differs from the cells' " + Foam::name(hBox)
      : "the mesh is not a uniform box: " + notBox
    );
    cellsAreNodes_ = false;
    if (extent) readExtent(ld);
    buildOwn(h);
    Info<< "MPM lattice: its own, spacing " << h
        << (given ? " (lattice spacing)" : " (default: the mesh's mean cell size;"
            " set lattice { spacing ...; } in mpmProperties)") << nl
        << "    (" << why.c_str() << ")" << nl;
    if (extent)
    {
        Info<< "    extent " << extent_ << " (the mesh's bounding box cut to it);"
            << " its sides inside the mesh: " << mpm::wallTypeName(extentWall_.type);
        if (extentWall_.type == mpm::WallType::friction) Info<< ' ' << extentWall_.frictionCoefficient;
        Info<< nl;
    }
}

void Foam::meshLattice::readExtent(const dictionary& ld)
{
    const Pair<vector> e(ld.get<Pair<vector>>("extent"));
    extent_ = boundBox(e.first(), e.second());
    const boundBox bb(mesh_.points(), true);
    for (direction d = 0; d < 3; ++d)
    {
        if (mesh_.solutionD()[d] <= 0) continue;
        const scalar lo = max(e.first()[d], bb.min()[d]), hi = min(e.second()[d], bb.max()[d]);
        if (!(e.second()[d] > e.first()[d]) || !(hi > lo))
        {
            FatalIOErrorInFunction(ld)
                << "lattice extent " << e << " does not overlap the mesh's "
                << "bounding box " << bb << " with a positive length in "
                << "direction " << label(d) << " (give ((min) (max)) with "
                << "min < max, inside the mesh)" << exit(FatalIOError);
        }
    }
    // The extent's sides inside the mesh are walls: their condition
    extentWall_ = mpm::WallCondition{};
    if (ld.found("extentWall"))
    {
        const dictionary& w = ld.subDict("extentWall");
        checkKeywords(w, {"type", "frictionCoefficient"}, "extentWall");
        extentWall_ = readWallCondition(w, "extentWall", "noSlip slip friction outlet", false);
    }
}

Foam::scalar Foam::meshLattice::dividePeriods(scalar h) const
{
    // A cyclic pair must lie on the lattice's sides: the default spacing is
    // rounded to divide the mesh's length along each periodic direction
    // (the last one exactly; a given spacing is taken as given, and checked
    // by readWallConditions)
    const boundBox bb(mesh_.points(), true);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp)) continue;
        // The patch's axis, from any rank holding a face of it
        vector n(Zero);
        if (pp.size()) n = pp.faceNormals()[0];
        reduce(n, maxMagSqrOp<vector>());
        if (magSqr(n) == 0) continue;
        direction a = 0;
        for (direction i = 1; i < 3; ++i) if (mag(n[i]) > mag(n[a])) a = i;
        if (mesh_.solutionD()[a] <= 0) continue;
        const scalar len = bb.span()[a];
        const label cells = max(label(1), label(std::round(len/h)));
        if (mag(cells*h - len) > 1e-6*h)
        {
            Info<< "MPM lattice: default spacing " << h << " rounded to " << len/cells
                << " to divide the periodic length " << len << " (patch "
                << pp.name() << ", " << cells << " cells)" << nl;
            h = len/cells;
        }
    }
    return h;
}

Foam::scalar Foam::meshLattice::meanCellSize() const
{
    // The lattice then has about as many cells within the mesh as the mesh
    const scalar volume = returnReduce(sum(mesh_.cellVolumes()), sumOp<scalar>());
    const label nCells = returnReduce(mesh_.nCells(), sumOp<label>());
    const boundBox bb(mesh_.points(), true);
    const Vector<label>& solD = mesh_.solutionD();
    scalar thickness = 1;
    label dim = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (solD[d] > 0) ++dim; else thickness *= bb.span()[d];
    }
    return std::pow(volume/thickness/nCells, 1.0/dim);
}

void Foam::meshLattice::buildOwn(scalar h)
{
    const boundBox meshBox(mesh_.points(), true);
    boundBox bb(meshBox);
    if (extent_.valid())
    {
        // The lattice covers the extent's part of the mesh; a side the
        // extent cuts is a wall (extentWall)
        for (direction d = 0; d < 3; ++d)
        {
            if (mesh_.solutionD()[d] <= 0) continue;
            const scalar tol = 1e-9*meshBox.mag();
            if (extent_.min()[d] > meshBox.min()[d] + tol)
            {
                bb.min()[d] = extent_.min()[d];
                extentSide_[2*d] = true;
            }
            if (extent_.max()[d] < meshBox.max()[d] - tol)
            {
                bb.max()[d] = extent_.max()[d];
                extentSide_[2*d + 1] = true;
            }
        }
    }
    const Vector<label>& solD = mesh_.solutionD();
    lattice_.h = h;
    unsolvedSpan_ = meshBox.span();
    cellVolume_ = 1;
    for (direction d = 0; d < 3; ++d)
    {
        lattice_.solved[d] = solD[d] > 0;
        lattice_.origin[d] = bb.min()[d];
        const scalar len = bb.span()[d];
        // Whole cells over the bounding box: its min faces are the
        // lattice's, its max faces too where the length is a multiple
        lattice_.nCells[d] = lattice_.solved[d]
          ? max(label(1), label(std::ceil(len/h - 1e-6))) : 1;
        if (extentSide_[2*d + 1])
        {
            // A cut max side is the extent's own (whole cells below it)
            lattice_.nCells[d] = max(label(1), label(std::floor(len/h + 1e-6)));
        }
        cellVolume_ *= lattice_.solved[d] ? h : meshBox.span()[d];
    }
    lattice_.pad = 2;
    try
    {
        lattice_.finalise();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << e.what() << " (lattice spacing " << h << " over the mesh's"
            << " bounding box " << bb << ": give a smaller lattice spacing)"
            << exit(FatalError);
    }
    mapCellCentres();
    if (Pstream::parRun()) decomposeOwn();
}

void Foam::meshLattice::mapCellCentres()
{
    // A uniform box's cells are one node each; any other mesh's many cells
    // may share the lattice cell holding their centres
    cellNode_.setSize(mesh_.nCells());
    cellIjk_.resize(mesh_.nCells());
    forAll(mesh_.cellCentres(), celli)
    {
        label ijk[3];
        indicesOf(mesh_.cellCentres()[celli], ijk);
        cellIjk_[celli] = {int(ijk[0]), int(ijk[1]), int(ijk[2])};
        cellNode_[celli] = lattice_.realNode(ijk[0], ijk[1], ijk[2]);
        if (!cellsAreNodes_) continue;
        const label lin = lattice_.cellIndex(ijk[0], ijk[1], ijk[2]);
        const label other = latticeCell_.lookup(lin, -1);
        if (other != -1)
        {
            FatalErrorInFunction
                << "Cells " << other << " and " << celli
                << " map to the same lattice node: the mesh is not a "
                << "uniform Cartesian box" << exit(FatalError);
        }
        latticeCell_.set(lin, celli);
    }
}

void Foam::meshLattice::decomposeOwn()
{
    // Each rank claims the lattice cells whose centres its cells hold (on a
    // shared face the higher rank, as maxEqOp combines)
    const label n = label(lattice_.nRealNodes);
    latticeOwner_.setSize(n, -1);
    const boundBox local(mesh_.points(), false);
    label lo[3], hi[3];
    indicesOf(local.min(), lo);
    indicesOf(local.max(), hi);
    for (label k = lo[2]; k <= hi[2]; ++k)
    for (label j = lo[1]; j <= hi[1]; ++j)
    for (label i = lo[0]; i <= hi[0]; ++i)
    {
        const label lin = lattice_.cellIndex(i, j, k);
        if (mesh_.findCell(cellCentre(lin)) >= 0) latticeOwner_[lin] = Pstream::myProcNo();
    }
    Pstream::listCombineGather(latticeOwner_, maxEqOp<label>());
    Pstream::listCombineScatter(latticeOwner_);
    // Lattice cells outside the mesh (walls, the box's corners) take the
    // owner of a neighbour, breadth first from the claimed cells in index
    // order: the same on every rank. Their nodes carry the walls' mass.
    DynamicList<label> front;
    forAll(latticeOwner_, lin) if (latticeOwner_[lin] >= 0) front.append(lin);
    if (front.empty())
    {
        FatalErrorInFunction
            << "No lattice cell centre lies in a cell of the mesh: the lattice"
            << " spacing " << lattice_.h << " is too coarse" << exit(FatalError);
    }
    for (label f = 0; f < front.size(); ++f)
    {
        const label lin = front[f];
        forEachFaceNeighbour(lin, [&](label nb)
        {
            if (latticeOwner_[nb] >= 0) return;
            latticeOwner_[nb] = latticeOwner_[lin];
            front.append(nb);
        });
    }
    meshOwner_ = latticeOwner_;
    labelList count(Pstream::nProcs(), Zero);
    for (const label o : latticeOwner_) ++count[o];
    Info<< "MPM lattice decomposition: lattice cells per processor " << count
        << " (each owns the cells whose centres its mesh cells hold)" << nl;
    // A processor may own none (its mesh cells all beyond the lattice's
    // extent): it does no MPM work. Its cells must then overlap no lattice
    // cell, which the exchange's weights check (buildExchangeWeights).
    forAll(count, proc)
    {
        if (count[proc] == 0)
        {
            Info<< "    processor " << proc << " owns no lattice cell (its mesh"
                << " cells hold no lattice cell centre): no MPM work there" << nl;
        }
    }
}

void Foam::meshLattice::buildFromCells(const vector& h0)
{
    const pointField& pts = mesh_.points();
    const boundBox bb(pts, true);   // the whole domain when decomposed
    const Vector<label>& solD = mesh_.solutionD();
    scalar h = -1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        lattice_.solved[d] = solD[d] > 0;
        lattice_.origin[d] = bb.min()[d];
        if (!lattice_.solved[d]) continue;
        if (h < 0) h = h0[d];
    }
    lattice_.h = h;
    unsolvedSpan_ = bb.span();
    cellVolume_ = 1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        cellVolume_ *= lattice_.solved[d] ? h : bb.span()[d];
    }

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar len = bb.span()[d];
        lattice_.nCells[d] = lattice_.solved[d] ? label(std::round(len/h)) : 1;
        if (lattice_.solved[d] && mag(lattice_.nCells[d]*h - len) > 1e-6*len)
        {
            FatalErrorInFunction
                << "Domain length " << len << " in direction " << d
                << " is not a whole number of cells " << h
                << exit(FatalError);
        }
    }
    try
    {
        lattice_.finalise();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    mapCellCentres();
    if (Pstream::parRun())
    {
        // The owners that follow the mesh: each cell's rank, the first
        // table of a balance by points (latticeBalance)
        latticeOwner_.setSize(label(lattice_.nRealNodes), -1);
        forAll(cellIjk_, celli)
        {
            const auto& r = cellIjk_[celli];
            latticeOwner_[lattice_.cellIndex(r[0], r[1], r[2])] = Pstream::myProcNo();
        }
        Pstream::listCombineGather(latticeOwner_, maxEqOp<label>());
        Pstream::listCombineScatter(latticeOwner_);
        meshOwner_ = latticeOwner_;
    }
}

std::vector<std::array<int, 3>> Foam::meshLattice::ownedLatticeCells() const
{
    // A uniform box's own cells, in cell order, while its owners follow it
    if (cellsAreNodes_ && ownersFollowMesh_) return cellIjk_;
    std::vector<std::array<int, 3>> mine;
    for (int k = 0; k < lattice_.nCells[2]; ++k)
    for (int j = 0; j < lattice_.nCells[1]; ++j)
    for (int i = 0; i < lattice_.nCells[0]; ++i)
    {
        if (ownsLatticeCell(label(lattice_.cellIndex(i, j, k)))) mine.push_back({i, j, k});
    }
    return mine;
}

bool Foam::meshLattice::ownsLatticeCell(label i, label j, label k) const
{
    return ownsLatticeCell(label(lattice_.cellIndex(i, j, k)));
}

namespace
{

using tet = Foam::FixedList<Foam::point, 4>;

Foam::scalar tetVolume(const tet& t)
{
    return Foam::mag(((t[1] - t[0]) ^ (t[2] - t[0])) & (t[3] - t[0]))/6;
}

// The convex prism of triangles (a0 a1 a2) and (b0 b1 b2), with edges
// ai-bi, as three tets
template<class Op>
void prismTets
(
    const Foam::point& a0, const Foam::point& a1, const Foam::point& a2,
    const Foam::point& b0, const Foam::point& b1, const Foam::point& b2, Op& op
)
{
    op(tet({a0, a1, a2, b2}));
    op(tet({a0, a1, b1, b2}));
    op(tet({a0, b0, b1, b2}));
}

// Cuts t by the plane x_a = X into convex pieces, each split into tets:
// above(piece) for those with x_a >= X, below(piece) for x_a <= X. The
// cut points lie on the plane exactly. (Written here rather than with
// tetrahedron::sliceWithPlane, whose header does not compile on its own in
// this OpenFOAM: tetPoints is used there before it is complete.)
template<class Above, class Below>
void sliceTet(const tet& t, int a, Foam::scalar X, Above& above, Below& below)
{
    using namespace Foam;
    int up[4], down[4], nUp = 0, nDown = 0;
    for (int i = 0; i < 4; ++i)
    {
        if (t[i][a] > X) up[nUp++] = i; else down[nDown++] = i;
    }
    if (nDown == 0) { above(t); return; }
    if (nUp == 0) { below(t); return; }
    // The point on edge (i, j) at the plane
    auto cut = [&](int i, int j)
    {
        const scalar f = (t[i][a] - X)/(t[i][a] - t[j][a]);
        point q(t[i] + f*(t[j] - t[i]));
        q[a] = X;
        return q;
    };
    if (nUp == 1 || nDown == 1)
    {
        // One corner alone on its side: a tet there, a prism on the other
        const bool upAlone = nUp == 1;
        const int c = upAlone ? up[0] : down[0];
        const int* o = upAlone ? down : up;
        const point q0(cut(c, o[0])), q1(cut(c, o[1])), q2(cut(c, o[2]));
        const tet corner({t[c], q0, q1, q2});
        if (upAlone)
        {
            above(corner);
            prismTets(q0, q1, q2, t[o[0]], t[o[1]], t[o[2]], below);
        }
        else
        {
            below(corner);
            prismTets(q0, q1, q2, t[o[0]], t[o[1]], t[o[2]], above);
        }
        return;
    }
    // Two and two: a prism on each side
    const int i = up[0], j = up[1], k = down[0], l = down[1];
    const point qik(cut(i, k)), qil(cut(i, l)), qjk(cut(j, k)), qjl(cut(j, l));
    prismTets(t[i], qik, qil, t[j], qjk, qjl, above);
    prismTets(t[k], qik, qjk, t[l], qil, qjl, below);
}

// Adds the pieces of tet t, cut by the lattice's planes x_a = origin_a + k h
// in each solved direction a from `axis` on, to the lattice cell of each
// piece's centroid: the exact overlap volumes, to round-off. Pieces of
// neighbouring cells share their faces' triangles, so a lattice cell inside
// the mesh is covered exactly once. Planes are taken in increasing k from
// kMin, so a piece is never cut twice by one plane.
template<class Add>
void clipTet(const tet& t, const mpm::Lattice& L, int axis, Foam::scalar kMin, Add& add)
{
    using namespace Foam;
    for (int a = axis; a < 3; ++a, kMin = -GREAT)
    {
        if (!L.solved[a]) continue;
        scalar lo = t[0][a], hi = lo;
        for (int i = 1; i < 4; ++i) { lo = min(lo, t[i][a]); hi = max(hi, t[i][a]); }
        scalar k = max(kMin, std::floor((lo - L.origin[a])/L.h) + 1);
        scalar X = L.origin[a] + k*L.h;
        if (X <= lo) { k += 1; X += L.h; }
        if (!(X < hi)) continue;
        // Below the plane: no more planes along a; above: the next ones
        auto below = [&](const tet& p) { clipTet(p, L, a + 1, -GREAT, add); };
        auto above = [&](const tet& p) { clipTet(p, L, a, k + 1, add); };
        sliceTet(t, a, X, above, below);
        return;
    }
    add(0.25*(t[0] + t[1] + t[2] + t[3]), tetVolume(t));
}

} // namespace

void Foam::meshLattice::buildOverlaps() const
{
    const label nCells = mesh_.nCells();
    weightStart_.setSize(nCells + 1);
    DynamicList<label> cells;
    DynamicList<scalar> fractions;
    const pointField& pts = mesh_.points();
    std::map<label, scalar> overlap;
    for (label celli = 0; celli < nCells; ++celli)
    {
        overlap.clear();
        const point& cc = mesh_.cellCentres()[celli];
        auto add = [&](const point& x, scalar v)
        {
            // Beyond a lattice extent the cell overlaps no lattice cell
            if (!insideLattice(x)) return;
            label ijk[3];
            indicesOf(x, ijk);
            overlap[label(lattice_.cellIndex(ijk[0], ijk[1], ijk[2]))] += v;
        };
        for (const label facei : mesh_.cells()[celli])
        {
            const face& f = mesh_.faces()[facei];
            for (label i = 1; i + 1 < f.size(); ++i)
            {
                clipTet(tet({cc, pts[f[0]], pts[f[i]], pts[f[i + 1]]}), lattice_, 0, -GREAT, add);
            }
        }
        // Fractions of the mesh's cell volume: with a warped face they sum
        // to a hair off 1 (OpenFOAM decomposes about the face centre); what
        // moves between the two sides is conserved either way (the same
        // weights)
        // A lattice plane through a face of the cell cuts off round-off
        // slivers (1e-17 of it) of the lattice cell beyond: they are
        // dropped and the rest scaled to the same sum, so a cell whose
        // faces lie on lattice planes overlaps its own lattice cells only
        // (a neighbour's velocity would otherwise show in a massless
        // cell's mass-weighted U.solid)
        const scalar V = mesh_.cellVolumes()[celli];
        scalar all = 0, kept = 0;
        for (const auto& o : overlap)
        {
            all += o.second;
            if (o.second > sliver*V) kept += o.second;
        }
        weightStart_[celli] = cells.size();
        for (const auto& o : overlap)
        {
            if (o.second <= sliver*V) continue;
            cells.append(o.first);
            fractions.append(o.second/V*(all/kept));
        }
    }
    weightStart_[nCells] = cells.size();
    weightCell_.transfer(cells);
    weightFraction_.transfer(fractions);
    Info<< "MPM lattice <-> mesh exchange: "
        << returnReduce(weightCell_.size(), sumOp<label>()) << " overlaps of "
        << returnReduce(nCells, sumOp<label>()) << " cells with lattice cells"
        << " (cut exactly by the lattice's planes)" << nl;
}

void Foam::meshLattice::localiseOverlaps() const
{
    if (weightStart_.empty()) buildOverlaps();
    // The nodes the MPM arrays live on: the domain's, or this rank's box,
    // which holds every lattice cell this rank's mesh cells overlap (the
    // Subdomain's extra cells: overlappedCells)
    const mpm::Lattice& arrays = subdomain_ ? subdomain_->local() : lattice_;
    coverage_.assign(std::size_t(arrays.nNodes), 0.0);
    weightNode_.setSize(weightCell_.size());
    forAll(weightCell_, k)
    {
        label r[3];
        cellIjk(weightCell_[k], r);
        const label I = subdomain_
          ? label(subdomain_->localNode(r[0], r[1], r[2]))
          : label(lattice_.realNode(r[0], r[1], r[2]));
        if (I < 0)
        {
            FatalErrorInFunction
                << "Lattice cell (" << r[0] << ' ' << r[1] << ' ' << r[2]
                << ") overlapped by processor " << Pstream::myProcNo()
                << "'s cells lies beyond its box lattice" << abort(FatalError);
        }
        weightNode_[k] = I;
    }
    forAll(mesh_.cells(), celli)
    {
        const scalar V = mesh_.cellVolumes()[celli];
        for (label k = weightStart_[celli]; k < weightStart_[celli + 1]; ++k)
        {
            coverage_[std::size_t(weightNode_[k])] += weightFraction_[k]*V/cellVolume_;
        }
    }
    localised_ = true;
}

std::vector<std::array<int, 3>> Foam::meshLattice::overlappedCells() const
{
    // A uniform box's cells are their lattice cells
    if (cellsAreNodes_) return cellIjk_;
    if (weightStart_.empty()) buildOverlaps();
    labelList lin(weightCell_);
    Foam::sort(lin);
    std::vector<std::array<int, 3>> out;
    forAll(lin, k)
    {
        if (k && lin[k] == lin[k - 1]) continue;
        label r[3];
        cellIjk(lin[k], r);
        out.push_back({int(r[0]), int(r[1]), int(r[2])});
    }
    return out;
}

void Foam::meshLattice::setOwners(labelList&& owners)
{
    latticeOwner_.transfer(owners);
    localised_ = false;
    ownersFollowMesh_ = false;
}

Foam::label Foam::meshLattice::fvCellOf(const point& x) const
{
    if (cellsAreNodes_)
    {
        label ijk[3];
        indicesOf(x, ijk);
        return cellOf(ijk[0], ijk[1], ijk[2]);
    }
    const label celli = mesh_.findCell(x);
    // Containment keeps a point on a wall's surface, a hair outside it may
    // be judged outside the mesh (serially: decomposed, the nearest cell of
    // this rank may be far from another rank's point)
    return celli >= 0 || Pstream::parRun() ? celli : mesh_.findNearestCell(x);
}

void Foam::meshLattice::attach(const std::shared_ptr<const mpm::Subdomain>& subdomain)
{
    subdomain_ = subdomain;
    localised_ = false;
    forAll(cellNode_, celli)
    {
        const auto& r = cellIjk_[celli];
        cellNode_[celli] = label(subdomain->localNode(r[0], r[1], r[2]));
    }
}

Foam::point Foam::meshLattice::cellCentre(label globalCell) const
{
    label r[3];
    cellIjk(globalCell, r);
    point c;
    for (direction d = 0; d < 3; ++d)
    {
        // Unsolved directions: the mesh's mid-plane
        c[d] = lattice_.origin[d]
          + (lattice_.solved[d] ? (r[d] + 0.5)*lattice_.h : 0.5*unsolvedSpan_[d]);
    }
    return c;
}

bool Foam::meshLattice::ownsLatticeCell(label globalCell) const
{
    if (cellsAreNodes_ && ownersFollowMesh_) return latticeCell_.found(globalCell);
    return latticeCellOwner(globalCell) == Pstream::myProcNo();
}

bool Foam::meshLattice::insideLattice(const point& x) const
{
    for (direction d = 0; d < 3; ++d)
    {
        if (!lattice_.solved[d]) continue;
        const scalar s = (x[d] - lattice_.origin[d])/lattice_.h;
        if (s < 0 || s > lattice_.nCells[d]) return false;
    }
    return true;
}

Foam::label Foam::meshLattice::cellOf(label i, label j, label k) const
{
    return latticeCell_.lookup(lattice_.cellIndex(i, j, k), -1);
}

void Foam::meshLattice::indicesOf(const point& x, label ijk[3]) const
{
    for (direction d = 0; d < 3; ++d)
    {
        label i = label(std::floor((x[d] - lattice_.origin[d])/lattice_.h));
        if (!lattice_.solved[d]) i = 0;
        ijk[d] = max(label(0), min(i, label(lattice_.nCells[d] - 1)));
    }
}

void Foam::meshLattice::report(Ostream& os) const
{
    os  << "MPM lattice: " << lattice_.dim << "D, h = " << lattice_.h
        << ", cells (" << lattice_.nCells[0] << ' ' << lattice_.nCells[1]
        << ' ' << lattice_.nCells[2] << "), ";
    if (!cellsAreNodes_)
    {
        os  << "origin " << point(lattice_.origin[0], lattice_.origin[1], lattice_.origin[2])
            << ", its own (not the mesh's cells), ";
    }
    os  << "nodes at cell centres, " << lattice_.pad << " ghost layers" << nl;
}
