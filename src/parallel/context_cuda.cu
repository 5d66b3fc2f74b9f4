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
}

Context<Cuda>::~Context() {
  if (stream_) {
    cudaStreamSynchronize(stream_);
    cudaStreamDestroy(stream_);
  }
}

void Context<Cuda>::synchronize() { GDEL_CUDA_CHECK(cudaStreamSynchronize(stream_)); }

}  // namespace gdel::par
