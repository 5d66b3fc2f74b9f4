// Backend tags and the execution context of the parallel layer.
//
// Algorithm code is written once as templates over a backend tag B (Cpu or Cuda)
// and per-element functors (GDEL_HD functions, GDEL_LAMBDA lambdas: core/macros.hpp).
// Host translation units (*.cpp, Thrust OpenMP system) instantiate B = Cpu; CUDA
// translation units (*.cu) instantiate B = Cuda.
// Synchronisation: every primitive is enqueued on the context's stream; only calls
// documented as "synchronizes" (those returning a host value, to_host, ...) wait.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/macros.hpp"
#include "parallel/profile.hpp"

#if defined(__CUDACC__)
#include <cuda_runtime.h>
#endif

namespace gdel::par {

struct Cpu {
  static constexpr bool is_device = false;
  static constexpr const char* name = "cpu";
};
struct Cuda {
  static constexpr bool is_device = true;
  static constexpr const char* name = "cuda";
};

// Bytes currently held and the peak, per context (buffers and temporaries).
class MemoryStats {
 public:
  void add(std::size_t bytes) {
    std::size_t now = current_.fetch_add(bytes, std::memory_order_relaxed) + bytes;
    raise(peak_, now);
    raise(interval_peak_, now);
  }
  void sub(std::size_t bytes) { current_.fetch_sub(bytes, std::memory_order_relaxed); }
  // A cap on current() for the CUDA allocator (0: none), from Options::device_memory_limit.
  void set_limit(std::size_t bytes) { limit_ = bytes; }
  std::size_t limit() const { return limit_; }
  std::size_t current() const { return current_.load(std::memory_order_relaxed); }
  std::size_t peak() const { return peak_.load(std::memory_order_relaxed); }
  void reset_peak() { peak_.store(current(), std::memory_order_relaxed); }
  // The peak since the previous call (or since construction), then restarted from now:
  // the profiler's per-step memory (parallel/profile.hpp).
  std::size_t take_interval_peak() {
    return interval_peak_.exchange(current(), std::memory_order_relaxed);
  }

 private:
  static void raise(std::atomic<std::size_t>& a, std::size_t now) {
    std::size_t p = a.load(std::memory_order_relaxed);
    while (now > p && !a.compare_exchange_weak(p, now, std::memory_order_relaxed)) {
    }
  }
  std::atomic<std::size_t> current_{0};
  std::atomic<std::size_t> peak_{0};
  std::atomic<std::size_t> interval_peak_{0};
  std::size_t limit_ = 0;
};

template <class B>
class Context;

template <>
class Context<Cpu> {
 public:
  Context() { profile_start(); }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  MemoryStats& memory() { return mem_; }
  void synchronize() {}

  // Step profiler (parallel/profile.hpp): mark(name) charges the time since the
  // previous mark to name; profile_start() sets the origin; profile_report() sums.
  bool profiling() const { return prof_on_; }
  void mark(const char* name) {
    if (!prof_on_) return;
    prof_names_.push_back(name);
    prof_t_.push_back(now());
    prof_peak_.push_back(mem_.take_interval_peak());
  }
  void profile_start() {
    prof_names_.clear();
    prof_peak_.clear();
    prof_t_.assign(1, now());
    mem_.take_interval_peak();
  }
  ProfileTotals profile_report() const { return profile_totals(prof_names_, prof_t_, prof_peak_); }

 private:
  static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  MemoryStats mem_;
  bool prof_on_ = profiling_requested();
  std::vector<const char*> prof_names_;
  std::vector<double> prof_t_;
  std::vector<std::size_t> prof_peak_;  // memory peak of each interval
};

#if defined(__CUDACC__)
// One device, one stream. Memory comes from a stream-ordered pool that the context owns
// (cudaMallocFromPoolAsync), so temporaries are cheap and need no host synchronisation.
// The pool keeps what is freed until the context ends (release threshold: no limit): a
// pool with the default threshold (0) hands its unused memory back to the driver at
// every host synchronisation, and the next allocations map it again (measured: 3-5 %
// of uniform 10^7, 16 % of the 10^6 sphere; bench/RESULTS.md, session 14). The memory goes
// back when the context is destroyed, or when an allocation fails (the pool is trimmed,
// then the allocation is tried once more). GDEL_DEVICE_POOL=default selects the device's
// default pool with its default threshold instead (for comparison).
template <>
class Context<Cuda> {
 public:
  explicit Context(int device = 0);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  MemoryStats& memory() { return mem_; }
  cudaStream_t stream() const { return stream_; }
  int device() const { return device_; }
  int sm_count() const { return sm_count_; }
  void synchronize();
  // The context's pool; nullptr with GDEL_DEVICE_POOL=default (cudaMallocAsync's pool).
  cudaMemPool_t pool() const { return pool_; }
  // Waits for the stream, then returns the pool's unused memory to the driver.
  void trim_pool();
  // Device memory free for new allocations: the driver's free memory and what the
  // pool holds unused.
  std::size_t free_bytes();

  // Step profiler (parallel/profile.hpp): events on the stream, read back by
  // profile_report() (synchronizes).
  bool profiling() const { return prof_on_; }
  void mark(const char* name) {
    if (!prof_on_) return;
    prof_names_.push_back(name);
    prof_peak_.push_back(mem_.take_interval_peak());
    record_event();
  }
  void profile_start();
  ProfileTotals profile_report();

 private:
  void record_event();
  MemoryStats mem_;
  cudaStream_t stream_ = nullptr;
  cudaMemPool_t pool_ = nullptr;
  int device_ = 0;
  int sm_count_ = 1;
  bool prof_on_ = profiling_requested();
  std::vector<const char*> prof_names_;
  std::vector<std::size_t> prof_peak_;  // memory peak of each interval
  std::vector<cudaEvent_t> prof_events_;  // pool; the first prof_used_ are recorded
  std::size_t prof_used_ = 0;
};
#endif

// Marks the end of a profiled step (no-op unless GDEL_PROFILE is set).
template <class B>
inline void mark(Context<B>& c, const char* name) {
  c.mark(name);
}

}  // namespace gdel::par
