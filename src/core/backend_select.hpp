// Internal entry points of the CUDA backend, callable from host translation units.
// Defined in *.cu files; only linked when GDEL_HAVE_CUDA.
#pragma once

#include <cstdint>

#include <span>

#include "gdel/delaunay.hpp"
#include "gdel/verify.hpp"

namespace gdel::cuda_backend {
bool device_available();
Triangulation delaunay(std::span<const double> points, const Options& options);
// chunk_items: see verify_detail::run; <= 0 sizes the chunks from free device memory.
VerifyReport verify(const double* xyz, std::int64_t n, const std::int32_t* tets, std::int64_t m, const double* w,
                    std::int64_t chunk_items);
}  // namespace gdel::cuda_backend
