#include "migrate.hpp"
#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {

Index migrate(SystemState& s)
{
    if (!s.subdomain) return 0;
    const Subdomain& sd = *s.subdomain;
    const Communicator& comm = sd.comm();
    const int me = comm.rank(), np = comm.size();
    auto& P = s.particles;
    const Index n = P.size();
    std::vector<int> dest(n);
    const std::int64_t none = std::numeric_limits<std::int64_t>::max();
    std::int64_t lost = none;
    Index sent = 0;
    #pragma omp parallel for reduction(min:lost) reduction(+:sent) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        dest[p] = sd.ownerOf(x);
        // One step moves a point to a cell its stencil reached: its owner
        // shares halo nodes with this rank.
        if (dest[p] != me && !sd.isNeighbour(dest[p])) lost = std::min<std::int64_t>(lost, P.id[p]);
        sent += dest[p] != me;
    }
    lost = comm.min(lost);
    if (lost != none)
    {
        std::ostringstream os;
        os << "material point id " << lost << " moved beyond its processor's "
           << "halo in one step (more than " << stencilReach(s.options.shape)
           << " cells): the time step is far too large for the Courant number";
        throw std::runtime_error(os.str());
    }
    std::vector<std::vector<char>> send(np), recv(np);
    std::vector<Index> leaving;
    leaving.reserve(sent);
    for (Index p = 0; p < n; ++p)
    {
        if (dest[p] == me) continue;
        P.pack(p, send[dest[p]]);
        leaving.push_back(p);
    }
    // Sizes to and from the halo neighbours only, then the points: no
    // all-to-all, whatever the number of ranks.
    std::vector<std::vector<char>> sizeOut(np), sizeIn(np);
    for (const int q : sd.neighbours())
    {
        const std::int64_t bytes = std::int64_t(send[q].size());
        appendBytes(sizeOut[q], &bytes, 1);
        sizeIn[q].resize(sizeof(std::int64_t));
    }
    comm.exchange(sizeOut, sizeIn, true);
    for (const int q : sd.neighbours())
    {
        std::int64_t bytes;
        std::size_t at = 0;
        readBytes(sizeIn[q], at, &bytes, 1);
        recv[q].resize(std::size_t(bytes));
    }
    comm.exchange(send, recv, true);
    P.remove(leaving);
    for (int q = 0; q < np; ++q) P.unpack(recv[q]);
    s.migrated += sent;
    return sent;
}

} // namespace mpm
