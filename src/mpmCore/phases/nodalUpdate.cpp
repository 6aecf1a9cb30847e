#include "nodalUpdate.hpp"
#include "halo.hpp"
#include "walls.hpp"
#include "../kernels/nodal.hpp"
#include "../transfer/stencil.hpp"

namespace mpm {

void updateMassTolerance(SystemState& s)
{
    const Index n = s.particles.size();
    Real total = 0;
    for (Index p = 0; p < n; ++p) total += s.particles.mass[p];
    const Real count = s.sumAll(Real(n));
    total = s.sumAll(total);
    s.massTolerance = count > 0 ? 1e-10*total/count : 0;
}

namespace {

// m g on every node, from the P2G masses (before the halo sum and fold)
void addGravity(SystemState& s)
{
    const Real gravity[3] = {s.options.gravity[0], s.options.gravity[1], s.options.gravity[2]};
    const GridView g = gridView(s.grid);
    s.forEachActiveNode([&](Index I) { gravityNode(g, gravity, I); });
}

void lumpedVelocity(SystemState& s, std::array<StaggeredArray<Real>, 3>& v)
{
    const GridView g = gridView(s.grid);
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Real tol = s.massTolerance;
    s.forEachActiveNode([&](Index I) { lumpedVelocityNode(g, vp, tol, I); });
}

// x = M^-1 rhs for the lumped mass, or the consistent mass approximated by
// Jacobi sweeps x <- x + M_L^-1 (rhs - M_C x), where M_C x is evaluated
// matrix-free as the P2G of m_p times the G2P of x. Low wavenumbers converge
// fast (the error shrinks like ((kh)^2/3)^sweeps); the highest ones keep a
// lumped-like mass, so the scheme stays bounded where M_C is singular.
// With diag (the coupling's dt K + M_a, >= 0) it solves (M + diag) x = rhs,
// preconditioned by M_L + diag: a positive diagonal only speeds the sweeps.
template<class K, int D>
void solveMassAs(SystemState& s, const std::array<StaggeredArray<Real>, 3>& rhs, std::array<StaggeredArray<Real>, 3>& x,
               const std::vector<Real>* diag)
{
    const Index nNodes = s.lattice.nNodes;
    const Real tol = s.massTolerance;
    const auto& m = s.grid.mass;
    // Jacobi preconditioner: the lumped mass plus the extra diagonal
    auto diagonal = [&](Index I) { return diag ? m[I] + (*diag)[I] : m[I]; };
    s.forEachActiveNode([&](Index I)
    {
        const Real inv = m[I] > tol ? 1.0/diagonal(I) : 0.0;
        for (int d = 0; d < 3; ++d) x[d][I] = rhs[d][I]*inv;
    });
    if (s.options.massMatrix == MassMatrix::lumped) return;

    fillGhosts(s, x);
    auto& P = s.particles;
    const Lattice& L = s.lattice;
    const Index nPoints = P.size();
    auto& pointScratch = s.pointScratch;
    auto& nodeScratch = s.nodeScratch;
    for (auto& a : pointScratch) a.resize(nPoints);
    for (auto& a : nodeScratch) a.resize(nNodes);
    Real* Mx[3] = {nodeScratch[0].data(), nodeScratch[1].data(), nodeScratch[2].data()};
    for (int sweep = 0; sweep < s.options.consistentMassIterations; ++sweep)
    {
        #pragma omp parallel for schedule(static) if(s.worthThreads(nPoints))
        for (Index p = 0; p < nPoints; ++p)
        {
            Stencil<K, D> st;
            st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            Real u[3] = {0, 0, 0};
            st.forEach(L, [&](Index I, Real N, const Real*, const Real*)
            {
                for (int d = 0; d < 3; ++d) u[d] += N*x[d][I];
            });
            for (int d = 0; d < 3; ++d) pointScratch[d][p] = P.mass[p]*u[d];
        }
        s.region.zero({Mx[0], Mx[1], Mx[2]});
        s.forEachPointColoured([&](Index p)
        {
            Stencil<K, D> st;
            st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            const Real u0 = pointScratch[0][p], u1 = pointScratch[1][p], u2 = pointScratch[2][p];
            st.forEach(L, [&](Index I, Real N, const Real*, const Real*)
            {
                Mx[0][I] += N*u0; Mx[1][I] += N*u1; Mx[2][I] += N*u2;
            });
        });
        sumHalo(s, {nodeScratch[0].data(), nodeScratch[1].data(), nodeScratch[2].data()});
        foldVector(s, nodeScratch);
        s.forEachActiveNode([&](Index I)
        {
            const Real inv = m[I] > tol ? 1.0/diagonal(I) : 0.0;
            const Real Dx = diag ? (*diag)[I] : 0.0;
            for (int d = 0; d < 3; ++d) x[d][I] += (rhs[d][I] - Mx[d][I] - Dx*x[d][I])*inv;
        });
        fillGhosts(s, x);
    }
}

void solveMass(SystemState& s, const std::array<StaggeredArray<Real>, 3>& rhs, std::array<StaggeredArray<Real>, 3>& x,
               const std::vector<Real>* diag = nullptr)
{
    s.dispatch([&](auto k, auto d) { solveMassAs<decltype(k), decltype(d)::value>(s, rhs, x, diag); });
}

// Beyond an open face the fluid is the image cell's (zero gradient): the
// material leaving feels the drag per unit solid volume it felt inside
// (K = beta V_cell grows with the solid there)
void extendCouplingBeyondOpenFaces(SystemState& s, bool addedMass)
{
    auto& g = s.grid;
    auto& c = s.coupling;
    for (const auto& fi : s.boundary.freeNodes())
    {
        const Real Vi = g.volume[fi.second];
        c.K[fi.first] = Vi > 0 ? c.K[fi.second]*g.volume[fi.first]/Vi : 0.0;
        for (int d = 0; d < 3; ++d)
        {
            c.U[d][fi.first] = c.U[d][fi.second];
            c.F[d][fi.first] = c.F[d][fi.second];
            if (addedMass) c.fluidAcceleration[d][fi.first] = c.fluidAcceleration[d][fi.second];
        }
    }
}

} // namespace

void massToVelocity(SystemState& s, std::array<StaggeredArray<Real>, 3>& v)
{
    if (s.options.massMatrix == MassMatrix::lumped) lumpedVelocity(s, v);
    else solveMass(s, s.grid.momentum, v);
}

void nodalAfterScatter(SystemState& s, Real dt, bool withForce)
{
    addGravity(s);
    sumHalo(s, foldMass | foldMomentum | (withForce ? foldForce : 0u));
    foldGhosts(s, foldMass);
    decideWallContact(s, dt, withForce);
    foldGhosts(s, foldMomentum | (withForce ? foldForce : 0u));
    massToVelocity(s, s.grid.velocityOld);
    fillGhosts(s, s.grid.velocityOld);
}

void foldScatteredForce(SystemState& s)
{
    sumHalo(s, foldForce);
    foldGhosts(s, foldForce);
}

void nodalAfterRemap(SystemState& s)
{
    sumHalo(s, foldMomentum);
    foldGhosts(s, foldMomentum);
    massToVelocity(s, s.grid.velocity);
    applyFriction(s, s.grid.velocity, 0);
    applyLevelSetWalls(s, s.grid.velocity);
    fillGhosts(s, s.grid.velocity);
}

void nodalUpdate(SystemState& s, Real dt)
{
    const Index n = s.lattice.nNodes;
    auto& g = s.grid;
    auto& c = s.coupling;
    auto& nodeRhs = s.nodeRhs;
    auto& nodeDiag = s.nodeDiag;
    const bool coupled = c.active();
    const bool addedMass = coupled && c.addedMassDensity > 0;
    if (coupled) extendCouplingBeyondOpenFaces(s, addedMass);
    for (auto& a : nodeRhs) a.resize(n);
    if (coupled) nodeDiag.resize(n);
    // (M + D) v = p + dt f, with M lumped or consistent. Coupled, the drag
    // is implicit and the added mass M_a = Cvm rho_f V_s too:
    //   D = dt K + M_a,
    //   rhs += dt (V_s F + K U + M_a a_f) + M_a v_old.
    s.forEachActiveNode([&](Index I)
    {
        for (int d = 0; d < 3; ++d) nodeRhs[d][I] = g.momentum[d][I] + dt*g.force[d][I];
        if (!coupled) return;
        const Real Ma = addedMass ? c.addedMassDensity*g.volume[I] : 0.0;
        nodeDiag[I] = dt*c.K[I] + Ma;
        for (int d = 0; d < 3; ++d)
        {
            nodeRhs[d][I] += dt*(g.volume[I]*c.F[d][I] + c.K[I]*c.U[d][I]);
            if (addedMass) nodeRhs[d][I] += Ma*(g.velocityOld[d][I] + dt*c.fluidAcceleration[d][I]);
        }
    });
    solveMass(s, nodeRhs, g.velocity, coupled ? &nodeDiag : nullptr);
    applyFriction(s, g.velocity, dt);
    applyLevelSetWalls(s, g.velocity);
    fillGhosts(s, g.velocity);
    if (coupled)
    {
        // Outside the region the velocity is zero: the integral keeps its sum
        s.forEachActiveNode([&](Index I)
        {
            for (int d = 0; d < 3; ++d) c.velocityIntegral[d][I] += dt*g.velocity[d][I];
        });
        c.time += dt;
    }
}

} // namespace mpm
