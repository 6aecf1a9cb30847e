// The resident step on the host: the stand-in for the CUDA runtime that lets
// a machine without a GPU run, and test, the resident step's code
// (residentStepImpl.hpp). "Device" buffers are vectors, kernels are serial
// loops and the atomics are plain operations. Chosen with
// StepOptions::residentStandIn (tests); not a back-end for runs.
#include "residentStepImpl.hpp"
#include <algorithm>
#include <cstring>
#include <vector>

namespace mpm {

namespace {

struct HostExec
{
    template<class T>
    class Buffer
    {
    public:
        void resize(std::size_t n) { v_.resize(n); }
        T* data() { return v_.data(); }
        std::size_t size() const { return v_.size(); }
        void upload(const T* h, std::size_t n) { v_.assign(h, h + n); }
        void download(T* h, std::size_t n) const
        {
            if (n > v_.size()) throw std::runtime_error("download of more than the buffer holds");
            std::copy(v_.begin(), v_.begin() + std::ptrdiff_t(n), h);
        }
        void zero() { std::fill(v_.begin(), v_.end(), T{}); }
    private:
        std::vector<T> v_;
    };

    template<class T> static void copyToDevice(T* d, const T* h, std::size_t n) { std::copy(h, h + n, d); }
    template<class T> static void copyToHost(T* h, const T* d, std::size_t n) { std::copy(d, d + n, h); }
    static void zero(Real* d, std::size_t n) { std::fill(d, d + n, 0.0); }

    template<class Body>
    static void forEach(Index n, const Body& body, const char*) { for (Index i = 0; i < n; ++i) body(i); }

    static void add(Real* a, Real x) { *a += x; }
    // One thread: no warp to reduce over
    template<bool Warp> using P2gAdd = PlainAdd;
    static void min(unsigned long long* a, unsigned long long x) { *a = std::min(*a, x); }
    static void count(unsigned long long* a) { ++*a; }
    static void max(unsigned long long* a, Real x)
    {
        Real y;
        std::memcpy(&y, a, sizeof y);
        if (x > y) std::memcpy(a, &x, sizeof x);
    }
};

} // namespace

std::unique_ptr<ResidentStep> makeResidentStandIn()
{
    return std::make_unique<resident::Step<HostExec>>();
}

} // namespace mpm
