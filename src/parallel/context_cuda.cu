// The CUDA context: device selection, one stream, device properties.
#include "parallel/backend.hpp"
#include "parallel/check.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace gdel::par {

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
    cudaMemPoolProps props{};
    props.allocType = cudaMemAllocationTypePinned;
    props.handleTypes = cudaMemHandleTypeNone;
    props.location.type = cudaMemLocationTypeDevice;
    props.location.id = device_;
    cudaError_t e = cudaMemPoolCreate(&pool_, &props);
    if (e != cudaSuccess) {
      cudaStreamDestroy(stream_);
      stream_ = nullptr;
      GDEL_CUDA_CHECK(e);
    }
    std::uint64_t keep = ~std::uint64_t(0);  // keep everything freed until the context ends
    GDEL_CUDA_CHECK(cudaMemPoolSetAttribute(pool_, cudaMemPoolAttrReleaseThreshold, &keep));
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
  if (pool_) cudaMemPoolDestroy(pool_);
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
  std::uint64_t reserved = 0, used = 0;
  GDEL_CUDA_CHECK(cudaMemPoolGetAttribute(pool_, cudaMemPoolAttrReservedMemCurrent, &reserved));
  GDEL_CUDA_CHECK(cudaMemPoolGetAttribute(pool_, cudaMemPoolAttrUsedMemCurrent, &used));
  return free_b + static_cast<std::size_t>(reserved > used ? reserved - used : 0);
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
