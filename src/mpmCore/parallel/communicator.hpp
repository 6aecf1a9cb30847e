// What the core needs from a message-passing layer, and nothing more: the
// rank, reductions, an all-gather and a personalised exchange of byte
// buffers. The OpenFOAM layer implements it with Pstream (one obvious home
// for MPI); the core stays free of MPI and of OpenFOAM types, and a serial
// run has no communicator at all.
#pragma once
#include "../types.hpp"
#include <cstdint>
#include <cstring>
#include <vector>

namespace mpm {

enum class ReduceOp { sum, min, max };

class Communicator
{
public:
    virtual ~Communicator() = default;

    virtual int rank() const = 0;
    virtual int size() const = 0;

    // In-place reduction over all ranks of n values.
    virtual void allReduce(Real* values, int n, ReduceOp op) const = 0;
    virtual void allReduce(std::int64_t* values, int n, ReduceOp op) const = 0;

    // out = every rank's `mine`, rank after rank (all of one size).
    virtual void allGather(const std::vector<std::int64_t>& mine, std::vector<std::int64_t>& out) const = 0;

    // send[r] goes to rank r; recv[r] is what rank r sent here. With
    // sizesKnown, recv[r] is already sized to the incoming message (the
    // halo's fixed lists: no size exchange); otherwise it is resized.
    virtual void exchange
    (
        const std::vector<std::vector<char>>& send,
        std::vector<std::vector<char>>& recv,
        bool sizesKnown
    ) const = 0;

    // Typed conveniences
    Real sum(Real x) const { allReduce(&x, 1, ReduceOp::sum); return x; }
    Real max(Real x) const { allReduce(&x, 1, ReduceOp::max); return x; }
    Real min(Real x) const { allReduce(&x, 1, ReduceOp::min); return x; }
    std::int64_t sum(std::int64_t x) const { allReduce(&x, 1, ReduceOp::sum); return x; }
    std::int64_t min(std::int64_t x) const { allReduce(&x, 1, ReduceOp::min); return x; }
    std::int64_t max(std::int64_t x) const { allReduce(&x, 1, ReduceOp::max); return x; }
};

// Appends / reads plain values to / from a byte buffer.
template<class T>
inline void appendBytes(std::vector<char>& buf, const T* v, std::size_t n)
{
    const std::size_t at = buf.size();
    buf.resize(at + n*sizeof(T));
    if (n) std::memcpy(buf.data() + at, v, n*sizeof(T));
}

template<class T>
inline void readBytes(const std::vector<char>& buf, std::size_t& at, T* v, std::size_t n)
{
    if (n) std::memcpy(v, buf.data() + at, n*sizeof(T));
    at += n*sizeof(T);
}

} // namespace mpm
