// The CUDA context: device selection, one stream, device properties.
#include "gdel/device_memory.hpp"
#include "parallel/backend.hpp"
#include "parallel/check.hpp"
#include "parallel/device_pool.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>

namespace gdel::par {

namespace {
// A pool on the device that keeps what is freed (release threshold: no limit).
cudaError_t new_pool(int device, cudaMemPool_t* pool) {
  cudaMemPoolProps props{};
  props.allocType = cudaMemAllocationTypePinned;
  props.handleTypes = cudaMemHandleTypeNone;
  props.location.type = cudaMemLocationTypeDevice;
  props.location.id = device;
  cudaError_t e = cudaMemPoolCreate(pool, &props);
  if (e != cudaSuccess) return e;
  std::uint64_t keep = ~std::uint64_t(0);  // keep everything freed until the pool ends
  e = cudaMemPoolSetAttribute(*pool, cudaMemPoolAttrReleaseThreshold, &keep);
  if (e != cudaSuccess) cudaMemPoolDestroy(*pool);
  return e;
}

// The pools shared across calls (gdel/device_memory.hpp): one per device, made when a
// context first asks for it and never destroyed; their memory is trimmed to kept_bound
// when a context on them ends, and to 0 when released (or on a failed allocation, like a
// context's own pool). kept_bound 0: every context makes a pool of its own, which keeps
// what is freed only until the context ends.
std::mutex kept_mutex;
std::map<int, cudaMemPool_t> kept_pools;
std::atomic<std::size_t> kept_bound{0};
std::once_flag kept_env_once;

// GDEL_DEVICE_POOL=keep: no bound from the start (read before the first use of the bound)
void read_kept_env() {
  std::call_once(kept_env_once, [] {
    const char* k = std::getenv("GDEL_DEVICE_POOL");
    if (k && std::strcmp(k, "keep") == 0) kept_bound.store(~std::size_t(0));
  });
}

cudaError_t kept_pool(int device, cudaMemPool_t* pool) {
  std::lock_guard<std::mutex> lock(kept_mutex);
  auto it = kept_pools.find(device);
  if (it == kept_pools.end()) {
    cudaMemPool_t p = nullptr;
    const cudaError_t e = new_pool(device, &p);
    if (e != cudaSuccess) return e;
    it = kept_pools.emplace(device, p).first;
  }
  *pool = it->second;
  return cudaSuccess;
}

// What pool p holds: reserved from the driver, and of that in use.
cudaError_t read_pool(cudaMemPool_t p, PoolBytes* b) {
  std::uint64_t reserved = 0, used = 0;
  cudaError_t e = cudaMemPoolGetAttribute(p, cudaMemPoolAttrReservedMemCurrent, &reserved);
  if (e == cudaSuccess) e = cudaMemPoolGetAttribute(p, cudaMemPoolAttrUsedMemCurrent, &used);
  b->reserved = static_cast<std::size_t>(reserved);
  b->used = static_cast<std::size_t>(used);
  return e;
}

bool is_kept(int device, cudaMemPool_t pool) {
  std::lock_guard<std::mutex> lock(kept_mutex);
  auto it = kept_pools.find(device);
  return it != kept_pools.end() && it->second == pool;
}

// Pool p down to `bytes` of reserved memory, only where it holds more (only memory no
// call is using is given back). cudaMemPoolTrimTo itself is not called with a bound at
// or above what the pool holds: called with SIZE_MAX (no bound) it emptied the pool on
// the H100 (driver 580.159.04; bench/RESULTS.md, session 73). Driver errors are dropped:
// gdel/device_memory.hpp's calls report none.
void trim_to(cudaMemPool_t p, std::size_t bytes) {
  PoolBytes b;
  if (read_pool(p, &b) == cudaSuccess && b.reserved > bytes) cudaMemPoolTrimTo(p, bytes);
  cudaGetLastError();
}

// Every shared pool down to `bytes` (trim_to).
void trim_kept(std::size_t bytes) {
  std::lock_guard<std::mutex> lock(kept_mutex);
  for (const auto& dp : kept_pools) trim_to(dp.second, bytes);
}
}  // namespace

Context<Cuda>::Context(int device) : device_(device) {
  int count = 0;
  cudaError_t e = cudaGetDeviceCount(&count);
  if (e != cudaSuccess || count <= device) {
    cudaGetLastError();
    throw BackendUnavailable("no CUDA device " + std::to_string(device) + " (found " + std::to_string(count) + ")");
  }
  GDEL_CUDA_CHECK(cudaSetDevice(device_));
  GDEL_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
  GDEL_CUDA_CHECK(cudaDeviceGetAttribute(&sm_count_, cudaDevAttrMultiProcessorCount, device_));
  const char* kind = std::getenv("GDEL_DEVICE_POOL");
  if (!(kind && std::strcmp(kind, "default") == 0)) {
    read_kept_env();
    const cudaError_t e = kept_bound.load() > 0 ? kept_pool(device_, &pool_) : new_pool(device_, &pool_);
    if (e != cudaSuccess) {
      cudaStreamDestroy(stream_);
      stream_ = nullptr;
      GDEL_CUDA_CHECK(e);
    }
  }
  if (prof_on_) profile_start();
}

Context<Cuda>::~Context() {
  if (stream_) {
    cudaStreamSynchronize(stream_);
    cudaStreamDestroy(stream_);
  }
  // Allocations still outstanding (none, when every Buffer died first) would keep the
  // pool's memory until they are freed; the driver destroys the pool then.
  // A shared pool keeps up to the bound of what is free in it now.
  if (pool_) {
    if (is_kept(device_, pool_)) trim_to(pool_, kept_bound.load());
    else cudaMemPoolDestroy(pool_);
  }
  for (cudaEvent_t e : prof_events_) cudaEventDestroy(e);
}

void Context<Cuda>::trim_pool() {
  GDEL_CUDA_CHECK(cudaStreamSynchronize(stream_));
  if (pool_) GDEL_CUDA_CHECK(cudaMemPoolTrimTo(pool_, 0));
}

std::size_t Context<Cuda>::free_bytes() {
  std::size_t free_b = 0, total_b = 0;
  GDEL_CUDA_CHECK(cudaMemGetInfo(&free_b, &total_b));
  if (!pool_) return free_b;
  PoolBytes b;
  GDEL_CUDA_CHECK(read_pool(pool_, &b));
  return free_b + (b.reserved > b.used ? b.reserved - b.used : 0);
}

PoolBytes kept_pool_bytes(int device) {
  std::lock_guard<std::mutex> lock(kept_mutex);
  PoolBytes b;
  auto it = kept_pools.find(device);
  if (it == kept_pools.end()) return b;
  GDEL_CUDA_CHECK(read_pool(it->second, &b));
  return b;
}

void Context<Cuda>::record_event() {
  if (prof_used_ == prof_events_.size()) {
    cudaEvent_t e;
    GDEL_CUDA_CHECK(cudaEventCreate(&e));
    prof_events_.push_back(e);
  }
  GDEL_CUDA_CHECK(cudaEventRecord(prof_events_[prof_used_++], stream_));
}

void Context<Cuda>::profile_start() {
  if (!prof_on_) return;
  prof_names_.clear();
  prof_peak_.clear();
  prof_used_ = 0;
  mem_.take_interval_peak();
  record_event();
}

ProfileTotals Context<Cuda>::profile_report() {
  if (!prof_on_ || prof_used_ == 0) return {};
  GDEL_CUDA_CHECK(cudaStreamSynchronize(stream_));
  std::vector<double> t(prof_used_, 0.0);
  for (std::size_t k = 1; k < prof_used_; ++k) {
    float ms = 0;
    GDEL_CUDA_CHECK(cudaEventElapsedTime(&ms, prof_events_[0], prof_events_[k]));
    t[k] = 1e-3 * ms;
  }
  return profile_totals(prof_names_, t, prof_peak_);
}

void Context<Cuda>::synchronize() { GDEL_CUDA_CHECK(cudaStreamSynchronize(stream_)); }

}  // namespace gdel::par

namespace gdel {

void keep_device_memory(std::size_t bytes) noexcept {
  par::read_kept_env();
  par::kept_bound.store(bytes);
  par::trim_kept(bytes);
}

void release_device_memory() noexcept { par::trim_kept(0); }

std::size_t kept_device_memory_bound() noexcept {
  par::read_kept_env();
  return par::kept_bound.load();
}

}  // namespace gdel
