#include "runEnergies.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "floatingPointTraps.H"

Foam::runEnergies Foam::measureEnergies(const mpm::MpmSystem& system)
{
    // A diverging run must still be reported (the NaN check names it)
    const floatingPointTrapsOff noTraps;
    const mpm::Particles& P = system.particles();
    const std::array<mpm::Real, 3>& g = system.options().gravity;
    runEnergies e;
    scalar vmax2 = 0;
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        const vector v(P.v[0][p], P.v[1][p], P.v[2][p]);
        e.kinetic += 0.5*P.mass[p]*magSqr(v);
        e.potential -= P.mass[p]*(g[0]*P.x[0][p] + g[1]*P.x[1][p] + g[2]*P.x[2][p]);
        e.momentum += P.mass[p]*v;
        e.mass += P.mass[p];
        vmax2 = max(vmax2, magSqr(v));
        mpm::Real F[9];
        for (int k = 0; k < 9; ++k) F[k] = P.F[k][p];
        const mpm::Real sig[6] = {P.sigma[0][p], P.sigma[1][p], P.sigma[2][p],
                                  P.sigma[3][p], P.sigma[4][p], P.sigma[5][p]};
        e.stored += P.volume0[p]*system.material(P.material[p]).storedEnergy(sig, F);
    }
    reduce(e.kinetic, sumOp<scalar>());
    reduce(e.stored, sumOp<scalar>());
    reduce(e.potential, sumOp<scalar>());
    reduce(e.mass, sumOp<scalar>());
    reduce(e.momentum, sumOp<vector>());
    reduce(vmax2, maxOp<scalar>());
    e.maxSpeed = Foam::sqrt(vmax2);
    return e;
}
