// Floating-point expansion arithmetic (Shewchuk 1997, "Adaptive precision floating-point
// arithmetic and fast robust geometric predicates", sections 2.3-2.8), written for gdel.
//
// An expansion is a sum of doubles e[0] + e[1] + ... + e[n-1] stored in a caller-provided
// buffer, components ordered by increasing magnitude and non-overlapping; every routine
// here eliminates zero components, so a zero value is the empty expansion (n == 0) and the
// sign of an expansion is the sign of its last (largest) component.
//
// Preconditions shared by all routines (the predicates' documented input range guarantees
// them, see predicates.hpp):
//  * round-to-nearest, ties-to-even (IEEE 754 default; the device intrinsics of fp.hpp);
//  * no overflow: every magnitude stays below 2^1023, and any operand that is split
//    (the factors of two_product) has magnitude at most 2^995, so 134217729*a is finite;
//  * no underflow: every product's exact value is an integer multiple of 2^-1022, so all
//    results are zero or normal and the error-free transformations are exact.
//
// Length bounds (number of components, before zero elimination shortens them):
//   two_sum / two_diff / two_product : 2
//   sum(e, f)                        : len(e) + len(f)        -> sum_len
//   scale(e, b)                      : 2 len(e)               -> scale_len
//   product(e, f)                    : 2 len(e) len(f)        -> product_len
#pragma once

#include <cstddef>

#include "core/macros.hpp"
#include "geometry/fp.hpp"

namespace gdel::geom::ex {

// ---------------------------------------------------------------------------------------
// Compile-time length bounds
// ---------------------------------------------------------------------------------------
GDEL_HD constexpr int sum_len(int elen, int flen) { return elen + flen; }
GDEL_HD constexpr int scale_len(int elen) { return 2 * elen; }
GDEL_HD constexpr int product_len(int elen, int flen) { return 2 * elen * flen; }
// Scratch doubles needed by product() besides its output.
GDEL_HD constexpr int product_work(int elen) { return scale_len(elen); }

// ---------------------------------------------------------------------------------------
// Error-free transformations of two doubles
// ---------------------------------------------------------------------------------------

// x + y == a + b exactly, x = fl(a + b) (Knuth's branch-free two-sum).
GDEL_HD GDEL_FORCEINLINE void two_sum(double a, double b, double& x, double& y) {
  x = fp::add(a, b);
  const double bv = fp::sub(x, a);   // the part of x that came from b
  const double av = fp::sub(x, bv);  // the part of x that came from a
  y = fp::add(fp::sub(a, av), fp::sub(b, bv));
}

// x + y == a + b exactly, x = fl(a + b); requires |a| >= |b| or a == 0 (Dekker).
GDEL_HD GDEL_FORCEINLINE void fast_two_sum(double a, double b, double& x, double& y) {
  x = fp::add(a, b);
  y = fp::sub(b, fp::sub(x, a));
}

// x + y == a - b exactly, x = fl(a - b).
GDEL_HD GDEL_FORCEINLINE void two_diff(double a, double b, double& x, double& y) {
  x = fp::sub(a, b);
  const double bv = fp::sub(a, x);   // equals b up to the rounding error of x
  const double av = fp::add(x, bv);
  y = fp::add(fp::sub(a, av), fp::sub(bv, b));
}

// Veltkamp/Dekker splitting: a == hi + lo with hi, lo representable in 26 bits each
// (the 53-bit significand split at bit 27; lo carries the sign trick). Needs
// |a| <= 2^995. The subtraction c - a below is exactly what an FMA would swallow.
inline constexpr double kSplitter = 134217729.0;  // 2^27 + 1
GDEL_HD GDEL_FORCEINLINE void split(double a, double& hi, double& lo) {
  const double c = fp::mul(kSplitter, a);
  const double big = fp::sub(c, a);
  hi = fp::sub(c, big);
  lo = fp::sub(a, hi);
}

// x + y == a * b exactly, x = fl(a * b), with b already split into (bhi, blo).
// The four partial products are exact (26 x 26 bits), so the three subtractions peel
// off the rounding error of x exactly (Dekker 1971; Shewchuk Theorem 18).
GDEL_HD GDEL_FORCEINLINE void two_product_presplit(double a, double b, double bhi, double blo,
                                                   double& x, double& y) {
  x = fp::mul(a, b);
  double ahi, alo;
  split(a, ahi, alo);
  const double r1 = fp::sub(x, fp::mul(ahi, bhi));
  const double r2 = fp::sub(r1, fp::mul(alo, bhi));
  const double r3 = fp::sub(r2, fp::mul(ahi, blo));
  y = fp::sub(fp::mul(alo, blo), r3);
}

// x + y == a * b exactly, x = fl(a * b). No FMA is used (see fp.hpp).
GDEL_HD GDEL_FORCEINLINE void two_product(double a, double b, double& x, double& y) {
  double bhi, blo;
  split(b, bhi, blo);
  two_product_presplit(a, b, bhi, blo, x, y);
}

// ---------------------------------------------------------------------------------------
// Expansions
// ---------------------------------------------------------------------------------------

// Writes the non-zero parts of the two-term expansion (lo, hi) to h; returns the length.
GDEL_HD GDEL_FORCEINLINE int store2(double lo, double hi, double* h) {
  int n = 0;
  if (lo != 0.0) h[n++] = lo;
  if (hi != 0.0) h[n++] = hi;
  return n;
}

// h = e + f, zero-eliminating linear merge sum (Shewchuk's Fast-Expansion-Sum, Theorem 13:
// for strongly non-overlapping inputs and round-to-even the output is strongly
// non-overlapping). Returns len(h) <= elen + flen.
//
// Aliasing: h may overlap e when h + flen <= e (h starts at least flen doubles before e):
// each output component is written only after at least one more input component than its
// index has been consumed, so unread components of e are never overwritten. h must not
// overlap f otherwise. This lets an accumulator grow downwards in place (Accumulator).
GDEL_HD inline int sum(int elen, const double* e, int flen, const double* f, double* h) {
  if (elen == 0) {
    for (int k = 0; k < flen; ++k) h[k] = f[k];
    return flen;
  }
  if (flen == 0) {
    for (int k = 0; k < elen; ++k) h[k] = e[k];  // forward copy: h <= e
    return elen;
  }
  int i = 0, j = 0, n = 0;
  const int total = elen + flen;
  double q, hh;
  // Components are consumed in order of increasing magnitude (a merge of e and f).
  if (fp::abs(e[0]) < fp::abs(f[0])) {
    q = e[i++];
  } else {
    q = f[j++];
  }
  if (i + j < total) {
    double g;
    if (j >= flen || (i < elen && fp::abs(e[i]) < fp::abs(f[j]))) {
      g = e[i++];
    } else {
      g = f[j++];
    }
    fast_two_sum(g, q, q, hh);  // |g| >= |q|: g is next in magnitude order
    if (hh != 0.0) h[n++] = hh;
    while (i + j < total) {
      if (j >= flen || (i < elen && fp::abs(e[i]) < fp::abs(f[j]))) {
        g = e[i++];
      } else {
        g = f[j++];
      }
      two_sum(q, g, q, hh);
      if (hh != 0.0) h[n++] = hh;
    }
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

// h = b * e, zero-eliminating (Shewchuk's Scale-Expansion, Theorem 19; preserves the
// non-overlapping, strongly non-overlapping and non-adjacent properties under
// round-to-even). h must not overlap e. Returns len(h) <= 2 elen.
GDEL_HD inline int scale(int elen, const double* e, double b, double* h) {
  if (elen == 0 || b == 0.0) return 0;
  double bhi, blo;
  split(b, bhi, blo);
  int n = 0;
  double q, hh, p1, p0, s;
  two_product_presplit(e[0], b, bhi, blo, q, hh);
  if (hh != 0.0) h[n++] = hh;
  for (int i = 1; i < elen; ++i) {
    two_product_presplit(e[i], b, bhi, blo, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0.0) h[n++] = hh;
    fast_two_sum(p1, s, q, hh);
    if (hh != 0.0) h[n++] = hh;
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

// Negates an expansion in place (exact).
GDEL_HD GDEL_FORCEINLINE void negate(int elen, double* e) {
  for (int k = 0; k < elen; ++k) e[k] = -e[k];
}

// Sign (-1, 0, +1) of an expansion: the sign of its most significant non-zero component.
GDEL_HD GDEL_FORCEINLINE int sign(int elen, const double* e) {
  for (int k = elen - 1; k >= 0; --k) {
    if (e[k] > 0.0) return 1;
    if (e[k] < 0.0) return -1;
  }
  return 0;
}

// Builds an expansion as a sum of terms inside buf[0, cap), growing downwards from the
// end so that each sum() runs in place (see the aliasing rule of sum()). The capacity must
// be at least the sum of the lengths of all added terms. finish() moves the result to
// buf[0, len).
class Accumulator {
 public:
  GDEL_HD Accumulator(double* buf, int cap) : buf_(buf), start_(cap), len_(0) {}
  // Adds the expansion f (which must not lie inside buf).
  GDEL_HD void add(int flen, const double* f) {
    if (flen == 0) return;
    const int s = start_ - flen;
    len_ = sum(len_, buf_ + start_, flen, f, buf_ + s);
    start_ = s;
  }
  GDEL_HD int length() const { return len_; }
  GDEL_HD const double* data() const { return buf_ + start_; }
  GDEL_HD int finish() {
    for (int k = 0; k < len_; ++k) buf_[k] = buf_[start_ + k];  // forward copy: start_ >= 0
    start_ = 0;
    return len_;
  }

 private:
  double* buf_;
  int start_;
  int len_;
};

// h = e * f (scaling e by every component of f and summing). h needs product_len(elen,
// flen) doubles, work needs product_work(elen); neither may overlap e or f.
GDEL_HD inline int product(int elen, const double* e, int flen, const double* f, double* h,
                           double* work) {
  Accumulator acc(h, product_len(elen, flen));
  for (int j = 0; j < flen; ++j) acc.add(scale(elen, e, f[j], work), work);
  return acc.finish();
}

}  // namespace gdel::geom::ex
