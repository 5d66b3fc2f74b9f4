// RAII buffers in a backend's memory (host memory for Cpu, device memory for Cuda),
// growable, with every byte accounted in the context's MemoryStats.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gdel/errors.hpp"
#include "parallel/backend.hpp"
#include "parallel/check.hpp"

namespace gdel::par {

namespace detail {

template <class B>
struct Memory;

template <>
struct Memory<Cpu> {
  static void* allocate(Context<Cpu>&, std::size_t bytes) {
    if (bytes == 0) return nullptr;
    std::size_t rounded = (bytes + 63) / 64 * 64;
    void* p = std::aligned_alloc(64, rounded);
    if (!p) throw OutOfDeviceMemory("host memory exhausted allocating " + std::to_string(bytes) + " bytes", bytes, 0);
    return p;
  }
  static void deallocate(Context<Cpu>&, void* p) noexcept { std::free(p); }
  static void copy(Context<Cpu>&, void* dst, const void* src, std::size_t bytes) {
    if (bytes) std::memcpy(dst, src, bytes);
  }
  static void to_host(Context<Cpu>& c, void* dst, const void* src, std::size_t bytes) { copy(c, dst, src, bytes); }
  static void from_host(Context<Cpu>& c, void* dst, const void* src, std::size_t bytes) { copy(c, dst, src, bytes); }
  static void memset(Context<Cpu>&, void* dst, int v, std::size_t bytes) {
    if (bytes) std::memset(dst, v, bytes);
  }
};

#if defined(__CUDACC__)
template <>
struct Memory<Cuda> {
  static void* allocate(Context<Cuda>& c, std::size_t bytes) {
    if (bytes == 0) return nullptr;
    const std::size_t lim = c.memory().limit();
    if (lim != 0 && c.memory().current() + bytes > lim)
      throw OutOfDeviceMemory("out of device memory: needed " + std::to_string(bytes) + " more bytes, " +
                                  std::to_string(lim - std::min(lim, c.memory().current())) +
                                  " left of the limit of " + std::to_string(lim) + " (Options::device_memory_limit)",
                              bytes, lim - std::min(lim, c.memory().current()));
    void* p = nullptr;
    auto alloc = [&] {
      return c.pool() ? cudaMallocFromPoolAsync(&p, bytes, c.pool(), c.stream()) : cudaMallocAsync(&p, bytes, c.stream());
    };
    cudaError_t e = alloc();
    if (e == cudaErrorMemoryAllocation && c.pool()) {  // the pool's unused memory back, and once more
      cudaGetLastError();
      c.trim_pool();
      e = alloc();
    }
    if (e == cudaErrorMemoryAllocation) {
      cudaGetLastError();
      std::size_t free_b = 0, total_b = 0;
      cudaMemGetInfo(&free_b, &total_b);
      throw OutOfDeviceMemory("out of device memory: needed " + std::to_string(bytes) + " bytes, " +
                                  std::to_string(free_b) + " free of " + std::to_string(total_b),
                              bytes, free_b);
    }
    GDEL_CUDA_CHECK(e);
    return p;
  }
  static void deallocate(Context<Cuda>& c, void* p) noexcept {
    if (p) cudaFreeAsync(p, c.stream());
  }
  static void copy(Context<Cuda>& c, void* dst, const void* src, std::size_t bytes) {
    if (bytes) GDEL_CUDA_CHECK(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToDevice, c.stream()));
  }
  // Synchronizes: the host data is valid on return.
  static void to_host(Context<Cuda>& c, void* dst, const void* src, std::size_t bytes) {
    if (!bytes) return;
    GDEL_CUDA_CHECK(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToHost, c.stream()));
    GDEL_CUDA_CHECK(cudaStreamSynchronize(c.stream()));
  }
  // Synchronizes, so the caller may free the host data on return.
  static void from_host(Context<Cuda>& c, void* dst, const void* src, std::size_t bytes) {
    if (!bytes) return;
    GDEL_CUDA_CHECK(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyHostToDevice, c.stream()));
    GDEL_CUDA_CHECK(cudaStreamSynchronize(c.stream()));
  }
  static void memset(Context<Cuda>& c, void* dst, int v, std::size_t bytes) {
    if (bytes) GDEL_CUDA_CHECK(cudaMemsetAsync(dst, v, bytes, c.stream()));
  }
};
#endif

}  // namespace detail

// A growable array in backend memory. Elements are trivially copyable and are NOT
// initialised on allocation (use fill). Move-only.
template <class T, class B>
class Buffer {
  static_assert(std::is_trivially_copyable_v<T>, "Buffer holds trivially copyable types");
  using M = detail::Memory<B>;

 public:
  explicit Buffer(Context<B>& ctx, std::size_t n = 0) : ctx_(&ctx) { resize(n); }
  ~Buffer() { release(); }
  Buffer(Buffer&& o) noexcept : ctx_(o.ctx_), data_(o.data_), size_(o.size_), cap_(o.cap_) {
    o.data_ = nullptr;
    o.size_ = o.cap_ = 0;
  }
  Buffer& operator=(Buffer&& o) noexcept {
    if (this != &o) {
      release();
      ctx_ = o.ctx_;
      data_ = o.data_;
      size_ = o.size_;
      cap_ = o.cap_;
      o.data_ = nullptr;
      o.size_ = o.cap_ = 0;
    }
    return *this;
  }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return cap_; }
  bool empty() const { return size_ == 0; }
  std::size_t bytes() const { return size_ * sizeof(T); }
  Context<B>& context() const { return *ctx_; }

  // Exact capacity, contents kept.
  void reserve(std::size_t n) {
    if (n <= cap_) return;
    T* p = static_cast<T*>(M::allocate(*ctx_, n * sizeof(T)));
    ctx_->memory().add(n * sizeof(T));
    if (data_) M::copy(*ctx_, p, data_, size_ * sizeof(T));
    free_storage();
    data_ = p;
    cap_ = n;
  }
  // Size n, contents of the first min(n, size) elements kept; grows capacity
  // geometrically (x1.5) so repeated growth is amortised.
  void resize(std::size_t n) {
    if (n > cap_) reserve(std::max(n, cap_ + cap_ / 2));
    size_ = n;
  }
  // Size n without keeping contents (no copy on growth).
  void resize_discard(std::size_t n) {
    if (n > cap_) {
      free_storage();
      data_ = static_cast<T*>(M::allocate(*ctx_, n * sizeof(T)));
      ctx_->memory().add(n * sizeof(T));
      cap_ = n;
    }
    size_ = n;
  }
  void clear() { size_ = 0; }
  void release() {
    free_storage();
    size_ = 0;
  }
  // Byte-wise fill (0 or 0xff patterns).
  void memset(int v) { M::memset(*ctx_, data_, v, size_ * sizeof(T)); }

  void assign(const T* host, std::size_t n) {
    resize_discard(n);
    M::from_host(*ctx_, data_, host, n * sizeof(T));
  }
  void assign(const std::vector<T>& host) { assign(host.data(), host.size()); }
  // Synchronizes.
  std::vector<T> to_host() const {
    if constexpr (!B::is_device) {
      return std::vector<T>(data_, data_ + size_);  // one pass: no zeroing before the copy
    } else {
      std::vector<T> v(size_);
      M::to_host(*ctx_, v.data(), data_, size_ * sizeof(T));
      return v;
    }
  }
  void copy_to_host(T* dst, std::size_t n, std::size_t offset = 0) const {
    M::to_host(*ctx_, dst, data_ + offset, n * sizeof(T));
  }
  // Single elements (synchronize).
  T get(std::size_t i) const {
    T v;
    M::to_host(*ctx_, &v, data_ + i, sizeof(T));
    return v;
  }
  void set(std::size_t i, const T& v) { M::from_host(*ctx_, data_ + i, &v, sizeof(T)); }

  // This buffer's storage as a buffer of n elements of U (n * sizeof(U) at most its
  // capacity in bytes, which must be a whole number of U), contents as bytes kept; this
  // buffer is left empty. For a stage that rewrites an array in place as another type.
  template <class U>
  Buffer<U, B> recast(std::size_t n) && {
    static_assert(alignof(U) <= alignof(T) && sizeof(T) % sizeof(U) == 0);
    Buffer<U, B> o(*ctx_);
    o.adopt(reinterpret_cast<U*>(data_), n, cap_ * (sizeof(T) / sizeof(U)));
    data_ = nullptr;
    size_ = cap_ = 0;
    if (n > o.capacity()) o.resize(n);
    return o;
  }
  // (recast's other side: takes storage of cap elements, already counted in the
  // context's memory, as this empty buffer's)
  void adopt(T* p, std::size_t n, std::size_t cap) {
    release();
    data_ = p;
    cap_ = cap;
    size_ = std::min(n, cap);
  }

 private:
  void free_storage() {
    if (data_) {
      M::deallocate(*ctx_, data_);
      ctx_->memory().sub(cap_ * sizeof(T));
    }
    data_ = nullptr;
    cap_ = 0;
  }

  Context<B>* ctx_;
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t cap_ = 0;
};

}  // namespace gdel::par
