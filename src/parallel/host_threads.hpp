// Host work in a few large pieces on OpenMP's team (both backends: the splayer's huge
// stars beside a running kernel, the CPU insertion's pieces of the curve).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>

#include <omp.h>

namespace gdel::par {

// Runs job(i) for every i in [0, n), each index on one thread of OpenMP's team, handed
// out one at a time (pieces of uneven cost). threads: the team's size (0: OpenMP's
// count, so OMP_NUM_THREADS limits it, like the CPU backend's loops); never more threads
// than pieces. OpenMP's own workers, not threads of our own: those would compete with
// the team's idle workers, which spin for a while after every parallel loop (bench/
// RESULTS.md, session 16). An exception in a job stops the hand-out of further indices
// and is rethrown here once the team has joined (never std::terminate).
template <class Job>
void on_host_threads(std::size_t n, Job job, int threads = 0) {
  if (n == 0) return;
  const int asked = threads > 0 ? threads : std::max(1, omp_get_max_threads());
  const int team = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(asked)));
  std::atomic<bool> stop{false};
  std::exception_ptr err;
#pragma omp parallel for schedule(dynamic, 1) num_threads(team)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      job(static_cast<std::size_t>(i));
    } catch (...) {
      stop.store(true, std::memory_order_relaxed);
#pragma omp critical(gdel_on_host_threads)
      {
        if (!err) err = std::current_exception();
      }
    }
  }
  if (err) std::rethrow_exception(err);
}

}  // namespace gdel::par
