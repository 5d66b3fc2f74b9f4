// The CUDA context: device selection, one stream, device properties.
#include "parallel/backend.hpp"
#include "parallel/check.hpp"

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
  if (prof_on_) profile_start();
}

Context<Cuda>::~Context() {
  if (stream_) {
    cudaStreamSynchronize(stream_);
    cudaStreamDestroy(stream_);
  }
  for (cudaEvent_t e : prof_events_) cudaEventDestroy(e);
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
