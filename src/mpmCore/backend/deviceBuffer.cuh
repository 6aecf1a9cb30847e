// An array in device memory that frees itself (CUDA translation units only).
//
// Sized with resize(), which keeps the allocation when it is large enough
// (a step's point count changes by a few points; reallocating every step
// would cost a cudaFree/cudaMalloc pair, each a device synchronisation).
// The contents are not preserved by a growing resize. Copies to and from
// host memory are checked (cudaCheck) and name the buffer.
#pragma once
#include "cudaCheck.cuh"
#include <cstddef>
#include <string>
#include <utility>

namespace mpm::cuda {

template<class T>
class DeviceBuffer
{
public:
    explicit DeviceBuffer(const char* name = "buffer") : name_(name) {}
    ~DeviceBuffer() { if (data_) cudaFree(data_); }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    DeviceBuffer(DeviceBuffer&& o) noexcept
    : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)),
      capacity_(std::exchange(o.capacity_, 0)), name_(o.name_) {}

    void resize(std::size_t n)
    {
        if (n > capacity_)
        {
            if (data_) cudaCheck(cudaFree(data_), what("cudaFree").c_str());
            data_ = nullptr;
            capacity_ = 0;
            // 1/8 headroom: a point count that creeps up reallocates rarely
            const std::size_t cap = n + n/8;
            cudaCheck(cudaMalloc(reinterpret_cast<void**>(&data_), cap*sizeof(T)), what("cudaMalloc").c_str());
            capacity_ = cap;
        }
        size_ = n;
    }

    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return size_; }

    void upload(const T* host, std::size_t n)
    {
        resize(n);
        if (n) cudaCheck(cudaMemcpy(data_, host, n*sizeof(T), cudaMemcpyHostToDevice), what("cudaMemcpy to device").c_str());
    }
    void download(T* host, std::size_t n) const
    {
        if (n > size_) throw std::runtime_error(what("download of more than the buffer holds"));
        if (n) cudaCheck(cudaMemcpy(host, data_, n*sizeof(T), cudaMemcpyDeviceToHost), what("cudaMemcpy to host").c_str());
    }
    void zero()
    {
        if (size_) cudaCheck(cudaMemset(data_, 0, size_*sizeof(T)), what("cudaMemset").c_str());
    }

private:
    std::string what(const char* call) const { return std::string(call) + " of " + name_; }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
    const char* name_;
};

} // namespace mpm::cuda
