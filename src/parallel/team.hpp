// A team: one group of threads that runs a body together, with barriers and prefix sums
// between its phases. It is for chains of small dependent steps, each of which would
// otherwise be a launch of its own (or several: a device-wide selection is two kernels)
// while the work of each is a few hundred items (gFlip3D's small flip iterations:
// bench/RESULTS.md, session 28).
//
//   CUDA: one block of kTeamThreads threads, one launch (team_run); sync() is the
//         block's barrier, which also makes each thread's earlier global-memory writes
//         and atomics visible to the others.
//   CPU:  the calling thread alone (size 1): the same body, its loops run in order.
//
// A body is written for any team size: loops stride by size() from rank(), and every
// thread reaches every sync() and exclusive_sum() (they are collective). Results are the
// same for every size where the body's writes depend only on the sums' order (rank
// order = index order), as in team_select below.
#pragma once

#include <algorithm>
#include <cstdint>

#include "core/macros.hpp"
#include "parallel/backend.hpp"

#if defined(__CUDACC__)
#include <cub/block/block_scan.cuh>
#endif

namespace gdel::par {

inline constexpr int kTeamThreads = 1024;  // CUDA: the block

#if defined(__CUDACC__)
namespace detail {
using TeamScan = cub::BlockScan<std::int64_t, kTeamThreads>;
}
#endif

class Team {
 public:
  GDEL_HD Team(int rank, int size, void* scan_storage) : rank_(rank), size_(size), scan_(scan_storage) {}
  GDEL_HD int rank() const { return rank_; }
  GDEL_HD int size() const { return size_; }
  GDEL_HD void sync() const {
#if GDEL_DEVICE_PASS
    __syncthreads();
#endif
  }
  // Exclusive prefix sum of v over the team in rank order; *total gets the team's sum.
  // Collective.
  GDEL_HD std::int64_t exclusive_sum(std::int64_t v, std::int64_t* total) const {
#if GDEL_DEVICE_PASS
    std::int64_t r = 0;
    detail::TeamScan(*static_cast<typename detail::TeamScan::TempStorage*>(scan_)).ExclusiveSum(v, r, *total);
    __syncthreads();  // the scan's storage is reused by the next one
    return r;
#else
    *total = v;
    return 0;
#endif
  }

 private:
  int rank_;
  int size_;
  void* scan_;
};

// The team's threads on backend B (the scratch a body needs per thread is sized by it).
template <class B>
constexpr int team_size() {
  return B::is_device ? kTeamThreads : 1;
}

// Indices i in [0, n) with pred(i), ascending, to out; returns the count (to every
// thread). Collective; the list is visible to every thread on return.
template <class Pred>
GDEL_HD std::int64_t team_select(const Team& tm, std::int64_t n, std::int32_t* out, Pred pred) {
  std::int64_t base = 0;
  for (std::int64_t i0 = 0; i0 < n; i0 += tm.size()) {
    const std::int64_t i = i0 + tm.rank();
    const bool keep = i < n && pred(i);
    std::int64_t total = 0;
    const std::int64_t at = tm.exclusive_sum(keep ? 1 : 0, &total);
    if (keep) out[base + at] = static_cast<std::int32_t>(i);
    base += total;
  }
  tm.sync();  // (the last chunk's writes came after the last sum's barrier)
  return base;
}

// Distinct keys in[0, k) to out[0, k) in ascending order (in and out apart). Collective;
// out is visible to every thread on return. On the device each key is written at its
// rank, counted against all k keys: k^2 / size() comparisons per thread, all threads
// reading the same key at once (for the lists one team handles: a few thousand keys).
template <class T>
GDEL_HD void team_sort_distinct(const Team& tm, const T* in, std::int64_t k, T* out) {
#if GDEL_DEVICE_PASS
  for (std::int64_t j = tm.rank(); j < k; j += tm.size()) {
    const T x = in[j];
    std::int64_t r = 0;
    for (std::int64_t i = 0; i < k; ++i) r += in[i] < x ? 1 : 0;
    out[r] = x;
  }
  tm.sync();
#else
  (void)tm;
  std::copy(in, in + k, out);
  std::sort(out, out + k);
#endif
}

// Runs body(team) once per thread of one team. Does not wait for the host.
template <class F>
void team_run(Context<Cpu>&, F body) {
  body(Team(0, 1, nullptr));
}

#if defined(__CUDACC__)
namespace detail {
template <class F>
__global__ void __launch_bounds__(kTeamThreads) team_kernel(F body) {
  __shared__ typename TeamScan::TempStorage scan;
  body(Team(static_cast<int>(threadIdx.x), kTeamThreads, &scan));
}
}  // namespace detail

template <class F>
void team_run(Context<Cuda>& c, F body) {
  detail::team_kernel<<<1, kTeamThreads, 0, c.stream()>>>(body);
  GDEL_CUDA_CHECK_LAUNCH("team_run");
}
#endif

}  // namespace gdel::par
