// gStar4D stages 3-5 (ALGORITHMS.md §5.4-5.6) over the star splaying engine: from a
// working set per point (any candidate neighbour lists, e.g. from the digital Voronoi
// diagram, stage 2) to the exact Delaunay triangulation.
//
//   3. initial stars: every point's star built by beneath-beyond insertion of ∞ and its
//      working set (Splayer::build_stars: ∞ first, then nearest first), one thread per
//      star;
//   4. splaying rounds until no new pair appears (Splayer::run: reciprocating requests
//      from every new link triangle, a history of tried pairs, confinement proofs for
//      drowned and submerged points, proofs of ∞ handed to the stars around it), then
//      the global check of ∞'s link (below), whose failures feed new pairs back;
//   5. tets: each tet once, from the star of its smallest vertex; tets with ∞ and flat
//      tets dropped; neighbours by matching face keys (-1 on the hull only).
//
// The lifted point at infinity ∞ (vertical, above every lifted point) is a vertex of every
// star that it is not inside of: the stars are those of hull(lifted points ∪ {∞}), whose
// facets are the lower-hull tets and the cones from ∞ over the 3-D hull triangles. So no
// star ever holds an upper-hull (furthest-point) facet, every star tet is positive in 3-D,
// insertion always walks (star_insert), and the star of a 3-D hull vertex is its Delaunay
// star plus a fan around ∞ over its hull neighbours (the thesis' code builds the whole
// 4-D hull and throws the upper half away, ALGORITHMS.md §5.7).
//
// ∞ has no star of its own: its link is the 3-D hull surface, the triangles (a, b) around
// ∞ in the stars of hull vertices. Convex, mutually consistent finite stars make that
// surface closed and locally convex (every hull edge and vertex is checked inside a
// finite star), but nothing local sees that it is ONE surface: from k-nearest-neighbour
// lists on a sphere, splaying converged to an ∞-link of two pieces (a lens of 8
// co-circular hull points closed on itself; tests/common/star_stage_cases.hpp keeps that
// input). A closed, connected, locally convex surface bounds a convex body (a sphere), so
// after convergence the engine checks the Euler characteristic of ∞'s link,
//   Σ over hull stars of (6 − number of its link triangles holding ∞) = 12
// (V − E + F = 2 with E = 3F/2): one reduction. Every piece being a convex sphere, a
// larger sum means several pieces; then the pieces are labelled (connected components
// over the hull edges) and pairs joining hull vertices of different pieces (neighbours
// in the Hilbert order of the ids, i.e. nearby in space) are inserted, and splaying
// resumes, until the check passes or no untried pair is left. Without ∞ the same local
// rules also converged to stars that were convex and consistent but not the hull (several
// closed 4-D pieces); with ∞ every piece must contain ∞ (a closed piece without it would
// need upper, 3-D-negative facets, which no star with ∞ tried can hold), so the same check
// covers that case. The result is still certified by the exact verifier (api): the
// argument above needs the fixed point to be consistent, which the engine does not
// check in full.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "parallel/atomic.hpp"
#include "mesh/open_faces.hpp"
#include "splay/splayer.hpp"

namespace gdel::star4d {

using par::Buffer;
using par::Context;
using splay::I64;
using splay::U64;

struct StarStageResult {
  I64 stars = 0, flat_removed = 0, exact_evaluations = 0, tets = 0;
  // ∞-link checks that failed (each fed bridging pairs back into splaying) and the
  // pairs fed
  I64 link_repairs = 0, link_pairs = 0;
  splay::SplayStats splay;
};

template <class B>
class StarStage {
 public:
  // g: the m distinct points (internal ids 0..m-1) and ∞ = m (its kernel point set).
  StarStage(Context<B>& ctx, flip::Geo g, I64 m) : ctx_(ctx), g_(g), m_(m), sp_(ctx, g, static_cast<vid_t>(m + 1)) {}

  // Pseudo-random long-range partners added to every working set (a fixed hash of the
  // point: deterministic). Not needed for correctness (the ∞-link check is); a knob to
  // study the splaying work they save or cost (0: none, the default).
  int long_range = 0;

  splay::Splayer<B>& splayer() { return sp_; }
  const StarStageResult& result() const { return res_; }

  // Stages 3 and 4. offsets (m + 1) and cand: each point's working set (CSR, any order,
  // duplicates and self ids allowed but wasteful); every point needs >= 3 candidates.
  void splay(const I64* offsets, const vid_t* cand) {
    const I64 m = m_;
    const vid_t inf = g_.inf;
    const int lr = long_range;
    // pairs (v, x) for the candidates and (v, ∞); sorted, unique, no self pairs
    I64 nc = 0, first = 0;
    par::detail::Memory<B>::to_host(ctx_, &nc, offsets + m, sizeof(I64));
    par::detail::Memory<B>::to_host(ctx_, &first, offsets, sizeof(I64));
    nc -= first;
    Buffer<U64, B> lk(ctx_, static_cast<std::size_t>(nc + (1 + lr) * m));
    U64* kp = lk.data();
    par::parallel_for(ctx_, m, [=] GDEL_LAMBDA(I64 v) {
      const I64 a = offsets[v], b = offsets[v + 1], base = a - offsets[0];
      for (I64 i = a; i < b; ++i) {
        const vid_t x = cand[i];
        kp[base + (i - a)] = x == static_cast<vid_t>(v) ? ~U64(0) : splay::pair_key(static_cast<vid_t>(v), x);
      }
      U64* extra = kp + nc + (1 + lr) * v;
      extra[0] = splay::pair_key(static_cast<vid_t>(v), inf);
      for (int r = 0; r < lr; ++r) {
        U64 h = static_cast<U64>(v) * 0x9E3779B97F4A7C15ull + static_cast<U64>(r + 1) * 0xD1B54A32D192ED03ull;
        h ^= h >> 31;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 29;
        const vid_t x = static_cast<vid_t>(h % static_cast<U64>(m));
        extra[1 + r] = x == static_cast<vid_t>(v) ? ~U64(0) : splay::pair_key(static_cast<vid_t>(v), x);
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
    // the global check of ∞'s link; bridging pairs between its pieces until it passes
    const bool debug = std::getenv("GDEL_SPLAY_DEBUG") != nullptr;
    for (I64 reach = 4;; reach *= 2) {
      const I64 defect = infinity_link_defect();
      if (debug) std::fprintf(stderr, "gstar4d: ∞-link Euler defect %lld (reach %lld)\n", (long long)defect, (long long)reach);
      if (defect == 0) break;
      ++res_.link_repairs;
      Buffer<U64, B> bridge(ctx_);
      const I64 hull = bridge_pairs(reach, bridge);
      res_.link_pairs += static_cast<I64>(bridge.size());
      sp_.run(bridge);
      if (reach > hull) break;  // every bridge tried: left to the certificate
    }
    sp_.largest_star();
    res_.splay = sp_.stats();
    if (debug)
      std::fprintf(stderr, "gstar4d: largest star %lld triangles, critical path %lld insertions, %lld rounds\n",
                   (long long)res_.splay.largest, (long long)res_.splay.critical, (long long)res_.splay.rounds);
  }

  // Σ over live stars holding ∞ of (6 − their link triangles holding ∞), minus 12: zero
  // iff ∞'s link (the 3-D hull surface) has Euler characteristic 2.
  I64 infinity_link_defect() {
    const I64 ns = sp_.num_stars();
    const splay::StarView sv = sp_.view();
    const vid_t inf = g_.inf;
    Buffer<I64, B> d(ctx_, static_cast<std::size_t>(std::max<I64>(ns, 1)));
    I64* dp = d.data();
    par::parallel_for(ctx_, ns, [=] GDEL_LAMBDA(I64 s) {
      I64 c = 0;
      if (!sv.dead(s))
        for (std::int32_t i = 0; i < sv.count[s]; ++i) c += splay::tri_pos(sv.tri[sv.begin[s] + i], inf) >= 0 ? 1 : 0;
      dp[s] = c > 0 ? 6 - c : 0;
    });
    return par::reduce_sum(ctx_, dp, static_cast<std::size_t>(ns)) - 12;
  }

  // The pieces of ∞'s link (connected components over its edges, labelled by their
  // smallest vertex: hooking and pointer jumping until stable), and pairs joining them:
  // with the hull vertices in id order (Hilbert order: nearby ids are nearby points), at
  // every change of piece between positions b-1 and b, the pairs (h[b-1-j], h[b+j]) for
  // j < reach, both directions, where the two differ in piece. Returns the number of hull
  // vertices.
  I64 bridge_pairs(I64 reach, Buffer<U64, B>& out) {
    const I64 ns = sp_.num_stars();
    const I64 nv = m_;
    const splay::StarView sv = sp_.view();
    const vid_t inf = g_.inf;
    Buffer<vid_t, B> label(ctx_, static_cast<std::size_t>(nv));
    vid_t* lp = label.data();
    par::sequence(ctx_, lp, static_cast<std::size_t>(nv), vid_t(0));
    Buffer<std::int32_t, B> changed(ctx_, 1);
    std::int32_t* cp = changed.data();
    for (;;) {
      par::fill(ctx_, cp, std::size_t(1), std::int32_t(0));
      par::parallel_for(ctx_, ns, [=] GDEL_LAMBDA(I64 s) {
        if (sv.dead(s)) return;
        const vid_t me = sv.vert[s];
        for (std::int32_t i = 0; i < sv.count[s]; ++i) {
          const splay::Tri& t = sv.tri[sv.begin[s] + i];
          const int p = splay::tri_pos(t, inf);
          if (p < 0) continue;
          for (int q = 1; q <= 2; ++q) {
            const vid_t a = par::atomic_load(lp + me), b = par::atomic_load(lp + t.v[(p + q) % 3]);
            if (a == b) continue;
            par::atomic_min(lp + (a > b ? a : b), a > b ? b : a);  // hook the larger label
            par::atomic_or(cp, std::int32_t(1));
          }
        }
      });
      par::parallel_for(ctx_, nv, [=] GDEL_LAMBDA(I64 v) {
        vid_t r = par::atomic_load(lp + v);
        while (par::atomic_load(lp + r) != r) r = par::atomic_load(lp + r);
        par::atomic_min(lp + v, r);
      });
      std::int32_t c = 0;
      changed.copy_to_host(&c, 1);
      if (c == 0) break;
    }
    // hull vertices in id order (the stars of live hull vertices)
    Buffer<vid_t, B> hv(ctx_, static_cast<std::size_t>(std::max<I64>(ns, 1)));
    Buffer<I64, B> hs(ctx_, static_cast<std::size_t>(std::max<I64>(ns, 1)));
    I64 nh = static_cast<I64>(par::select_indices(ctx_, static_cast<std::size_t>(ns), hs.data(), [=] GDEL_LAMBDA(I64 s) {
      if (sv.dead(s)) return false;
      for (std::int32_t i = 0; i < sv.count[s]; ++i)
        if (splay::tri_pos(sv.tri[sv.begin[s] + i], inf) >= 0) return true;
      return false;
    }));
    vid_t* hp = hv.data();
    const I64* hsp = hs.data();
    par::parallel_for(ctx_, nh, [=] GDEL_LAMBDA(I64 i) { hp[i] = sv.vert[hsp[i]]; });
    par::sort_keys(ctx_, hp, static_cast<std::size_t>(nh));
    // (stars are in vertex order already for gStar4D; the sort keeps this independent of it)
    const I64 r = reach;
    out.resize(static_cast<std::size_t>(std::max<I64>(2 * r * nh, 1)));
    U64* op = out.data();
    par::parallel_for(ctx_, nh, [=] GDEL_LAMBDA(I64 b) {
      U64* o = op + 2 * r * b;
      for (I64 j = 0; j < r; ++j) {
        const bool ok = b > 0 && b - 1 - j >= 0 && b + j < nh && lp[hp[b - 1]] != lp[hp[b]] &&
                        lp[hp[b - 1 - j]] != lp[hp[b + j]];
        o[2 * j] = ok ? splay::pair_key(hp[b - 1 - j], hp[b + j]) : ~U64(0);
        o[2 * j + 1] = ok ? splay::pair_key(hp[b + j], hp[b - 1 - j]) : ~U64(0);
      }
    });
    Buffer<U64, B> packed(ctx_, out.size());
    std::size_t k = par::copy_if(ctx_, op, packed.data(), out.size(), [=] GDEL_LAMBDA(U64 key) { return key != ~U64(0); });
    packed.resize(k);
    out = std::move(packed);
    return nh;
  }

  // Stage 5: tets (internal ids, positive) and neighbours (-1 on the hull).
  void extract(Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr) {
    Buffer<I64, B> num(ctx_);
    const I64 n = sp_.plan_star_tets(num, res_.flat_removed, res_.exact_evaluations);
    tets.resize(static_cast<std::size_t>(4 * n));
    nbr.resize(static_cast<std::size_t>(4 * n));
    sp_.write_star_tets(num, tets.data(), nbr.data(), 0);
    mesh::match_open_faces(ctx_, tets.data(), nbr.data(), n);
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
