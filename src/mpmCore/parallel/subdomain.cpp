#include "subdomain.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mpm {

namespace {

// The Index values of a byte buffer
std::vector<Index> indicesIn(const std::vector<char>& buf)
{
    std::vector<Index> out(buf.size()/sizeof(Index));
    std::size_t at = 0;
    readBytes(buf, at, out.data(), out.size());
    return out;
}

std::string cellText(const int r[3])
{
    return "(" + std::to_string(r[0]) + " " + std::to_string(r[1]) + " " + std::to_string(r[2]) + ")";
}

} // namespace

Index Subdomain::globalCellId(const int r[3]) const
{
    return global_.cellIndex(r[0], r[1], r[2]);
}

Index Subdomain::localNode(int i, int j, int k) const
{
    const int r[3] = {i, j, k};
    int l[3];
    for (int a = 0; a < 3; ++a)
    {
        l[a] = r[a] - boxLo_[a];
        if (l[a] < 0 || l[a] >= local_.nodes[a]) return -1;
    }
    return local_.node(l[0], l[1], l[2]);
}

bool Subdomain::ownsCell(Index id) const
{
    return ownerOfCell(id) == comm_->rank();
}

void Subdomain::cellCoords(Index id, int r[3]) const
{
    const Index n0 = global_.nCells[0], n1 = global_.nCells[1];
    r[0] = int(id % n0);
    r[1] = int((id/n0) % n1);
    r[2] = int(id/(n0*n1));
}

int Subdomain::ownerAt(const int r[3]) const
{
    const Index l = localNode(r[0], r[1], r[2]);
    if (l >= 0 && boxOwner_[l] >= 0) return boxOwner_[l];
    const auto it = owner_.find(globalCellId(r));
    return it == owner_.end() ? -1 : it->second;
}

int Subdomain::ownerOfCell(Index id) const
{
    int r[3];
    cellCoords(id, r);
    return ownerAt(r);
}

int Subdomain::ownerOf(const Real* x) const
{
    // Called for every point every step: no id round trip.
    int r[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
    {
        if (!global_.solved[a]) continue;
        const Index c = Index(std::floor((x[a] - global_.origin[a])/global_.h));
        r[a] = int(std::min<Index>(std::max<Index>(c, 0), global_.nCells[a] - 1));
    }
    return ownerAt(r);
}

void Subdomain::build
(
    const Lattice& global,
    const std::vector<std::array<int, 3>>& owned,
    int reach,
    const std::array<bool, 3>& periodic,
    const Communicator& comm,
    const std::vector<std::array<int, 3>>& extra
)
{
    comm_ = &comm;
    global_ = global;
    periodic_ = periodic;
    const int me = comm.rank(), np = comm.size();
    const int pad = global.pad;
    // Bounding box of the owned cells, then the box lattice around it. A
    // rank that owns no cell (its mesh cells all beyond the lattice's
    // extent, say) keeps a box around cell (0 0 0) that it owns nothing of
    // and no stencil of it reaches: no halo, no points; it still takes part
    // in every exchange. The others see its box as empty.
    std::array<int, 3> lo{{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()}};
    std::array<int, 3> hi{{-1, -1, -1}};
    for (const auto& c : owned)
    {
        for (int a = 0; a < 3; ++a) { lo[a] = std::min(lo[a], c[a]); hi[a] = std::max(hi[a], c[a]); }
    }
    const std::vector<std::int64_t> myBox{lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
    if (owned.empty() && extra.empty()) lo = hi = {0, 0, 0};
    // The box holds the extra cells too (copies for the exchange)
    for (const auto& c : extra)
    {
        for (int a = 0; a < 3; ++a) { lo[a] = std::min(lo[a], c[a]); hi[a] = std::max(hi[a], c[a]); }
    }
    local_ = global;
    local_.checkGhostLayers = false;
    for (int a = 0; a < 3; ++a)
    {
        if (!global.solved[a]) { boxLo_[a] = boxHi_[a] = 0; offset_[a] = 0; continue; }
        const int n = global.nCells[a];
        int bl = lo[a] - pad, bh = hi[a] + pad;
        if (!periodic[a])
        {
            // Mirror ghosts of owned nodes next to a wall are folded here.
            if (lo[a] < pad) bl = std::min(bl, -1 - std::min(hi[a], pad - 1));
            if (hi[a] >= n - pad) bh = std::max(bh, 2*n - 1 - std::max(lo[a], n - pad));
        }
        bl = std::max(bl, -pad);
        bh = std::min(bh, n - 1 + pad);
        boxLo_[a] = bl; boxHi_[a] = bh;
        offset_[a] = bl + pad;
        local_.origin[a] = global.origin[a] + offset_[a]*global.h;
        local_.nCells[a] = bh - bl + 1 - 2*pad;
    }
    local_.finalise();
    const Index nNodes = local_.nNodes;

    // Box coordinates of local node l
    auto coords = [&](Index l, int r[3])
    {
        Index rest = l;
        for (int a = 2; a >= 0; --a)
        {
            const Index s = local_.stride[a];
            const int li = int(rest/s);
            rest -= Index(li)*s;
            r[a] = li + boxLo_[a];
        }
    };
    // Canonical node (periodic directions wrapped) and its real image (walls
    // reflected) of global real coordinates r.
    auto canonical = [&](const int r[3], int c[3], int img[3])
    {
        for (int a = 0; a < 3; ++a)
        {
            const int n = global.nCells[a];
            c[a] = r[a];
            if (global.solved[a] && periodic[a]) c[a] = ((r[a] % n) + n) % n;
            img[a] = c[a];
            if (img[a] < 0) img[a] = -1 - img[a];
            else if (img[a] >= n) img[a] = 2*n - 1 - img[a];
        }
    };

    // Owners: own cells first; every other canonical image of a box node is
    // asked of the ranks whose owned bounding boxes contain it.
    boxOwner_.assign(nNodes, -1);
    for (const auto& c : owned) boxOwner_[localNode(c[0], c[1], c[2])] = me;
    owner_.clear();

    std::vector<std::int64_t> boxes;
    comm.allGather(myBox, boxes);

    std::vector<Index> needed;
    for (Index l = 0; l < nNodes; ++l)
    {
        int r[3], c[3], img[3];
        coords(l, r);
        canonical(r, c, img);
        const Index li = localNode(img[0], img[1], img[2]);
        if (li >= 0 && boxOwner_[li] == me) continue;
        needed.push_back(globalCellId(img));
    }
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());

    std::vector<std::vector<char>> send(np), recv(np);
    for (const Index id : needed)
    {
        int r[3];
        cellCoords(id, r);
        for (int q = 0; q < np; ++q)
        {
            if (q == me) continue;
            bool inside = true;
            for (int a = 0; a < 3; ++a) inside = inside && r[a] >= boxes[6*q + a] && r[a] <= boxes[6*q + 3 + a];
            if (inside) appendBytes(send[q], &id, 1);
        }
    }
    comm.exchange(send, recv, false);
    // Answer: the queried cells this rank owns
    std::vector<std::vector<char>> answer(np), answered(np);
    for (int s = 0; s < np; ++s)
    {
        for (const Index id : indicesIn(recv[s]))
        {
            if (ownsCell(id)) appendBytes(answer[s], &id, 1);
        }
    }
    comm.exchange(answer, answered, false);
    for (int q = 0; q < np; ++q)
    {
        for (const Index id : indicesIn(answered[q])) owner_[id] = q;
    }
    for (Index l = 0; l < nNodes; ++l)
    {
        int r[3];
        coords(l, r);
        bool real = true;
        for (int a = 0; a < 3; ++a) real = real && r[a] >= 0 && r[a] < global.nCells[a];
        if (!real || boxOwner_[l] >= 0) continue;
        const auto it = owner_.find(globalCellId(r));
        if (it != owner_.end()) boxOwner_[l] = it->second;
    }

    // Nodes a stencil of an owned cell can reach: the owned cells dilated
    // by `reach` along each solved axis in turn.
    std::vector<char> near(nNodes, 0), grown(nNodes, 0);
    for (const auto& c : owned) near[localNode(c[0], c[1], c[2])] = 1;
    for (int a = 0; a < 3; ++a)
    {
        if (!global.solved[a]) continue;
        std::fill(grown.begin(), grown.end(), 0);
        const Index s = local_.stride[a];
        for (Index l = 0; l < nNodes; ++l)
        {
            if (!near[l]) continue;
            const int li = int((l/s) % local_.nodes[a]);
            for (int d = -reach; d <= reach; ++d)
            {
                if (li + d >= 0 && li + d < local_.nodes[a]) grown[l + d*s] = 1;
            }
        }
        near.swap(grown);
    }

    // The halo of the nodes marked in `mask`: each copy (a node another
    // rank owns, or a periodic image of an owned one) paired with its
    // owner's node there, the owner told which of its nodes each is.
    auto haloOf = [&](const std::vector<char>& mask)
    {
        Halo h;
        h.copyIdx.assign(np, {});
        h.ownerIdx.assign(np, {});
        std::vector<std::vector<char>> ids(np), idsIn(np);
        for (Index l = 0; l < nNodes; ++l)
        {
            if (ownerSide_[l] || !mask[l]) continue;
            int r[3], c[3], img[3];
            coords(l, r);
            canonical(r, c, img);
            const int q = ownerOfCell(globalCellId(img));
            if (q < 0)
            {
                throw std::runtime_error
                (
                    "subdomain: no processor owns cell " + cellText(img)
                  + ", which processor " + std::to_string(me) + "'s stencils reach"
                );
            }
            if (q == me)
            {
                const Index owner = localNode(c[0], c[1], c[2]);
                if (owner < 0) throw std::logic_error("subdomain: periodic image outside the box");
                h.selfPairs.emplace_back(l, owner);
                continue;
            }
            const Index gid = global.node(c[0] + global.padOf(0), c[1] + global.padOf(1), c[2] + global.padOf(2));
            h.copyIdx[q].push_back(l);
            appendBytes(ids[q], &gid, 1);
        }
        comm.exchange(ids, idsIn, false);
        for (int s = 0; s < np; ++s)
        {
            const std::vector<Index> gids(indicesIn(idsIn[s]));
            h.ownerIdx[s].resize(gids.size());
            for (std::size_t k = 0; k < gids.size(); ++k)
            {
                const Index gid = gids[k];
                int r[3];
                Index rest = gid;
                for (int a = 2; a >= 0; --a)
                {
                    const Index st = global.stride[a];
                    r[a] = int(rest/st) - global.padOf(a);
                    rest -= (r[a] + global.padOf(a))*st;
                }
                const Index l = localNode(r[0], r[1], r[2]);
                if (l < 0 || !ownerSide_[l])
                {
                    throw std::logic_error
                    (
                        "subdomain: processor " + std::to_string(s) + " sends node "
                      + cellText(r) + " that processor " + std::to_string(me) + " does not own"
                    );
                }
                h.ownerIdx[s][k] = l;
            }
        }
        return h;
    };

    // Owner side: the owned real nodes, and the wall mirror ghosts of
    // owned nodes (a periodic image is a copy, even of an owned node)
    ownerSide_.assign(nNodes, 0);
    for (Index l = 0; l < nNodes; ++l)
    {
        int r[3], c[3], img[3];
        coords(l, r);
        canonical(r, c, img);
        const bool isCanonical = r[0] == c[0] && r[1] == c[1] && r[2] == c[2];
        if (isCanonical && ownerOfCell(globalCellId(img)) == me) ownerSide_[l] = 1;
    }
    // The step's halo: the copies the stencils reach. The exchange's: those
    // and the extra cells, the same lists unless an extra cell lies beyond
    // the stencils' reach (collective: every rank builds the exchange's
    // lists if any has such a cell)
    step_ = haloOf(near);
    std::int64_t beyond = 0;
    for (const auto& c : extra) beyond += !near[localNode(c[0], c[1], c[2])];
    exchangeIsStep_ = comm.max(beyond) == 0;
    if (!exchangeIsStep_)
    {
        for (const auto& c : extra) near[localNode(c[0], c[1], c[2])] = 1;
        exchange_ = haloOf(near);
    }
    neighbours_.clear();
    isNeighbour_.assign(np, 0);
    for (int q = 0; q < np; ++q)
    {
        if (q != me && (!step_.copyIdx[q].empty() || !step_.ownerIdx[q].empty()))
        {
            neighbours_.push_back(q);
            isNeighbour_[q] = 1;
        }
    }
    sendBuf_.assign(np, {});
    recvBuf_.assign(np, {});

    haloNodeList_.clear();
    for (const auto& list : step_.copyIdx) haloNodeList_.insert(haloNodeList_.end(), list.begin(), list.end());
    for (const auto& list : step_.ownerIdx) haloNodeList_.insert(haloNodeList_.end(), list.begin(), list.end());
    for (const auto& pr : step_.selfPairs) { haloNodeList_.push_back(pr.first); haloNodeList_.push_back(pr.second); }
    std::sort(haloNodeList_.begin(), haloNodeList_.end());
    haloNodeList_.erase(std::unique(haloNodeList_.begin(), haloNodeList_.end()), haloNodeList_.end());
}

void Subdomain::post
(
    const std::vector<Real*>& arrays,
    const std::vector<std::vector<Index>>& from,
    const std::vector<std::vector<Index>>& to
) const
{
    const std::size_t k = arrays.size();
    for (int q = 0; q < comm_->size(); ++q)
    {
        auto& b = sendBuf_[q];
        b.resize(from[q].size()*k*sizeof(Real));
        Real* v = reinterpret_cast<Real*>(b.data());
        for (const Real* a : arrays) for (const Index l : from[q]) *v++ = a[l];
        recvBuf_[q].resize(to[q].size()*k*sizeof(Real));
    }
    comm_->exchange(sendBuf_, recvBuf_, true);
}

const Subdomain::Halo& Subdomain::halo(HaloKind kind) const
{
    return kind == HaloKind::exchange && !exchangeIsStep_ ? exchange_ : step_;
}

void Subdomain::sum(const std::vector<Real*>& arrays, HaloKind kind) const
{
    const Halo& h = halo(kind);
    post(arrays, h.copyIdx, h.ownerIdx);
    // Fixed order (rank by rank): the sums do not depend on message timing.
    for (int s = 0; s < comm_->size(); ++s)
    {
        if (s == comm_->rank())
        {
            for (Real* a : arrays) for (const auto& pr : h.selfPairs) a[pr.second] += a[pr.first];
            continue;
        }
        const Real* v = reinterpret_cast<const Real*>(recvBuf_[s].data());
        for (Real* a : arrays) for (const Index l : h.ownerIdx[s]) a[l] += *v++;
    }
}

void Subdomain::copy(const std::vector<Real*>& arrays, HaloKind kind) const
{
    const Halo& h = halo(kind);
    post(arrays, h.ownerIdx, h.copyIdx);
    for (Real* a : arrays) for (const auto& pr : h.selfPairs) a[pr.first] = a[pr.second];
    for (int q = 0; q < comm_->size(); ++q)
    {
        const Real* v = reinterpret_cast<const Real*>(recvBuf_[q].data());
        for (Real* a : arrays) for (const Index l : h.copyIdx[q]) a[l] = *v++;
    }
}

Index Subdomain::haloNodes(HaloKind kind) const
{
    Index n = 0;
    for (const auto& c : halo(kind).copyIdx) n += Index(c.size());
    return n;
}


} // namespace mpm
