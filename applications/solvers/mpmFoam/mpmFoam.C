/*---------------------------------------------------------------------------*\
Application
    mpmFoam

Group
    grpLagrangianSolvers

Description
    Material Point Method solver for solid and granular material, with the
    finite-volume mesh as the background lattice.

    Pure MPM: reads constant/mpmProperties, constant/g and the material
    points of the start time (lagrangian/materialPoints, seeded by
    mpmSetParticles); writes the points and the lattice fields alpha.solid
    and U.solid.

    With a fluid (constant/transportProperties, 0/U, 0/p): a volume-averaged
    incompressible fluid is solved with PIMPLE and coupled to the solids by
    drag, buoyancy and the fluid fraction (mpmProperties::coupling); the
    solids sub-cycle within each fluid step. Without a fluid no fluid
    equation is constructed or solved.

    The time loop is the solver module mpmFoam (src/mpmFoam/solverModule,
    the same as `foamRun -solver mpmFoam`) run by runSolverModule.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmFoamModule.H"
#include "errorsOnce.H"
#include "constitutive/constitutiveLaw.hpp"
#include "drag/dragLaw.hpp"

int main(int argc, char *argv[])
{
    // The models, from the run-time tables (never a list by hand)
    std::string laws, drags;
    for (const auto& l : mpm::availableLaws()) laws += (laws.empty() ? "" : ", ") + l.name;
    for (const auto& d : mpm::availableDragLaws()) drags += (drags.empty() ? "" : ", ") + d.name;
    argList::addNote
    (
        "Material Point Method solver for solids and granular material"
        " (constitutive models: " + laws + "), the mesh"
        " being the background lattice, or a lattice of its own on any other"
        " mesh; with constant/transportProperties,"
        " 0/U and 0/p the grains are coupled to a volume-averaged"
        " incompressible fluid solved with PIMPLE (drag: " + drags + ";"
        " pressure gradient, buoyancy).\n"
        "Reads constant/mpmProperties and the points seeded by"
        " mpmSetParticles (system/mpmSetParticlesDict).\n"
        "Annotated example case files: $MPMFOAM_DIR/etc/caseDicts"
        " (mpmProperties, mpmSetParticlesDict, fvSchemes, fvSolution,"
        " decomposeParDict); example cases: $MPMFOAM_DIR/tutorials;"
        " documentation: $MPMFOAM_DIR/README.md and docs/."
    );
    argList::addBoolOption
    (
        "adviseTimeStep",
        "Set the case up as a run does (mesh, lattice, points, fluid and"
        " coupling), print the time-step advice - a coupled case the"
        " coupled analysis' (the lines of coupling { timeStepAdvice yes; }),"
        " a case without a fluid the pure-MPM check - and stop: no time"
        " step, nothing written (mpmAdviseTimeStep <case> prints the"
        " advice alone; docs/stabilityAnalysis.md 7b.7)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    // Constructed directly (no selection): this application links
    // libmpmFoam, and its log stays that of mpmFoam. An input error is
    // printed once in a decomposed run (errorsOnce.H)
    reportErrorsOnce([&]()
    {
        const bool adviseOnly = args.found("adviseTimeStep");
        mpmFoamModule module(mesh, adviseOnly);
        if (adviseOnly)
        {
            Info<< "-adviseTimeStep: the case set up as for a run; no time "
                << "step taken, nothing written" << nl << endl;
        }
        else
        {
            runSolverModule(runTime, module);
        }
    });

    Info<< "End\n" << endl;
    return 0;
}
