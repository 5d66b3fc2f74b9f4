// The device pools that gdel::keep_device_memory shares across calls
// (include/gdel/device_memory.hpp; parallel/context_cuda.cu). CUDA builds only.
#pragma once

#include <cstddef>

namespace gdel::par {

// What the shared pool on `device` holds: bytes reserved from the driver, and of them
// the bytes in use; both 0 where that pool was never made. For tests and diagnostics.
struct PoolBytes {
  std::size_t reserved = 0, used = 0;
};
PoolBytes kept_pool_bytes(int device);

}  // namespace gdel::par
