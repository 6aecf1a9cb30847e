#include "summaryDiagnostic.H"
#include "mpmModel.H"
#include "floatingPointTraps.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(summaryDiagnostic, 0);
    addToRunTimeSelectionTable(mpmDiagnostic, summaryDiagnostic, dictionary);
}

void Foam::summaryDiagnostic::report(Ostream& log)
{
    const floatingPointTrapsOff noTraps;
    const mpm::MpmSystem& s = mpm_.system();
    const mpm::Particles& P = s.particles();
    scalar ke = 0, se = 0, vmax = 0, mass = 0;
    vector mom(Zero);
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        const vector v(P.v[0][p], P.v[1][p], P.v[2][p]);
        ke += 0.5*P.mass[p]*magSqr(v);
        mom += P.mass[p]*v;
        mass += P.mass[p];
        vmax = max(vmax, magSqr(v));
        mpm::Real F[9];
        for (int e = 0; e < 9; ++e) F[e] = P.F[e][p];
        const mpm::Real sig[6] = {P.sigma[0][p], P.sigma[1][p], P.sigma[2][p],
                             P.sigma[3][p], P.sigma[4][p], P.sigma[5][p]};
        se += P.volume0[p]*s.material(P.material[p]).storedEnergy(sig, F);
    }
    reduce(ke, sumOp<scalar>());
    reduce(se, sumOp<scalar>());
    reduce(mass, sumOp<scalar>());
    reduce(mom, sumOp<vector>());
    reduce(vmax, maxOp<scalar>());
    const vector vcm(mass > 0 ? mom/mass : vector(Zero));
    log << "MPM: step " << label(s.stepCount()) << ", kinetic energy "
        << ke << ", elastic energy " << se << ", max |U| "
        << Foam::sqrt(vmax) << nl;

    if (!Pstream::master()) return;
    file
    (
        "mpmSummary",
        "# time kineticEnergy elasticEnergy Ucm_x Ucm_y Ucm_z maxU\n"
        "# elasticEnergy: stored energy of each law (strain energy,"
        " complementary energy, fluid compression energy)\n"
    )
        << mpm_.mesh().time().value() << ' ' << ke << ' ' << se << ' '
        << vcm.x() << ' ' << vcm.y() << ' ' << vcm.z() << ' '
        << Foam::sqrt(vmax) << endl;
}
