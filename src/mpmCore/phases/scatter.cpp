#include "scatter.hpp"
#include "../kernels/p2g.hpp"
#include <chrono>
#include <type_traits>

namespace mpm {

void binPoints(SystemState& s)
{
    s.binning.build(s.lattice, s.particles);
    if (s.options.reorderPoints && s.binning.fragmented())
    {
        s.particles.permute(s.binning.order());
        s.binning.setIdentityOrder();
        s.hostAhead = true;
    }
    static const std::vector<Index> none;
    auto& g = s.grid;
    s.region.build
    (
        s.lattice, s.binning, stencilReach(s.options.shape), s.boundary,
        s.subdomain ? s.subdomain->haloNodeList() : none,
        {
            g.mass.data(), g.volume.data(),
            g.momentum[0].data(), g.momentum[1].data(), g.momentum[2].data(),
            g.force[0].data(), g.force[1].data(), g.force[2].data(),
            g.velocityOld[0].data(), g.velocityOld[1].data(), g.velocityOld[2].data(),
            g.velocity[0].data(), g.velocity[1].data(), g.velocity[2].data()
        }
    );
}

namespace {

template<class K, int D, bool MassMomentum, bool Force, bool Apic, bool Rows>
void scatterKernel(SystemState& s)
{
    const std::vector<Real> invRho0 = s.inverseDensities();
    const PointView P = s.points();
    const GridView g = gridView(s.grid);
    const Lattice& L = s.lattice;
    const bool grainVolume = s.options.constantGrainVolume;
    s.forEachPointColoured([&](Index p)
    {
        p2gPoint<K, D, MassMomentum, Force, Apic, Rows>(L, P, g, invRho0.data(), grainVolume, p, PlainAdd{});
    });
}

// P2G. massMomentum: mass, volume and momentum; force: internal force;
// velocityOnly: momentum only, from the (new) point velocities (MUSL).
// The choices become template arguments so the node loop has no branches.
template<class K, int D>
void scatterAs(SystemState& s, bool massMomentum, bool force, bool velocityOnly)
{
    // A fresh P2G (massMomentum) always follows binPoints, which left every
    // grid array zero; the force scatter alone (USF) adds the internal
    // force to the gravity there; the MUSL re-map starts its momentum anew.
    auto& g = s.grid;
    if (velocityOnly) s.region.zero({g.momentum[0].data(), g.momentum[1].data(), g.momentum[2].data()});
    auto pick = [](bool x, auto&& k) { if (x) k(std::true_type{}); else k(std::false_type{}); };
    const bool apic = s.options.transfer == Transfer::apic;
    // Only the 3D P2G without APIC has the two loops to choose from
    const bool choice = D == 3 && !apic;
    const bool rows = choice ? s.p2gRows.rows(s.stepCount) : true;
    const auto t0 = std::chrono::steady_clock::now();
    pick(massMomentum, [&](auto mm)
    {
        pick(force, [&](auto f)
        {
            pick(apic, [&](auto a)
            {
                constexpr bool MM = decltype(mm)::value, F = decltype(f)::value, A = decltype(a)::value;
                if constexpr (D == 3 && !A)
                {
                    pick(rows, [&](auto r) { scatterKernel<K, D, MM, F, A, decltype(r)::value>(s); });
                }
                else
                {
                    scatterKernel<K, D, MM, F, A, true>(s);
                }
            });
        });
    });
    if (choice)
    {
        s.p2gRows.record(s.stepCount, rows,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
}

void scatter(SystemState& s, bool massMomentum, bool force, bool velocityOnly)
{
    s.dispatch([&](auto k, auto d)
    {
        scatterAs<decltype(k), decltype(d)::value>(s, massMomentum, force, velocityOnly);
    });
}

} // namespace

void scatterMassMomentum(SystemState& s, bool withForce) { scatter(s, true, withForce, false); }
void scatterForce(SystemState& s) { scatter(s, false, true, false); }
void remapMomentum(SystemState& s) { scatter(s, false, false, true); }

} // namespace mpm
