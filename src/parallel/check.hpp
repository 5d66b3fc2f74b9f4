// CUDA error checking: every runtime call and every launch goes through these.
#pragma once

#if defined(__CUDACC__)
#include <cuda_runtime.h>

#include <string>

#include "gdel/errors.hpp"

namespace gdel::par::detail {
[[noreturn]] inline void throw_cuda(cudaError_t e, const char* what, const char* file, int line) {
  cudaGetLastError();  // clear a sticky-free error so the context stays usable
  throw CudaError(std::string("CUDA error '") + cudaGetErrorString(e) + "' in " + what + " at " + file + ":" +
                  std::to_string(line));
}
}  // namespace gdel::par::detail

#define GDEL_CUDA_CHECK(expr)                                                          \
  do {                                                                                 \
    cudaError_t gdel_err_ = (expr);                                                    \
    if (gdel_err_ != cudaSuccess) ::gdel::par::detail::throw_cuda(gdel_err_, #expr, __FILE__, __LINE__); \
  } while (0)

// After a kernel launch: catches launch-configuration errors without synchronising.
#define GDEL_CUDA_CHECK_LAUNCH(name) GDEL_CUDA_CHECK(cudaGetLastError())
#endif
