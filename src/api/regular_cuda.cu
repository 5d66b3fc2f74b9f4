// CUDA instantiation of gdel::regular (gReg3D).
#include "api/device_precheck.hpp"
#include "api/regular_impl.hpp"

namespace gdel::cuda_backend {
api::RegularRun regular(std::span<const double> points, std::span<const double> weights, const Options& options) {
  par::Context<par::Cuda> ctx(options.device);
  ctx.memory().set_limit(options.device_memory_limit);
  api::device_memory_precheck(ctx, static_cast<std::int64_t>(points.size() / 3), options.algorithm, true);
  return api::regular_on(ctx, points, weights, options);
}
}  // namespace gdel::cuda_backend
