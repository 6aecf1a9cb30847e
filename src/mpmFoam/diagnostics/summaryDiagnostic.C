#include "summaryDiagnostic.H"
#include "mpmModel.H"
#include "runEnergies.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(summaryDiagnostic, 0);
    addToRunTimeSelectionTable(mpmDiagnostic, summaryDiagnostic, dictionary);
}

void Foam::summaryDiagnostic::report(Ostream& log)
{
    const mpm::MpmSystem& s = mpm_.system();
    const runEnergies e(measureEnergies(s));
    const vector vcm(e.centreOfMassVelocity());
    log << "MPM: step " << label(s.stepCount()) << ", kinetic energy "
        << e.kinetic << ", elastic energy " << e.stored
        << ", potential energy " << e.potential << ", max |U| "
        << e.maxSpeed << nl;

    if (!Pstream::master()) return;
    file
    (
        "mpmSummary",
        "# time kineticEnergy elasticEnergy Ucm_x Ucm_y Ucm_z maxU potentialEnergy\n"
        "# elasticEnergy: stored energy of each law (strain energy,"
        " complementary energy, fluid compression energy)\n"
        "# potentialEnergy: -sum m g.x (gravity; origin at x = 0)\n",
        "summary.dat"   // the documented name, read by mpmPost.read_summary
    )
        << mpm_.mesh().time().value() << ' ' << e.kinetic << ' ' << e.stored << ' '
        << vcm.x() << ' ' << vcm.y() << ' ' << vcm.z() << ' '
        << e.maxSpeed << ' ' << e.potential << endl;
}
