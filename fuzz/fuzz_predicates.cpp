// libFuzzer target: gdel's exact predicates against exact GMP evaluation (the oracle of
// tests/cpu/predicates_oracle.hpp). The input decodes to five points, five weights and five
// distinct indices inside the documented exact range (src/geometry/predicates.hpp); every
// stage (filter, exact, filter+exact, SoS, lifting SoS) of orient3d, insphere and power must
// agree with the oracle. A disagreement prints the case and aborts.
//
// Input: byte 0 picks the decoding, the rest feeds it (missing bytes read as 0):
//   0  raw doubles (8 bytes each), exponents folded into the exact range, NaN/Inf -> 0
//   1  small integers (int8) times a common power of two: coplanar, cospherical, equal points
//   2  as 1, then one coordinate moved by a few ulps: near-degenerate
//   3  integer points of one sphere (x^2+y^2+z^2 = 2925), scaled and translated: cospherical
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpu/predicates_oracle.hpp"
#include "geometry/predicates.hpp"

namespace {

using namespace gdel::geom;
using gdel_test::Case;
using gdel_test::Generator;
using gdel_test::Oracle;

class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t u8() { return pos_ < n_ ? d_[pos_++] : 0; }
  std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{u8()} << (8 * i);
    return v;
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_, pos_ = 0;
};

// x with its binary exponent folded into [lo, hi] (|x| in [2^(lo-1), 2^hi)); 0 stays 0.
double fold(double x, int lo, int hi) {
  if (!std::isfinite(x) || x == 0.0) return 0.0;
  int e;
  const double m = std::frexp(x, &e);  // |m| in [0.5, 1)
  const int span = hi - lo + 1;
  e = lo + (((e - lo) % span) + span) % span;
  return std::ldexp(m, e);
}
// Coordinates: 2^-152 <= |x| <= 2^200; weights: 2^-356 <= |w| <= 2^400.
double coord(double x) { return fold(x, -151, 200); }
double weight(double w) { return fold(w, -355, 400); }

Case decode(const std::uint8_t* data, std::size_t size) {
  Bytes b(data, size);
  Case k{};
  const int mode = b.u8() % 4;
  if (mode == 0) {
    for (auto& p : k.p)
      for (double& c : p) c = coord(std::bit_cast<double>(b.u64()));
    for (double& w : k.w) w = weight(std::bit_cast<double>(b.u64()));
  } else if (mode == 1 || mode == 2) {
    const int s = b.i8() % 120;  // common scale 2^s
    for (auto& p : k.p)
      for (double& c : p) c = std::ldexp(static_cast<double>(b.i8() % 8), s);
    for (double& w : k.w) w = std::ldexp(static_cast<double>(b.i8() % 16), 2 * s);
    if (mode == 2) {
      const int i = b.u8() % 5, c = b.u8() % 3, steps = 1 + b.u8() % 4;
      const double to = (b.u8() & 1) ? INFINITY : -INFINITY;
      double v = k.p[i][c];
      for (int t = 0; t < steps; ++t) v = std::nextafter(v, to);
      k.p[i][c] = coord(v);
      if (b.u8() & 1) k.w[i] = weight(std::nextafter(k.w[i], to));
    }
  } else {
    const auto& sphere = Generator::sphere_points();
    const int s = b.i8() % 100;
    const double ox = b.i8() % 64, oy = b.i8() % 64, oz = b.i8() % 64;
    for (auto& p : k.p) {
      const auto& q = sphere[b.u8() % sphere.size()];
      p[0] = coord(std::ldexp(q[0] + ox, s));
      p[1] = coord(std::ldexp(q[1] + oy, s));
      p[2] = coord(std::ldexp(q[2] + oz, s));
    }
    for (double& w : k.w) w = 0.0;
  }
  // Distinct indices: the low byte is the position, the high bits come from the input
  // (any order, sometimes beyond 2^32).
  const bool wide = b.u8() & 1;
  for (int i = 0; i < 5; ++i) {
    const std::uint64_t hi = wide ? (b.u64() >> 12) : b.u8();
    k.id[i] = static_cast<std::int64_t>((hi << 8) | static_cast<std::uint64_t>(i));
  }
  return k;
}

[[noreturn]] void mismatch(const char* what, const Case& k, int got, int want) {
  std::fprintf(stderr, "fuzz_predicates: %s = %d, GMP says %d\n", what, got, want);
  for (int i = 0; i < 5; ++i) {
    std::fprintf(stderr, "  p%d = (%a, %a, %a) w = %a id = %lld\n", i, k.p[i][0], k.p[i][1], k.p[i][2], k.w[i],
                 static_cast<long long>(k.id[i]));
  }
  std::abort();
}

void expect(const char* what, const Case& k, int got, int want) {
  if (got != want) mismatch(what, k, got, want);
}

// A filter may say "uncertain", never a wrong sign.
void expect_filter(const char* what, const Case& k, int got, int want) {
  if (got != kUncertain && got != want) mismatch(what, k, got, want);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Case k = decode(data, size);
  static std::vector<double> work(kPredicateWork);
  double* w = work.data();
  const double *a = k.p[0], *b = k.p[1], *c = k.p[2], *d = k.p[3], *e = k.p[4];
  const double* W = k.w;
  static Oracle o;

  // orient3d
  o.load(k, 4, false);
  const int x3 = o.orient3d();
  expect_filter("orient3d_filter", k, orient3d_filter(a, b, c, d), x3);
  expect("orient3d_exact", k, orient3d_exact(a, b, c, d, w), x3);
  expect("orient3d", k, orient3d(a, b, c, d, w), x3);
  const int s3 = orient3d_sos(a, b, c, d, k.id[0], k.id[1], k.id[2], k.id[3], w);
  expect("orient3d_sos", k, s3, x3 != 0 ? x3 : o.em_sos(4, k.id));

  // insphere
  o.load(k, 5, false);
  const int xi = o.lifted();
  expect_filter("insphere_filter", k, insphere_filter(a, b, c, d, e), xi);
  expect("insphere_exact", k, insphere_exact(a, b, c, d, e, w), xi);
  expect("insphere", k, insphere(a, b, c, d, e, w), xi);
  const int si = insphere_sos(a, b, c, d, e, k.id[0], k.id[1], k.id[2], k.id[3], k.id[4], w);
  const int li = insphere_lift_sos(a, b, c, d, e, k.id[0], k.id[1], k.id[2], k.id[3], k.id[4], w);
  if (xi != 0) {
    expect("insphere_sos", k, si, xi);
    expect("insphere_lift_sos", k, li, xi);
  } else {
    expect("insphere_lift_sos (degenerate)", k, li, o.lift_sos(k.id));
    expect("insphere_sos (degenerate)", k, si, o.em_sos(5, k.id));
  }

  // power
  o.load(k, 5, true);
  const int xp = o.lifted();
  expect_filter("power_filter", k, power_filter(a, b, c, d, e, W[0], W[1], W[2], W[3], W[4]), xp);
  expect("power_exact", k, power_exact(a, b, c, d, e, W[0], W[1], W[2], W[3], W[4], w), xp);
  expect("power", k, power(a, b, c, d, e, W[0], W[1], W[2], W[3], W[4], w), xp);
  const int lp = power_lift_sos(a, b, c, d, e, W[0], W[1], W[2], W[3], W[4], k.id[0], k.id[1], k.id[2], k.id[3],
                                k.id[4], w);
  expect("power_lift_sos", k, lp, xp != 0 ? xp : o.lift_sos(k.id));
  const int sp = power_sos(a, b, c, d, e, W[0], W[1], W[2], W[3], W[4], k.id[0], k.id[1], k.id[2], k.id[3], k.id[4], w);
  expect("power_sos", k, sp, xp != 0 ? xp : o.em_sos(5, k.id));
  return 0;
}
