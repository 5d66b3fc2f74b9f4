// Device memory kept between calls (CUDA backend).
//
// By default every call on a GPU (gdel::delaunay, delaunay_device, regular, verify) takes
// the device memory it needs from a memory pool of its own and returns all of it when it
// ends, so nothing stays allocated between calls. Mapping that memory afresh costs time
// at every call (uniform 10^7 points on an H100: 3-19 ms of 0.43-0.45 s, bench/RESULTS.md,
// sessions 72 and 74), as it does in any program that frees its GPU memory after each use.
//
// keep_device_memory(bytes), bytes > 0: from then on the calls on a device share one pool
// per device, which after each call keeps up to `bytes` of the memory the calls freed
// (more while calls are running: a call's own peak is never trimmed under it), so that a
// later call finds that memory already mapped. The kept memory is free to gdel's calls
// only: other users of the device (PyTorch, CuPy, another process) see it as taken, as
// they see the caches of PyTorch's and CuPy's allocators. Results handed to the caller
// (DeviceTriangulation's arrays) never come from the pool.
// keep_device_memory(0), the default: no pool is shared, and what the shared pools keep is
// given back to the device at once.
// release_device_memory(): gives back what the shared pools keep now; the setting stays.
//
// The environment variable GDEL_DEVICE_POOL=keep starts a process with no bound (as
// keep_device_memory(SIZE_MAX)); a call to keep_device_memory() overrides it.
// Process-wide and thread-safe; a call running in another thread keeps what it uses.
// In a build without CUDA the setting is only recorded (kept_device_memory_bound()
// returns it) and release_device_memory() does nothing. Errors of the driver are not
// reported.
#pragma once

#include <cstddef>

namespace gdel {

void keep_device_memory(std::size_t bytes) noexcept;
void release_device_memory() noexcept;
// The current setting (bytes; 0: none kept).
std::size_t kept_device_memory_bound() noexcept;

}  // namespace gdel
