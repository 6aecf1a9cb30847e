// Decomposed steps (parallel/subdomain.hpp) against the serial step, in one
// process: N "ranks" are threads that talk through an in-memory
// Communicator. Cells are given to ranks at random, so every subdomain is
// scattered over the whole box: every node's neighbours (diagonal, periodic,
// across walls) belong to other ranks, the harshest case for the owner
// lookup, the halo and migration. Periodic x, walls of every kind in y and
// z, gravity, an elastic law; every shape function and stress update.
#include "testHelpers.hpp"
#include "constitutive/linearElastic.hpp"
#include "parallel/subdomain.hpp"
#include <gtest/gtest.h>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>

using namespace mpm;
using namespace mpm::test;

namespace {

// All ranks' mailboxes and a reusable barrier.
struct World
{
    explicit World(int n) : n(n), mail(n, std::vector<std::vector<char>>(n)), reals(n), ints(n) {}
    void barrier()
    {
        std::unique_lock<std::mutex> lock(m);
        const int gen = generation;
        if (++arrived == n) { arrived = 0; ++generation; cv.notify_all(); }
        else cv.wait(lock, [&] { return generation != gen; });
    }
    int n;
    std::mutex m;
    std::condition_variable cv;
    int arrived = 0, generation = 0;
    std::vector<std::vector<std::vector<char>>> mail;   // [from][to]
    std::vector<std::vector<Real>> reals;
    std::vector<std::vector<std::int64_t>> ints;
};

class ThreadComm : public Communicator
{
public:
    ThreadComm(World& w, int rank) : w_(w), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return w_.n; }

    void allReduce(Real* v, int n, ReduceOp op) const override { reduce(w_.reals, v, n, op); }
    void allReduce(std::int64_t* v, int n, ReduceOp op) const override { reduce(w_.ints, v, n, op); }

    void allGather(const std::vector<std::int64_t>& mine, std::vector<std::int64_t>& out) const override
    {
        w_.ints[rank_] = mine;
        w_.barrier();
        out.clear();
        for (const auto& o : w_.ints) out.insert(out.end(), o.begin(), o.end());
        w_.barrier();
    }

    void exchange(const std::vector<std::vector<char>>& send, std::vector<std::vector<char>>& recv, bool sizesKnown) const override
    {
        for (int q = 0; q < w_.n; ++q) w_.mail[rank_][q] = send[q];
        w_.barrier();
        recv.resize(w_.n);
        for (int q = 0; q < w_.n; ++q)
        {
            // A known size must be the sent one (empty: nothing expected)
            if (sizesKnown && !recv[q].empty()) EXPECT_EQ(recv[q].size(), w_.mail[q][rank_].size());
            recv[q] = w_.mail[q][rank_];
        }
        w_.barrier();
    }

private:
    template<class T>
    void reduce(std::vector<std::vector<T>>& slots, T* v, int n, ReduceOp op) const
    {
        slots[rank_].assign(v, v + n);
        w_.barrier();
        for (int i = 0; i < n; ++i)
        {
            T r = slots[0][i];
            for (int q = 1; q < w_.n; ++q)
            {
                const T x = slots[q][i];
                r = op == ReduceOp::sum ? r + x : (op == ReduceOp::min ? std::min(r, x) : std::max(r, x));
            }
            v[i] = r;
        }
        w_.barrier();
    }
    World& w_;
    int rank_;
};

// Periodic x; y: slip below, no-slip above; z: friction below, slip above.
BoundarySpec mixedWalls(const Lattice& L)
{
    BoundarySpec b;
    b.conditions = {{WallType::periodic, 0}, {WallType::slip, 0}, {WallType::noSlip, 0}, {WallType::friction, 0.3}};
    const int sideCondition[6] = {0, 0, 1, 2, 3, 1};
    for (int side = 0; side < 6; ++side)
    {
        const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        b.faceCondition[side].assign(std::size_t(L.nCells[std::min(a1, a2)])*L.nCells[std::max(a1, a2)], sideCondition[side]);
    }
    return b;
}

struct State { std::array<Real, 3> x, v; std::array<Real, 6> s; };

std::map<std::int64_t, State> collect(const Particles& P)
{
    std::map<std::int64_t, State> out;
    for (Index p = 0; p < P.size(); ++p)
    {
        State st;
        for (int d = 0; d < 3; ++d) { st.x[d] = P.x[d][p]; st.v[d] = P.v[d][p]; }
        for (int c = 0; c < 6; ++c) st.s[c] = P.sigma[c][p];
        out[P.id[p]] = st;
    }
    return out;
}

void addLaw(MpmSystem& s) { s.materials().push_back(std::make_unique<LinearElastic>(1000, 1e4, 0.3)); }

constexpr int nSteps = 25;

// The serial run and its points before the first step.
std::map<std::int64_t, State> serialRun(const Lattice& L, const StepOptions& o, Particles& seeded)
{
    MpmSystem s;
    s.setup(L, mixedWalls(L), o);
    addLaw(s);
    seedRandom(s, 1500, 0.15, 0.85, 7);
    // A body of about 6 points per cell at 1000 kg/m^3, drifting across
    // the cells (and the periodic seam) with a little random motion
    Particles& P = s.particles();
    const Real drift[3] = {0.8, 0.3, -0.2};
    for (Index p = 0; p < P.size(); ++p)
    {
        P.volume0[p] = P.volume[p] = 1.6e-4;
        P.mass[p] = 1000*P.volume0[p];
        for (int d = 0; d < 3; ++d) P.v[d][p] = drift[d] + 0.1*P.v[d][p];
    }
    seeded = s.particles();
    for (int i = 0; i < nSteps; ++i) s.step(s.stableDeltaT(0.4));
    return collect(s.particles());
}

std::map<std::int64_t, State> decomposedRun(const Lattice& L, const StepOptions& o, const Particles& seeded, int nRanks, Index& migrated)
{
    // Random owner per cell
    Lattice G = L;
    G.finalise();
    std::mt19937 rng(11);
    std::vector<std::vector<std::array<int, 3>>> owned(nRanks);
    for (int k = 0; k < G.nCells[2]; ++k)
    for (int j = 0; j < G.nCells[1]; ++j)
    for (int i = 0; i < G.nCells[0]; ++i) owned[rng() % nRanks].push_back({i, j, k});

    World world(nRanks);
    std::vector<std::map<std::int64_t, State>> results(nRanks);
    std::vector<Index> sent(nRanks, 0);
    std::vector<std::thread> threads;
    for (int r = 0; r < nRanks; ++r)
    {
        threads.emplace_back([&, r]
        {
            ThreadComm comm(world, r);
            const BoundarySpec spec = mixedWalls(G);
            auto sd = std::make_shared<Subdomain>();
            sd->build(G, owned[r], MpmSystem::stencilReach(o.shape), Boundary::periodicAxes(G, spec), comm);
            MpmSystem s;
            s.setup(G, spec, o, sd);
            addLaw(s);
            for (Index p = 0; p < seeded.size(); ++p)
            {
                const Real x[3] = {seeded.x[0][p], seeded.x[1][p], seeded.x[2][p]};
                if (sd->ownerOf(x) != r) continue;
                const Index q = s.particles().add({x[0], x[1], x[2]}, {seeded.v[0][p], seeded.v[1][p], seeded.v[2][p]},
                                                  seeded.mass[p], seeded.volume0[p], seeded.material[p]);
                s.particles().id[q] = seeded.id[p];
            }
            for (int i = 0; i < nSteps; ++i) s.step(s.stableDeltaT(0.4));
            results[r] = collect(s.particles());
            sent[r] = s.migratedCount();
        });
    }
    for (auto& t : threads) t.join();
    std::map<std::int64_t, State> all;
    migrated = 0;
    for (int r = 0; r < nRanks; ++r)
    {
        for (const auto& kv : results[r]) EXPECT_TRUE(all.insert(kv).second) << "point " << kv.first << " on two ranks";
        migrated += sent[r];
    }
    return all;
}

} // namespace

TEST(Subdomain, RandomDecompositionMatchesSerial)
{
    const Lattice L = box(10, 9, 8);
    const StressUpdate updates[] = {StressUpdate::USL, StressUpdate::USF, StressUpdate::MUSL};
    const ShapeKind shapes[] = {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline};
    for (int c = 0; c < 3; ++c)
    {
        StepOptions o;
        o.shape = shapes[c];
        o.stressUpdate = updates[c];
        o.transfer = c == 1 ? Transfer::apic : Transfer::picFlip;
        o.massMatrix = c == 2 ? MassMatrix::consistent : MassMatrix::lumped;
        o.gravity = {0, -10, -10};
        Particles seeded;
        const auto serial = serialRun(L, o, seeded);
        for (int nRanks : {2, 5})
        {
            Index migrated = 0;
            const auto par = decomposedRun(L, o, seeded, nRanks, migrated);
            ASSERT_EQ(par.size(), serial.size()) << "points lost or duplicated";
            // Cells owned at random: a point changes rank at most cell
            // crossings (about two per point over the run)
            EXPECT_GT(migrated, Index(serial.size())/2);
            Real dx = 0, dv = 0, ds = 0, vmax = 0, smax = 0;
            for (const auto& kv : serial)
            {
                const State& a = kv.second;
                const State& b = par.at(kv.first);
                for (int d = 0; d < 3; ++d)
                {
                    dx = std::max(dx, std::abs(a.x[d] - b.x[d]));
                    dv = std::max(dv, std::abs(a.v[d] - b.v[d]));
                    vmax = std::max(vmax, std::abs(a.v[d]));
                }
                for (int e = 0; e < 6; ++e)
                {
                    ds = std::max(ds, std::abs(a.s[e] - b.s[e]));
                    smax = std::max(smax, std::abs(a.s[e]));
                }
            }
            EXPECT_LT(dx, 1e-12) << shapeName(o.shape) << ", " << nRanks << " ranks";
            EXPECT_LT(dv, 1e-10*vmax) << shapeName(o.shape) << ", " << nRanks << " ranks";
            EXPECT_LT(ds, 1e-10*smax) << shapeName(o.shape) << ", " << nRanks << " ranks";
        }
    }
}

// The exchange halo: cells a rank reads or writes beyond its stencils (a
// fluid mesh's overlaps where the lattice is decomposed its own way). Owners
// at random, each rank lists random extra cells anywhere in the box; sum()
// over the exchange halo gives each owner the number of ranks listing its
// cell, copy() gives that number back to every listing rank, and the step's
// halo is the one built without extras.
TEST(Subdomain, ExchangeHaloReachesExtraCells)
{
    Lattice G = box(9, 7, 5);
    G.finalise();
    const int nRanks = 3;
    std::mt19937 rng(5);
    std::vector<std::vector<std::array<int, 3>>> owned(nRanks), extra(nRanks);
    std::map<Index, int> listed;   // global cell -> how many ranks list it
    for (int k = 0; k < G.nCells[2]; ++k)
    for (int j = 0; j < G.nCells[1]; ++j)
    for (int i = 0; i < G.nCells[0]; ++i)
    {
        owned[rng() % nRanks].push_back({i, j, k});
        for (int r = 0; r < nRanks; ++r)
        {
            if (rng() % 4 != 0) continue;
            extra[r].push_back({i, j, k});
            ++listed[G.cellIndex(i, j, k)];
        }
    }
    World world(nRanks);
    std::vector<std::thread> threads;
    for (int r = 0; r < nRanks; ++r)
    {
        threads.emplace_back([&, r]
        {
            ThreadComm comm(world, r);
            const std::array<bool, 3> periodic{false, false, false};
            Subdomain plain, sd;
            plain.build(G, owned[r], 1, periodic, comm);
            sd.build(G, owned[r], 1, periodic, comm, extra[r]);
            EXPECT_EQ(sd.haloNodes(), plain.haloNodes()) << "extras changed the step's halo";
            EXPECT_GE(sd.haloNodes(Subdomain::HaloKind::exchange), sd.haloNodes());
            std::vector<Real> a(std::size_t(sd.local().nNodes), 0.0);
            for (const auto& c : extra[r]) a[std::size_t(sd.localNode(c[0], c[1], c[2]))] += 1;
            sd.sum({a.data()}, Subdomain::HaloKind::exchange);
            for (const auto& c : owned[r])
            {
                const Index g = G.cellIndex(c[0], c[1], c[2]);
                const auto it = listed.find(g);
                EXPECT_EQ(a[std::size_t(sd.localNode(c[0], c[1], c[2]))], it == listed.end() ? 0 : it->second);
            }
            sd.copy({a.data()}, Subdomain::HaloKind::exchange);
            for (const auto& c : extra[r])
            {
                EXPECT_EQ(a[std::size_t(sd.localNode(c[0], c[1], c[2]))], listed.at(G.cellIndex(c[0], c[1], c[2])));
            }
        });
    }
    for (auto& t : threads) t.join();
}
