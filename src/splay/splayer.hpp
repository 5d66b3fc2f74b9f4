// The star splaying engine (ALGORITHMS.md §4.4, §4.8, §5.5), written once over the
// backend tag B: stars in one flat growable layout, and the bulk splaying rounds
//
//   requests (target star ← vertex)  →  sort + unique  →  drop those already tried
//   (history) or present  →  insert by beneath-beyond, one thread per star  →
//   drowned / submerged pairs  →  confinement proofs  →  new requests from proofs and
//   from every link triangle created since the last round (each tet sabc of star s
//   asks stars a, b, c for the other three vertices)
//
// until a round produces no new request. Inserting v into star s is attempted at most
// once (a star's cone only grows, so a drowned or submerged vertex stays inside).
// Stars that a request targets but that do not exist yet are obtained from a Source
// (gDel3D: from the triangulation T; they are convex there). ∞ never gets a star; a
// proof that ∞ is inside the star of s is handed to every star holding a link
// triangle with both s and ∞ (the stars that make up "∞'s star").
// Weighted points (Geo::w, gReg3D, ALGORITHMS.md §6): a star dies when a point is
// beyond all its facets (its point is redundant); its death certificate (5 points whose
// lifted simplex holds it, certify_deaths) is sent to every live star whose link holds
// the dead point, which removes it there; dead stars take no requests and emit no tets.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <cstdint>
#include <stdexcept>
#include <atomic>
#include <exception>
#include <vector>

#include <omp.h>

#include "parallel/atomic.hpp"
#include "parallel/exact_batch.hpp"
#include "parallel/host_threads.hpp"
#include "parallel/primitives.hpp"
#include "splay/flipflop.hpp"
#include "splay/star.hpp"

namespace gdel::splay {

using par::Buffer;
using par::Context;
using I64 = std::int64_t;
using U64 = std::uint64_t;

GDEL_HD inline U64 pair_key(vid_t target, vid_t v) {
  return (static_cast<U64>(static_cast<std::uint32_t>(target)) << 32) | static_cast<std::uint32_t>(v);
}
GDEL_HD inline vid_t key_target(U64 k) { return static_cast<vid_t>(k >> 32); }
GDEL_HD inline vid_t key_vertex(U64 k) { return static_cast<vid_t>(k & 0xffffffffu); }

// The index of k in the sorted keys a[0, n), or -1.
GDEL_HD inline I64 sorted_find(const U64* a, I64 n, U64 k) {
  I64 lo = 0, hi = n;
  while (lo < hi) {
    const I64 mid = (lo + hi) / 2;
    if (a[mid] < k) lo = mid + 1;
    else hi = mid;
  }
  return lo < n && a[lo] == k ? lo : -1;
}
GDEL_HD inline bool sorted_contains(const U64* a, I64 n, U64 k) { return sorted_find(a, n, k) >= 0; }

// The group of item i (0 <= i < heads[k]) for the heads of k groups (heads[0] = 0, non-
// decreasing, heads[k] the items' count): the j < k with heads[j] <= i < heads[j + 1].
// For kernels over the items of all groups at once (one thread per item, not per group).
GDEL_HD inline I64 group_of(const I64* heads, I64 k, I64 i) {
  I64 lo = 0, hi = k - 1;
  while (lo < hi) {
    const I64 mid = lo + (hi - lo + 1) / 2;
    if (heads[mid] <= i) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

// Inserts q into the star of s (star_insert) and records in out[k, kend) the pair
// (s, x) of every vertex x that left the star, and (s, q) if q drowned. Running out of
// room or a broken star sets *err. Returns star_insert's result (kStarDead: weighted
// points only; the caller marks the star dead and stops inserting into it).
template <class Work>
GDEL_HD int insert_recording(const flip::Geo& g, Tri* T, std::uint8_t* S, std::int32_t& count,
                                     std::int32_t cap, vid_t s, vid_t q, Work work, U64* out, I64& k, I64 kend,
                                     std::int32_t* err, std::int32_t* nonpos = nullptr) {
  auto record = [&](vid_t x) {
    if (k < kend) out[k++] = pair_key(s, x);
    else *err = 3;
  };
  const int r = star_insert(g, T, S, count, cap, s, q, work, record, 0, nonpos);
  if (r == kDrowned) record(q);
  else if (r != kInserted && r != kStarDead) *err = r == kStarFull ? 2 : 1;
  return r;
}

// One star of Splayer::build_stars: the 4-simplex of the first four points of ov, then
// beneath-beyond insertion of the others (∞ first, nearest first), gone pairs recorded in
// gp[*gk, gend). Host and device (the CUDA backend builds huge stars on the host).
template <class Work>
GDEL_HD void build_one_star(const flip::Geo& g, Tri* T, std::uint8_t* S, std::int32_t cap, vid_t me,
                            const vid_t* ov, I64 len, Work work, U64* gp, I64& gk, I64 gend,
                            std::int32_t* err, vid_t* killer, std::int32_t* count_out) {
  if (len < 4) {
    *err = 7;
    return;
  }
  star_simplex(g, T, S, me, ov, kTriNew, work);
  std::int32_t count = 4;
  std::int32_t nonpos = 0;
  for (int q = 0; q < 4; ++q) nonpos += (S[q] & kTriNonPositive) ? 1 : 0;
  for (I64 i = 4; i < len; ++i)
    if (insert_recording(g, T, S, count, cap, me, ov[i], work, gp, gk, gend, err, &nonpos) == kStarDead) {
      *killer = ov[i];
      break;
    }
  *count_out = count;
}

// A star's working set as its group of sorted pair keys (me << 32 | x): the index of a
// vertex by binary search, and back (star_flipflop's WorkingSet).
struct KeyedSet {
  const U64* k;
  std::int32_t n;
  vid_t me;
  GDEL_HD std::int32_t operator()(vid_t x) const {
    return static_cast<std::int32_t>(sorted_find(k, n, pair_key(me, x)));
  }
  GDEL_HD vid_t vertex(std::int32_t i) const { return key_vertex(k[i]); }
};

// One star of Splayer::build_stars when a seed star is given (gDel3D: the star of the
// failed vertex as it is in T, `seeded` triangles, or -1): Flip-Flop convexification
// (flipflop.hpp); if that gives up, the seed is discarded and the star is built by
// build_one_star. keys: the working set as sorted pair keys; ov: the same vertices in
// build order. Returns 1 if Flip-Flop made the star, 0 if it was rebuilt.
template <class Work>
GDEL_HD int seeded_build(const flip::Geo& g, Tri* T, std::uint8_t* S, std::int32_t cap, vid_t me,
                         const U64* keys, const vid_t* ov, I64 len, std::int32_t seeded, Work work, U64* gp,
                         I64& gk, I64 gend, std::int32_t* err, vid_t* killer, std::int32_t* count_out,
                         I64 step_cap = -1) {
  if (seeded >= 4 && !g.w) {  // (weighted stars may die: no Flip-Flop for them)
    std::int32_t count = seeded;
    const I64 gk0 = gk;
    bool full = false;
    auto record = [&](vid_t x) {
      if (gk < gend) gp[gk++] = pair_key(me, x);
      else full = true;
    };
    const std::int32_t n = static_cast<std::int32_t>(len);
    if (star_flipflop(g, T, S, count, cap, me, n, KeyedSet{keys, n, me}, record, work, step_cap) && !full) {
      *count_out = count;
      return 1;
    }
    gk = gk0;
    for (std::int32_t i = 0; i < cap; ++i) S[i] = kTriFree;
  }
  build_one_star(g, T, S, cap, me, ov, len, work, gp, gk, gend, err, killer, count_out);
  return 0;
}

// No seed stars (gStar4D, gReg3D): build_stars builds every star by beneath-beyond.
struct NoSeed {
  static constexpr bool enabled = false;
  template <class... A>
  void operator()(A&&...) const {}
};

// Plain pointers to the stars, for kernels.
struct StarView {
  vid_t* vert;          // star -> its vertex
  I64* begin;           // star -> first triangle slot
  std::int32_t* cap;    // star -> slots reserved
  std::int32_t* count;  // star -> triangles in use, [0, count)
  Tri* tri;
  std::uint8_t* state;
  vid_t* killer;        // star -> the vertex that killed it (weighted points), -1 while alive
  vid_t* cert;          // star -> 5 vertices whose lifted simplex holds it (dead stars), else -1
  GDEL_HD bool dead(I64 st) const { return killer[st] >= 0; }
};

struct SplayStats {
  I64 rounds = 0, insertions = 0, stars_pulled = 0, proofs = 0, dead = 0;
  // seeded stars (gDel3D's failed stars) made convex by Flip-Flop, and rebuilt instead
  I64 flipflop = 0, rebuilt = 0;
  // huge stars (CUDA backend: Splayer::host_build_min) built on the host, and the
  // insertions made into huge stars on the host
  I64 host_built = 0, host_insertions = 0;
  // the critical path of one thread per star: Σ over the build and every round of the most
  // insertions into one star (counted only with GDEL_SPLAY_DEBUG set: it costs a reduction
  // per round), and the most triangles one star held (largest_star())
  I64 critical = 0, largest = 0;
};

template <class B>
class Splayer {
 public:
  Splayer(Context<B>& ctx, flip::Geo g, vid_t num_vertices)
      : ctx_(ctx), g_(g), star_of_(ctx, static_cast<std::size_t>(num_vertices)), vert_(ctx),
        begin_(ctx), cap_(ctx), count_(ctx), killer_(ctx), cert_(ctx), tri_(ctx), state_(ctx), history_(ctx),
        inf_proof_key_(ctx),
        inf_proof_(ctx), error_(ctx, 1) {
    par::fill(ctx, star_of_.data(), star_of_.size(), std::int32_t(-1));
    par::fill(ctx, error_.data(), std::size_t(1), std::int32_t(0));
  }

  I64 num_stars() const { return nst_; }
  I64 slot_count() const { return slots_; }
  const std::int32_t* star_of() { return star_of_.data(); }
  StarView view() {
    return StarView{vert_.data(), begin_.data(), cap_.data(), count_.data(), tri_.data(), state_.data(),
                    killer_.data(), cert_.data()};
  }
  SplayStats& stats() { return ss_; }

  // Appends stars for the given vertices (which must not have one) with the given
  // capacities (host arrays); returns the id of the first new star. Triangles are
  // left for the caller to fill (count = 0).
  I64 add_stars(const Buffer<vid_t, B>& verts, const Buffer<std::int32_t, B>& caps) {
    const I64 k = static_cast<I64>(verts.size());
    const I64 s0 = nst_;
    if (k == 0) return s0;
    vert_.resize(static_cast<std::size_t>(s0 + k));
    begin_.resize(static_cast<std::size_t>(s0 + k + 1));
    cap_.resize(static_cast<std::size_t>(s0 + k));
    count_.resize(static_cast<std::size_t>(s0 + k));
    killer_.resize(static_cast<std::size_t>(s0 + k));
    cert_.resize(static_cast<std::size_t>(5 * (s0 + k)));
    vid_t* kl = killer_.data();
    vid_t* ce = cert_.data();
    vid_t* vp = vert_.data();
    I64* bp = begin_.data();
    std::int32_t* cp = cap_.data();
    std::int32_t* np = count_.data();
    std::int32_t* so = star_of_.data();
    const vid_t* in = verts.data();
    const std::int32_t* ic = caps.data();
    Buffer<I64, B> off(ctx_, static_cast<std::size_t>(k + 1));
    I64* op = off.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 i) { op[i] = ic[i]; });
    const I64 total = par::counts_to_offsets(ctx_, op, static_cast<std::size_t>(k));
    const I64 base = slots_;
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 i) {
      const I64 s = s0 + i;
      vp[s] = in[i];
      bp[s] = base + op[i];
      cp[s] = ic[i];
      np[s] = 0;
      kl[s] = -1;
      for (int c = 0; c < 5; ++c) ce[5 * s + c] = -1;
      so[in[i]] = static_cast<std::int32_t>(s);
    });
    slots_ = base + total;
    tri_.resize(static_cast<std::size_t>(slots_));
    state_.resize(static_cast<std::size_t>(slots_));
    std::uint8_t* sp = state_.data();
    par::parallel_for(ctx_, total, [=] GDEL_LAMBDA(I64 i) { sp[base + i] = kTriFree; });
    nst_ = s0 + k;
    return s0;
  }

  // Makes every star's capacity at least need[s] (device array over stars), moving all
  // stars to a fresh layout when one must grow.
  void ensure_capacity(const std::int32_t* need) {
    if (nst_ == 0) return;
    std::int32_t* cp = cap_.data();
    Buffer<std::int32_t, B> grow(ctx_, static_cast<std::size_t>(nst_));
    std::int32_t* gp = grow.data();
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) { gp[s] = need[s] > cp[s] ? 1 : 0; });
    if (par::reduce_max(ctx_, gp, static_cast<std::size_t>(nst_), std::int32_t(0)) == 0) return;
    Buffer<I64, B> off(ctx_, static_cast<std::size_t>(nst_ + 1));
    I64* op = off.data();
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      const std::int32_t c = need[s] > cp[s] ? need[s] + need[s] / 4 : cp[s];
      gp[s] = c;
      op[s] = c;
    });
    const I64 total = par::counts_to_offsets(ctx_, op, static_cast<std::size_t>(nst_));
    Buffer<Tri, B> nt(ctx_, static_cast<std::size_t>(total));
    Buffer<std::uint8_t, B> ns(ctx_, static_cast<std::size_t>(total));
    Tri* ntp = nt.data();
    std::uint8_t* nsp = ns.data();
    const Tri* otp = tri_.data();
    const std::uint8_t* osp = state_.data();
    I64* bp = begin_.data();
    const std::int32_t* np = count_.data();
    // 32 threads per star, side by side over its slots (one thread per star copied each
    // star's slots alone: ≈ 28 ms of the sphere's rounds; bench/RESULTS.md, session 46)
    constexpr I64 kLanes = 32;
    par::parallel_for(ctx_, kLanes * nst_, [=] GDEL_LAMBDA(I64 x) {
      const I64 s = x / kLanes;
      const I64 b = bp[s], d = op[s];
      for (std::int32_t i = static_cast<std::int32_t>(x % kLanes); i < gp[s]; i += static_cast<std::int32_t>(kLanes)) {
        if (i < np[s]) {
          ntp[d + i] = otp[b + i];
          nsp[d + i] = osp[b + i];
        } else {
          nsp[d + i] = kTriFree;
        }
      }
    });
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      bp[s] = op[s];
      cp[s] = gp[s];
    });
    tri_ = std::move(nt);
    state_ = std::move(ns);
    slots_ = total;
  }

  // Group starts of sorted pair keys by target: heads[j] for j in [0, k], k groups.
  Buffer<I64, B> group_heads(const Buffer<U64, B>& keys, I64& k) {
    const I64 n = static_cast<I64>(keys.size());
    const U64* kp = keys.data();
    Buffer<I64, B> heads(ctx_, static_cast<std::size_t>(n + 1));
    k = static_cast<I64>(par::select_indices(ctx_, static_cast<std::size_t>(n), heads.data(), [=] GDEL_LAMBDA(I64 i) {
      return i == 0 || key_target(kp[i - 1]) != key_target(kp[i]);
    }));
    I64* hp = heads.data();
    const I64 kk = k;
    par::parallel_for(ctx_, 1, [=] GDEL_LAMBDA(I64) { hp[kk] = n; });
    return heads;
  }

  // Creates one star per target of `lk` (sorted unique pair keys (v << 32 | x); v must
  // not have a star yet, and needs at least 4 such x) by beneath-beyond insertion of its
  // x's: ∞ first, then nearest first. The order changes only the work, never the result
  // (the convex star over a point set is unique): with ∞ first no star holds upper
  // facets, every tet is positive in 3-D and insertion walks instead of scanning
  // (star_insert); nearest first makes far points drown against a small star instead of
  // growing it (O(k * true degree), not O(k^2), for the huge link of a point on a
  // coplanar hull face). Every triangle is New; the pairs become history; drowned and
  // submerged pairs go to `gone`. Returns the id of the first new star (stars follow in
  // the order of the groups).
  // With a Seed (gDel3D), seed(ctx, s0, k, view(), seeded) writes each star s0 + j's
  // triangles as they are in the input triangulation into its slots (adjacency set; S
  // flags the edges Flip-Flop starts from, see star_flipflop) and seeded[j] their number,
  // or -1; such a star is convexified by Flip-Flop (seeded_build) and rebuilt only if
  // that gives up.
  template <class Seed = NoSeed>
  I64 build_stars(const Buffer<U64, B>& lk, Buffer<U64, B>& gone, Seed seed = Seed{}) {
    I64 k = 0;
    Buffer<I64, B> lh = group_heads(lk, k);
    const I64* lhp = lh.data();
    const I64 nl = static_cast<I64>(lk.size());
    const U64* lp = lk.data();
    Buffer<vid_t, B> gv(ctx_, static_cast<std::size_t>(k));
    Buffer<std::int32_t, B> caps(ctx_, static_cast<std::size_t>(k));
    vid_t* gvp = gv.data();
    std::int32_t* cp = caps.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) {
      gvp[j] = key_target(lp[lhp[j]]);
      cp[j] = static_cast<std::int32_t>(4 * (lhp[j + 1] - lhp[j]) + 8);
    });
    if (debug_)
      std::fprintf(stderr, "splay: building %lld stars, largest working set %d\n", (long long)k,
                   k ? par::reduce_max(ctx_, cp, static_cast<std::size_t>(k), std::int32_t(0)) / 4 - 2 : 0);
    const I64 s0 = add_stars(gv, caps);
    if (debug_) ss_.critical += most_per_star(lhp, k, nl);  // a debug statistic: costs a sync
    add_history(lk);
    Buffer<U64, B> okey(ctx_, static_cast<std::size_t>(nl));
    Buffer<vid_t, B> ordv(ctx_, static_cast<std::size_t>(nl));
    {
      U64* okp = okey.data();
      vid_t* ovp = ordv.data();
      const flip::Geo gg = g_;
      const vid_t inf = g_.inf;
      par::parallel_for(ctx_, nl, [=] GDEL_LAMBDA(I64 i) {
        const vid_t v = key_target(lp[i]), x = key_vertex(lp[i]);
        std::uint32_t bits = 0;  // ∞: distance 0, first
        if (x != inf) {
          double d2 = 0;
          for (int c = 0; c < 3; ++c) {
            const double t = gg.p(x)[c] - gg.p(v)[c];
            d2 += t * t;
          }
          const float f = static_cast<float>(d2);  // order only: rounding is harmless
          std::memcpy(&bits, &f, sizeof bits);
        }
        okp[i] = (U64(static_cast<std::uint32_t>(v)) << 32) | bits;
        ovp[i] = x;
      });
      par::sort_pairs(ctx_, okp, ovp, static_cast<std::size_t>(nl));  // stable: ties by id
    }
    const vid_t* ov = ordv.data();
    Buffer<I64, B> room(ctx_, static_cast<std::size_t>(k + 1));
    I64* rmp = room.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) { rmp[j] = 2 * (lhp[j + 1] - lhp[j]) + 4; });
    const I64 total = par::counts_to_offsets(ctx_, rmp, static_cast<std::size_t>(k));
    Buffer<U64, B> g1(ctx_, static_cast<std::size_t>(std::max<I64>(total, 1)));
    U64* gp = g1.data();
    Buffer<I64, B> used(ctx_, static_cast<std::size_t>(k));
    I64* up = used.data();
    const StarView sv = view();
    const flip::Geo g = g_;
    std::int32_t* ep = error_.data();
    // seed stars (-1: none), and per star 1 if Flip-Flop made it
    Buffer<std::int32_t, B> seeded(ctx_, static_cast<std::size_t>(std::max<I64>(k, 1)));
    Buffer<std::int32_t, B> ffm(ctx_, static_cast<std::size_t>(std::max<I64>(k, 1)));
    std::int32_t* sdp = seeded.data();
    std::int32_t* ffp = ffm.data();
    if constexpr (Seed::enabled) {
      seed(ctx_, s0, k, sv, sdp);
    } else {
      par::fill(ctx_, sdp, static_cast<std::size_t>(k), std::int32_t(-1));
    }
    // (GDEL_PROFILE: the star builds' steps under their own names, from gDel3D's failed
    // stars and from the rounds' pulls alike)
    par::mark(ctx_, "stars: groups, order, seeds");
    // On the CUDA backend a star with a huge working set (a point on a coplanar hull face:
    // thousands of link vertices, every predicate degenerate) would be built by one GPU
    // thread at tens of µs per exact, symbolically perturbed test (bench/RESULTS.md
    // 2026-11-25: 7.3 s for one 1 845-point star on the H100). Those few stars are built
    // on the host's cores instead, with the same code, while the kernel builds the rest.
    // (host_pick raises it where more stars than host_star_cap() would go)
    I64 host_min = host_build_min();
    // GDEL_FLIPFLOP_STEPS=N caps Flip-Flop's steps per star (tests: 0 makes every seeded
    // star take the rebuild fallback)
    const I64 ff_cap = std::getenv("GDEL_FLIPFLOP_STEPS") ? std::atoll(std::getenv("GDEL_FLIPFLOP_STEPS")) : -1;
    const std::vector<I64> huge = host_pick(k, host_min, host_gate(), [=] GDEL_LAMBDA(I64 j) { return lhp[j + 1] - lhp[j]; });
    HostJobs hjobs;
    if (!huge.empty()) hjobs = host_jobs(huge, s0, lhp, rmp, gvp, ov, lp, sdp);
    par::mark(ctx_, "stars: host jobs' inputs");
    ss_.host_built += static_cast<I64>(huge.size());
    // The kernel takes the stars largest working set first (most_first; Flip-Flop's loop
    // runs in lockstep with the warp's other stars: par::Lockstep; bench/RESULTS.md, session 44).
    const Buffer<U64, B> order = most_first(k, [=] GDEL_LAMBDA(I64 j) { return lhp[j + 1] - lhp[j]; });
    const U64* orp = order.data();
    par::for_each_with_scratch(ctx_, k, geom::kPredicateWork, [=] GDEL_LAMBDA(I64 i, auto work) {
      const I64 j = static_cast<I64>(orp[i] & 0xffffffffu);
      const I64 s = s0 + j;
      const I64 a = lhp[j], b = lhp[j + 1];
      up[j] = 0;
      ffp[j] = 0;
      if (b - a > host_min) return;  // built on the host
      I64 gk = rmp[j];
      ffp[j] = seeded_build(g, sv.tri + sv.begin[s], sv.state + sv.begin[s], sv.cap[s], gvp[j], lp + a, ov + a, b - a,
                            sdp[j], work, gp, gk, rmp[j + 1], ep, sv.killer + s, sv.count + s, ff_cap);
      up[j] = gk - rmp[j];
    }, g.int_all);
    if (!huge.empty()) run_host_jobs(hjobs, gp, up, ffp, ff_cap);  // while the kernel runs; then writes back
    par::mark(ctx_, "stars: build (kernel, host jobs)");
    throw_if_error("building stars");
    if constexpr (Seed::enabled) {
      const I64 ff = par::reduce_sum(ctx_, ffp, static_cast<std::size_t>(k));
      ss_.flipflop += ff;
      ss_.rebuilt += k - ff;
      if (debug_) std::fprintf(stderr, "splay: %lld stars made convex by Flip-Flop, %lld rebuilt\n", (long long)ff,
                               (long long)(k - ff));
    }
    gone = pack_pairs(gp, rmp, up, k);
    certify_deaths();
    par::mark(ctx_, "stars: gone pairs, deaths");
    return s0;
  }

  // build_stars' huge stars (indices j of its groups) on the host: the points (and
  // weights) and each star's inputs come to host memory (host_jobs, before the kernel for
  // the other stars is launched), build_one_star runs there, one host thread per star, while
  // that kernel runs, and the triangles, count, killer and gone pairs go back
  // (run_host_jobs). A stage of the repair moved from the GPU to the host: docs/gdel3d.md.
  // 48, with at most host_star_cap() stars per build or round and only where one
  // exceeds kHostGate: on the H200 the grid's star builds took 225 ms at 512, 108 at 128
  // and 75 at 48 (its largest working set 1 824); the sphere's (largest 179) the same at
  // 512 and 128, but without a cap it sent thousands of stars to the host at 48: 1.8 s
  // (bench/RESULTS.md, session 19). With the cap and gate the grid's repair 0.14 → 0.11 s
  // and the sphere's unchanged (session 20, s20b).
  static constexpr I64 kHostBuildMin = 48;
  // Working sets above this go to the host: kHostBuildMin on the CUDA backend, never on the
  // CPU backend; GDEL_HOST_STAR_MIN=N sets it on both (tests run the host path on the CPU).
  static I64 host_build_min() {
    if (const char* e = std::getenv("GDEL_HOST_STAR_MIN")) return std::max<I64>(4, std::atoll(e));
    return B::is_device ? kHostBuildMin : I64(1) << 62;
  }
  // At most this many stars of one build or insertion round go to the host: 4 per host
  // thread (GDEL_HOST_STAR_CAP=N sets it). Each costs a few small copies each way, and
  // beyond a few per thread the host becomes the slower side: with the threshold at 48
  // and no cap the sphere sent thousands and took 1.8 s instead of 0.86 (bench/
  // RESULTS.md, session 19).
  static std::size_t host_star_cap() {
    if (const char* e = std::getenv("GDEL_HOST_STAR_CAP")) return static_cast<std::size_t>(std::max(1LL, std::atoll(e)));
    return 4 * static_cast<std::size_t>(std::max(1, omp_get_max_threads()));
  }
  // The host path is taken only where a star exceeds this (working-set points; twice as
  // many triangles for the insertions). It was set when the first job copied every point
  // to the host, 320 MB at 10^7 points, which the uniform generator's few stars above 48
  // did not repay: its repair took 0.31 s instead of 0.08, 3.6 s instead of 1.1 at 10^8
  // (bench/RESULTS.md, session 20); the jobs now fetch only the points they read
  // (fetch_points, session 46), and the gate is not re-measured. GDEL_HOST_STAR_GATE=N sets
  // it (tests); with GDEL_HOST_STAR_MIN set and no GDEL_HOST_STAR_GATE, no gate.
  static constexpr I64 kHostGate = 128;
  static I64 host_gate() {
    if (const char* e = std::getenv("GDEL_HOST_STAR_GATE")) return std::max<I64>(0, std::atoll(e));
    return std::getenv("GDEL_HOST_STAR_MIN") ? host_build_min() : kHostGate;
  }
  // The groups j in [0, n) with size(j) > min, for the host, if the largest exceeds gate:
  // if more than host_star_cap() qualify, only the largest. min is raised to the size of
  // the largest one left out (ties at the cut stay too; all of them where the gate
  // stops the host path), so that "size(j) > min" is again exactly the host's share for
  // the kernel that skips those groups. Empty where nothing goes to the host.
  template <class Size>
  std::vector<I64> host_pick(I64 n, I64& min, I64 gate, Size size) {
    if (n <= 0 || min >= (I64(1) << 61)) return {};
    const I64 lim = min;
    Buffer<I64, B> hj(ctx_, static_cast<std::size_t>(n));
    const std::size_t nh = par::select_indices(ctx_, static_cast<std::size_t>(n), hj.data(),
                                               [=] GDEL_LAMBDA(I64 j) { return size(j) > lim; });
    if (nh == 0) return {};
    hj.resize(nh);
    Buffer<I64, B> sz(ctx_, nh);
    I64* zp = sz.data();
    const I64* jp = hj.data();
    par::parallel_for(ctx_, static_cast<I64>(nh), [=] GDEL_LAMBDA(I64 i) { zp[i] = size(jp[i]); });
    const std::vector<I64> sizes = sz.to_host();
    const I64 top = *std::max_element(sizes.begin(), sizes.end());
    if (top <= gate) {
      min = top;
      return {};
    }
    std::vector<I64> idx = hj.to_host();
    const std::size_t cap = host_star_cap();
    if (nh <= cap) return idx;
    std::vector<I64> order = sizes;
    std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(cap), order.end(), std::greater<I64>());
    min = order[cap];  // the (cap + 1)-th largest
    std::vector<I64> out;
    for (std::size_t i = 0; i < nh; ++i)
      if (sizes[i] > min) out.push_back(idx[i]);
    return out;
  }
  // Many small copies between host and backend memory, one copy each way for all of them
  // (each copy synchronizes, ≈ 25 µs on the H200: the sphere's 61 host jobs spent ≈ 8 ms
  // on their inputs one copy at a time; bench/RESULTS.md, session 46). A piece: count
  // items between backend memory `dev` and host memory `host`.
  struct Piece {
    const void* dev;
    void* host;
    std::size_t bytes;
  };
  template <class T>
  static Piece piece(const T* dev, const T* host, std::size_t count) {  // (host written only to_host)
    return Piece{dev, const_cast<T*>(host), count * sizeof(T)};
  }
  // to_host: every piece's backend bytes to its host memory; else the other way.
  void copy_pieces(const std::vector<Piece>& ps, bool to_host) {
    std::vector<Piece> p;
    for (const Piece& x : ps)
      if (x.bytes) p.push_back(x);
    if (p.empty()) return;
    const std::size_t n = p.size();
    // one buffer: n + 1 offsets, n addresses, then (the other way) the bytes
    std::vector<I64> head(2 * n + 1);
    I64 total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      head[i] = total;
      total += static_cast<I64>(p[i].bytes);
      head[n + 1 + i] = static_cast<I64>(reinterpret_cast<std::uintptr_t>(p[i].dev));
    }
    head[n] = total;
    const std::size_t hb = head.size() * sizeof(I64);
    std::vector<std::uint8_t> staged(hb + (to_host ? 0 : static_cast<std::size_t>(total)));
    std::memcpy(staged.data(), head.data(), hb);
    if (!to_host)
      for (std::size_t i = 0; i < n; ++i) std::memcpy(staged.data() + hb + head[i], p[i].host, p[i].bytes);
    Buffer<std::uint8_t, B> d(ctx_);
    d.assign(staged);
    const I64* op = reinterpret_cast<const I64*>(d.data());
    const I64* ap = op + n + 1;
    const I64 k = static_cast<I64>(n);
    if (to_host) {
      Buffer<std::uint8_t, B> packed(ctx_, static_cast<std::size_t>(total));
      std::uint8_t* pp = packed.data();
      par::parallel_for(ctx_, total, [=] GDEL_LAMBDA(I64 x) {
        const I64 i = group_of(op, k, x);
        pp[x] = reinterpret_cast<const std::uint8_t*>(static_cast<std::uintptr_t>(ap[i]))[x - op[i]];
      });
      const std::vector<std::uint8_t> h = packed.to_host();
      for (std::size_t i = 0; i < n; ++i) std::memcpy(p[i].host, h.data() + head[i], p[i].bytes);
    } else {
      const std::uint8_t* src = d.data() + hb;
      par::parallel_for(ctx_, total, [=] GDEL_LAMBDA(I64 x) {
        const I64 i = group_of(op, k, x);
        reinterpret_cast<std::uint8_t*>(static_cast<std::uintptr_t>(ap[i]))[x - op[i]] = src[x];
      });  // (the pieces' host data was staged by the upload: the caller may free it now)
    }
  }
  // A star worked on the host (its group j, star s, slots [begin, begin + cap), room for
  // gone pairs [g0, g1) of the round's list, used of it), and its write-back.
  struct HostStar {
    I64 j = 0, s = 0, begin = 0, g0 = 0, g1 = 0, used = 0;
    std::int32_t cap = 0, count = 0, err = 0;
    vid_t me = -1, killer = -1;
    std::vector<Tri> T;
    std::vector<std::uint8_t> S;
    std::vector<U64> gone;
  };
  // A host job's results, as pieces for one copy_pieces to the backend (the job must
  // outlive that copy).
  void write_back(const HostStar& J, U64* gp, I64* up, std::vector<Piece>& out) {
    const StarView sv = view();
    out.push_back(piece(sv.tri + J.begin, J.T.data(), J.T.size()));
    out.push_back(piece(sv.state + J.begin, J.S.data(), J.S.size()));
    out.push_back(piece(sv.count + J.s, &J.count, 1));
    if (J.killer >= 0) out.push_back(piece(sv.killer + J.s, &J.killer, 1));
    if (J.used > 0) out.push_back(piece(gp + J.g0, J.gone.data(), static_cast<std::size_t>(J.used)));
    out.push_back(piece(up + J.j, &J.used, 1));
    if (J.err != 0) out.push_back(piece(error_.data(), &J.err, 1));
  }
  struct HostJob : HostStar {
    I64 a = 0, b = 0;
    std::vector<vid_t> pts;
    std::int32_t seeded = -1, ff = 0;
    std::vector<U64> keys;
  };
  using HostJobs = std::vector<HostJob>;
  // The points (and weights, and SoS ids) in host memory for the host jobs, at their
  // internal ids: arrays of n + 1 entries allocated once per splayer and left
  // uninitialised (pages never written cost nothing), into which fetch_points copies only
  // the points the jobs read. Copying every point took ≈ 20 ms at 10^6 points on the H200
  // (grid and sphere alike: bench/RESULTS.md, session 46), for jobs that read a few
  // thousand.
  struct HostGeo {
    std::unique_ptr<double[]> xyz, w;
    std::unique_ptr<std::int64_t[]> sid;
    flip::Geo g{};
  };
  const flip::Geo& host_geo() {
    HostGeo& H = host_geo_;
    if (H.xyz) return H.g;
    const std::size_t np = static_cast<std::size_t>(g_.inf) + 1;  // n points and K
    H.xyz.reset(new double[3 * np]);
    H.sid.reset(new std::int64_t[np]);
    H.g = g_;
    H.g.xyz = H.xyz.get();
    H.g.sid = H.sid.get();
    if (g_.w) {
      H.w.reset(new double[np]);
      H.g.w = H.w.get();
    }
    if (std::getenv("GDEL_HOST_STAR_MIN")) {  // tests: a point no fetch brought is NaN, not a stale value
      std::fill_n(H.xyz.get(), 3 * np, std::numeric_limits<double>::quiet_NaN());
      if (H.w) std::fill_n(H.w.get(), np, std::numeric_limits<double>::quiet_NaN());
    }
    return H.g;
  }
  // Brings the points ids (any order, repeats allowed; ∞'s K is always added) into
  // host_geo's arrays: gathered on the backend, one copy, scattered on the host. (With
  // Geo::k_centroid the four points whose centroid K is come too.)
  void fetch_points(std::vector<vid_t> ids) {
    host_geo();
    ids.push_back(g_.inf);
    if (g_.k_centroid) ids.insert(ids.end(), g_.kq, g_.kq + 4);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    constexpr int kStride = 5;  // x, y, z, the SoS id's bits, the weight
    Buffer<vid_t, B> di(ctx_);
    di.assign(ids);
    Buffer<double, B> pk(ctx_, kStride * ids.size());
    const vid_t* dp = di.data();
    double* pp = pk.data();
    const flip::Geo g = g_;
    par::parallel_for(ctx_, static_cast<I64>(ids.size()), [=] GDEL_LAMBDA(I64 i) {
      const vid_t v = dp[i];
      double* o = pp + kStride * i;
      for (int c = 0; c < 3; ++c) o[c] = g.p(v)[c];
      std::memcpy(o + 3, g.sid + v, sizeof(double));
      o[4] = g.w ? g.w[v] : 0.0;
    });
    const std::vector<double> h = pk.to_host();
    HostGeo& H = host_geo_;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::size_t v = static_cast<std::size_t>(ids[i]);
      const double* o = h.data() + kStride * i;
      for (int c = 0; c < 3; ++c) H.xyz[3 * v + c] = o[c];
      std::memcpy(&H.sid[v], o + 3, sizeof(double));
      if (H.w) H.w[v] = o[4];
    }
  }
  HostJobs host_jobs(const std::vector<I64>& huge, I64 s0, const I64* lhp, const I64* rmp, const vid_t* gvp,
                     const vid_t* ov, const U64* lp, const std::int32_t* sdp) {
    HostJobs H(huge.size());
    const StarView sv = view();
    // each job's scalars, gathered on the backend and copied in one piece
    const std::vector<I64> f = gather_host_fields(huge, [=] GDEL_LAMBDA(I64 j, I64* o) {
      const I64 s = s0 + j;
      o[0] = lhp[j];
      o[1] = lhp[j + 1];
      o[2] = rmp[j];
      o[3] = rmp[j + 1];
      o[4] = sv.begin[s];
      o[5] = sv.cap[s];
      o[6] = gvp[j];
      o[7] = sdp[j];
    });
    std::vector<Piece> in;  // each job's arrays, in one copy
    for (std::size_t h = 0; h < huge.size(); ++h) {
      HostJob& J = H[h];
      const I64* o = f.data() + kHostFields * h;
      J.j = huge[h];
      J.s = s0 + J.j;
      J.a = o[0];
      J.b = o[1];
      J.g0 = o[2];
      J.g1 = o[3];
      J.begin = o[4];
      J.cap = static_cast<std::int32_t>(o[5]);
      J.me = static_cast<vid_t>(o[6]);
      J.pts.resize(static_cast<std::size_t>(J.b - J.a));
      in.push_back(piece(ov + J.a, J.pts.data(), J.pts.size()));
      J.T.resize(static_cast<std::size_t>(J.cap));
      J.S.assign(static_cast<std::size_t>(J.cap), std::uint8_t(kTriFree));
      J.seeded = static_cast<std::int32_t>(o[7]);
      if (J.seeded >= 0) {  // the seed star (its triangles; the rest is scratch)
        in.push_back(piece(static_cast<const Tri*>(sv.tri + J.begin), J.T.data(), static_cast<std::size_t>(J.seeded)));
        in.push_back(piece(static_cast<const std::uint8_t*>(sv.state + J.begin), J.S.data(),
                           static_cast<std::size_t>(J.seeded)));
        J.keys.resize(J.pts.size());
        in.push_back(piece(lp + J.a, J.keys.data(), J.keys.size()));
      }
      J.gone.resize(static_cast<std::size_t>(std::max<I64>(J.g1 - J.g0, 1)));
    }
    copy_pieces(in, true);
    // the points a build reads: its working set (the seed's vertices among them) and its own
    std::vector<vid_t> ids;
    for (const HostJob& J : H) {
      ids.insert(ids.end(), J.pts.begin(), J.pts.end());
      ids.push_back(J.me);
    }
    fetch_points(std::move(ids));
    return H;
  }
  // kHostFields scalars per host job: field(j, out) writes those of group huge[h] to
  // out[kHostFields * h, ...) on the backend; one copy brings them all (not one small
  // copy per scalar and job).
  static constexpr std::size_t kHostFields = 8;
  template <class Field>
  std::vector<I64> gather_host_fields(const std::vector<I64>& huge, Field field) {
    Buffer<I64, B> js(ctx_);
    js.assign(huge);
    Buffer<I64, B> out(ctx_, kHostFields * huge.size());
    const I64* jp = js.data();
    I64* op = out.data();
    par::parallel_for(ctx_, static_cast<I64>(huge.size()),
                      [=] GDEL_LAMBDA(I64 h) { field(jp[h], op + kHostFields * static_cast<std::size_t>(h)); });
    return out.to_host();
  }
  void run_host_jobs(HostJobs& H, U64* gp, I64* up, std::int32_t* ffp, I64 ff_cap) {
    const flip::Geo& hg = host_geo_.g;
    par::on_host_threads(H.size(), [&](std::size_t h) {
      const auto t0 = std::chrono::steady_clock::now();
      std::vector<double> work(geom::kPredicateWork);
      HostJob& J = H[h];
      I64 gk = 0;
      J.ff = seeded_build(hg, J.T.data(), J.S.data(), J.cap, J.me, J.keys.data(), J.pts.data(),
                          static_cast<I64>(J.pts.size()), J.seeded, work.data(), J.gone.data(), gk, J.g1 - J.g0,
                          &J.err, &J.killer, &J.count, ff_cap);
      J.used = gk;
      if (debug_)
        std::fprintf(stderr, "splay: host star %lld: working set %zu, seed %d -> %d triangles, %s, %.2f ms\n",
                     (long long)J.s, J.pts.size(), J.seeded, J.count, J.ff ? "Flip-Flop" : "rebuilt",
                     std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    });
    std::vector<Piece> out;
    for (HostJob& J : H) {
      write_back(J, gp, up, out);
      out.push_back(piece(ffp + J.j, &J.ff, 1));
    }
    copy_pieces(out, false);
  }

  // insert_round's huge stars (indices j of its request groups) on the host: the star's
  // triangles (all cap slots), count and requests come to host memory before the kernel
  // for the other stars is launched; run_insert_jobs inserts, one host thread per star,
  // while that kernel runs, and writes the star, its killer and its gone pairs back.
  struct InsertJob : HostStar {
    I64 inserted = 0;
    std::vector<U64> req;
  };
  std::vector<InsertJob> insert_jobs(const std::vector<I64>& huge, const Buffer<U64, B>& req,
                                     const Buffer<I64, B>& heads, I64 nh, const Buffer<I64, B>& room) {
    const StarView sv = view();
    const I64 n = static_cast<I64>(req.size());
    std::vector<InsertJob> jobs(huge.size());
    // each job's scalars, gathered on the backend and copied in one piece
    const I64* hp = heads.data();
    const I64* rmp = room.data();
    const U64* rp = req.data();
    const std::int32_t* so = star_of_.data();
    const std::vector<I64> f = gather_host_fields(huge, [=] GDEL_LAMBDA(I64 j, I64* o) {
      const I64 a = hp[j];
      const std::int32_t s = so[key_target(rp[a])];
      o[0] = a;
      o[1] = j + 1 < nh ? hp[j + 1] : n;
      o[2] = s;
      o[3] = sv.begin[s];
      o[4] = sv.cap[s];
      o[5] = sv.count[s];
      o[6] = rmp[j];
      o[7] = rmp[j + 1];
    });
    std::vector<Piece> in;  // each job's arrays, in one copy
    for (std::size_t h = 0; h < huge.size(); ++h) {
      InsertJob& J = jobs[h];
      const I64* o = f.data() + kHostFields * h;
      J.j = huge[h];
      const I64 a = o[0], b = o[1];
      J.req.resize(static_cast<std::size_t>(b - a));
      in.push_back(piece(req.data() + a, J.req.data(), J.req.size()));
      J.s = o[2];
      J.begin = o[3];
      J.cap = static_cast<std::int32_t>(o[4]);
      J.count = static_cast<std::int32_t>(o[5]);
      J.g0 = o[6];
      J.g1 = o[7];
      J.T.resize(static_cast<std::size_t>(J.cap));
      J.S.resize(static_cast<std::size_t>(J.cap));
      in.push_back(piece(static_cast<const Tri*>(sv.tri + J.begin), J.T.data(), J.T.size()));
      in.push_back(piece(static_cast<const std::uint8_t*>(sv.state + J.begin), J.S.data(), J.S.size()));
      J.gone.resize(static_cast<std::size_t>(std::max<I64>(J.g1 - J.g0, 1)));
    }
    copy_pieces(in, true);
    for (InsertJob& J : jobs) J.me = key_target(J.req[0]);
    // the points an insertion reads: the star's own, its triangles' and the inserted ones
    std::vector<vid_t> ids;
    for (const InsertJob& J : jobs) {
      ids.push_back(J.me);
      for (std::int32_t q = 0; q < J.count; ++q)
        for (int c = 0; c < 3; ++c) ids.push_back(J.T[static_cast<std::size_t>(q)].v[c]);
      for (const U64 key : J.req) ids.push_back(key_vertex(key));
    }
    fetch_points(std::move(ids));
    return jobs;
  }
  void run_insert_jobs(std::vector<InsertJob>& jobs, U64* gp, I64* up) {
    const flip::Geo& hg = host_geo_.g;
    par::on_host_threads(jobs.size(), [&](std::size_t h) {
      std::vector<double> work(geom::kPredicateWork);
      InsertJob& J = jobs[h];
      std::int32_t nonpos = 0;
      for (std::int32_t q = 0; q < J.count; ++q) nonpos += (J.S[static_cast<std::size_t>(q)] & kTriNonPositive) ? 1 : 0;
      I64 k = 0;
      for (const U64 key : J.req) {
        ++J.inserted;
        if (insert_recording(hg, J.T.data(), J.S.data(), J.count, J.cap, J.me, key_vertex(key), work.data(),
                             J.gone.data(), k, J.g1 - J.g0, &J.err, &nonpos) == kStarDead) {
          J.killer = key_vertex(key);
          break;
        }
      }
      J.used = k;
    });
    std::vector<Piece> out;
    for (InsertJob& J : jobs) {
      ss_.host_insertions += J.inserted;
      write_back(J, gp, up, out);
    }
    copy_pieces(out, false);
  }

  // Runs splaying rounds from the given requests (keys pair_key(target, vertex), any
  // order, duplicates allowed) until no new request appears.
  // The source of stars that do not exist yet: must create the stars of the vertices in
  // the given device list (vertex ids without a star).
  void set_source(std::function<void(const Buffer<vid_t, B>&)> pull) { pull_ = std::move(pull); }

  void run(Buffer<U64, B>& req) {
    for (;;) {
      I64 n = static_cast<I64>(req.size());
      if (n > 0) {
        par::sort_keys(ctx_, req.data(), static_cast<std::size_t>(n));
        n = static_cast<I64>(par::unique(ctx_, req.data(), static_cast<std::size_t>(n)));
        req.resize(static_cast<std::size_t>(n));
      }
      if (n > 0) pull_targets(req);
      par::mark(ctx_, "splay: requests, pull stars");
      if (debug_ > 1) std::fprintf(stderr, "  convexity violations: %lld, largest star %d triangles\n",
                               (long long)convexity_violations(),
                               nst_ ? par::reduce_max(ctx_, count_.data(), static_cast<std::size_t>(nst_), 0) : 0);
      const I64 n_raw = n;
      n = filter(req);
      par::mark(ctx_, "splay: filter");
      if (debug_) std::fprintf(stderr, "splay round %lld: %lld requests, %lld new, %lld stars\n", (long long)ss_.rounds,
                               (long long)n_raw, (long long)n, (long long)nst_);
      if (n == 0) break;
      ++ss_.rounds;
      ss_.insertions += n;
      add_history(req);
      par::mark(ctx_, "splay: history");
      Buffer<U64, B> gone(ctx_);
      insert_round(req, gone);
      par::mark(ctx_, "splay: insert round");
      Buffer<U64, B> next(ctx_);
      proofs(gone, next);
      par::mark(ctx_, "splay: proofs");
      checks(next);
      par::mark(ctx_, "splay: checks");
      req = std::move(next);
    }
  }

  // Output tets from the stars: the tet (s, a, b, c) of every link triangle abc of the
  // star of s, emitted once, by the star of its smallest vertex that has a star, unless
  // it holds ∞ or is flat (exact orient3d = 0: only on coplanar hull faces). A negative
  // tet would be an upper-hull facet, which no star that tried ∞ can hold: an
  // inconsistency, reported.
  // num (slots + 1) gets the exclusive prefix count of emitted tets per slot; returns
  // their number, adds the flat tets dropped to `flat` and the exact evaluations to `exact`.
  I64 plan_star_tets(Buffer<I64, B>& num, I64& flat, I64& exact) {
    const I64 slots = slots_;
    const StarView sv = view();
    const std::int32_t* so = star_of_.data();
    const vid_t inf = g_.inf;
    const flip::Geo g = g_;
    Buffer<I64, B> slot_star(ctx_, static_cast<std::size_t>(std::max<I64>(slots, 1)));
    I64* ssp = slot_star.data();
    par::fill(ctx_, ssp, slot_star.size(), I64(-1));
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      if (sv.dead(s)) return;  // a dead (redundant) vertex has no tets
      for (std::int32_t i = 0; i < sv.count[s]; ++i) ssp[sv.begin[s] + i] = s;
    });
    auto candidate = [=] GDEL_LAMBDA(I64 q, vid_t* tet) -> bool {
      const I64 s = ssp[q];
      if (s < 0) return false;
      const Tri& tr = sv.tri[q];
      tet[0] = sv.vert[s];
      for (int i = 0; i < 3; ++i) tet[1 + i] = tr.v[i];
      for (int i = 1; i < 4; ++i) {
        if (tet[i] == inf) return false;
        if (so[tet[i]] >= 0 && !sv.dead(so[tet[i]]) && tet[i] < tet[0]) return false;  // owned by a smaller star
      }
      return true;
    };
    Buffer<std::int8_t, B> sgn(ctx_, static_cast<std::size_t>(std::max<I64>(slots, 1)));
    std::int8_t* sfp = sgn.data();
    exact += par::two_stage_signs(
        ctx_, slots, sfp,
        [=] GDEL_LAMBDA(I64 q) -> std::int8_t {
          vid_t v[4] = {0, 0, 0, 0};
          return candidate(q, v) ? g.volume_sign_fast(v) : std::int8_t(0);
        },
        [=] GDEL_LAMBDA(I64 q, double* work) -> std::int8_t {
          vid_t v[4] = {0, 0, 0, 0};
          return candidate(q, v) ? g.volume_sign_exact(v, work) : std::int8_t(0);
        },
        geom::kPredicateWork);
    std::int32_t* ep = error_.data();
    par::parallel_for(ctx_, slots, [=] GDEL_LAMBDA(I64 q) {
      if (sfp[q] < 0) ep[0] = 8;
    });
    throw_if_error("extracting tets");
    num.resize(static_cast<std::size_t>(slots + 1));
    I64* np = num.data();
    par::parallel_for(ctx_, slots, [=] GDEL_LAMBDA(I64 q) {
      vid_t v[4];
      np[q] = (candidate(q, v) && sfp[q] == 0) ? 1 : 0;
    });
    flat += par::reduce_sum(ctx_, np, static_cast<std::size_t>(slots));
    par::parallel_for(ctx_, slots, [=] GDEL_LAMBDA(I64 q) { np[q] = sfp[q] > 0 ? 1 : 0; });
    return par::counts_to_offsets(ctx_, np, static_cast<std::size_t>(slots));
  }

  // Writes the tets planned by plan_star_tets at tets[4 * (base + num[q])], their
  // neighbours as -2 (to be matched by mesh::match_open_faces).
  void write_star_tets(const Buffer<I64, B>& num, vid_t* tets, std::int32_t* nbr, I64 base) {
    const I64* np = num.data();
    const StarView sv = view();
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      for (std::int32_t i = 0; i < sv.count[s]; ++i) {
        const I64 q = sv.begin[s] + i;
        if (np[q + 1] == np[q]) continue;
        const I64 d = base + np[q];
        tets[4 * d + 0] = sv.vert[s];
        for (int k = 0; k < 3; ++k) tets[4 * d + 1 + k] = sv.tri[q].v[k];
        for (int k = 0; k < 4; ++k) nbr[4 * d + k] = -2;
      }
    });
  }

  // The longest of k groups starting at heads[0..k) (the last ends at n).
  I64 most_per_star(const I64* heads, I64 k, I64 n) {
    if (k == 0) return 0;
    Buffer<I64, B> len(ctx_, static_cast<std::size_t>(k));
    I64* lp = len.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) { lp[j] = (j + 1 < k ? heads[j + 1] : n) - heads[j]; });
    return par::reduce_max(ctx_, lp, static_cast<std::size_t>(k), I64(0));
  }

  // Records the most triangles any star holds now in stats().largest and returns it.
  I64 largest_star() {
    if (nst_ == 0) return 0;
    ss_.largest = std::max<I64>(ss_.largest, par::reduce_max(ctx_, count_.data(), static_cast<std::size_t>(nst_), 0));
    return ss_.largest;
  }

  // Fails loudly if a kernel saw a broken (non-convex) star.
  void throw_if_error(const char* where) {
    std::int32_t e = 0;
    error_.copy_to_host(&e, 1);
    if (e != 0)
      throw std::runtime_error(std::string("gdel internal error: star splaying found an inconsistent star (") +
                               where + ", code " + std::to_string(e) + ")");
  }

  std::int32_t* error_ptr() { return error_.data(); }

  // Debug: number of (star, triangle, link vertex) triples where the link vertex is
  // beyond the triangle (0 iff every star is convex).
  I64 convexity_violations() {
    if (nst_ == 0) return 0;
    const StarView sv = view();
    const flip::Geo g = g_;
    Buffer<I64, B> bad(ctx_, static_cast<std::size_t>(nst_));
    I64* bp = bad.data();
    par::for_each_with_scratch(ctx_, nst_, geom::kPredicateWork, [=] GDEL_LAMBDA(I64 s, auto work) {
      const Tri* T = sv.tri + sv.begin[s];
      I64 c = 0;
      if (sv.dead(s)) {
        bp[s] = 0;
        return;
      }
      for (std::int32_t i = 0; i < sv.count[s]; ++i)
        for (std::int32_t j = 0; j < sv.count[s]; ++j)
          for (int k = 0; k < 3; ++k) {
            const vid_t x = T[j].v[k];
            if (tri_pos(T[i], x) >= 0) continue;
            if (star_side(g, T[i], sv.vert[s], x, work) > 0) ++c;
          }
      bp[s] = c;
    }, g.int_all);
    return par::reduce_sum(ctx_, bp, static_cast<std::size_t>(nst_));
  }

  // The order of a kernel over items j in [0, k) whose work grows with size(j), one thread
  // each: keys (~size << 32 | j), sorted, largest first; the item is key & 0xffffffff. A
  // warp's 32 items then take similar numbers of steps, and the longest start first, but
  // neighbouring threads no longer work on neighbouring memory: a gain where a warp's
  // slowest item dominates (build_stars, sphere: 55 -> 48 ms), a loss elsewhere
  // (insert_round: 55 -> 95 ms; bench/RESULTS.md, session 44).
  template <class Size>
  Buffer<U64, B> most_first(I64 k, Size size) {
    Buffer<U64, B> ord(ctx_, static_cast<std::size_t>(std::max<I64>(k, 1)));
    U64* op = ord.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) {
      const I64 z = size(j);
      const std::uint32_t c = z < I64(0xffffffff) ? static_cast<std::uint32_t>(z) : 0xffffffffu;
      op[j] = (U64(0xffffffffu - c) << 32) | U64(j);
    });
    par::sort_keys(ctx_, op, static_cast<std::size_t>(k));
    return ord;
  }

  // (public for nvcc's extended lambdas)
  void pull_targets(Buffer<U64, B>& req) {
    const I64 n = static_cast<I64>(req.size());
    const U64* rp = req.data();
    const std::int32_t* so = star_of_.data();
    Buffer<vid_t, B> miss(ctx_, static_cast<std::size_t>(n));
    vid_t* mp = miss.data();
    Buffer<I64, B> idx(ctx_, static_cast<std::size_t>(n));
    const std::size_t k = par::select_indices(ctx_, static_cast<std::size_t>(n), idx.data(), [=] GDEL_LAMBDA(I64 i) {
      const vid_t t = key_target(rp[i]);
      return so[t] < 0 && (i == 0 || key_target(rp[i - 1]) != t);
    });
    if (k == 0) return;
    const I64* ip = idx.data();
    par::parallel_for(ctx_, static_cast<I64>(k), [=] GDEL_LAMBDA(I64 i) { mp[i] = key_target(rp[ip[i]]); });
    miss.resize(k);
    ss_.stars_pulled += static_cast<I64>(k);
    pull_(miss);
  }

  // Whether star s's link holds vertex x (filter, proofs): a scan of its triangles, or for
  // a star of more than kLinkScanMax triangles (a point on a coplanar hull face:
  // thousands) a binary search in `big`, the sorted link keys of such stars
  // (link_keys_above), not one thread's scan of every triangle per query (the grid's
  // filter: bench/RESULTS.md, session 46).
  static constexpr std::int32_t kLinkScanMax = 256;
  struct LinkQuery {
    StarView sv;
    const U64* big;
    I64 nb;
    GDEL_HD bool has(std::int32_t s, vid_t x) const {
      if (sv.count[s] > kLinkScanMax) return sorted_contains(big, nb, pair_key(sv.vert[s], x));
      return star_has(sv.tri + sv.begin[s], sv.count[s], x);
    }
  };
  LinkQuery link_query(const Buffer<U64, B>& big) {
    return LinkQuery{view(), big.data(), static_cast<I64>(big.size())};
  }
  // The link keys pair_key(star vertex, link vertex) of the live stars of more than `min`
  // triangles, sorted, unique (one thread per triangle).
  Buffer<U64, B> link_keys_above(std::int32_t min) {
    const StarView sv = view();
    Buffer<I64, B> bs(ctx_, static_cast<std::size_t>(std::max<I64>(nst_, 1)));
    const std::size_t nbs = par::select_indices(ctx_, static_cast<std::size_t>(nst_), bs.data(), [=] GDEL_LAMBDA(I64 s) {
      return sv.count[s] > min && !sv.dead(s);
    });
    Buffer<U64, B> keys(ctx_);
    if (nbs == 0) return keys;
    const I64 m = static_cast<I64>(nbs);
    const I64* sp = bs.data();
    Buffer<I64, B> off(ctx_, static_cast<std::size_t>(m + 1));
    I64* op = off.data();
    par::parallel_for(ctx_, m, [=] GDEL_LAMBDA(I64 j) { op[j] = sv.count[sp[j]]; });
    const I64 nt = par::counts_to_offsets(ctx_, op, static_cast<std::size_t>(m));
    keys.resize(static_cast<std::size_t>(3 * nt));
    U64* kp = keys.data();
    par::parallel_for(ctx_, nt, [=] GDEL_LAMBDA(I64 x) {
      const I64 j = group_of(op, m, x);
      const I64 s = sp[j];
      const Tri& t = sv.tri[sv.begin[s] + (x - op[j])];
      for (int c = 0; c < 3; ++c) kp[3 * x + c] = pair_key(sv.vert[s], t.v[c]);
    });
    par::sort_keys(ctx_, kp, static_cast<std::size_t>(3 * nt));
    keys.resize(par::unique(ctx_, kp, static_cast<std::size_t>(3 * nt)));
    return keys;
  }
  // Drops requests already tried (history) or whose vertex is in the target's link;
  // compacts req; returns the number left.
  I64 filter(Buffer<U64, B>& req) {
    const I64 n = static_cast<I64>(req.size());
    if (n == 0) return 0;
    const U64* rp = req.data();
    const U64* hp = history_.data();
    const I64 nh = static_cast<I64>(history_.size());
    const std::int32_t* so = star_of_.data();
    const StarView sv = view();
    const Buffer<U64, B> big = link_keys_above(kLinkScanMax);
    const LinkQuery lq = link_query(big);
    Buffer<U64, B> out(ctx_, static_cast<std::size_t>(n));
    const std::size_t k = par::copy_if(ctx_, rp, out.data(), static_cast<std::size_t>(n), [=] GDEL_LAMBDA(U64 key) {
      if (sorted_contains(hp, nh, key)) return false;
      const std::int32_t s = so[key_target(key)];
      if (sv.dead(s)) return false;  // a dead star takes no more points
      return !lq.has(s, key_vertex(key));
    });
    out.resize(k);
    req = std::move(out);
    return static_cast<I64>(k);
  }

  void add_history(const Buffer<U64, B>& req) {
    const std::size_t h = history_.size(), n = req.size();
    history_.resize(h + n);
    U64* hp = history_.data() + h;
    const U64* rp = req.data();
    par::parallel_for(ctx_, static_cast<I64>(n), [=] GDEL_LAMBDA(I64 i) { hp[i] = rp[i]; });
    par::sort_keys(ctx_, history_.data(), h + n);
  }

  // Inserts the (sorted, filtered) requests, one thread per target star. Pairs (s, v)
  // with v drowned or submerged in star s go to `gone` as pair_key(s_vertex, v).
  void insert_round(const Buffer<U64, B>& req, Buffer<U64, B>& gone) {
    const I64 n = static_cast<I64>(req.size());
    const U64* rp = req.data();
    const std::int32_t* so = star_of_.data();
    // per-star request ranges
    Buffer<I64, B> heads(ctx_, static_cast<std::size_t>(n));
    const std::size_t nh = par::select_indices(ctx_, static_cast<std::size_t>(n), heads.data(), [=] GDEL_LAMBDA(I64 i) {
      return i == 0 || key_target(rp[i - 1]) != key_target(rp[i]);
    });
    const I64* hp = heads.data();
    // capacity: count + 2 per insertion, doubled for the transient fan, + 2
    Buffer<std::int32_t, B> need(ctx_, static_cast<std::size_t>(nst_));
    std::int32_t* np = need.data();
    const std::int32_t* cnt = count_.data();
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) { np[s] = 0; });
    par::parallel_for(ctx_, static_cast<I64>(nh), [=] GDEL_LAMBDA(I64 j) {
      const I64 a = hp[j], b = (j + 1 < static_cast<I64>(nh)) ? hp[j + 1] : n;
      const std::int32_t s = so[key_target(rp[a])];
      np[s] = 2 * (cnt[s] + 2 * static_cast<std::int32_t>(b - a)) + 4;
    });
    ensure_capacity(np);
    // (GDEL_PROFILE: the round's steps under their own names; the rest is "splay: insert round")
    par::mark(ctx_, "insert: groups, capacity");
    if (debug_) ss_.critical += most_per_star(hp, static_cast<I64>(nh), n);
    // room for gone pairs: every link vertex and every insertion at most once
    Buffer<I64, B> room(ctx_, static_cast<std::size_t>(nh + 1));
    I64* rmp = room.data();
    par::parallel_for(ctx_, static_cast<I64>(nh), [=] GDEL_LAMBDA(I64 j) {
      const I64 a = hp[j], b = (j + 1 < static_cast<I64>(nh)) ? hp[j + 1] : n;
      const std::int32_t s = so[key_target(rp[a])];
      rmp[j] = cnt[s] / 2 + 3 + 3 * (b - a);
    });
    const I64 total = par::counts_to_offsets(ctx_, rmp, static_cast<std::size_t>(nh));
    gone.resize(static_cast<std::size_t>(std::max<I64>(total, 1)));
    U64* gp = gone.data();
    Buffer<I64, B> used(ctx_, static_cast<std::size_t>(nh));
    I64* up = used.data();
    const StarView sv = view();
    const flip::Geo g = g_;
    std::int32_t* ep = error_.data();
    // On the CUDA backend the huge stars (more than 2 * host_build_min() triangles: the
    // coplanar hull faces' stars that build_stars made on the host) take their insertions
    // on the host's cores too, with the same code, while the kernel serves the others:
    // on one GPU thread their every degenerate test cost tens of µs (bench/RESULTS.md,
    // session 14: 0.7 s of the grid's splaying rounds).
    // (host_pick raises it where more stars than host_star_cap() would go)
    I64 host_tri_min = host_build_min() < (I64(1) << 61) ? 2 * host_build_min() : I64(1) << 62;
    std::vector<InsertJob> ijobs;
    const std::vector<I64> huge = host_pick(static_cast<I64>(nh), host_tri_min, 2 * host_gate(), [=] GDEL_LAMBDA(I64 j) {
      return static_cast<I64>(cnt[so[key_target(rp[hp[j]])]]);
    });
    if (!huge.empty()) ijobs = insert_jobs(huge, req, heads, static_cast<I64>(nh), room);
    par::mark(ctx_, "insert: host jobs' inputs");
    // (in memory order: most insertions first, as build_stars takes its stars, ran 55 -> 95
    // ms on the sphere: bench/RESULTS.md, session 44)
    par::for_each_with_scratch(ctx_, static_cast<I64>(nh), geom::kPredicateWork, [=] GDEL_LAMBDA(I64 j, auto work) {
      const I64 a = hp[j], b = (j + 1 < static_cast<I64>(nh)) ? hp[j + 1] : n;
      const vid_t sv_vert = key_target(rp[a]);
      const std::int32_t s = so[sv_vert];
      if (cnt[s] > host_tri_min) return;  // on the host (insert_jobs)
      Tri* T = sv.tri + sv.begin[s];
      std::uint8_t* S = sv.state + sv.begin[s];
      std::int32_t count = sv.count[s];
      std::int32_t nonpos = 0;
      for (std::int32_t q = 0; q < count; ++q) nonpos += (S[q] & kTriNonPositive) ? 1 : 0;
      I64 k = rmp[j];
      const I64 kend = rmp[j + 1];
      for (I64 i = a; i < b; ++i)
        if (insert_recording(g, T, S, count, sv.cap[s], sv_vert, key_vertex(rp[i]), work, gp, k, kend, ep, &nonpos) ==
            kStarDead) {
          sv.killer[s] = key_vertex(rp[i]);
          break;
        }
      sv.count[s] = count;
      up[j] = k - rmp[j];
    }, g.int_all);
    if (!ijobs.empty()) run_insert_jobs(ijobs, gp, up);  // while the kernel runs; then writes back
    par::mark(ctx_, "insert: kernel, host jobs");
    throw_if_error("insertion");
    gone = pack_pairs(gp, rmp, up, static_cast<I64>(nh));
    certify_deaths();
  }

  // Death certificates (ALGORITHMS.md §6.4) of the stars that died since the last call:
  // cert = (killer k, e, t0, t1, t2) with the star's vertex inside their lifted 4-simplex
  // (star_proof with reflect). Stars holding a dead vertex receive these five points
  // (checks()), which removes it from their links.
  void certify_deaths() {
    if (nst_ == 0 || !g_.w) return;
    const StarView sv = view();
    const flip::Geo g = g_;
    std::int32_t* ep = error_.data();
    Buffer<I64, B> fresh(ctx_, static_cast<std::size_t>(nst_));
    I64* fp = fresh.data();
    par::for_each_with_scratch(ctx_, nst_, geom::kPredicateWork, [=] GDEL_LAMBDA(I64 s, auto work) {
      fp[s] = 0;
      if (!sv.dead(s) || sv.cert[5 * s] >= 0) return;
      fp[s] = 1;
      vid_t out[4];
      const vid_t k = sv.killer[s];
      if (!star_proof(g, sv.tri + sv.begin[s], sv.count[s], sv.vert[s], k, out, work, /*reflect=*/true)) {
        ep[0] = 9;
        return;
      }
      sv.cert[5 * s] = k;
      for (int c = 0; c < 4; ++c) sv.cert[5 * s + 1 + c] = out[c];
    }, g.int_all);
    throw_if_error("death certificate");
    ss_.dead += par::reduce_sum(ctx_, fp, static_cast<std::size_t>(nst_));
  }

  // The death certificate of every dead star, host copy: (star vertex, 5 vertices).
  // A certificate holding ∞ (s above the lower hull near the 3-D hull boundary: s inside
  // the vertical prism over a lifted triangle or tet) is left out: the caller certifies
  // such a point by locating it in the output instead.
  std::vector<vid_t> death_certificates() {
    std::vector<vid_t> out;
    if (nst_ == 0) return out;
    auto kl = killer_.to_host();
    auto ce = cert_.to_host();
    auto vv = vert_.to_host();
    for (I64 s = 0; s < nst_; ++s) {
      if (kl[s] < 0 || std::find(ce.begin() + 5 * s, ce.begin() + 5 * s + 5, g_.inf) != ce.begin() + 5 * s + 5) continue;
      out.push_back(vv[s]);
      for (int c = 0; c < 5; ++c) out.push_back(ce[5 * s + c]);
    }
    return out;
  }

  // The pairs recorded per item j in raw[room[j], room[j] + used[j]), gathered, sorted
  // and made unique.
  Buffer<U64, B> pack_pairs(const U64* raw, const I64* room, const I64* used, I64 items) {
    Buffer<I64, B> off(ctx_, static_cast<std::size_t>(items + 1));
    I64* op = off.data();
    par::parallel_for(ctx_, items, [=] GDEL_LAMBDA(I64 j) { op[j] = used[j]; });
    const I64 n = par::counts_to_offsets(ctx_, op, static_cast<std::size_t>(items));
    Buffer<U64, B> packed(ctx_, static_cast<std::size_t>(n));
    U64* pk = packed.data();
    par::parallel_for(ctx_, items, [=] GDEL_LAMBDA(I64 j) {
      for (I64 i = 0; i < used[j]; ++i) pk[op[j] + i] = raw[room[j] + i];
    });
    if (n > 0) {
      par::sort_keys(ctx_, pk, static_cast<std::size_t>(n));
      packed.resize(par::unique(ctx_, pk, static_cast<std::size_t>(n)));
    }
    return packed;
  }

  // For every gone pair (s, v): the proof of v inside star s. v finite: requests
  // (v ← proof); v = ∞: remembered, and handed out by checks().
  void proofs(const Buffer<U64, B>& gone_all, Buffer<U64, B>& next) {
    // A proof is needed only where star v still holds s (§4.4); stars of v that do not
    // exist yet are pulled first (they hold s when T has the edge).
    const vid_t inf = g_.inf;
    Buffer<U64, B> gone(ctx_);
    {
      const I64 n0 = static_cast<I64>(gone_all.size());
      if (n0 == 0) return;
      Buffer<U64, B> rev(ctx_, static_cast<std::size_t>(n0));
      U64* rv = rev.data();
      const U64* ga = gone_all.data();
      par::parallel_for(ctx_, n0, [=] GDEL_LAMBDA(I64 i) {
        const vid_t v = key_vertex(ga[i]);
        rv[i] = v == inf ? ~U64(0) : pair_key(v, key_target(ga[i]));
      });
      par::sort_keys(ctx_, rv, static_cast<std::size_t>(n0));
      Buffer<U64, B> revc(ctx_, static_cast<std::size_t>(n0));
      const std::size_t kr = par::copy_if(ctx_, rv, revc.data(), static_cast<std::size_t>(n0),
                                          [=] GDEL_LAMBDA(U64 k) { return k != ~U64(0); });
      revc.resize(kr);
      if (kr > 0) pull_targets(revc);
      const std::int32_t* so = star_of_.data();
      const StarView sv = view();
      const Buffer<U64, B> big = link_keys_above(kLinkScanMax);
      const LinkQuery lq = link_query(big);
      gone.resize(static_cast<std::size_t>(n0));
      const std::size_t kg = par::copy_if(ctx_, ga, gone.data(), static_cast<std::size_t>(n0), [=] GDEL_LAMBDA(U64 k) {
        // a dead star needs no proofs: its certificate reaches every star holding it
        if (sv.dead(so[key_target(k)])) return false;
        const vid_t v = key_vertex(k);
        if (v == inf) return true;
        const std::int32_t st = so[v];
        return st >= 0 && !sv.dead(st) && lq.has(st, key_target(k));
      });
      gone.resize(kg);
    }
    const I64 n = static_cast<I64>(gone.size());
    ss_.proofs += n;
    next.resize(static_cast<std::size_t>(4 * n));
    if (n == 0) return;
    const U64* gp = gone.data();
    U64* np = next.data();
    const std::int32_t* so = star_of_.data();
    const StarView sv = view();
    const flip::Geo g = g_;
    std::int32_t* ep = error_.data();
    Buffer<vid_t, B> pf(ctx_, static_cast<std::size_t>(4 * n));
    vid_t* pp = pf.data();
    par::for_each_with_scratch(ctx_, n, geom::kPredicateWork, [=] GDEL_LAMBDA(I64 i, auto work) {
      const vid_t s = key_target(gp[i]), v = key_vertex(gp[i]);
      const std::int32_t st = so[s];
      vid_t out[4];
      if (!star_proof(g, sv.tri + sv.begin[st], sv.count[st], s, v, out, work)) {
        ep[0] = 4;
        for (int k = 0; k < 4; ++k) np[4 * i + k] = ~U64(0);
        return;
      }
      for (int k = 0; k < 4; ++k) {
        pp[4 * i + k] = out[k];
        np[4 * i + k] = (v == inf || out[k] == inf) ? ~U64(0) : pair_key(v, out[k]);
      }
    }, g.int_all);
    throw_if_error("confinement proof");
    // proofs of ∞: keep (s -> proof) sorted by s
    Buffer<I64, B> idx(ctx_, static_cast<std::size_t>(n));
    const std::size_t k = par::select_indices(ctx_, static_cast<std::size_t>(n), idx.data(),
                                              [=] GDEL_LAMBDA(I64 i) { return key_vertex(gp[i]) == inf; });
    if (k > 0) {
      const std::size_t h = inf_proof_key_.size();
      inf_proof_key_.resize(h + k);
      inf_proof_.resize(4 * (h + k));
      U64* kp = inf_proof_key_.data();
      vid_t* ip = inf_proof_.data();
      const I64* xp = idx.data();
      par::parallel_for(ctx_, static_cast<I64>(k), [=] GDEL_LAMBDA(I64 j) {
        const I64 i = xp[j];
        kp[h + j] = (U64(static_cast<std::uint32_t>(key_target(gp[i]))) << 32) | U64(h + j);
        for (int q = 0; q < 4; ++q) ip[4 * (h + j) + q] = pp[4 * i + q];
      });
      // sort by star vertex (the low bits keep the proof slot)
      par::sort_keys(ctx_, inf_proof_key_.data(), h + k);
    }
    // drop the ~0 placeholders
    Buffer<U64, B> out(ctx_, next.size());
    const std::size_t m = par::copy_if(ctx_, next.data(), out.data(), next.size(),
                                       [=] GDEL_LAMBDA(U64 key) { return key != ~U64(0); });
    out.resize(m);
    next = std::move(out);
  }

  // Requests from every link triangle created since the last round (then marked
  // checked): tet (s,a,b,c) asks a, b and c for the other three vertices. Also hands
  // the proofs of ∞ to the stars with a link triangle holding both s and ∞.
  void checks(Buffer<U64, B>& next) {
    if (nst_ == 0) return;
    const StarView sv = view();
    const vid_t inf = g_.inf;
    const U64* ikp = inf_proof_key_.data();
    const vid_t* ipp = inf_proof_.data();
    const I64 ni = static_cast<I64>(inf_proof_key_.size());
    Buffer<I64, B> cnt(ctx_, static_cast<std::size_t>(nst_ + 1));
    I64* cp = cnt.data();
    // number of requests per star
    auto inf_proof_of = [=] GDEL_LAMBDA(vid_t x) -> I64 {  // index into inf_proof_, or -1
      const U64 lo = U64(static_cast<std::uint32_t>(x)) << 32;
      I64 a = 0, b = ni;
      while (a < b) {
        const I64 mid = (a + b) / 2;
        if (ikp[mid] < lo) a = mid + 1;
        else b = mid;
      }
      return (a < ni && (ikp[a] >> 32) == (lo >> 32)) ? static_cast<I64>(ikp[a] & 0xffffffffu) : -1;
    };
    // a link vertex whose star died: its certificate's points go to this star
    const std::int32_t* so = star_of_.data();
    const bool weighted = g_.w != nullptr;
    auto dead_vertex = [=] GDEL_LAMBDA(vid_t x) -> std::int32_t {  // the dead star of x, or -1
      if (!weighted || x == inf) return -1;
      const std::int32_t st = so[x];
      return (st >= 0 && sv.dead(st)) ? st : -1;
    };
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      const Tri* T = sv.tri + sv.begin[s];
      const std::uint8_t* S = sv.state + sv.begin[s];
      I64 c = 0;
      if (!sv.dead(s))
        for (std::int32_t i = 0; i < sv.count[s]; ++i) {
          if (tri_kind(S[i]) == kTriNew) c += 9;
          if (ni > 0 && tri_pos(T[i], inf) >= 0) c += 12;
          for (int q = 0; q < 3 && weighted; ++q)
            if (dead_vertex(T[i].v[q]) >= 0) c += 5;
        }
      cp[s] = c;
    });
    const I64 total = par::counts_to_offsets(ctx_, cp, static_cast<std::size_t>(nst_));
    const I64 base = static_cast<I64>(next.size());
    next.resize(static_cast<std::size_t>(base + total));
    U64* np = next.data() + base;
    par::parallel_for(ctx_, nst_, [=] GDEL_LAMBDA(I64 s) {
      Tri* T = sv.tri + sv.begin[s];
      std::uint8_t* S = sv.state + sv.begin[s];
      const vid_t me = sv.vert[s];
      I64 k = cp[s];
      const I64 kend = cp[s + 1];
      for (std::int32_t i = 0; i < sv.count[s] && !sv.dead(s); ++i) {
        const vid_t* v = T[i].v;
        for (int q = 0; q < 3 && weighted; ++q) {
          const std::int32_t d = dead_vertex(v[q]);
          if (d < 0) continue;
          for (int c = 0; c < 5; ++c) {
            const vid_t y = sv.cert[5 * d + c];
            np[k++] = (y < 0 || y == inf || y == me) ? ~U64(0) : pair_key(me, y);
          }
        }
        if (tri_kind(S[i]) == kTriNew) {
          set_kind(S[i], kTriChecked);
          const vid_t tet[4] = {me, v[0], v[1], v[2]};
          for (int a = 1; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
              if (b == a) continue;
              np[k++] = tet[a] == inf ? ~U64(0) : pair_key(tet[a], tet[b]);
            }
        }
        if (ni > 0) {
          const int pi = tri_pos(T[i], inf);
          if (pi >= 0) {
            for (int q = 1; q <= 2; ++q) {
              const vid_t x = v[(pi + q) % 3];
              const I64 pr = inf_proof_of(x);
              for (int w = 0; w < 4; ++w) {
                const vid_t y = pr >= 0 ? ipp[4 * pr + w] : inf;
                np[k++] = (pr < 0 || y == inf || y == me) ? ~U64(0) : pair_key(me, y);
              }
            }
            for (int w = 0; w < 4; ++w) np[k++] = ~U64(0);
          }
        }
      }
      while (k < kend) np[k++] = ~U64(0);
    });
    Buffer<U64, B> out(ctx_, next.size());
    const std::size_t m = par::copy_if(ctx_, next.data(), out.data(), next.size(),
                                       [=] GDEL_LAMBDA(U64 key) { return key != ~U64(0); });
    out.resize(m);
    next = std::move(out);
  }

 private:
  Context<B>& ctx_;
  flip::Geo g_;
  Buffer<std::int32_t, B> star_of_;
  Buffer<vid_t, B> vert_;
  Buffer<I64, B> begin_;
  Buffer<std::int32_t, B> cap_, count_;
  Buffer<vid_t, B> killer_, cert_;  // weighted points: per star, see StarView
  Buffer<Tri, B> tri_;
  Buffer<std::uint8_t, B> state_;
  Buffer<U64, B> history_;
  Buffer<U64, B> inf_proof_key_;  // (star vertex << 32 | proof slot), sorted
  Buffer<vid_t, B> inf_proof_;    // 4 per proof slot
  Buffer<std::int32_t, B> error_;
  I64 nst_ = 0;
  I64 slots_ = 0;
  std::function<void(const Buffer<vid_t, B>&)> pull_;
  HostGeo host_geo_;  // the points on the host, for the huge stars' host jobs
  // GDEL_SPLAY_DEBUG=1: a line per round; 2: also an O(k^2) convexity check of every star
  int debug_ = std::getenv("GDEL_SPLAY_DEBUG") ? std::atoi(std::getenv("GDEL_SPLAY_DEBUG")) : 0;
  SplayStats ss_;
};

}  // namespace gdel::splay
