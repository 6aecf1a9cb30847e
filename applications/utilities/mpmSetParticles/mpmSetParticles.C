/*---------------------------------------------------------------------------*\
Application
    mpmSetParticles

Description
    Seeds material points for mpmFoam from system/mpmSetParticlesDict:
    regions (searchableSurfaces: box, cylinder, sphere, STL) filled with a
    number of points per cell and direction, with a material, an initial
    velocity (uniform or sinusoidal) and an initial stress. Writes the
    lagrangian cloud materialPoints at the start time, replacing any there.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "meshLattice.H"
#include "materialLibrary.H"
#include "pointSeeder.H"
#include "materialPointsIO.H"
#include "cloud.H"
#include "knownKeywords.H"

int main(int argc, char *argv[])
{
    argList::addNote("Seed material points for mpmFoam");
    argList::addOption("dict", "file", "Alternative mpmSetParticlesDict");
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

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
    const meshLattice lattice(mesh);
    lattice.report(Info);

    if (!seedDict.isDict("regions"))
    {
        FatalIOErrorInFunction(seedDict)
            << "Missing sub-dictionary regions { name { type box; ... } }"
            << exit(FatalIOError);
    }
    mpm::Particles points;
    const label nLocal = seedRegions(mesh, lattice, materials, seedDict.subDict("regions"), points);
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
    writeMaterialPoints(mesh, lattice, points);

    Info<< "End\n" << endl;
    return 0;
}
