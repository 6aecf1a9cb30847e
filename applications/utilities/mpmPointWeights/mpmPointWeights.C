/*---------------------------------------------------------------------------*\
Application
    mpmPointWeights

Description
    Writes the cell field pointWeights = (material points in the cell) +
    the option -empty (default 0.1) for the selected times, so that
    decomposePar can balance the points, not the cells, when a decomposed
    run is re-decomposed at a restart:

        reconstructPar -latestTime
        mpmPointWeights -latestTime
        # system/decomposeParDict: method scotch; weightField pointWeights;
        decomposePar -force -latestTime
        mpirun -np N mpmFoam -parallel

    -empty is the weight of a cell without points relative to one point:
    such cells still cost the nodal update, but far less than a point.
    Runs serially or decomposed (each rank counts its own points).
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "timeSelector.H"
#include "meshLattice.H"
#include "materialPointsIO.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write pointWeights (points per cell + -empty) for a decomposition"
        " that balances material points (decomposeParDict weightField)"
    );
    timeSelector::addOptions();
    argList::addOption("empty", "scalar", "Weight of a cell without points (default 0.1)");
    #include "setRootCase.H"
    #include "createTime.H"
    const instantList times = timeSelector::select0(runTime, args);
    #include "createMesh.H"

    const scalar empty = args.getOrDefault<scalar>("empty", 0.1);
    if (!(empty > 0))
    {
        FatalErrorInFunction
            << "-empty " << empty << " must be > 0: decomposePar needs"
            << " positive weights" << exit(FatalError);
    }
    const IOdictionary mpmDict
    (
        IOobject("mpmProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const meshLattice lattice(mesh, mpmDict);

    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        Info<< "Time = " << runTime.timeName() << endl;
        mpm::Particles points;
        readMaterialPoints(mesh, points);
        volScalarField w
        (
            IOobject("pointWeights", runTime.timeName(), mesh,
                IOobject::NO_READ, IOobject::AUTO_WRITE),
            mesh, dimensionedScalar("empty", dimless, empty)
        );
        for (mpm::Index p = 0; p < points.size(); ++p)
        {
            const label celli = lattice.fvCellOf(point(points.x[0][p], points.x[1][p], points.x[2][p]));
            if (celli >= 0) w[celli] += 1;
        }
        w.write();
        Info<< "    pointWeights: " << returnReduce(label(points.size()), sumOp<label>())
            << " points, weight of an empty cell " << empty << nl << endl;
    }
    Info<< "End\n" << endl;
    return 0;
}
