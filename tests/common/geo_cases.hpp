// flip::Geo's exact forms without a scratch (work = nullptr) on integer input
// (Geo::int_points), and the tiered fast/exact pass that relies on them
// (par::fast_then_exact_tiered); written once over the backend tag and instantiated by
// tests/cpu/gflip3d.cpp (Cpu) and tests/gpu/gflip3d.cu (Cuda).
//
// Checked: on lattice points (most tests exact ties) an exact form given no scratch
// answers exactly what it answers with one, unless ∞'s kernel point takes part without
// Geo::int_all, where it answers kUndecided; without either flag it always answers
// kUndecided; all_integer_points' condition at both scales; that the tiered pass decides
// every item as the plain exact pass does, the scratch-free items in its first tier; and
// (Geo::int_all) that for_each_with_scratch without a scratch gives the same signs.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "flip/geo.hpp"
#include "parallel/exact_batch.hpp"

namespace gdel::test {

// Per tuple (five vertices v): orient4(v), insphere(v[0..3], v[4]), orient3d(v[0..3]) and
// the volume sign of v[1..4] by the exact forms, with a scratch or (scratch = false)
// with work = nullptr. Work: double* (a scratch, or null) or std::nullptr_t (the
// instances without expansions that the library's scratch-free passes run).
inline constexpr int kTests = 4, kOrient = 2;
template <class Work>
GDEL_HD void geo_exact_signs(const flip::Geo& g, const vid_t* v, Work work, std::int8_t* r) {
  r[0] = static_cast<std::int8_t>(g.orient4<true>(v, work));
  r[1] = static_cast<std::int8_t>(g.insphere<true>(v, v[4], work));
  r[2] = static_cast<std::int8_t>(g.orient<true>(v[0], v[1], v[2], v[3], work));
  r[3] = g.volume_sign_exact(v + 1, work);
}
template <class B>
std::vector<std::int8_t> geo_tuple_signs(par::Context<B>& ctx, const flip::Geo& g, const vid_t* up, int T,
                                         bool scratch) {
  using namespace gdel::par;
  Buffer<std::int8_t, B> r(ctx, static_cast<std::size_t>(kTests * T));
  std::int8_t* rp = r.data();
  if (scratch) {
    for_each_with_scratch(ctx, T, geom::kPredicateWork, [=] GDEL_LAMBDA(std::int64_t t, double* work) {
      geo_exact_signs(g, up + 5 * t, work, rp + kTests * t);
    });
  } else {
    parallel_for(ctx, T, [=] GDEL_LAMBDA(std::int64_t t) { geo_exact_signs(g, up + 5 * t, nullptr, rp + kTests * t); });
  }
  return r.to_host();
}

// unit = 2^21: the lattice reaches 2^23, points of the stage at scale 1 only, and the
// kernel point (a quarter) is not of the stage: Geo::int_points. unit = 2^19: everything
// within 2^21, the kernel point included at the quarter scale: Geo::int_all.
template <class B>
void geo_scratch_free_cases(double unit) {
  using namespace gdel::par;
  using flip::Geo;
  Context<B> ctx;
  std::mt19937_64 rng(2026);
  const bool all = unit < 0x1p20;
  // n lattice points: {0..3}^3 scaled by unit and moved by unit: nearly every insphere /
  // orient4 test among them is an exact tie. Slot n is ∞'s kernel point, a multiple of
  // 1/4 (as gFlip3D's centroid of four integer points).
  const int n = 64;
  std::vector<double> xyz(3 * (n + 1));
  for (int i = 0; i < n; ++i) {
    xyz[3 * i + 0] = (i % 4) * unit + unit;
    xyz[3 * i + 1] = ((i / 4) % 4) * unit - unit;
    xyz[3 * i + 2] = (i / 16) * unit;
  }
  xyz[3 * n + 0] = 1.5 * unit + 0.25;
  xyz[3 * n + 1] = 0.5 * unit + 0.25;
  xyz[3 * n + 2] = 1.5 * unit + 0.75;
  std::vector<std::int64_t> sid(n + 1);
  for (int i = 0; i <= n; ++i) sid[i] = (i * 37) % (n + 1);  // a permutation: distinct SoS indices
  Buffer<double, B> P(ctx);
  P.assign(xyz);
  Buffer<std::int64_t, B> S(ctx);
  S.assign(sid);

  // all_integer_points: true here; false with a fraction, past 2^23, or a weight past 2^46;
  // at the quarter scale with the kernel point (n + 1 points) only within 2^21
  ASSERT_TRUE(flip::all_integer_points(ctx, P.data(), nullptr, n));
  EXPECT_FALSE(flip::all_integer_points(ctx, P.data(), nullptr, n + 1));  // the kernel point at scale 1
  EXPECT_EQ(flip::all_integer_points(ctx, P.data(), nullptr, n + 1, geom::kQuarterScale), all);
  for (double bad : {0.5, 0x1p23 + 1.0, -0x1p23 - 1.0}) {
    std::vector<double> q = xyz;
    q[3 * 17 + 1] = bad;
    Buffer<double, B> Q(ctx);
    Q.assign(q);
    EXPECT_FALSE(flip::all_integer_points(ctx, Q.data(), nullptr, n)) << bad;
  }
  {
    std::vector<double> w(n, 0x1p46);
    Buffer<double, B> W(ctx);
    W.assign(w);
    EXPECT_TRUE(flip::all_integer_points(ctx, P.data(), W.data(), n));
    w[5] = 0x1p46 + 2.0;
    W.assign(w);
    EXPECT_FALSE(flip::all_integer_points(ctx, P.data(), W.data(), n));
  }

  // tuples of five distinct vertices; one in eight holds ∞ (vertex n) as v[0]
  const int T = 20000;
  std::vector<vid_t> tup(5 * T);
  for (int t = 0; t < T; ++t) {
    for (int k = 0; k < 5; ++k) {
      vid_t v;
      bool dup;
      do {
        v = (k == 0 && t % 8 == 0) ? vid_t(n) : static_cast<vid_t>(rng() % n);
        dup = false;
        for (int j = 0; j < k; ++j) dup |= tup[5 * t + j] == v;
      } while (dup);
      tup[5 * t + k] = v;
    }
  }
  Buffer<vid_t, B> U(ctx);
  U.assign(tup);
  const vid_t* up = U.data();
  const Geo gi{P.data(), S.data(), static_cast<vid_t>(n), nullptr, !all, all};
  const Geo gp{P.data(), S.data(), static_cast<vid_t>(n), nullptr, false, false};
  const std::vector<std::int8_t> exact = geo_tuple_signs(ctx, gp, up, T, true);
  const std::vector<std::int8_t> free_int = geo_tuple_signs(ctx, gi, up, T, false);
  const std::vector<std::int8_t> free_plain = geo_tuple_signs(ctx, gp, up, T, false);
  long decided = 0, inf_refused = 0, mismatches = 0, ties = 0;
  for (int t = 0; t < T; ++t) {
    const bool has_inf = t % 8 == 0;
    for (int k = 0; k < kTests; ++k) {
      const std::int8_t fi = free_int[kTests * t + k], fp = free_plain[kTests * t + k], ex = exact[kTests * t + k];
      if (ex == kUndecided) ++mismatches;  // with a scratch: always decided
      if (fp != kUndecided) ++mismatches;  // without Geo::int_points: never without a scratch
      // ∞ among a test's points (v[0]): a plain orient3d with ∞ reads the kernel point
      // and is refused without a scratch unless Geo::int_all. orient4 and insphere with
      // ∞ reduce to an orient3d of four finite points, and the volume sign reads v[1..4].
      if (has_inf && k == kOrient && !all) {
        inf_refused += fi == kUndecided;
        if (fi != kUndecided) ++mismatches;
      } else {
        if (fi != ex) ++mismatches;
        decided += fi != kUndecided;
      }
    }
    // the tests the filter leaves (the lattice's cospherical tuples: exact ties)
    const vid_t* v = tup.data() + 5 * t;
    const int f = has_inf ? 1
                          : geom::insphere_filter(&xyz[3 * v[0]], &xyz[3 * v[1]], &xyz[3 * v[2]], &xyz[3 * v[3]],
                                                  &xyz[3 * v[4]]);
    if (f == 0 || f == geom::kUncertain) ++ties;
  }
  std::printf("[geo scratch-free] %d tuples: %ld tests decided without a scratch (%ld insphere tests left by the filter), %ld with ∞ refused\n",
              T, decided, ties, inf_refused);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(inf_refused, all ? 0 : T / 8);
  EXPECT_GT(ties, T / 20);

  // The tiered pass: the items "fast" leaves (two in three) go to exact with a scratch
  // only where they need one. Same signs as the plain exact pass; the first tier (no
  // scratch) takes exactly the tuples without ∞. With a tally (the flip iterations' form:
  // no wait for the host) the count of exact items goes to the counter, not the result.
  Buffer<std::int8_t, B> exd(ctx);
  exd.assign(exact);
  const std::int8_t* exs = exd.data();
  const std::int64_t undecided = T - (T + 2) / 3;
  for (int variant = 0; variant < 4; ++variant) {
    const bool tiered = variant % 2 == 0, tallied = variant >= 2;
    Buffer<std::int8_t, B> r(ctx, static_cast<std::size_t>(kTests * T));
    Buffer<std::int8_t, B> tier(ctx, static_cast<std::size_t>(T));
    Buffer<std::int8_t, B> und(ctx, static_cast<std::size_t>(T));
    Buffer<std::int64_t, B> tally(ctx, 1);
    tally.set(0, 5);
    std::int8_t* rp = r.data();
    std::int8_t* tp = tier.data();
    const std::int64_t m = fast_then_exact_tiered(
        ctx, T, und.data(),
        [=] GDEL_LAMBDA(std::int64_t t) {
          if (t % 3 != 0) return false;
          for (int k = 0; k < kTests; ++k) rp[kTests * t + k] = exs[kTests * t + k];
          tp[t] = 0;
          return true;
        },
        [=] GDEL_LAMBDA(std::int64_t t, auto work) {
          std::int8_t s[kTests];
          geo_exact_signs(gi, up + 5 * t, work, s);
          for (int k = 0; k < kTests; ++k)
            if (s[k] == kUndecided) return false;
          for (int k = 0; k < kTests; ++k) rp[kTests * t + k] = s[k];
          tp[t] = geom::no_scratch(work) ? 1 : 2;
          return true;
        },
        geom::kPredicateWork, tiered, tallied ? tally.data() : nullptr);
    EXPECT_EQ(m, tallied ? 0 : undecided);
    EXPECT_EQ(tally.get(0), tallied ? 5 + undecided : 5);
    const std::vector<std::int8_t> rh = r.to_host(), th = tier.to_host();
    long first = 0;
    for (int t = 0; t < T; ++t) {
      first += th[t] == 1;
      EXPECT_EQ(th[t], t % 3 == 0 ? 0 : (tiered && (all || t % 8 != 0)) ? 1 : 2) << t;
      for (int k = 0; k < kTests; ++k) EXPECT_EQ(rh[kTests * t + k], exact[kTests * t + k]) << t << " " << k;
    }
    std::printf("[tiered pass] tiered=%d tally=%d: %ld of %lld exact items decided without a scratch\n", int(tiered),
                int(tallied), first, static_cast<long long>(undecided));
  }
  // Geo::int_all: for_each_with_scratch without a scratch (the star splaying engine's
  // kernels on integer input) gives the signs of the plain exact pass
  if (all) {
    Buffer<std::int8_t, B> r(ctx, static_cast<std::size_t>(kTests * T));
    std::int8_t* rp = r.data();
    for_each_with_scratch(
        ctx, T, geom::kPredicateWork,
        [=] GDEL_LAMBDA(std::int64_t t, auto work) { geo_exact_signs(gi, up + 5 * t, work, rp + kTests * t); },
        /*scratch_free=*/true);
    EXPECT_EQ(r.to_host(), exact);
  }
}

}  // namespace gdel::test
