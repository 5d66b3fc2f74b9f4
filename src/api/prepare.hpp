// The preparation every entry point shares, on one backend: exact duplicates merged,
// bounding box, internal (Hilbert) order of the distinct points, SoS indices. Written
// once over the backend tag.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "gdel/errors.hpp"
#include "mesh/conventions.hpp"
#include "parallel/primitives.hpp"
#include "sort/point_sort.hpp"

namespace gdel::api {

template <class B>
struct Prepared {
  explicit Prepared(par::Context<B>& ctx) : rep(ctx), P(ctx), sid(ctx), W(ctx) {}
  std::int64_t n = 0, m = 0;  // input points, distinct points
  par::Buffer<std::int64_t, B> rep;  // n: the input id that represents each input point
  par::Buffer<double, B> P;          // 3 (m + 1): distinct points in internal order; slot m: ∞'s kernel point
  par::Buffer<std::int64_t, B> sid;  // m + 1: input id of each internal id (SoS index); slot m: n
  par::Buffer<double, B> W;          // m + 1 weights in internal order (weighted input only; slot m: 0)
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // bounding box of the distinct points
};

// xp: 3n coordinates on the backend; wp: n weights on the backend or nullptr. With
// weights the representative of equal points is the heaviest (sort::distinct_hilbert_order).
// Throws DegenerateInput with fewer than 4 distinct points.
template <class B>
void prepare_points(par::Context<B>& ctx, const double* xp, std::int64_t n, const double* wp, Prepared<B>& pr) {
  using I64 = std::int64_t;
  pr.n = n;
  // bounding box of the points (the same as the distinct points')
  {
    par::Buffer<double, B> coord(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    double* cp = coord.data();
    for (int a = 0; a < 3; ++a) {
      par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 k) { cp[k] = xp[3 * k + a]; });
      pr.lo[a] = par::reduce_min(ctx, cp, static_cast<std::size_t>(n), HUGE_VAL);
      pr.hi[a] = par::reduce_max(ctx, cp, static_cast<std::size_t>(n), -HUGE_VAL);
    }
  }
  pr.rep.resize(static_cast<std::size_t>(std::max<I64>(n, 1)));
  par::Buffer<I64, B> ids(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));  // distinct points (input ids), Hilbert order
  I64* idp = ids.data();
  const I64 m = sort::distinct_hilbert_order(ctx, xp, n, pr.lo, pr.hi, pr.rep.data(), idp, wp);
  pr.m = m;
  if (m < 4) throw DegenerateInput("need at least 4 distinct points, got " + std::to_string(m));
  pr.P.resize(static_cast<std::size_t>(3 * (m + 1)));
  pr.sid.resize(static_cast<std::size_t>(m + 1));
  double* pp = pr.P.data();
  I64* sp = pr.sid.data();
  par::parallel_for(ctx, m, [=] GDEL_LAMBDA(I64 k) {
    for (int a = 0; a < 3; ++a) pp[3 * k + a] = xp[3 * idp[k] + a];
    sp[k] = idp[k];
  });
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(I64) { sp[m] = n; });  // ∞ perturbs least; any fixed index works
  if (wp) {
    pr.W.resize(static_cast<std::size_t>(m + 1));
    double* wq = pr.W.data();
    par::parallel_for(ctx, m + 1, [=] GDEL_LAMBDA(I64 k) { wq[k] = k < m ? wp[sp[k]] : 0.0; });
  }
}

// Vertex ids of a tet list, internal (Hilbert order) -> input ids, in place on the backend.
template <class B>
void to_input_ids(par::Context<B>& ctx, par::Buffer<vid_t, B>& tets, const par::Buffer<std::int64_t, B>& sid) {
  vid_t* tp = tets.data();
  const std::int64_t* sp = sid.data();
  par::parallel_for(ctx, static_cast<std::int64_t>(tets.size()),
                    [=] GDEL_LAMBDA(std::int64_t i) { tp[i] = static_cast<vid_t>(sp[tp[i]]); });
}

}  // namespace gdel::api
