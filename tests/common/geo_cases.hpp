// flip::Geo's fast forms on integer input (Geo::int_points), written once over the backend
// tag and instantiated by tests/cpu/gflip3d.cpp (Cpu) and tests/gpu/gflip3d.cu (Cuda).
//
// On points of the integer stage a fast form whose filter fails decides at once with the
// exact form and no work buffer (work = nullptr). Checked here: that decision equals the
// exact form's (evaluated with a work buffer in the deferred pass), on lattice points
// where most tests are exact ties; that it is taken (without the flag the same tests are
// undecided); that tests with ∞ still defer; and all_integer_points' condition.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "flip/geo.hpp"
#include "parallel/exact_batch.hpp"

namespace gdel::test {

// Per tuple (five vertices v): orient4(v), insphere(v[0..3], v[4]), orient3d(v[0..3]) and
// the volume sign of v[1..4], by the fast forms (exact = false) or the exact forms.
inline constexpr int kTests = 4, kOrient = 2;
template <class B>
std::vector<std::int8_t> geo_tuple_signs(par::Context<B>& ctx, const double* xyz, const std::int64_t* sid, int n,
                                         const vid_t* up, int T, bool int_points, bool exact) {
  using namespace gdel::par;
  const flip::Geo g{xyz, sid, static_cast<vid_t>(n), nullptr, int_points};
  Buffer<std::int8_t, B> r(ctx, static_cast<std::size_t>(kTests * T));
  std::int8_t* rp = r.data();
  if (!exact) {
    parallel_for(ctx, T, [=] GDEL_LAMBDA(std::int64_t t) {
      const vid_t* v = up + 5 * t;
      rp[kTests * t + 0] = static_cast<std::int8_t>(g.orient4<false>(v, nullptr));
      rp[kTests * t + 1] = static_cast<std::int8_t>(g.insphere<false>(v, v[4], nullptr));
      rp[kTests * t + 2] = static_cast<std::int8_t>(g.orient<false>(v[0], v[1], v[2], v[3], nullptr));
      rp[kTests * t + 3] = g.volume_sign_fast(v + 1);
    });
  } else {
    for_each_with_scratch(ctx, T, geom::kPredicateWork, [=] GDEL_LAMBDA(std::int64_t t, double* work) {
      const vid_t* v = up + 5 * t;
      rp[kTests * t + 0] = static_cast<std::int8_t>(g.orient4<true>(v, work));
      rp[kTests * t + 1] = static_cast<std::int8_t>(g.insphere<true>(v, v[4], work));
      rp[kTests * t + 2] = static_cast<std::int8_t>(g.orient<true>(v[0], v[1], v[2], v[3], work));
      rp[kTests * t + 3] = g.volume_sign_exact(v + 1, work);
    });
  }
  return r.to_host();
}

template <class B>
void geo_integer_fast_cases() {
  using namespace gdel::par;
  using flip::Geo;
  Context<B> ctx;
  std::mt19937_64 rng(2026);
  // n lattice points: {0..3}^3 scaled by 2^21 (coordinates up to 3 * 2^21 < 2^23) and
  // moved by 2^21: nearly every insphere / orient4 test among them is an exact tie.
  // Slot n is ∞'s kernel point, not integral (as in gFlip3D).
  const int n = 64;
  std::vector<double> xyz(3 * (n + 1));
  for (int i = 0; i < n; ++i) {
    xyz[3 * i + 0] = (i % 4) * 0x1p21 + 0x1p21;
    xyz[3 * i + 1] = ((i / 4) % 4) * 0x1p21 - 0x1p21;
    xyz[3 * i + 2] = (i / 16) * 0x1p21;
  }
  xyz[3 * n + 0] = 1.5 * 0x1p21 + 0.25;
  xyz[3 * n + 1] = 0.5 * 0x1p21 + 0.25;
  xyz[3 * n + 2] = 1.5 * 0x1p21 + 0.25;
  std::vector<std::int64_t> sid(n + 1);
  for (int i = 0; i <= n; ++i) sid[i] = (i * 37) % (n + 1);  // a permutation: distinct SoS indices
  Buffer<double, B> P(ctx);
  P.assign(xyz);
  Buffer<std::int64_t, B> S(ctx);
  S.assign(sid);

  // all_integer_points: true here; false with a fraction, past 2^23, or a weight past 2^46
  ASSERT_TRUE(flip::all_integer_points(ctx, P.data(), nullptr, n));
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

  // tuples of five distinct vertices; one in eight holds ∞ (vertex n)
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
  const std::vector<std::int8_t> fast_int = geo_tuple_signs(ctx, P.data(), S.data(), n, up, T, true, false);
  const std::vector<std::int8_t> fast_plain = geo_tuple_signs(ctx, P.data(), S.data(), n, up, T, false, false);
  const std::vector<std::int8_t> exact = geo_tuple_signs(ctx, P.data(), S.data(), n, up, T, false, true);
  long decided_by_int = 0, inf_deferred = 0, mismatches = 0;
  for (int t = 0; t < T; ++t) {
    const bool has_inf = t % 8 == 0;
    for (int k = 0; k < kTests; ++k) {
      const std::int8_t fi = fast_int[kTests * t + k], fp = fast_plain[kTests * t + k], ex = exact[kTests * t + k];
      if (fp == kUndecided && fi != kUndecided) ++decided_by_int;
      // ∞ among a test's points (∞ is v[0]): the integer decision does not apply to a
      // plain orient3d with ∞ (the kernel point is not integral), which stays as without
      // the flag. orient4 and insphere with ∞ reduce to an orient3d of four finite
      // points, and the volume sign reads v[1..4]: those are decided.
      const bool inf_in_test = has_inf && k == kOrient;
      if (inf_in_test) {
        inf_deferred += fi == kUndecided;
        if (fi != fp) ++mismatches;
      } else if (fi == kUndecided) {
        ++mismatches;  // finite integer points: always decided
      }
      if (fi != kUndecided && fi != ex) ++mismatches;
      if (fp != kUndecided && fp != ex) ++mismatches;
    }
  }
  std::printf("[geo integer] %d tuples: %ld tests decided by the integer fast form, %ld with ∞ deferred\n", T,
              decided_by_int, inf_deferred);
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(decided_by_int, T / 4);  // ties (7 502 of the 80 000 tests on the CPU run)
  EXPECT_GT(inf_deferred, 0);
}

}  // namespace gdel::test
