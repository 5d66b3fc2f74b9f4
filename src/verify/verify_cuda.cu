// CUDA instantiation of the exact verifier.
#include "core/backend_select.hpp"
#include "verify/verify_impl.hpp"

namespace gdel::cuda_backend {
VerifyReport verify(const double* xyz, std::int64_t n, const std::int32_t* tets, std::int64_t m, const double* w) {
  par::Context<par::Cuda> ctx;
  return verify_detail::run(ctx, xyz, n, tets, m, w);
}
}  // namespace gdel::cuda_backend
