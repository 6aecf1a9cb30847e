#include "pstreamCommunicator.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "UIPstream.H"
#include "UOPstream.H"

int Foam::pstreamCommunicator::rank() const
{
    return Pstream::myProcNo();
}

int Foam::pstreamCommunicator::size() const
{
    return Pstream::nProcs();
}

namespace
{

template<class T>
void reduceAll(T* v, int n, mpm::ReduceOp op)
{
    using namespace Foam;
    for (int i = 0; i < n; ++i)
    {
        switch (op)
        {
            case mpm::ReduceOp::sum: reduce(v[i], sumOp<T>()); break;
            case mpm::ReduceOp::min: reduce(v[i], minOp<T>()); break;
            default: reduce(v[i], maxOp<T>()); break;
        }
    }
}

} // namespace

void Foam::pstreamCommunicator::allReduce(mpm::Real* v, int n, mpm::ReduceOp op) const
{
    reduceAll(v, n, op);
}

void Foam::pstreamCommunicator::allReduce(std::int64_t* v, int n, mpm::ReduceOp op) const
{
    reduceAll(v, n, op);
}

void Foam::pstreamCommunicator::allGather
(
    const std::vector<std::int64_t>& mine,
    std::vector<std::int64_t>& out
) const
{
    List<List<int64_t>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = List<int64_t>(mine.begin(), mine.end());
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    out.clear();
    for (const auto& l : all) out.insert(out.end(), l.begin(), l.end());
}

void Foam::pstreamCommunicator::exchange
(
    const std::vector<std::vector<char>>& send,
    std::vector<std::vector<char>>& recv,
    bool sizesKnown
) const
{
    const label np = Pstream::nProcs(), me = Pstream::myProcNo();
    recv.resize(np);
    if (!sizesKnown)
    {
        labelList sendSizes(np), recvSizes(np);
        forAll(sendSizes, q) sendSizes[q] = label(send[q].size());
        UPstream::allToAll(sendSizes, recvSizes);
        forAll(recvSizes, q) recv[q].resize(recvSizes[q]);
    }
    const label start = UPstream::nRequests();
    for (label q = 0; q < np; ++q)
    {
        if (q == me || recv[q].empty()) continue;
        UIPstream::read(UPstream::commsTypes::nonBlocking, q, recv[q].data(), recv[q].size());
    }
    for (label q = 0; q < np; ++q)
    {
        if (q == me || send[q].empty()) continue;
        UOPstream::write(UPstream::commsTypes::nonBlocking, q, send[q].data(), send[q].size());
    }
    UPstream::waitRequests(start);
    recv[me] = send[me];
}
