#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "gdel/options.hpp"
#include "core/backend_select.hpp"

namespace gdel {

const char* to_string(Backend b) {
  switch (b) {
    case Backend::Auto: return "auto";
    case Backend::Cpu: return "cpu";
    case Backend::Cuda: return "cuda";
  }
  return "?";
}

const char* to_string(Initial i) {
  switch (i) {
    case Initial::Default: return "default";
    case Initial::grid: return "grid";
  }
  return "?";
}

bool cuda_device_available() {
#if defined(GDEL_HAVE_CUDA)
  return cuda_backend::device_available();
#else
  return false;
#endif
}

Backend resolve_backend(Backend requested) {
  if (requested == Backend::Cpu) return Backend::Cpu;
  bool have = cuda_device_available();
  if (requested == Backend::Cuda && !have)
    throw BackendUnavailable(
#if defined(GDEL_HAVE_CUDA)
        "the CUDA backend was requested but no CUDA device is visible"
#else
        "the CUDA backend was requested but this build of gdel has no CUDA support (rebuild with the cuda preset)"
#endif
    );
  return have ? Backend::Cuda : Backend::Cpu;
}

}  // namespace gdel
