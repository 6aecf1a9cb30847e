#include "latticeBalance.H"
#include "choice.H"
#include "scotchRepartition.H"
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
    migrationRatio_ = readBounded(ld, "migrationRatio", 0.2, numberRange{0, 100, true, true}, echo);
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

    // The master holds the whole graph of the material's lattice cells
    labelList active, weight, present;
    labelListList graph;
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
        present.setSize(active.size());
        forAll(active, a)
        {
            index.set(active[a], a);
            weight[a] = total[active[a]];
            present[a] = lattice.latticeCellOwner(active[a]);
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

    labelList owner(meshOwners);
    if (Pstream::master())
    {
        // Repartition from the present owners: moving a cell costs its
        // points (times migrationRatio_) against 1 per cut face, so a drift
        // moves the cells at the parts' edges, not half the material
        const labelList part
        (
            scotchRepartition
            (
                graph, weight, present, weight, migrationRatio_, Pstream::nProcs(), partBalance_
            )
        );
        // The material's cells, then layers around them breadth first
        boolList set(owner.size(), false);
        DynamicList<label> front;
        forAll(active, a)
        {
            owner[active[a]] = part[a];
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
