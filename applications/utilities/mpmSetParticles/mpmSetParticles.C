/*---------------------------------------------------------------------------*\
Application
    mpmSetParticles

Description
    Seeds material points for mpmFoam from system/mpmSetParticlesDict:
    regions (searchableSurfaces: box, cylinder, sphere, STL) filled with a
    number of points per cell and direction, with a material, an initial
    velocity (uniform or sinusoidal) and an initial stress. Writes the
    lagrangian cloud materialPoints at the start time, replacing any there.

    A time that holds a run's results (a time after controlDict's startTime,
    or one with the lattice fields mpmFoam writes) is not overwritten unless
    -overwrite is given: seeding there would throw the run away.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "meshLattice.H"
#include "materialLibrary.H"
#include "pointSeeder.H"
#include "materialPointsIO.H"
#include "cloud.H"
#include "knownKeywords.H"
#include "completeTimes.H"
#include "obstacles.H"
#include "errorsOnce.H"

int main(int argc, char *argv[])
{
    argList::addNote("Seed material points for mpmFoam");
    argList::addOption("dict", "file", "Alternative mpmSetParticlesDict");
    argList::addBoolOption
    (
        "overwrite",
        "Replace the material points of a time that holds a run's results"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    // An input error is printed once in a decomposed run (errorsOnce.H)
    reportErrorsOnce([&]()
    {
        // startFrom latestTime (as the tutorials) selects a run's last time:
        // refuse to replace its points, unless asked to
        {
            std::string results;
            for (const word f : {"alpha.solid", "U.solid"})
            {
                if (isFile(runTime.timePath()/f)) results += (results.empty() ? "" : " ") + f;
            }
            const scalar startTime =
                runTime.controlDict().getOrDefault<scalar>("startTime", 0);
            const bool later = runTime.value() > startTime + 0.5*runTime.deltaTValue();
            if ((later || !results.empty()) && !args.found("overwrite"))
            {
                FatalErrorInFunction
                    << "Time " << runTime.timeName() << " holds the results of a"
                    << " run (" << (later ? "after controlDict startTime " : "")
                    << (later ? Foam::name(startTime) : word::null)
                    << (later && !results.empty() ? "; " : "")
                    << (results.empty() ? "" : "mpmFoam fields ")
                    << results.c_str() << "): seeding would replace its material points."
                    << nl << "To seed the start time, remove the later times"
                    << " (foamListTimes -rm) or set startFrom startTime; to"
                    << " replace this time's points, run mpmSetParticles"
                    << " -overwrite." << exit(FatalError);
            }
        }

        const word dictName("mpmSetParticlesDict");
        #include "setSystemMeshDictionaryIO.H"
        const IOdictionary seedDict(dictIO);
        checkKeywords(seedDict, {"regions"}, "mpmSetParticlesDict");

        const IOdictionary mpmDict
        (
            IOobject("mpmProperties", runTime.constant(), mesh,
                IOobject::MUST_READ, IOobject::NO_WRITE)
        );
        const materialLibrary materials(mpmDict, false);
        const meshLattice lattice(mesh, mpmDict);
        lattice.report(Info);

        if (!seedDict.isDict("regions"))
        {
            FatalIOErrorInFunction(seedDict)
                << "Missing sub-dictionary regions { name { type box; ... } }"
                << exit(FatalIOError);
        }
        mpm::Particles points;
        label nLocal = seedRegions(mesh, lattice, materials, seedDict.subDict("regions"), points);

        // Points inside obstacles (level-set walls) are left out, counted
        {
            const std::vector<mpm::LevelSetWall> obstacles(readObstacles(mesh, mpmDict, false));
            List<label> inside(obstacles.size(), Zero);
            std::vector<mpm::Index> out;
            for (label p = 0; p < nLocal; ++p)
            {
                const mpm::Real x[3] = {points.x[0][p], points.x[1][p], points.x[2][p]};
                forAll(obstacles, w)
                {
                    mpm::Real n[3];
                    if (obstacles[w].shape->distance(x, n, GREAT) < 0)
                    {
                        ++inside[w];
                        out.push_back(p);
                        break;
                    }
                }
            }
            points.remove(out);
            nLocal = points.size();
            Pstream::listCombineGather(inside, plusEqOp<label>());
            Pstream::listCombineScatter(inside);
            forAll(obstacles, w)
            {
                Info<< "Obstacle " << obstacles[w].name.c_str() << ": left out "
                    << inside[w] << " points inside it" << nl;
            }
        }
        const label n = returnReduce(nLocal, sumOp<label>());
        if (n == 0)
        {
            FatalIOErrorInFunction(seedDict)
                << "No material points were seeded: no region contains any "
                << "sub-cell point" << exit(FatalIOError);
        }

        scalar mass = 0;
        for (label p = 0; p < nLocal; ++p) mass += points.mass[p];
        reduce(mass, sumOp<scalar>());
        Info<< nl << "Writing " << n << " material points (total mass " << mass
            << ") to " << runTime.timeName()/cloud::prefix/materialPointsCloudName
            << nl << endl;
        writeMaterialPoints(mesh, lattice, points, materials.names());
        markTimeComplete(runTime);
    });

    Info<< "End\n" << endl;
    return 0;
}
