#include "meshCellSearch.H"
#include "PstreamBuffers.H"
#include "boundBox.H"

namespace
{

using namespace Foam;

// Sends the points marked for other processors (dest[p] != me) there;
// returns how many left this processor
label sendPoints(mpm::Particles& P, const labelUList& dest)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    List<std::vector<char>> out(Pstream::nProcs());
    std::vector<mpm::Index> leaving;
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        const label q = dest[p];
        if (q < 0 || q == Pstream::myProcNo()) continue;
        P.pack(p, out[q]);
        leaving.push_back(p);
    }
    forAll(out, q)
    {
        if (q == Pstream::myProcNo()) continue;
        UOPstream os(q, buffers);
        os << List<char>(out[q].begin(), out[q].end());
    }
    buffers.finishedSends();
    P.remove(leaving);
    for (label q = 0; q < Pstream::nProcs(); ++q)
    {
        if (q == Pstream::myProcNo()) continue;
        UIPstream is(q, buffers);
        List<char> in(is);
        if (in.size()) P.unpack(std::vector<char>(in.begin(), in.end()));
    }
    return label(leaving.size());
}

} // namespace


Foam::labelList Foam::meshCellRanks(const fvMesh& mesh, const UList<point>& x, const bool strict)
{
    const label me = Pstream::myProcNo();
    labelList rank(x.size(), -1);
    forAll(x, i) if (mesh.findCell(x[i]) >= 0) rank[i] = me;
    if (!Pstream::parRun()) return rank;

    // Every processor's mesh bounding box, grown a hair
    List<boundBox> boxes(Pstream::nProcs());
    {
        boundBox local(mesh.points(), false);
        const boundBox all(mesh.points(), true);
        local.inflate(1e-9*all.mag()/max(local.mag(), SMALL));
        boxes[me] = local;
    }
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);

    // Round 1: each point found nowhere here goes to its candidates
    List<DynamicList<label>> asked(Pstream::nProcs());   // my point indices, per processor
    {
        PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
        List<DynamicList<point>> query(Pstream::nProcs());
        forAll(x, i)
        {
            if (rank[i] >= 0) continue;
            forAll(boxes, q)
            {
                if (q == me || !boxes[q].contains(x[i])) continue;
                query[q].append(x[i]);
                asked[q].append(i);
            }
        }
        forAll(query, q)
        {
            if (q == me) continue;
            UOPstream os(q, buffers);
            os << query[q];
        }
        buffers.finishedSends();
        // Round 2: the answers, found or not, in the order asked
        PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
        for (label q = 0; q < Pstream::nProcs(); ++q)
        {
            if (q == me) continue;
            UIPstream is(q, buffers);
            const List<point> theirs(is);
            boolList found(theirs.size());
            forAll(theirs, k) found[k] = mesh.findCell(theirs[k]) >= 0;
            UOPstream os(q, answers);
            os << found;
        }
        answers.finishedSends();
        labelList byBox(x.size(), labelMax);
        for (label q = 0; q < Pstream::nProcs(); ++q)
        {
            if (q == me) continue;
            UIPstream is(q, answers);
            const boolList found(is);
            forAll(found, k)
            {
                const label i = asked[q][k];
                if (found[k] && (rank[i] < 0 || q < rank[i])) rank[i] = q;
                byBox[i] = min(byBox[i], q);
            }
        }
        // Found nowhere: the lowest processor whose box holds it (this one
        // too), where the nearest cell is near
        forAll(x, i)
        {
            if (rank[i] >= 0 || strict) continue;
            const label b = boxes[me].contains(x[i]) ? min(me, byBox[i]) : byBox[i];
            if (b != labelMax) rank[i] = b;
        }
    }
    return rank;
}


Foam::label Foam::toMeshCellRanks(const fvMesh& mesh, mpm::Particles& P)
{
    if (!Pstream::parRun()) return 0;
    List<point> x(P.size());
    forAll(x, p) x[p] = point(P.x[0][p], P.x[1][p], P.x[2][p]);
    return returnReduce(sendPoints(P, meshCellRanks(mesh, x)), sumOp<label>());
}


Foam::label Foam::toLatticeOwners(const meshLattice& lattice, mpm::Particles& P)
{
    if (!Pstream::parRun()) return 0;
    // Decomposed, every lattice holds its owners' table
    const mpm::Lattice& L = lattice.lattice();
    labelList dest(P.size());
    forAll(dest, p)
    {
        const point x(P.x[0][p], P.x[1][p], P.x[2][p]);
        label ijk[3];
        lattice.indicesOf(x, ijk);
        const label lin(L.cellIndex(ijk[0], ijk[1], ijk[2]));
        dest[p] = lattice.latticeCellOwner(lin);
        if (dest[p] < 0)
        {
            FatalErrorInFunction
                << "Material point " << label(P.id[p]) << " at " << x
                << " lies in no cell of the mesh" << exit(FatalError);
        }
    }
    return returnReduce(sendPoints(P, dest), sumOp<label>());
}
