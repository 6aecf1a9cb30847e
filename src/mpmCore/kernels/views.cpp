#include "views.hpp"
#include "../grid/gridState.hpp"
#include "../particles/particles.hpp"

namespace mpm {

PointView pointView
(
    Particles& P, std::array<StaggeredArray<Real>, 9>& L, std::array<StaggeredArray<Real>, 3>& dx
)
{
    PointView w;
    w.n = P.size();
    for (int a = 0; a < 3; ++a)
    {
        w.x[a] = P.x[a].data();
        w.v[a] = P.v[a].data();
        w.dx[a] = dx[a].data();
    }
    w.mass = P.mass.data();
    w.volume0 = P.volume0.data();
    w.volume = P.volume.data();
    for (int e = 0; e < 9; ++e)
    {
        w.F[e] = P.F[e].data();
        w.C[e] = P.C[e].data();
        w.L[e] = L[e].data();
    }
    for (int c = 0; c < 6; ++c) w.sigma[c] = P.sigma[c].data();
    w.eqPlasticStrain = P.eqPlasticStrain.data();
    w.material = P.material.data();
    return w;
}

GridView gridView(GridState& g)
{
    GridView w;
    w.n = Index(g.mass.size());
    w.mass = g.mass.data();
    w.volume = g.volume.data();
    for (int a = 0; a < 3; ++a)
    {
        w.momentum[a] = g.momentum[a].data();
        w.force[a] = g.force[a].data();
        w.velocityOld[a] = g.velocityOld[a].data();
        w.velocity[a] = g.velocity[a].data();
    }
    return w;
}

} // namespace mpm
