#include "latticeBalance.H"
#include "choice.H"
#include "decompositionMethod.H"
#include "HashTable.H"
#include <algorithm>

namespace
{

const char* balanceName(bool byPoints) { return byPoints ? "scotch" : "none"; }

bool parseBalance(const std::string& s, bool& byPoints)
{
    for (const bool b : {true, false})
    {
        if (s == balanceName(b)) { byPoints = b; return true; }
    }
    return false;
}

} // namespace

Foam::latticeBalance::latticeBalance(const dictionary& ld)
{
    // Read (strictly) in serial runs too, echoed where it acts
    const bool echo = Pstream::parRun();
    if (echo) Info<< "MPM load balance (the lattice's owners by points):" << nl;
    enabled_ = readChoice(ld, "balance", parseBalance, balanceName, "scotch none", true, echo);
    maxImbalance_ = readBounded(ld, "maxImbalance", 1.1, numberRange{1, GREAT, false, true}, echo);
}

Foam::scalar Foam::latticeBalance::imbalance(label nPoints)
{
    const label most = returnReduce(nPoints, maxOp<label>());
    const label total = returnReduce(nPoints, sumOp<label>());
    return total > 0 ? scalar(most)*Pstream::nProcs()/total : 1;
}

Foam::labelList Foam::latticeBalance::owners
(
    const meshLattice& lattice,
    const mpm::Particles& P,
    const labelList& meshOwners
) const
{
    const mpm::Lattice& L = lattice.lattice();
    // This rank's points per lattice cell, gathered on the master
    Map<label> count;
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        label ijk[3];
        lattice.indicesOf(point(P.x[0][p], P.x[1][p], P.x[2][p]), ijk);
        ++count(label(L.cellIndex(ijk[0], ijk[1], ijk[2])), 0);
    }
    List<labelList> cells(Pstream::nProcs()), counts(Pstream::nProcs());
    cells[Pstream::myProcNo()] = count.sortedToc();
    counts[Pstream::myProcNo()].setSize(cells[Pstream::myProcNo()].size());
    forAll(cells[Pstream::myProcNo()], i)
    {
        counts[Pstream::myProcNo()][i] = count[cells[Pstream::myProcNo()][i]];
    }
    Pstream::gatherList(cells);
    Pstream::gatherList(counts);

    // The master holds the whole graph of the material's lattice cells;
    // the others give none (the decomposition gathers it there anyway)
    labelList active;
    scalarField weight;
    labelListList graph;
    pointField centres;
    Map<label> index;
    if (Pstream::master())
    {
        Map<label> total;
        forAll(cells, proc)
        {
            forAll(cells[proc], i) total(cells[proc][i], 0) += counts[proc][i];
        }
        active = total.sortedToc();
        weight.setSize(active.size());
        centres.setSize(active.size());
        forAll(active, a)
        {
            index.set(active[a], a);
            weight[a] = total[active[a]];
            centres[a] = lattice.cellCentre(active[a]);
        }
        graph.setSize(active.size());
        forAll(active, a)
        {
            DynamicList<label> nbrs;
            lattice.forEachFaceNeighbour(active[a], [&](label c)
            {
                const label b = index.lookup(c, -1);
                if (b >= 0) nbrs.append(b);
            });
            graph[a].transfer(nbrs);
        }
    }
    if (returnReduce(active.size(), sumOp<label>()) == 0) return meshOwners;

    dictionary decompDict;
    decompDict.add("numberOfSubdomains", Pstream::nProcs());
    decompDict.add("method", word("scotch"));
    const labelList part = decompositionMethod::New(decompDict)->decompose(graph, centres, weight);

    labelList owner(meshOwners);
    if (Pstream::master())
    {
        // Number the parts to keep the most points where they are: the
        // largest overlaps of part and present owner first
        const label np = Pstream::nProcs();
        List<Tuple2<scalar, labelPair>> overlap;
        {
            scalarSquareMatrix kept(np, Zero);
            forAll(active, a) kept(part[a], lattice.latticeCellOwner(active[a])) += weight[a];
            for (label i = 0; i < np; ++i)
            for (label j = 0; j < np; ++j)
            {
                if (kept(i, j) > 0) overlap.append(Tuple2<scalar, labelPair>(kept(i, j), labelPair(i, j)));
            }
        }
        std::stable_sort
        (
            overlap.begin(), overlap.end(),
            [](const Tuple2<scalar, labelPair>& x, const Tuple2<scalar, labelPair>& y) { return x.first() > y.first(); }
        );
        labelList rankOf(np, -1);
        boolList taken(np, false);
        for (const auto& o : overlap)
        {
            const label i = o.second().first(), j = o.second().second();
            if (rankOf[i] >= 0 || taken[j]) continue;
            rankOf[i] = j;
            taken[j] = true;
        }
        label next = 0;
        forAll(rankOf, i)
        {
            if (rankOf[i] >= 0) continue;
            while (taken[next]) ++next;
            rankOf[i] = next;
            taken[next] = true;
        }
        // The material's cells, then layers around them breadth first
        boolList set(owner.size(), false);
        DynamicList<label> front;
        forAll(active, a)
        {
            owner[active[a]] = rankOf[part[a]];
            set[active[a]] = true;
            front.append(active[a]);
        }
        for (label layer = 0; layer < layers_; ++layer)
        {
            DynamicList<label> nextFront;
            for (const label c : front)
            {
                lattice.forEachFaceNeighbour(c, [&](label b)
                {
                    if (set[b]) return;
                    set[b] = true;
                    owner[b] = owner[c];
                    nextFront.append(b);
                });
            }
            front.transfer(nextFront);
        }
    }
    Pstream::scatter(owner);
    return owner;
}
