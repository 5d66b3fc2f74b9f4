// CUDA instantiation of gdel::delaunay.
#include "api/delaunay_impl.hpp"
#include "core/backend_select.hpp"

namespace gdel::cuda_backend {
Triangulation delaunay(std::span<const double> points, const Options& options) {
  par::Context<par::Cuda> ctx(options.device);
  return api::delaunay_on(ctx, points, options);
}
}  // namespace gdel::cuda_backend
