// Before a CUDA run: the estimated need (gdel::estimated_device_bytes) against
// Options::device_memory_limit and the free device memory, so that a run that cannot fit
// fails at once (OutOfDeviceMemory, or the CPU with Options::fallback_to_cpu) rather than
// after minutes of work at some allocation. CUDA translation units only.
#pragma once

#include <cuda_runtime.h>

#include <cstdint>
#include <string>

#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "parallel/backend.hpp"
#include "parallel/check.hpp"

namespace gdel::api {

inline void device_memory_precheck(par::Context<par::Cuda>& ctx, std::int64_t n, Algorithm algorithm, bool weighted) {
  const std::size_t need = estimated_device_bytes(n, algorithm, weighted);
  const std::string head = "out of device memory: an estimated " + std::to_string(need) + " bytes are needed for " +
                           std::to_string(n) + " points (gdel::estimated_device_bytes), ";
  const std::size_t lim = ctx.memory().limit();
  if (lim != 0 && need > lim)
    throw OutOfDeviceMemory(head + "more than the limit of " + std::to_string(lim) + " (Options::device_memory_limit)",
                            need, lim);
  // free: the driver's, and what the context's pool holds unused (a pool kept across
  // calls, gdel::keep_device_memory, may hold a whole earlier run's peak)
  const std::size_t free_b = ctx.free_bytes();
  if (need > free_b) {
    std::size_t driver_free = 0, total_b = 0;
    GDEL_CUDA_CHECK(cudaMemGetInfo(&driver_free, &total_b));
    throw OutOfDeviceMemory(head + std::to_string(free_b) + " free of " + std::to_string(total_b), need, free_b);
  }
  // GDEL_POOL_PRIME=1 (a study, off by default): the pool maps the estimate in one
  // allocation, freed at once, before the run, so that the run's allocations come from
  // memory mapped in one piece instead of from the pool's growth step by step (a
  // kept pool, which skips that mapping in a later call, gained 5-19 ms at 10^7 on an
  // H100: bench/RESULTS.md, session 72). Where that allocation fails, the run goes on
  // as without it.
  if (ctx.pool() && par::knob_on("GDEL_POOL_PRIME")) {
    void* p = nullptr;
    if (cudaMallocFromPoolAsync(&p, need, ctx.pool(), ctx.stream()) == cudaSuccess) {
      GDEL_CUDA_CHECK(cudaFreeAsync(p, ctx.stream()));
    } else {
      cudaGetLastError();
    }
  }
}

}  // namespace gdel::api
