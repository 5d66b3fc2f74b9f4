#include <cuda_runtime.h>

#include "core/backend_select.hpp"

namespace gdel::cuda_backend {
bool device_available() {
  int count = 0;
  cudaError_t e = cudaGetDeviceCount(&count);
  if (e != cudaSuccess) {
    cudaGetLastError();
    return false;
  }
  return count > 0;
}
}  // namespace gdel::cuda_backend
