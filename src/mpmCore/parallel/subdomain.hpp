// One rank's share of a decomposed lattice: the cells it owns (from the
// mesh decomposition, any shape), a box lattice around them, and the halo
// that makes P2G and G2P on that box equal to the serial step.
//
// The box is the owned cells' bounding box grown by the lattice's ghost
// layers (and, next to a wall, by the mirror ghosts of owned nodes), in the
// global lattice's coordinates. Every box node is one of:
//   - owner side: a real node of an owned cell, or a wall mirror ghost whose
//     image is owned here (folded here by the Boundary, as in serial);
//   - a copy: any other node a stencil of an owned cell can reach (`reach`
//     layers: 1 for linear hats and quadratic B-splines, 2 for cubic). Its
//     owner is the rank owning its canonical node (periodic directions
//     wrapped), found by querying the ranks whose boxes hold it, so
//     diagonal neighbours and periodic partners count, whether or not they
//     share a processor patch;
//   - unused (never written or read).
// sum() adds every copy into its owner (after P2G); copy() sends the
// owner's value back to every copy (before G2P). Nothing assumes that a
// subdomain is a box or that it is thicker than the stencil: owners are
// looked up per node, not per neighbour.
#pragma once
#include "../grid/lattice.hpp"
#include "communicator.hpp"
#include <array>
#include <unordered_map>
#include <vector>

namespace mpm {

class Subdomain
{
public:
    // global: the whole box (finalised); owned: global real (i, j, k) of the
    // cells this rank owns (may be empty: then no halo and no points, see
    // build); periodic: per axis. extra: cells beyond the stencils' reach
    // that this rank reads or writes through the exchange halo (a fluid
    // mesh's cells overlap them where the lattice is decomposed its own
    // way); they widen the box but not the step's halo.
    void build
    (
        const Lattice& global,
        const std::vector<std::array<int, 3>>& owned,
        int reach,
        const std::array<bool, 3>& periodic,
        const Communicator& comm,
        const std::vector<std::array<int, 3>>& extra = {}
    );

    const Communicator& comm() const { return *comm_; }
    const Lattice& global() const { return global_; }
    const Lattice& local() const { return local_; }

    // Global real index of local real node 0, per axis.
    const std::array<int, 3>& offset() const { return offset_; }

    // Whether this rank owns the global cell (linear index, x fastest).
    bool ownsCell(Index globalCell) const;

    // Rank owning the cell that contains x (clamped into the box domain;
    // positions are already wrapped in periodic directions); -1 if it is
    // not within this rank's reach (moved too far in one step).
    int ownerOf(const Real* x) const;

    // Local padded node of global real (i, j, k), or -1 outside the box.
    Index localNode(int i, int j, int k) const;

    // 1 for owner-side nodes (see above); the rest are copies or unused.
    const std::vector<char>& ownerSide() const { return ownerSide_; }

    // Halo exchange of nodal arrays (each of local().nNodes values): the
    // step's (the stencils' copies, every step) or the exchange's (those
    // and the extra cells, for the fluid's maps).
    enum class HaloKind { step, exchange };
    void sum(const std::vector<Real*>& arrays, HaloKind kind = HaloKind::step) const;
    void copy(const std::vector<Real*>& arrays, HaloKind kind = HaloKind::step) const;

    // Values sent per sum() or copy() per array, summed over ranks'
    // messages from here (for the cost log and the docs' estimate).
    Index haloNodes(HaloKind kind = HaloKind::step) const;

    // Every local node that sum() or copy() reads or writes, once: the
    // sparse grid keeps them active (grid/activeRegion.hpp), since a copy
    // here may carry another rank's material.
    const std::vector<Index>& haloNodeList() const { return haloNodeList_; }
    int neighbourCount() const { return int(neighbours_.size()); }

    // Ranks sharing halo nodes with this one (a symmetric relation): the
    // only ranks a point can migrate to in one step, so migration talks to
    // them alone, with no all-to-all.
    const std::vector<int>& neighbours() const { return neighbours_; }
    bool isNeighbour(int rank) const { return rank >= 0 && isNeighbour_[rank]; }

private:
    Index globalCellId(const int r[3]) const;
    void cellCoords(Index globalCell, int r[3]) const;
    // Owner of the global real cell r: the box first, then the map
    // (periodic images beyond the box); -1 if unknown here.
    int ownerAt(const int r[3]) const;
    // Sends the values at from[q] to each rank q and sizes the receive
    // buffers for to[q] (the halo lists are symmetric).
    void post
    (
        const std::vector<Real*>& arrays,
        const std::vector<std::vector<Index>>& from,
        const std::vector<std::vector<Index>>& to
    ) const;
    int ownerOfCell(Index globalCell) const;

    const Communicator* comm_ = nullptr;
    Lattice global_, local_;
    std::array<int, 3> offset_{0, 0, 0};
    std::array<int, 3> boxLo_{0, 0, 0}, boxHi_{0, 0, 0};  // global real, inclusive
    std::array<bool, 3> periodic_{false, false, false};

    std::vector<char> ownerSide_;
    std::vector<int> boxOwner_;              // owner of each box real cell (-1: none)
    std::unordered_map<Index, int> owner_;   // canonical cells outside the box

    // A halo's lists per rank: copies here -> owner there (copyIdx[r][k]
    // goes to ownerIdx on rank r at the same k), and owners here <- copies
    // there; (copy, owner) pairs both here (periodic images).
    struct Halo
    {
        std::vector<std::vector<Index>> copyIdx, ownerIdx;
        std::vector<std::pair<Index, Index>> selfPairs;
    };
    Halo step_, exchange_;
    bool exchangeIsStep_ = true;
    const Halo& halo(HaloKind kind) const;
    std::vector<Index> haloNodeList_;
    std::vector<int> neighbours_;
    std::vector<char> isNeighbour_;

    mutable std::vector<std::vector<char>> sendBuf_, recvBuf_;
};

} // namespace mpm
