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

// Sorts the point indices idx[0..n) stably into lexicographic (x, y, z) order: equal
// points end up consecutive, in their order in idx.
template <class B>
void lexicographic_sort(par::Context<B>& ctx, const double* X, std::int64_t* idx, std::int64_t n) {
  par::Buffer<std::uint64_t, B> key(ctx, static_cast<std::size_t>(n));
  std::uint64_t* kp = key.data();
  for (int axis = 2; axis >= 0; --axis) {  // LSD passes: z, y, x (each stable)
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(std::int64_t k) { kp[k] = orderable(X[3 * idx[k] + axis]); });
    par::sort_pairs(ctx, kp, idx, static_cast<std::size_t>(n), 64);
  }
}

// order[k] = index of the k-th point in lexicographic (x, y, z) order; equal points
// are consecutive and in increasing index order.
template <class B>
void lexicographic_order(par::Context<B>& ctx, const double* X, std::int64_t n, std::int64_t* order) {
  par::sequence(ctx, order, static_cast<std::size_t>(n), std::int64_t(0));
  lexicographic_sort(ctx, X, order, n);
}

// order[k] = index of the k-th point along the 3-D Hilbert curve of the bounding box
// (21 bits per axis; ties keep index order). keys (n, optional): the sorted keys.
template <class B>
void hilbert_order(par::Context<B>& ctx, const double* X, std::int64_t n, const double lo[3], const double hi[3],
                   std::int64_t* order, std::uint64_t* keys = nullptr) {
  par::Buffer<std::uint64_t, B> key(ctx, keys ? 0 : static_cast<std::size_t>(n));
  std::uint64_t* kp = keys ? keys : key.data();
  const sfc::Quantizer q = sfc::Quantizer::from_box(lo, hi);
  par::parallel_for(ctx, n, [=] GDEL_LAMBDA(std::int64_t i) {
    kp[i] = sfc::hilbert_key(q, X[3 * i], X[3 * i + 1], X[3 * i + 2]);
    order[i] = i;
  });
  par::sort_pairs(ctx, kp, order, static_cast<std::size_t>(n), sfc::kKeyBits);
}

// The distinct points in Hilbert order, from one sort. Equal points have equal Hilbert
// keys, so only the points in runs of equal keys (none in most inputs) are compared: they
// are re-sorted by (key, x, y, z), stably, so that equal points are consecutive and in
// index order. Outputs:
//   rep[i]     the input id that represents point i: the smallest index of the points
//              equal to it, or with weights W (regular triangulation) the heaviest of them
//              (the others are hidden by it; the smallest index among equally heavy ones);
//   order[k]   k < m: the representative of the k-th distinct point along the curve of the
//              box [lo, hi] (which must hold every point).
// Returns m, the number of distinct points. Ties of the key between distinct points are
// in lexicographic order.
template <class B>
std::int64_t distinct_hilbert_order(par::Context<B>& ctx, const double* X, std::int64_t n, const double lo[3],
                                    const double hi[3], std::int64_t* rep, std::int64_t* order,
                                    const double* W = nullptr) {
  using I64 = std::int64_t;
  if (n == 0) return 0;
  par::Buffer<std::uint64_t, B> key(ctx, static_cast<std::size_t>(n));
  par::Buffer<I64, B> ord(ctx, static_cast<std::size_t>(n));
  std::uint64_t* kp = key.data();
  I64* op = ord.data();
  hilbert_order(ctx, X, n, lo, hi, op, kp);
  const sfc::Quantizer q = sfc::Quantizer::from_box(lo, hi);
  auto tied = [=] GDEL_LAMBDA(I64 k) { return (k > 0 && kp[k - 1] == kp[k]) || (k + 1 < n && kp[k + 1] == kp[k]); };
  const I64 nt = par::count_indices(ctx, static_cast<std::size_t>(n), tied);
  if (nt > 0) {
    par::Buffer<I64, B> pos(ctx, static_cast<std::size_t>(nt));
    par::Buffer<I64, B> sub(ctx, static_cast<std::size_t>(nt));
    par::Buffer<std::uint64_t, B> k2(ctx, static_cast<std::size_t>(nt));
    I64* pp = pos.data();
    I64* sp = sub.data();
    std::uint64_t* k2p = k2.data();
    par::select_indices(ctx, static_cast<std::size_t>(n), pp, tied);
    par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(I64 j) { sp[j] = op[pp[j]]; });
    // stable passes: the coordinates, then the key (the runs, in their order)
    lexicographic_sort(ctx, X, sp, nt);
    par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(I64 j) {
      k2p[j] = sfc::hilbert_key(q, X[3 * sp[j]], X[3 * sp[j] + 1], X[3 * sp[j] + 2]);
    });
    par::sort_pairs(ctx, k2p, sp, static_cast<std::size_t>(nt), sfc::kKeyBits);
    par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(I64 j) { op[pp[j]] = sp[j]; });  // the runs, re-sorted in place
  }
  key.release();
  // groups of equal points: st[k + 1] != st[k] at a group's first, st[k] its number
  par::Buffer<I64, B> start(ctx, static_cast<std::size_t>(n + 1));
  I64* st = start.data();
  par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 k) { st[k] = (k == 0 || !same_point(X, op[k - 1], op[k])) ? 1 : 0; });
  const I64 m = par::counts_to_offsets(ctx, st, static_cast<std::size_t>(n));
  par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 k) {
    if (st[k + 1] == st[k]) return;
    I64 best = op[k];
    for (I64 j = k + 1; W && j < n && st[j + 1] == st[j]; ++j)
      if (W[op[j]] > W[best]) best = op[j];
    for (I64 j = k; j < n && (j == k || st[j + 1] == st[j]); ++j) rep[op[j]] = best;
    order[st[k]] = best;
  });
  return m;
}

}  // namespace gdel::sort
