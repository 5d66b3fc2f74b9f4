// The generic evaluator behind every exact predicate and every simulation-of-simplicity
// minor: the sign of a "lifted orientation" determinant
//
//        | q_0  1 |
//   det  | ...  1 |      q_i = selected coordinates of the lifted point i,
//        | q_k  1 |            lifted point = (x, y, z, h),  h = x^2 + y^2 + z^2 - w,
//
// with k = number of selected columns (1..4) and k+1 rows. Columns are selected by a mask
// (bit 0 x, bit 1 y, bit 2 z, bit 3 h) and always appear in the order x, y, z, h, ones.
//   k = 3, columns xyz   : the raw orientation determinant, = -orient3d (conventions.hpp)
//   k = 4, columns xyzh  : the raw lifted determinant,     = -insphere / -power
//   k = 1..3 with h      : the lifted orient1/2/3 minors of the SoS tables
//   k = 1, 2 without h   : coordinate differences and orient2d on a coordinate pair
//
// Integer stage (exact, before the expansions): when every entry is a small integer, the
// determinant in 128-bit integers (det_ones_int below, with its bound).
//
// Exact stage: Laplace expansion along the last selected column, recursively, on the
// *untranslated* coordinates (translating would turn every entry into a two-component
// difference and multiply the expansion lengths by 2^degree). Entries are exact: a
// coordinate is one double, h is the exact expansion of x^2 + y^2 + z^2 - w (at most 7
// components). Expansion lengths (k = number of columns, m = length of the entries of the
// column expanded at that level; only the outermost column can be h):
//   len(1, m) = 2m                     (q_0 - q_1)
//   len(k, m) = (k+1) * 2m * len(k-1, 1)
//   => orient1 2, orient2 12, orient3 96; lifted orient1 14, lifted orient2 84,
//      lifted orient3 672; insphere (m = 6) 5760; power (m = 7) 6720.
// Work (doubles, result included):
//   work(1, 1) = 2, work(1, m > 1) = 4m
//   work(k, m) = len(k, m) + max(work(k-1, 1), 3 len(k-1, 1) + [m > 1] m)
//   => orient3 132, lifted orient3 715, insphere 6054, power 7015.
//
// Filter stage (generic, used for the SoS minors; the three main predicates have their own
// tuned filters in filters.hpp): subtract the last row from the others, which leaves the
// k x k determinant of differences D_ij = q_ij - q_kj; evaluate it by the same Laplace
// expansion, with the permanent alongside. See filters.hpp for the error analysis.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "core/macros.hpp"
#include "geometry/expansion.hpp"
#include "geometry/filter_bounds.hpp"
#include "geometry/fp.hpp"

namespace gdel::geom {

inline constexpr int kUncertain = 2;  // returned by filters when the sign is not certain

// Whether an exact evaluation goes without a scratch (see predicates.hpp): always for
// work of type std::nullptr_t (known at compile time), else when the pointer is null.
GDEL_HD constexpr bool no_scratch(std::nullptr_t) { return true; }
GDEL_HD constexpr bool no_scratch(const double* work) { return work == nullptr; }

// Column mask bits.
inline constexpr unsigned kColX = 1u, kColY = 2u, kColZ = 4u, kColH = 8u;

namespace detail {

// Up to five lifted points: coordinates and weights (h = |p|^2 - w).
struct LiftedRows {
  const double* p[5];
  double w[5];
};

// --- compile-time length / work bounds -------------------------------------------------
GDEL_HD constexpr int lift_len(bool weighted) { return weighted ? 7 : 6; }
// (Iterative, not recursive: these are also evaluated at run time in device code, where a
// recursive call would need a dynamically sized stack.)
GDEL_HD constexpr int det_len(int k, int m) {  // len(k, m) = m * 2 * prod_{j=2..k} 2 (j + 1)
  int len = 2;
  for (int j = 2; j <= k; ++j) len *= 2 * (j + 1);
  return m * len;
}
GDEL_HD constexpr int cmax(int a, int b) { return a > b ? a : b; }
GDEL_HD constexpr int det_work(int k, int m) {
  int work = 2;  // work(1, 1); the inner levels always have m = 1
  for (int j = 2; j <= k; ++j) {
    const int mj = j == k ? m : 1;
    work = det_len(j, mj) + cmax(work, 3 * det_len(j - 1, 1) + (mj > 1 ? mj : 0));
  }
  return k == 1 && m > 1 ? 4 * m : work;
}
static_assert(det_len(3, 1) == 96 && det_len(4, 6) == 5760 && det_len(4, 7) == 6720);
static_assert(det_work(3, 1) == 132 && det_work(3, 7) == 715 && det_work(4, 7) == 7015);

// Exact h = x^2 + y^2 + z^2 - w of point r into h[0..7); returns the length.
GDEL_HD inline int lift_exact(const LiftedRows& R, int r, double* h) {
  const double* p = R.p[r];
  double a[2], b[2], c[2], t[4];
  ex::two_product(p[0], p[0], a[1], a[0]);
  ex::two_product(p[1], p[1], b[1], b[0]);
  ex::two_product(p[2], p[2], c[1], c[0]);
  const int la = ex::store2(a[0], a[1], a);
  const int lb = ex::store2(b[0], b[1], b);
  const int lc = ex::store2(c[0], c[1], c);
  const int lt = ex::sum(la, a, lb, b, t);
  int lh = ex::sum(lt, t, lc, c, h);
  if (R.w[r] != 0.0) {
    const double mw = -R.w[r];
    double s[7];
    for (int k = 0; k < lh; ++k) s[k] = h[k];
    lh = ex::sum(lh, s, 1, &mw, h);
  }
  return lh;
}

// Exact determinant det[[q_rows[i], 1]] over the columns cols[0..K) (ascending, h only
// last). Result in buf[0, len); needs det_work(K, m) doubles at buf.
template <int K>
GDEL_HD int det_ones_exact(const LiftedRows& R, const int* rows, const int* cols, bool weighted,
                           double* buf) {
  const int c = cols[K - 1];
  if constexpr (K == 1) {
    if (c != 3) {
      double x, y;
      ex::two_diff(R.p[rows[0]][c], R.p[rows[1]][c], x, y);
      return ex::store2(y, x, buf);
    } else {
      const int m = lift_len(weighted);
      double* h0 = buf + 2 * m;
      double* h1 = h0 + m;
      const int l0 = lift_exact(R, rows[0], h0);
      const int l1 = lift_exact(R, rows[1], h1);
      ex::negate(l1, h1);
      return ex::sum(l0, h0, l1, h1, buf);
    }
  } else {
    const int m = c == 3 ? lift_len(weighted) : 1;
    const int cap = det_len(K, m);
    constexpr int sub_cap = det_len(K - 1, 1);
    double* sub = buf + cap;
    double* tmp = sub + sub_cap;
    double* hb = tmp + 2 * sub_cap;
    ex::Accumulator acc(buf, cap);
    for (int i = 0; i <= K; ++i) {
      int sub_rows[K];
      for (int t = 0, u = 0; t <= K; ++t)
        if (t != i) sub_rows[u++] = rows[t];
      const int sl = det_ones_exact<K - 1>(R, sub_rows, cols, weighted, sub);
      if (sl == 0) continue;
      // Cofactor sign of entry (i, K-1) in the (K+1)x(K+1) matrix (ones column last).
      const double sgn = ((i + K - 1) & 1) ? -1.0 : 1.0;
      if (c != 3) {
        const double v = R.p[rows[i]][c];
        acc.add(ex::scale(sl, sub, sgn * v, tmp), tmp);
      } else {
        const int hl = lift_exact(R, rows[i], hb);
        for (int j = 0; j < hl; ++j) acc.add(ex::scale(sl, sub, sgn * hb[j], tmp), tmp);
      }
    }
    return acc.finish();
  }
}

// --- integer stage ----------------------------------------------------------------------
// Between the filter and the expansions: when every entry of a determinant is a small
// integer, its exact value fits a signed 128-bit integer and is computed directly. These
// are exactly the inputs whose tests are mostly exact ties (lattice points: grids, voxel
// data, integer points on a common sphere), decided by the expansions (thousands of
// operations and up to 54 KB of work buffer for a lifted determinant) and then by the
// simulation of simplicity, whose minors go the same way. The result is the same sign:
// this is an evaluation order, not a change of predicate.
//
// Condition, checked per call on the entries used: every coordinate is an integer with
// |x| <= 2^23 and every weight an integer with |w| <= 2^46 (a weight of 0 for unweighted
// input). Bound (no overflow): a coordinate difference is at most 2^24; a height
// h = x^2 + y^2 + z^2 - w at most 3 * 2^46 + 2^46 = 2^48 (computed in int64), a height
// difference at most 2^49. With D the K x K matrix of differences to the last row
// (det[[q_i, 1]] = det D), only the last column can be h, and the permanent of D bounds
// every partial sum of the Laplace expansion along that column: for K = 4 it is at most
// 4 * 2^49 * 3! * (2^24)^3 < 2^127 - 1, for K <= 3 far less. No rounded floating-point
// operation is involved (so no contraction concern; the scale below is an exact product),
// and the bounds hold on host and device alike.
//
// Quarters: when some entry is not such an integer, the stage tries the entries times 4
// (weights times 16) under the same condition, i.e. multiples of 1/4 with |x| <= 2^21.
// The products are exact (a power of two), and det[[q_i, 1]] is multiplied by a positive
// constant (4 per coordinate column, 16 for the height column: h scales by 16), so its
// sign is unchanged. This takes in the centroid of four integer points: gFlip3D's kernel
// point K of ∞ (flip::Geo::int_all), so that on integer input every exact evaluation,
// ∞'s included, is integer arithmetic.
inline constexpr double kIntCoordMax = 0x1p23;
inline constexpr double kIntWeightMax = 0x1p46;
inline constexpr double kIntQuarter = 4.0;  // the second scale tried
using i128 = __int128;

// x as v when x is an integer with |x| <= max (false for NaN, infinities, fractions).
GDEL_HD GDEL_FORCEINLINE bool small_integer(double x, double max, std::int64_t& v) {
  if (!(fp::abs(x) <= max)) return false;
  v = static_cast<std::int64_t>(x);  // |x| <= 2^46: defined, truncates
  return static_cast<double>(v) == x;
}

// The entries of p that `need` asks for (bit c < 3: coordinate c; bit 3: the height) as
// integers of the stage at `scale` into q: q[c] = p[c] * scale, q[3] = x^2 + y^2 + z^2 - w
// with w times scale^2 (the height needs x, y, z and w); false when one of them is not
// such an integer (small_integer). Coordinates not asked for are left as they are, q[3]
// is 0 without the height. The one conversion of a point to the integer stage
// (int_entries, int_rows_at, and predicates.hpp's integer_point).
GDEL_HD GDEL_FORCEINLINE bool int_point(const double* p, double w, double scale, unsigned need,
                                        std::int64_t (&q)[4]) {
  const bool lifted = need >> 3 & 1u;
  for (int c = 0; c < 3; ++c)
    if ((lifted || (need >> c & 1u)) && !small_integer(fp::mul(p[c], scale), kIntCoordMax, q[c])) return false;
  std::int64_t wi = 0;
  if (lifted && !small_integer(fp::mul(w, fp::mul(scale, scale)), kIntWeightMax, wi)) return false;
  q[3] = lifted ? q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - wi : 0;
  return true;
}

// The entries of det[[q_rows[i], 1]] over the columns cols[0..K), times `scale` (weights
// times scale^2), into q when they are all integers in the stage's range; false otherwise.
template <int K>
GDEL_HD bool int_entries(const LiftedRows& R, const int* rows, const int* cols, double scale,
                         std::int64_t (&q)[K + 1][K]) {
  unsigned need = 0;
  for (int j = 0; j < K; ++j) need |= 1u << cols[j];
  for (int i = 0; i <= K; ++i) {
    std::int64_t v[4] = {0, 0, 0, 0};
    if (!int_point(R.p[rows[i]], R.w[rows[i]], scale, need, v)) return false;
    for (int j = 0; j < K; ++j)  // (by selects: cols may be known only at run time)
      q[i][j] = cols[j] == 0 ? v[0] : cols[j] == 1 ? v[1] : cols[j] == 2 ? v[2] : v[3];
  }
  return true;
}

// The integer stage's K x K matrix of differences to the last row, D_ij = q_ij - q_Kj (see
// above: |D_ij| <= 2^24 in a coordinate column, <= 2^49 in the h column, exact in int64),
// when the entries are integers at scale 1 or at the quarter scale; false otherwise.
template <int K>
GDEL_HD bool int_differences(const LiftedRows& R, const int* rows, const int* cols, std::int64_t (&d)[K][K]) {
  std::int64_t q[K + 1][K];
  if (!int_entries<K>(R, rows, cols, 1.0, q) && !int_entries<K>(R, rows, cols, kIntQuarter, q)) return false;
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) d[i][j] = q[i][j] - q[K][j];
  return true;
}

// The exact product of two int64 values (a widening multiply).
GDEL_HD GDEL_FORCEINLINE i128 mul_wide(std::int64_t a, std::int64_t b) { return i128(a) * i128(b); }

// det D in 128-bit integers throughout: valid for every D of the stage (bound above).
template <int K>
GDEL_HD i128 det_int_wide(const std::int64_t (&q)[K][K]) {
  i128 d[K][K];
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) d[i][j] = i128(q[i][j]);
  if constexpr (K == 1) {
    return d[0][0];
  } else if constexpr (K == 2) {
    return d[0][0] * d[1][1] - d[1][0] * d[0][1];
  } else {
    // 2x2 minors of columns 0, 1 over row pairs (a, b)
    auto m2 = [&](int a, int b) { return d[a][0] * d[b][1] - d[b][0] * d[a][1]; };
    // 3x3 minor of columns 0..2 over rows a < b < c (Laplace along column 2)
    auto m3 = [&](int a, int b, int c) { return d[a][2] * m2(b, c) - d[b][2] * m2(a, c) + d[c][2] * m2(a, b); };
    if constexpr (K == 3) {
      return m3(0, 1, 2);
    } else {  // Laplace along column 3
      return -d[0][3] * m3(1, 2, 3) + d[1][3] * m3(0, 2, 3) - d[2][3] * m3(0, 1, 3) + d[3][3] * m3(0, 1, 2);
    }
  }
}

// The narrow form: when every entry of the first K - 1 columns of D is at most 2^20 in
// magnitude, the minors of those columns fit int64, and only the last step (Laplace along
// the last column, whose entries may be any of the stage's: up to 2^49) needs 128 bits,
// in K widening products. Bound, with N = 2^20: a 2x2 minor is at most 2 N^2 = 2^41, a 3x3
// minor of columns 0..2 (all coordinate columns: only the last column can be h) at most
// 3 N * 2 N^2 = 1.5 * 2^62 < 2^63 - 1, every partial sum of it at most 2^62; the last step
// sums K <= 4 products of at most 2^49 * 1.5 * 2^62 < 2^113. This is most lattice input
// (the grid's 512^3 cells, the sphere generator's points up to radius 2^19) at a fraction
// of the 128-bit form's multiplies. Returns false (nothing evaluated) when it does not
// apply.
inline constexpr std::int64_t kIntNarrowMax = std::int64_t(1) << 20;
template <int K>
GDEL_HD bool det_int_narrow(const std::int64_t (&d)[K][K], i128& det) {
  if constexpr (K == 1) {
    det = d[0][0];
    return true;
  } else {
    bool narrow = true;
    for (int i = 0; i < K; ++i)
      for (int j = 0; j + 1 < K; ++j) narrow &= d[i][j] >= -kIntNarrowMax && d[i][j] <= kIntNarrowMax;
    if (!narrow) return false;
    constexpr int L = K - 1;  // the last column
    if constexpr (K == 2) {
      det = mul_wide(d[0][0], d[1][L]) - mul_wide(d[1][0], d[0][L]);
    } else {
      auto m2 = [&](int a, int b) { return d[a][0] * d[b][1] - d[b][0] * d[a][1]; };
      if constexpr (K == 3) {
        det = mul_wide(d[0][L], m2(1, 2)) - mul_wide(d[1][L], m2(0, 2)) + mul_wide(d[2][L], m2(0, 1));
      } else {
        const std::int64_t m01 = m2(0, 1), m02 = m2(0, 2), m03 = m2(0, 3), m12 = m2(1, 2), m13 = m2(1, 3),
                           m23 = m2(2, 3);
        const std::int64_t m123 = d[1][2] * m23 - d[2][2] * m13 + d[3][2] * m12;
        const std::int64_t m023 = d[0][2] * m23 - d[2][2] * m03 + d[3][2] * m02;
        const std::int64_t m013 = d[0][2] * m13 - d[1][2] * m03 + d[3][2] * m01;
        const std::int64_t m012 = d[0][2] * m12 - d[1][2] * m02 + d[2][2] * m01;
        det = -mul_wide(d[0][L], m123) + mul_wide(d[1][L], m023) - mul_wide(d[2][L], m013) +
              mul_wide(d[3][L], m012);
      }
    }
    return true;
  }
}

// Sign of det[[q_rows[i], 1]] over the columns cols[0..K) into `sign`, when the integer
// stage applies (see above: integers, else quarters); false otherwise (nothing evaluated).
// A last column of zeros (the heights of points on one sphere about the origin: every
// insphere test of the sphere generator) gives 0 at once; then the narrow form where it
// applies, else the 128-bit one.
template <int K>
GDEL_HD bool det_ones_int(const LiftedRows& R, const int* rows, const int* cols, int& sign) {
  std::int64_t d[K][K];
  if (!int_differences<K>(R, rows, cols, d)) return false;
  bool zero_column = true;
  for (int i = 0; i < K; ++i) zero_column &= d[i][K - 1] == 0;
  if (zero_column) {
    sign = 0;
    return true;
  }
  i128 det;
  if (!det_int_narrow<K>(d, det)) det = det_int_wide<K>(d);
  sign = (det > 0) - (det < 0);
  return true;
}

// out[first + i] = get(r) for r the i-th set bit of `mask` below N (ascending): the
// gather of a minor's rows or columns, by selects over fixed indices (an array indexed at
// run time would be put in local memory on the device).
template <int N, int M, class T, class Get>
GDEL_HD GDEL_FORCEINLINE void gather_masked(unsigned mask, int first, Get get, T (&out)[M]) {
  int slot = first;
  for (int r = 0; r < N; ++r) {
    if (!(mask >> r & 1u)) continue;
    const T v = get(r);
    for (int s = 0; s < M; ++s)
      if (slot == s) out[s] = v;
    ++slot;
  }
}

// The integer stage over a whole SoS walk (predicates.hpp): the N sorted rows converted
// once, x, y, z (and, for a lifted walk, h) of each as int64 at one scale, so that every
// minor of the walk is integer arithmetic on registers, with no conversion, filter or
// expansion per minor. One scale for every row: a minor's sign does not depend on it
// (a positive factor per column, see above), so the signs are the per-minor stage's.
struct IntRows {
  std::int64_t q[5][4];
};

// Q from R's first N rows at `scale` (weights times scale^2); false when some entry is
// not an integer of the stage's range (small_integer; h only when lifted).
template <int N>
GDEL_HD bool int_rows_at(const LiftedRows& R, bool lifted, double scale, IntRows& Q) {
  for (int r = 0; r < N; ++r)
    if (!int_point(R.p[r], R.w[r], scale, lifted ? 15u : 7u, Q.q[r])) return false;
  return true;
}
template <int N>
GDEL_HD bool int_rows(const LiftedRows& R, bool lifted, IntRows& Q) {
  return int_rows_at<N>(R, lifted, 1.0, Q) || int_rows_at<N>(R, lifted, kIntQuarter, Q);
}

// Sign of det[[q_r, 1]] over the rows of the mask `rows` (bit r: row r of Q) and the
// columns of the mask `cols` (kColX.. kColH, K = 1..3 of them; K + 1 rows). The K x K
// matrix of differences to the last row (as det_ones_int) is placed at the lower right of
// a 3 x 3 one whose other entries are those of the identity (same determinant), every
// index fixed at compile time (gather_masked). Its first two
// columns then hold coordinate differences (|d| <= 2^24) or 0 / 1, only the third can be
// a height difference (|d| <= 2^49): the 2x2 minors of the first two fit int64 (<= 2^49)
// and the last step is three widening products (< 2^100), for every entry of the stage.
GDEL_HD inline int int_minor_sign(const IntRows& Q, unsigned rows, unsigned cols) {
  const int k = int(cols & 1u) + int(cols >> 1 & 1u) + int(cols >> 2 & 1u) + int(cols >> 3 & 1u);
  const int first = 3 - k;  // padding rows and columns 0..first-1
  struct Row {
    std::int64_t v[3];
  };
  Row e[4] = {};  // the kept rows go to e[first..3], their columns to e[.].v[first..2]
  gather_masked<5>(
      rows, first,
      [&](int r) {
        Row row{};  // (the padding columns: 0)
        gather_masked<4>(cols, first, [&](int c) { return Q.q[r][c]; }, row.v);
        return row;
      },
      e);
  std::int64_t d[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] = i < first ? std::int64_t(i == j) : e[i].v[j] - e[3].v[j];
  auto m2 = [&](int a, int b) { return d[a][0] * d[b][1] - d[b][0] * d[a][1]; };
  const i128 det = mul_wide(d[0][2], m2(1, 2)) - mul_wide(d[1][2], m2(0, 2)) + mul_wide(d[2][2], m2(0, 1));
  return (det > 0) - (det < 0);
}

// Exact sign of det[[q_rows[i], 1]] over cols[0..K): the integer stage where it applies,
// else the expansions (det_work(K, m) doubles at work). Without a scratch (see
// predicates.hpp: work of type std::nullptr_t, or a null double*): the integer stage's
// sign, or kUncertain where it does not apply.
template <int K, class Work>
GDEL_HD int det_ones_exact_sign(const LiftedRows& R, const int* rows, const int* cols, bool weighted, Work work) {
  static_assert(std::is_same_v<Work, double*> || std::is_same_v<Work, std::nullptr_t>);
  int s;
  if (det_ones_int<K>(R, rows, cols, s)) return s;
  if constexpr (std::is_same_v<Work, std::nullptr_t>) {
    return kUncertain;
  } else {
    if (!work) return kUncertain;
    return ex::sign(det_ones_exact<K>(R, rows, cols, weighted, work), work);
  }
}

// -s for a sign, kUncertain kept (the exact forms given no scratch).
GDEL_HD constexpr int negate_sign(int s) { return s == kUncertain ? s : -s; }

// FP value and rounding-error-free "absolute" value of h (see filters.hpp for counts):
//   h  = ((x*x + y*y) + z*z) - w,   ha = ((x*x + y*y) + z*z) + |w|.
GDEL_HD GDEL_FORCEINLINE void lift_fp(const double* p, double w, double& h, double& ha) {
  const double s = fp::add(fp::add(fp::mul(p[0], p[0]), fp::mul(p[1], p[1])), fp::mul(p[2], p[2]));
  h = fp::sub(s, w);
  ha = fp::add(s, fp::abs(w));
}

// The K x K determinant (K = 1..3) of d in binary64, by the filters' evaluation order
// (Laplace along the last column for K = 3); with each sub replaced by an add and d by its
// absolute values (Abs), the matching permanent.
template <int K, bool Abs = false>
GDEL_HD GDEL_FORCEINLINE double det_small(const double (&d)[3][3]) {
  auto pm = [](double a, double b) { return Abs ? fp::add(a, b) : fp::sub(a, b); };
  if constexpr (K == 1) {
    return d[0][0];
  } else if constexpr (K == 2) {
    return pm(fp::mul(d[0][0], d[1][1]), fp::mul(d[1][0], d[0][1]));
  } else {  // + d02*m(1,2) - d12*m(0,2) + d22*m(0,1)
    const double m12 = pm(fp::mul(d[1][0], d[2][1]), fp::mul(d[2][0], d[1][1]));
    const double m02 = pm(fp::mul(d[0][0], d[2][1]), fp::mul(d[2][0], d[0][1]));
    const double m01 = pm(fp::mul(d[0][0], d[1][1]), fp::mul(d[1][0], d[0][1]));
    return fp::add(pm(fp::mul(d[0][2], m12), fp::mul(d[1][2], m02)), fp::mul(d[2][2], m01));
  }
}

// Generic filter for det[[q_rows[i], 1]], K = 1..3 columns; -1/+1 or kUncertain.
// Rounding counts N (see filter_bounds.hpp): the entries D_ij = q_ij - q_Kj carry 1
// rounding for a coordinate column, 5 for the h column (4 inside h, 1 for the difference);
// a 2x2 determinant adds a product and a subtraction; the 3x3 Laplace step adds a product
// and two additions. N = e0 (K=1); e0+e1+2 (K=2); e0+e1+2 + e2+3 (K=3).
template <int K>
GDEL_HD int det_ones_filter(const LiftedRows& R, const int* rows, const int* cols) {
  double d[3][3], a[3][3];
  int n_round[3];
  for (int j = 0; j < K; ++j) {
    const int c = cols[j];
    const int last = rows[K];
    if (c != 3) {
      n_round[j] = 1;
      for (int i = 0; i < K; ++i) {
        d[i][j] = fp::sub(R.p[rows[i]][c], R.p[last][c]);
        a[i][j] = fp::abs(d[i][j]);
      }
    } else {
      n_round[j] = 5;
      double hl, hal;
      lift_fp(R.p[last], R.w[last], hl, hal);
      for (int i = 0; i < K; ++i) {
        double h, ha;
        lift_fp(R.p[rows[i]], R.w[rows[i]], h, ha);
        d[i][j] = fp::sub(h, hl);
        a[i][j] = fp::add(ha, hal);
      }
    }
  }
  const double det = det_small<K>(d), perm = det_small<K, true>(a);
  int n = n_round[0];
  if constexpr (K >= 2) n += n_round[1] + 2;
  if constexpr (K == 3) n += n_round[2] + 3;
  if (!(perm >= bounds::kMinorThreshold && perm <= bounds::kMaxFinite)) return kUncertain;
  const double err = fp::mul(bounds::coefficient(n), perm);
  if (det > err) return 1;
  if (-det > err) return -1;
  return kUncertain;
}

// Filter then exact for K = 1..3 columns. Work: det_work(K, m) doubles (nullptr: see
// det_ones_exact_sign).
template <int K>
GDEL_HD int det_ones_sign(const LiftedRows& R, const int* rows, const int* cols, bool weighted,
                          double* work) {
  if constexpr (K == 1) {
    if (cols[0] != 3) {  // a coordinate difference: compare exactly
      const double u = R.p[rows[0]][cols[0]], v = R.p[rows[1]][cols[0]];
      return (u > v) - (u < v);
    }
  }
  const int f = det_ones_filter<K>(R, rows, cols);
  if (f != kUncertain) return f;
  return det_ones_exact_sign<K>(R, rows, cols, weighted, work);
}

// Decodes a column mask into ascending column ids; returns the count.
GDEL_HD GDEL_FORCEINLINE int mask_columns(unsigned mask, int* cols) {
  int k = 0;
  for (int c = 0; c < 4; ++c)
    if (mask & (1u << c)) cols[k++] = c;
  return k;
}

// Sign of the minor with rows `rows` (k+1 of them) and columns `mask` (k = 1..3 bits).
GDEL_HD inline int minor_sign(const LiftedRows& R, const int* rows, unsigned mask, bool weighted,
                              double* work) {
  int cols[4];
  const int k = mask_columns(mask, cols);
  switch (k) {
    case 1: return det_ones_sign<1>(R, rows, cols, weighted, work);
    case 2: return det_ones_sign<2>(R, rows, cols, weighted, work);
    case 3: return det_ones_sign<3>(R, rows, cols, weighted, work);
    default: return 0;  // not reached: callers pass 1..3 columns
  }
}

}  // namespace detail
}  // namespace gdel::geom
