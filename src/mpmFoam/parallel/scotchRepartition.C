#include "scotchRepartition.H"
#include "error.H"
#include "floatingPointTraps.H"

#include <cstdint>
#include <cstdio>
#include <vector>
extern "C"
{
#include "scotch.h"
}

namespace
{

void check(int rc, const char* what)
{
    if (rc != 0)
    {
        FatalErrorInFunction
            << "scotch failed in " << what << " (return code " << rc << ")"
            << Foam::exit(Foam::FatalError);
    }
}

} // namespace

Foam::labelList Foam::scotchRepartition
(
    const labelListList& graph,
    const labelList& weight,
    const labelList& oldPart,
    const labelList& migrationCost,
    scalar migrationRatio,
    label nParts,
    scalar balance
)
{
    const label n = graph.size();
    labelList part(n, 0);
    if (n == 0 || nParts <= 1) return part;
    // scotch's balance arithmetic divides by zero on small graphs (a few
    // points left before an outlet): OpenFOAM's scotchDecomp switches the
    // traps off around it too
    const floatingPointTrapsOff noTraps;

    // Compressed rows, as scotch reads them (SCOTCH_Num is scotch's own
    // integer; OpenFOAM's label may differ)
    std::vector<SCOTCH_Num> verttab(n + 1, 0), edgetab, velotab(n), parotab(n), vmlotab(n), parttab(n);
    for (label v = 0; v < n; ++v)
    {
        verttab[v + 1] = verttab[v] + SCOTCH_Num(graph[v].size());
        for (const label w : graph[v]) edgetab.push_back(SCOTCH_Num(w));
        velotab[v] = SCOTCH_Num(weight[v]);
        parotab[v] = SCOTCH_Num(oldPart[v]);
        vmlotab[v] = SCOTCH_Num(migrationCost[v]);
    }
    // scotch reads an empty edge array through its pointer all the same
    if (edgetab.empty()) edgetab.push_back(0);

    SCOTCH_Graph g;
    check(SCOTCH_graphInit(&g), "graphInit");
    check
    (
        SCOTCH_graphBuild
        (
            &g, 0, SCOTCH_Num(n), verttab.data(), nullptr, velotab.data(), nullptr,
            verttab[n], edgetab.data(), nullptr
        ),
        "graphBuild"
    );
    SCOTCH_Strat strat;
    check(SCOTCH_stratInit(&strat), "stratInit");
    check(SCOTCH_stratGraphMapBuild(&strat, SCOTCH_STRATDEFAULT, SCOTCH_Num(nParts), balance), "stratGraphMapBuild");
    check
    (
        SCOTCH_graphRepart
        (
            &g, SCOTCH_Num(nParts), parotab.data(), migrationRatio, vmlotab.data(),
            &strat, parttab.data()
        ),
        "graphRepart"
    );
    SCOTCH_stratExit(&strat);
    SCOTCH_graphExit(&g);

    forAll(part, v)
    {
        part[v] = label(parttab[v]);
        if (part[v] < 0 || part[v] >= nParts)
        {
            FatalErrorInFunction
                << "scotch gave vertex " << v << " of " << n << " the part "
                << part[v] << ", not one of 0.." << nParts - 1
                << exit(FatalError);
        }
    }
    return part;
}
