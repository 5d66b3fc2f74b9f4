// CUDA instantiation of the exact verifier.
#include <algorithm>

#include "core/backend_select.hpp"
#include "verify/verify_impl.hpp"

namespace gdel::cuda_backend {
VerifyReport verify(const double* xyz, std::int64_t n, const std::int32_t* tets, std::int64_t m, const double* w,
                    std::int64_t chunk_items) {
  par::Context<par::Cuda> ctx;
  if (chunk_items <= 0) {
    // Chunks sized from the free device memory left after the uploads (points,
    // weights, tets, one sign byte per tet): a facet chunk needs about 40 bytes per
    // item (ids, keys, the radix sort's second buffers, kinds, selections).
    const std::size_t free_b = ctx.free_bytes();
    const std::int64_t uploads = (w ? 32 : 24) * n + 17 * m;
    const std::int64_t left = static_cast<std::int64_t>(free_b) - uploads;
    chunk_items = std::max<std::int64_t>(std::int64_t(1) << 22, left / 64);
  }
  return verify_detail::run(ctx, xyz, n, tets, m, w, chunk_items);
}
}  // namespace gdel::cuda_backend
