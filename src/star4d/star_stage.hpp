// gStar4D stages 3-5 (ALGORITHMS.md §5.4-5.6) over the star splaying engine: from a
// working set per point (any candidate neighbour lists, e.g. from the digital Voronoi
// diagram, stage 2) to the exact Delaunay triangulation.
//
//   3. initial stars: every point's star built by beneath-beyond insertion of its
//      working set (Splayer::build_stars, nearest first), one thread per star;
//   4. splaying rounds until no new pair appears (Splayer::run: reciprocating requests
//      from every new link triangle, a history of tried pairs, confinement proofs for
//      drowned and submerged points);
//   5. tets: each lower-hull tet once, from the star of its smallest vertex; upper-hull
//      and vertical (flat) tets dropped; neighbours by matching face keys (-1 on the
//      hull only).
//
// The stars are those of the whole 4-D convex hull of the lifted points, as in the
// thesis' code (its §5.7): the stars of 3-D hull vertices also carry upper-hull
// (furthest-point) tets, computed and thrown away. The issue suggests the lifted point at
// infinity ∞ in every star instead (as in gDel3D); ∞ has no star of its own, so nothing
// checks that the hull triangles around ∞ form ONE sphere, and from k-nearest-neighbour
// lists on a sphere splaying converged to an ∞-link of two spheres (a lens of 8
// co-circular hull points; Euler characteristic 3). Without ∞ the same input (and the
// same input jittered by 1e-3, so in general position) ALSO converged to stars that are
// all convex, mutually consistent, equally oriented, a closed 3-manifold (χ = 0), yet
// 1132 star facets had a point beyond them: locally convex, globally wrong. Star
// splaying's local rules cannot see that. Measured remedy: kLongRange pseudo-random
// partners per point (every such case we tried then came out right), and gStar4D
// certifies its output with the exact verifier (star4d/gstar4d.hpp) — never trusting
// convergence alone.
#pragma once

#include <cstdint>
#include <stdexcept>

#include "splay/splayer.hpp"

namespace gdel::star4d {

using par::Buffer;
using par::Context;
using splay::I64;
using splay::U64;

struct StarStageResult {
  I64 stars = 0, flat_removed = 0, exact_evaluations = 0, tets = 0;
  splay::SplayStats splay;
};

template <class B>
class StarStage {
 public:
  // g: the m distinct points (internal ids 0..m-1) and ∞ = m (its kernel point set).
  StarStage(Context<B>& ctx, flip::Geo g, I64 m) : ctx_(ctx), g_(g), m_(m), sp_(ctx, g, static_cast<vid_t>(m + 1)) {}

  // Pseudo-random long-range partners added to every working set. Why: from purely
  // local lists (k nearest neighbours) on a sphere, splaying converged to stars that were
  // all convex and mutually consistent but not the hull (a small "lens" of 8 co-circular
  // hull points closed on itself; Euler characteristic 3; tests/common/star_stage_cases.hpp
  // keeps that input). Two random partners per point broke every such case we tried;
  // they cost two insertions per star. The result is certified anyway (gstar4d.hpp).
  static constexpr int kLongRange = 2;

  splay::Splayer<B>& splayer() { return sp_; }
  const StarStageResult& result() const { return res_; }

  // Stages 3 and 4. offsets (m + 1) and cand: each point's working set (CSR, any order,
  // duplicates and self ids allowed but wasteful); every point needs >= 3 candidates.
  void splay(const I64* offsets, const vid_t* cand) {
    const I64 m = m_;
    // pairs (v, x) for the candidates; sorted, unique, no self pairs
    I64 nc = 0, first = 0;
    par::detail::Memory<B>::to_host(ctx_, &nc, offsets + m, sizeof(I64));
    par::detail::Memory<B>::to_host(ctx_, &first, offsets, sizeof(I64));
    nc -= first;
    // plus kLongRange pseudo-random partners per point (a fixed hash: deterministic)
    Buffer<U64, B> lk(ctx_, static_cast<std::size_t>(nc + kLongRange * m));
    U64* kp = lk.data();
    par::parallel_for(ctx_, m, [=] GDEL_HD(I64 v) {
      const I64 a = offsets[v], b = offsets[v + 1], base = a - offsets[0];
      for (I64 i = a; i < b; ++i) {
        const vid_t x = cand[i];
        kp[base + (i - a)] = x == static_cast<vid_t>(v) ? ~U64(0) : splay::pair_key(static_cast<vid_t>(v), x);
      }
      for (int r = 0; r < kLongRange; ++r) {
        U64 h = static_cast<U64>(v) * 0x9E3779B97F4A7C15ull + static_cast<U64>(r + 1) * 0xD1B54A32D192ED03ull;
        h ^= h >> 31;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 29;
        const vid_t x = static_cast<vid_t>(h % static_cast<U64>(m));
        kp[nc + kLongRange * v + r] = x == static_cast<vid_t>(v) ? ~U64(0) : splay::pair_key(static_cast<vid_t>(v), x);
      }
    });
    par::sort_keys(ctx_, kp, lk.size());
    lk.resize(par::unique(ctx_, kp, lk.size()));
    if (lk.size() > 0 && lk.get(lk.size() - 1) == ~U64(0)) lk.resize(lk.size() - 1);  // self pairs
    sp_.set_source([](const Buffer<vid_t, B>&) {
      // every point has a star from the start: a request for a missing star is a bug
      throw std::logic_error("gstar4d: splaying asked for a star that was never built");
    });
    Buffer<U64, B> gone(ctx_);
    sp_.build_stars(lk, gone);
    res_.stars = m;
    Buffer<U64, B> req(ctx_);
    sp_.proofs(gone, req);
    sp_.checks(req);
    sp_.run(req);
    res_.splay = sp_.stats();
  }

  // Stage 5: lower-hull tets (internal ids, positive) and neighbours (-1 on the hull).
  void extract(Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr) {
    Buffer<I64, B> num(ctx_);
    const I64 n = sp_.plan_star_tets(num, res_.flat_removed, res_.exact_evaluations, /*upper_allowed=*/true);
    tets.resize(static_cast<std::size_t>(4 * n));
    nbr.resize(static_cast<std::size_t>(4 * n));
    sp_.write_star_tets(num, tets.data(), nbr.data(), 0);
    sp_.match_faces(tets, nbr, n);
    res_.tets = n;
  }

 private:
  Context<B>& ctx_;
  flip::Geo g_;
  I64 m_;
  splay::Splayer<B> sp_;
  StarStageResult res_;
};

}  // namespace gdel::star4d
