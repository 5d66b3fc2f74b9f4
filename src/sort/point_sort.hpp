// Point-set orderings on a backend: lexicographic order (exact duplicate detection)
// and Hilbert order (spatial locality). Both are stable, so ties keep index order
// and results are deterministic.
#pragma once

#include <cstdint>
#include <cstring>

#include "parallel/primitives.hpp"
#include "sort/sfc.hpp"

namespace gdel::sort {

// Order-preserving map of a double to an unsigned key (-0 and +0 map together).
GDEL_HD inline std::uint64_t orderable(double x) {
  if (x == 0.0) x = 0.0;
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return (u >> 63) ? ~u : (u | (std::uint64_t(1) << 63));
}

// Exact coordinate equality of points a and b (xyz AoS).
GDEL_HD inline bool same_point(const double* X, std::int64_t a, std::int64_t b) {
  return X[3 * a] == X[3 * b] && X[3 * a + 1] == X[3 * b + 1] && X[3 * a + 2] == X[3 * b + 2];
}

// order[k] = index of the k-th point in lexicographic (x, y, z) order; equal points
// are consecutive and in increasing index order.
template <class B>
void lexicographic_order(par::Context<B>& ctx, const double* X, std::int64_t n, std::int64_t* order) {
  par::Buffer<std::uint64_t, B> key(ctx, static_cast<std::size_t>(n));
  std::uint64_t* kp = key.data();
  par::sequence(ctx, order, static_cast<std::size_t>(n), std::int64_t(0));
  for (int axis = 2; axis >= 0; --axis) {  // LSD passes: z, y, x (each stable)
    par::parallel_for(ctx, n, [=] GDEL_HD(std::int64_t k) { kp[k] = orderable(X[3 * order[k] + axis]); });
    par::sort_pairs(ctx, kp, order, static_cast<std::size_t>(n), 64);
  }
}

// rep[i] = smallest index of a point equal to point i (rep[i] == i for the points
// kept when duplicates are removed). Returns the number of distinct points. With
// weights W (regular triangulation), the representative is the heaviest of the equal
// points (the others are hidden by it), the smallest index among equally heavy ones.
template <class B>
std::int64_t duplicate_representatives(par::Context<B>& ctx, const double* X, std::int64_t n, std::int64_t* rep,
                                       const double* W = nullptr) {
  if (n == 0) return 0;
  par::Buffer<std::int64_t, B> order(ctx, static_cast<std::size_t>(n));
  std::int64_t* o = order.data();
  lexicographic_order(ctx, X, n, o);
  par::Buffer<std::int64_t, B> start(ctx, static_cast<std::size_t>(n));
  std::int64_t* sp = start.data();
  par::parallel_for(ctx, n, [=] GDEL_HD(std::int64_t k) {
    sp[k] = (k == 0 || !same_point(X, o[k - 1], o[k])) ? 1 : 0;
  });
  std::int64_t distinct = par::reduce_sum(ctx, sp, static_cast<std::size_t>(n));
  par::parallel_for(ctx, n, [=] GDEL_HD(std::int64_t k) {
    if (!sp[k]) return;
    std::int64_t best = o[k];
    for (std::int64_t j = k + 1; W && j < n && !sp[j]; ++j)
      if (W[o[j]] > W[best]) best = o[j];
    for (std::int64_t j = k; j < n && (j == k || !sp[j]); ++j) rep[o[j]] = best;
  });
  return distinct;
}

// order[k] = index of the k-th point along the 3-D Hilbert curve of the bounding box
// (21 bits per axis; ties keep index order).
template <class B>
void hilbert_order(par::Context<B>& ctx, const double* X, std::int64_t n, const double lo[3], const double hi[3],
                   std::int64_t* order) {
  par::Buffer<std::uint64_t, B> key(ctx, static_cast<std::size_t>(n));
  std::uint64_t* kp = key.data();
  const sfc::Quantizer q = sfc::Quantizer::from_box(lo, hi);
  par::parallel_for(ctx, n, [=] GDEL_HD(std::int64_t i) {
    kp[i] = sfc::hilbert_key(q, X[3 * i], X[3 * i + 1], X[3 * i + 2]);
    order[i] = i;
  });
  par::sort_pairs(ctx, kp, order, static_cast<std::size_t>(n), sfc::kKeyBits);
}

}  // namespace gdel::sort
