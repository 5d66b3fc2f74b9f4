#include <algorithm>
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

std::size_t estimated_device_bytes(std::int64_t n, Algorithm algorithm, bool weighted) {
  const double np = static_cast<double>(std::max<std::int64_t>(n, 0));
  if (weighted || algorithm == Algorithm::gstar4d) return (std::size_t(64) << 20) + static_cast<std::size_t>(5400.0 * np);
  // gflip3d / gdel3d: 450 bytes per point (the mesh at about 7.2 tet slots per point, 33
  // bytes each, the points and their work arrays, the output) plus the largest flip
  // iteration's temporaries, 160 bytes per flip for up to 1.2n flips, at most 2^24 of them
  // per iteration (FlipConfig::max_flips_per_iteration). An envelope of the peaks measured
  // on uniform input (bench/RESULTS.md, session 61): 601, 520 and 454 bytes per point at
  // 10^6, 10^7 and 10^8 against an estimate of 709, 649 and 478 (470 bytes per point
  // before the tets' face bytes went, session 61).
  const double flips = std::min(1.2 * np, 16777216.0);
  return (std::size_t(64) << 20) + static_cast<std::size_t>(450.0 * np + 160.0 * flips);
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
