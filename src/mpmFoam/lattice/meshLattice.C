#include "meshLattice.H"
#include "cellModel.H"
#include "boundBox.H"

Foam::meshLattice::meshLattice(const fvMesh& mesh)
:
    mesh_(mesh)
{
    build();
}

void Foam::meshLattice::build()
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
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    const cellShapeList& shapes = mesh_.cellShapes();
    const pointField& pts = mesh_.points();
    const boundBox bb(pts, true);   // the whole domain when decomposed
    const Vector<label>& solD = mesh_.solutionD();

    // Cell size from the first cell; every other cell must match it.
    vector h0(Zero);
    forAll(shapes, celli)
    {
        if (shapes[celli].model() != hex)
        {
            FatalErrorInFunction
                << "MPM needs a uniform Cartesian hex mesh, but cell " << celli
                << " at " << mesh_.cellCentres()[celli] << " is a "
                << shapes[celli].model().name() << nl
                << "Use blockMesh with one hex block and uniform grading."
                << exit(FatalError);
        }
        const boundBox cb(pointField(pts, shapes[celli]), false);
        const vector span = cb.span();
        const scalar boxVol = span.x()*span.y()*span.z();
        if (mag(boxVol - mesh_.cellVolumes()[celli]) > 1e-6*boxVol)
        {
            FatalErrorInFunction
                << "MPM needs axis-aligned box cells, but cell " << celli
                << " at " << mesh_.cellCentres()[celli] << " has volume "
                << mesh_.cellVolumes()[celli] << " while its bounding box has "
                << boxVol << " (skewed or rotated cell)."
                << exit(FatalError);
        }
        if (celli == 0) h0 = span;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mag(span[d] - h0[d]) > 1e-6*mag(h0[d]))
            {
                FatalErrorInFunction
                    << "MPM needs a uniform mesh, but cell " << celli
                    << " at " << mesh_.cellCentres()[celli] << " has size " << span
                    << " while cell 0 has size " << h0 << nl
                    << "Remove grading (simpleGrading (1 1 1)) and use one "
                    << "block." << exit(FatalError);
            }
        }
    }

    scalar h = -1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        lattice_.solved[d] = solD[d] > 0;
        lattice_.origin[d] = bb.min()[d];
        if (!lattice_.solved[d]) continue;
        if (h < 0) h = h0[d];
        if (mag(h0[d] - h) > 1e-6*h)
        {
            FatalErrorInFunction
                << "MPM needs cubic (square in 2D) cells, but the cells are "
                << h0 << " in the solved directions " << solD << nl
                << "Choose the cell counts so that every solved direction "
                << "has the same spacing." << exit(FatalError);
        }
    }
    if (h < 0)
    {
        FatalErrorInFunction << "Mesh has no solved direction" << exit(FatalError);
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
    if (lattice_.nRealNodes != returnReduce(mesh_.nCells(), sumOp<label>()))
    {
        FatalErrorInFunction
            << "MPM needs the mesh to fill its bounding box " << bb
            << " with cells of size " << h << ": expected "
            << lattice_.nRealNodes << " cells, found " << returnReduce(mesh_.nCells(), sumOp<label>())
            << exit(FatalError);
    }

    cellNode_.setSize(mesh_.nCells());
    cellIjk_.resize(mesh_.nCells());
    forAll(mesh_.cellCentres(), celli)
    {
        label ijk[3];
        indicesOf(mesh_.cellCentres()[celli], ijk);
        cellIjk_[celli] = {int(ijk[0]), int(ijk[1]), int(ijk[2])};
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
        cellNode_[celli] = lattice_.realNode(ijk[0], ijk[1], ijk[2]);
    }
}

void Foam::meshLattice::attach(const std::shared_ptr<const mpm::Subdomain>& subdomain)
{
    forAll(cellNode_, celli)
    {
        const auto& r = cellIjk_[celli];
        cellNode_[celli] = label(subdomain->localNode(r[0], r[1], r[2]));
    }
}

Foam::point Foam::meshLattice::cellCentre(label globalCell) const
{
    const label n0 = lattice_.nCells[0], n1 = lattice_.nCells[1];
    const label r[3] = {globalCell % n0, (globalCell/n0) % n1, globalCell/(n0*n1)};
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
    return latticeCell_.found(globalCell);
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
        << ' ' << lattice_.nCells[2] << "), nodes at cell centres, "
        << lattice_.pad << " ghost layers" << nl;
}
