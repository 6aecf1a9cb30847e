#include "latticeBalance.H"
#include "choice.H"
#include "scotchRepartition.H"
#include "HashTable.H"

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

    // The master holds the whole graph: the material's lattice cells in
    // blocks of 2 cells a side, since scotch's time grows with the vertices
    // (11 500 cells: 20 ms; their 1 500 blocks: 3 ms), unless a block would
    // hold more than blockShare_ of a rank's points: then single cells, so
    // that small cases still balance finely
    labelList active, activeBlock, weight, present;
    labelListList graph;
    if (Pstream::master())
    {
        Map<label> total;
        label sum = 0;
        forAll(cells, proc)
        {
            forAll(cells[proc], i)
            {
                total(cells[proc][i], 0) += counts[proc][i];
                sum += counts[proc][i];
            }
        }
        active = total.sortedToc();
        for (const label B : {2, 1})
        {
            const label nb0 = (L.nCells[0] + B - 1)/B, nb1 = (L.nCells[1] + B - 1)/B;
            const auto blockOf = [&](label c)
            {
                label r[3];
                lattice.cellIjk(c, r);
                return r[0]/B + nb0*(r[1]/B + nb1*(r[2]/B));
            };
            Map<label> blockIndex;
            DynamicList<label> w, owned, most;  // most: the points of each block's fullest cell
            activeBlock.setSize(active.size());
            forAll(active, a)
            {
                const label key = blockOf(active[a]);
                label b = blockIndex.lookup(key, -1);
                if (b < 0)
                {
                    b = w.size();
                    blockIndex.set(key, b);
                    w.append(0);
                    owned.append(-1);
                    most.append(0);
                }
                activeBlock[a] = b;
                const label n = total[active[a]];
                w[b] += n;
                // A block's present owner: its fullest cell's (blocks
                // straddle owners only where these follow the mesh)
                if (n > most[b])
                {
                    most[b] = n;
                    owned[b] = lattice.latticeCellOwner(active[a]);
                }
            }
            if (B > 1 && max(w)*Pstream::nProcs() > blockShare_*sum) continue;
            List<DynamicList<label>> nbrs(w.size());
            forAll(active, a)
            {
                const label b = activeBlock[a];
                lattice.forEachFaceNeighbour(active[a], [&](label c)
                {
                    const label o = blockIndex.lookup(blockOf(c), -1);
                    if (o >= 0 && o != b && !nbrs[b].found(o)) nbrs[b].append(o);
                });
            }
            weight.transfer(w);
            present.transfer(owned);
            graph.setSize(weight.size());
            forAll(graph, b) graph[b].transfer(nbrs[b]);
            break;
        }
    }
    if (returnReduce(active.size(), sumOp<label>()) == 0) return meshOwners;

    labelList owner(meshOwners);
    if (Pstream::master())
    {
        // Repartition from the present owners: moving a block costs its
        // points (times migrationRatio_) against 1 per cut face, so a drift
        // moves the blocks at the parts' edges, not half the material
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
            owner[active[a]] = part[activeBlock[a]];
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
