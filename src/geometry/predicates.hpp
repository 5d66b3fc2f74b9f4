// Exact geometric predicates of gdel: orient3d, insphere, power (weighted insphere), the
// lifted minors, and their symbolically perturbed (never-zero) variants. Header-only,
// usable on host and device (GDEL_HD). Sign conventions: src/mesh/conventions.hpp.
//
//   orient3d(a,b,c,d)           = sign det[b-a, c-a, d-a]            (CGAL's sign; the
//                                 negative of Shewchuk's orient3d). > 0: positive tet.
//   insphere(a,b,c,d,e)         > 0 iff e is strictly inside the circumsphere of abcd
//                                 when orient3d(a,b,c,d) > 0 (it flips with abcd's sign).
//   power(a,b,c,d,e; wa..we)    > 0 iff the lifted point e+ = (e, |e|^2 - we) lies strictly
//                                 below the hyperplane through a+..d+ (abcd positive), i.e.
//                                 e is in conflict. Equal weights give insphere exactly.
// In determinant form, with rows (x, y, z, h, 1) and h = |p|^2 - w:
//   orient3d = -det4[(p, 1)],  insphere = -det5[(p, |p|^2, 1)],  power = -det5[(p, h, 1)].
//
// Every predicate P comes in stages:
//   P_filter(...)        -1 / +1 when the floating-point filter is certain, else kUncertain
//                        (a filter never certifies 0: exact zeros go to the exact stage).
//   P_exact(..., work)   exact sign: in 128-bit integers when every entry is a small
//                        integer (minors.hpp, "integer stage"), else by expansion
//                        arithmetic in the caller's work buffer.
//   P(..., work)         filter, then exact.
//   P_sos(..., ids, work)  Edelsbrunner-Muecke simulation of simplicity by ORIGINAL input
//                        indices (distinct): never 0; antisymmetric in (point, index) pairs.
//   insphere_lift_sos / power_lift_sos: perturbation of the lifting only (see below).
// Every work buffer of kPredicateWork doubles is large enough for every function here
// (per-function sizes: kOrient3dWork, kInsphereWork, kPowerWork, kMinorWork). The exact
// and SoS forms take the work as `Work`: double* (a scratch), or std::nullptr_t (none, at
// compile time: `nullptr`). Without a scratch (nullptr_t, or a null double*) they decide
// what the integer stage decides (every evaluation over points of the stage:
// integer_point below) and return kUncertain otherwise; their SoS walks run on the points
// converted to integers once (detail::IntRows) wherever those are of the stage. The
// nullptr_t instances hold no expansions and no per-minor walks: the scratch-free exact
// passes (par::for_each_with_scratch) run them with fewer registers and no spills
// (bench/RESULTS.md, session 42).
//
// ---------------------------------------------------------------------------------------
// EXACT INPUT RANGE
//   coordinates: 0 or 2^-152 <= |x| <= 2^200     (about 1.75e-46 .. 1.6e60)
//   weights:     0 or 2^-356 <= |w| <= 2^400
// Within this range every result here is exact (filters included) and every SoS sign is
// well defined. Derivation:
//  * No underflow. A non-zero double x with |x| >= 2^-152 is an integer multiple of
//    L = 2^(-152-52) = 2^-204; a weight with |w| >= 2^-356 is a multiple of 2^-408 = L^2.
//    Sums of multiples of 2^k are multiples of 2^k, products of multiples of 2^i and 2^j
//    are multiples of 2^(i+j), and rounding a multiple of 2^k (k >= -1074) to binary64
//    gives a multiple of 2^k. The predicates are polynomials of degree at most 5 in the
//    coordinates (h and w count as degree 2), so every quantity ever computed -- filter
//    intermediates, expansion components, the split halves and partial products inside
//    two_product -- is a multiple of L^5 = 2^-1020: zero or normal, never subnormal.
//  * No overflow. |h| <= 3 * 2^400 + 2^400 = 2^402. The largest determinant is the 5x5
//    lifted one, whose permanent is at most 5! * (2^200)^3 * 2^402 < 2^1009; every partial
//    sum and every expansion component is bounded by (1 + 2^-52) times the permanent of the
//    terms it sums, < 2^1010 < 2^1023. Split operands (factors of two_product) are
//    coordinates, components of h (< 2^403) or of minors of degree <= 3 (< 2^606), all far
//    below the 2^995 that keeps 134217729 * a finite.
// Outside the range: the filters stay correct for any finite input with |x| <= 2^200 and
// |w| <= 2^400 (their underflow thresholds handle tiny inputs, infinities and NaN give
// kUncertain), but the exact stage may lose bits (and needs finite input). Every sign here
// is invariant under multiplying all coordinates by 2^k and all weights by 2^(2k), so an
// API layer can move an input whose spread fits (max/min non-zero magnitude <= 2^352) into
// the range exactly. Inputs at scales below about 2^-80 (insphere/power) or 2^-270
// (orient3d) are in range but always miss the filter (its underflow threshold) and go to
// the exact stage.
// ---------------------------------------------------------------------------------------
//
// Simulation of simplicity (E-M, *_sos). Points are sorted by ascending original index
// (sorting network; the parity of the swaps flips the sign). Each coordinate entry (r, c)
// of the sorted rows is perturbed by eps^(2^(d r + c)): a smaller index, then an earlier
// coordinate (x, y, z, h) gets the larger perturbation; orient3d perturbs x, y, z
// (d = 3), insphere/power perturb the four coordinates of the lifted points (x, y, z, h)
// (d = 4). The perturbed sign is the sign of the first non-zero term of the sequence
// in sos_tables.hpp, generated by scripts/gen_sos.py; every minor is evaluated exactly
// (filter + exact). The indices must be distinct (duplicates defeat the perturbation).
//
// Lifting perturbation (Devillers-Teillaud style, *_lift_sos). If the exact sign is 0,
// the heights are perturbed as h_i + eps^(1 + rank_i) where rank 0 is the LARGEST index:
// the point with the largest index is raised the most (its weight lowered), so a later
// point on a common sphere is outside. The determinant is linear in the heights, so the
// sign is that of the first non-zero derivative dP/dh_i, taken in decreasing index order;
// dP/dh_i = (-1)^(i+1) orient3d(the other four points in their order), i = 0..4 the
// argument position (so for e: -orient3d(a,b,c,d)). If all five vanish (five coplanar
// points) the positions' perturbation decides, ordered below every lifting term (see
// detail::lift_sos_degenerate; orient3d_sos uses the same position perturbation, so
// lifted and plain decisions belong to one perturbed configuration). Never 0.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>

#include "core/macros.hpp"
#include "geometry/expansion.hpp"
#include "geometry/filter_bounds.hpp"
#include "geometry/filters.hpp"
#include "geometry/fp.hpp"
#include "geometry/minors.hpp"
#include "geometry/sos_tables.hpp"

namespace gdel::geom {

// ---------------------------------------------------------------------------------------
// Range and work sizes
// ---------------------------------------------------------------------------------------
inline constexpr int kCoordMinExp = -152;
inline constexpr int kCoordMaxExp = 200;
inline constexpr int kWeightMinExp = -356;
inline constexpr int kWeightMaxExp = 400;
static_assert(kCoordMaxExp == bounds::kFilterCoordMaxExp && kWeightMaxExp == bounds::kFilterWeightMaxExp);

GDEL_HD constexpr bool coordinate_in_range(double x) {
  const double a = x < 0.0 ? -x : x;
  return x == 0.0 || (a >= 0x1p-152 && a <= 0x1p200);
}
GDEL_HD constexpr bool weight_in_range(double w) {
  const double a = w < 0.0 ? -w : w;
  return w == 0.0 || (a >= 0x1p-356 && a <= 0x1p400);
}

inline constexpr std::size_t kOrient3dWork = detail::det_work(3, 1);                    // 132
inline constexpr std::size_t kInsphereWork = detail::det_work(4, detail::lift_len(false));  // 6054
inline constexpr std::size_t kPowerWork = detail::det_work(4, detail::lift_len(true));      // 7015
inline constexpr std::size_t kMinorWork = detail::det_work(3, detail::lift_len(true));      // 715
// Enough for every function of this header, SoS variants included.
inline constexpr std::size_t kPredicateWork = kPowerWork;
static_assert(kPredicateWork >= kOrient3dWork && kPredicateWork >= kInsphereWork &&
              kPredicateWork >= kMinorWork && kPredicateWork == 7015);

namespace detail {

// Sorts idx[0..N) ascending with a sorting network (N = 4 or 5), applying the same swaps
// to perm; returns the number of swaps (for distinct indices its parity is the parity of
// the sorting permutation).
template <int N>
GDEL_HD int sort_network(std::int64_t* idx, int* perm) {
  static_assert(N == 4 || N == 5);
  constexpr int kPairs4[5][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}, {1, 2}};
  constexpr int kPairs5[9][2] = {{0, 1}, {3, 4}, {2, 4}, {2, 3}, {0, 3},
                                 {0, 2}, {1, 4}, {1, 3}, {1, 2}};
  constexpr int n = N == 4 ? 5 : 9;
  int swaps = 0;
  for (int k = 0; k < n; ++k) {
    const int i = N == 4 ? kPairs4[k][0] : kPairs5[k][0];
    const int j = N == 4 ? kPairs4[k][1] : kPairs5[k][1];
    if (idx[i] > idx[j]) {
      const std::int64_t t = idx[i];
      idx[i] = idx[j];
      idx[j] = t;
      const int q = perm[i];
      perm[i] = perm[j];
      perm[j] = q;
      ++swaps;
    }
  }
  return swaps;
}

// The N points p (weights w when weighted) as rows sorted by ascending SoS index ids
// (sort_network): R.p / R.w in that order, rows N..4 empty. Returns the number of swaps
// (its parity is the sorting permutation's).
template <int N>
GDEL_HD int sorted_rows(const double* const* p, const double* w, const std::int64_t* ids, bool weighted,
                        LiftedRows& R) {
  std::int64_t idx[N];
  int perm[N];
  for (int i = 0; i < N; ++i) idx[i] = ids[i], perm[i] = i;
  const int swaps = sort_network<N>(idx, perm);
  for (int i = 0; i + 1 < N; ++i) assert(idx[i] != idx[i + 1] && "SoS indices must be distinct");
  for (int r = 0; r < 5; ++r) {
    R.p[r] = r < N ? p[perm[r]] : nullptr;
    R.w[r] = r < N && weighted ? w[perm[r]] : 0.0;
  }
  return swaps;
}

// The minors of a walk, minor(rows, cols) with bit masks of the N sorted rows and of the
// columns (kColX..kColH, 1..3 of them), in three stages:
//  * x, y, z over four rows (the lift walk's first terms, which decide the ties of points
//    on a common sphere: -orient3d of those rows): orient3d's filter;
//  * the integer stage on the rows converted once, at the first minor that needs it
//    (int_rows / int_minor_sign: integer input, every index fixed at compile time);
//  * else, with a scratch, filter + exact per minor (minor_sign, out of line); without one
//    kUncertain, which ends the walk (the signs of all three stages are the same).
// The std::nullptr_t instance holds no expansions (bench/RESULTS.md, session 42).
GDEL_NOINLINE GDEL_HD inline int minor_sign_masked(const LiftedRows& R, unsigned rows, unsigned cols, bool weighted,
                                                   double* work) {
  int rr[5], k = 0;
  for (int r = 0; r < 5; ++r)
    if (rows >> r & 1u) rr[k++] = r;
  return minor_sign(R, rr, cols, weighted, work);
}
template <int N, class Work>
struct WalkMinor {
  const LiftedRows& R;
  bool weighted;
  Work work;
  // Zeroed although int_rows writes it before any read: left uninitialized, nvcc kept
  // the walk's values in local memory (propose_flip<true>: 832 B of stack and 1 614 B of
  // spill stores against 272 and 0; bench/RESULTS.md, session 43).
  IntRows Q{};
  int integer = 0;  // Q: 0 not yet converted, 1 converted, -1 not of the integer stage
  GDEL_HD int operator()(unsigned rows, unsigned cols) {
    if (cols == (kColX | kColY | kColZ)) {  // the four rows' pointers (gather_masked)
      const double* p[4] = {nullptr, nullptr, nullptr, nullptr};
      gather_masked<5>(rows, 0, [&](int r) { return R.p[r]; }, p);
      const int f = orient3d_filter(p[0], p[1], p[2], p[3]);
      if (f != kUncertain) return -f;  // det[[q, 1]] over x, y, z = -orient3d
    }
    if (integer == 0) integer = int_rows<N>(R, N == 5, Q) ? 1 : -1;
    if (integer > 0) return int_minor_sign(Q, rows, cols);
    if constexpr (std::is_same_v<Work, std::nullptr_t>) {
      return kUncertain;
    } else {
      if (!work) return kUncertain;
      return minor_sign_masked(R, rows, cols, weighted, work);
    }
  }
};

// Sign of the perturbed raw determinant det[(q, 1)] of the sorted rows, given that its
// unperturbed value is 0: the first non-zero term of the generated table.
// kUncertain where a minor is (no scratch, not of the integer stage).
template <class Minor>
GDEL_HD int sos_table_walk(bool lifted, Minor& minor) {
  const int n = lifted ? sos::kLifted4Terms : sos::kOrient3Terms;
  for (int t = 0; t < n; ++t) {
    const sos::SosTerm term = lifted ? sos::lifted4_term(t) : sos::orient3_term(t);
    if (term.cols == 0) return term.sign;
    const int s = minor(term.rows, term.cols);
    if (s == kUncertain) return kUncertain;
    if (s != 0) return term.sign * s;
  }
  assert(false && "SoS table must end with a constant term");
  return 1;
}

// Lifting-first perturbation given that the exact value is 0: the sign of the perturbed
// det5 of the sorted rows. The model: sorted row r (ascending original index) is the
// lifted point (x + d^(2^(3r)), y + d^(2^(3r+1)), z + d^(2^(3r+2)), h + e_r) with e_r
// larger for a larger index, and every power of e dominating every power of d (terms are
// compared by their d-degree first, then by e). The determinant is linear in each height,
// so its terms are: for each set E of position perturbations (distinct rows and columns,
// at most 3 entries, taken in increasing d-exponent = increasing bitmask), the pure term,
// then the terms with one e_r in decreasing e order; each coefficient is a signed minor of
// the unperturbed matrix with rows (x, y, z, h, 1). E = {} gives the exact heights'
// derivatives dP/dh_r = +-orient3d(other four); five coplanar points go on to position
// terms (never the pure E-M table, whose order would not be compatible with this one).
// Every minor has at most 3 columns (the pure term of E = {} is the exact value, skipped;
// any other term loses a column to E or to an e_r): no 4-column evaluator is compiled in
// (on the GPU that path's registers and stack were the kernels'; RESULTS.md, session 41).
template <class Minor>
GDEL_HD int lift_walk(Minor& minor) {
  // sign of the permutation sigma (rows -> columns)
  auto parity = [](const int* sigma) {
    int inv = 0;
    for (int i = 0; i < 5; ++i)
      for (int j = i + 1; j < 5; ++j) inv += sigma[i] > sigma[j];
    return (inv & 1) ? -1 : 1;
  };
  for (unsigned E = 0; E < (1u << 15); ++E) {
    int row_of_col[3] = {-1, -1, -1};
    unsigned used_rows = 0;
    bool ok = true;
    for (int bit = 0; bit < 15 && ok; ++bit) {
      if (!(E & (1u << bit))) continue;
      const int r = bit / 3, c = bit % 3;
      if ((used_rows & (1u << r)) || row_of_col[c] >= 0) ok = false;
      used_rows |= 1u << r;
      row_of_col[c] = r;
    }
    if (!ok) continue;
    unsigned free_cols = 0;  // the unperturbed x, y, z columns left
    for (int c = 0; c < 3; ++c)
      if (row_of_col[c] < 0) free_cols |= 1u << c;
    // the term with only E (pure; E = {} is the exact value, known to be 0), then e_r
    for (int extra = (E == 0 ? 4 : 5); extra >= 0; --extra) {
      // extra == 5: pure term; else e on row `extra`
      if (extra < 5 && (used_rows & (1u << extra))) continue;
      int sigma[5];
      const unsigned all_rows = used_rows | (extra < 5 ? 1u << extra : 0u);
      for (int r = 0; r < 5; ++r) sigma[r] = -1;
      for (int c = 0; c < 3; ++c)
        if (row_of_col[c] >= 0) sigma[row_of_col[c]] = c;
      if (extra < 5) sigma[extra] = 3;
      // remaining rows (ascending) take the remaining columns (ascending)
      int cols[5];
      int nc = 0;
      for (int c = 0; c < 5; ++c) {
        const bool taken = (c < 3 && row_of_col[c] >= 0) || (c == 3 && extra < 5);
        if (!taken) cols[nc++] = c;
      }
      for (int r = 0, j = 0; r < 5; ++r)
        if (!(all_rows & (1u << r))) sigma[r] = cols[j++];
      // the minor over the remaining rows and the columns mask + the ones (mask 0: the
      // 1x1 determinant [1])
      const unsigned mask = free_cols | (extra < 5 ? 0u : unsigned(kColH));
      assert((mask & 15u) != 15u);
      const int m = mask == 0 ? 1 : minor(31u & ~all_rows, mask);
      if (m == kUncertain) return kUncertain;
      if (m != 0) return parity(sigma) * m;
    }
  }
  assert(false && "unreachable: E = {x, y, z} with an e term is the minor 1");
  return 1;
}

// Sign of the perturbed det[(q, 1)] of the N sorted rows R (N = 4: orient3d's table, 5:
// the lifted one) given that its unperturbed value is 0; kUncertain without a scratch
// where the integer stage does not apply.
template <int N, class Work>
GDEL_HD int sos_walk(const LiftedRows& R, bool weighted, Work work) {
  WalkMinor<N, Work> minor{R, weighted, work};
  return sos_table_walk(N == 5, minor);
}

template <class Work>
GDEL_HD int orient3d_exact_rows(const LiftedRows& R, Work work) {
  const int rows[4] = {0, 1, 2, 3};
  const int cols[3] = {0, 1, 2};
  return negate_sign(det_ones_exact_sign<3>(R, rows, cols, false, work));
}

template <class Work>
GDEL_HD int lifted_exact_rows(const LiftedRows& R, bool weighted, Work work) {
  const int rows[5] = {0, 1, 2, 3, 4};
  const int cols[4] = {0, 1, 2, 3};
  return negate_sign(det_ones_exact_sign<4>(R, rows, cols, weighted, work));
}

// E-M SoS of insphere/power given that the exact value is 0.
template <class Work>
GDEL_HD int lifted_sos_degenerate(const double* const* p, const double* w, const std::int64_t* ids, bool weighted,
                                  Work work) {
  LiftedRows R;
  const int swaps = sorted_rows<5>(p, w, ids, weighted, R);
  const int v = sos_walk<5>(R, weighted, work);  // sign of the perturbed det5 (sorted rows)
  return (swaps & 1) ? v : negate_sign(v);       // value = -det5(original order)
}

// The lifting-first perturbation (lift_walk) given that the exact value is 0; kUncertain
// without a scratch where the integer stage does not apply.
template <class Work>
GDEL_HD int lift_sos_degenerate(const double* const* p, const double* w, const std::int64_t* ids, bool weighted,
                                Work work) {
  LiftedRows R;
  const int swaps = sorted_rows<5>(p, w, ids, weighted, R);
  WalkMinor<5, Work> minor{R, weighted, work};
  const int v = lift_walk(minor);
  return (swaps & 1) ? v : negate_sign(v);  // value = -det5(original order)
}

}  // namespace detail

// ---------------------------------------------------------------------------------------
// Small-integer stage: exact in binary64, for filter-stage callers
// ---------------------------------------------------------------------------------------
// On points whose coordinates are multiples of 1/4 (integer_point at kQuarterScale: the
// caller guarantees it), a determinant of coordinate differences evaluated in binary64 is
// exact when every intermediate value, a multiple of its granularity, stays below 2^53:
//  * orient3d and every SoS minor over x, y, z columns only (k <= 3 columns, differences
//    to one row, all |d| <= D): 2x2 minors <= 2 D^2 (multiples of 2^-4), products and
//    partial sums of the 3x3 value <= 6 D^3 (multiples of 2^-6). With D <= 2^14 every
//    value is below 6 * 2^42 < 2^45 at a granularity of 2^-6: 51 bits, exact.
//  * insphere over five points with integer coordinates (integer_point at scale 1),
//    as insphere_filter evaluates it (translated to e, |d| <= D): l_i = |d_i|^2 <= 3 D^2,
//    2x2 minors <= 2 D^2, 3x3 minors <= 6 D^3, each l_i M_i <= 18 D^5, every partial sum
//    <= 72 D^5. With D <= 2^9 that is below 72 * 2^45 < 2^52: exact.
//  * five points on one sphere about the origin (integers with |x| <= 2^25, so that
//    h = |p|^2 < 2^53 is exact) have a lifted determinant of exactly 0: its h column is
//    h times the ones column.
//  * a lift walk's minors with the h column (integer points, |x| <= 2^23: h = |p|^2 and
//    its differences exact, at most Hd): the column h is last, the other columns are x, y, z
//    differences (at most D), so the 3x3 value's products and partial sums are at most
//    6 Hd D^2 and the 2x2 value at most 2 Hd D. A computed Hd D^2 (or Hd D) of at most 2^49
//    is at most 2^49 (1 + 2^-51) exactly: every value below 2^53, exact.
// A certified 0 goes on through the exact forms' own SoS walks (sos_table_walk, lift_walk)
// with SmallMinor evaluating the minors the same way; a minor past these bounds answers
// kUncertain, and so does the whole evaluation. The signs are the exact forms' (the same
// determinants, evaluated exactly): an evaluation order like the integer stage, for
// filter-stage code that would decide the exact ties of lattice input (grids, voxels,
// integer points on a sphere) without an exact pass. Only integers and multiples of 1/4
// are involved, so no rounding happens and contraction could not change a value either.
// No algorithm calls it yet: inlined into flip::Geo's fast forms it made every fast
// kernel heavier (gFlip3D's proposals 89 -> 126-148 registers) and uniform input up to
// 12 % slower, the star splaying engine's kernels slower still, while the grid's
// proposals gained nothing (their time is the walks' instructions, serialized in a warp,
// wherever they run): bench/RESULTS.md, session 47. Tried first in the exact proposals'
// own kernel for integer input (a face per thread, session 49): the grid's pass 20 -> 13
// ms, under the runs' noise, and the sphere 3-7 % slower (its spans are past the stage's,
// which then only adds work); not kept. Left to try: the stage only where the input's
// extent keeps every span within it.
inline constexpr double kSmallOrientSpan = 0x1p14;
inline constexpr double kSmallInsphereSpan = 0x1p9;
inline constexpr double kSmallSphereCoord = 0x1p25;
inline constexpr double kSmallHeightProduct = 0x1p49;

namespace detail {
// The minors of an SoS walk (predicates above: WalkMinor's interface) in binary64, exact
// under the bound above; kUncertain for the h column or past the bound.
struct SmallMinor {
  const LiftedRows& R;
  bool lifted;  // a lift walk over integer points: minors with the h column too
  GDEL_HD int operator()(unsigned rows, unsigned cols) const {
    const bool with_h = (cols & kColH) != 0;
    if (with_h && !lifted) return kUncertain;
    const int k = int(cols & 1u) + int(cols >> 1 & 1u) + int(cols >> 2 & 1u) + int(with_h);
    const double* p[4] = {nullptr, nullptr, nullptr, nullptr};
    gather_masked<5>(rows, 0, [&](int r) { return R.p[r]; }, p);
    int c[3] = {0, 0, 0};
    gather_masked<4>(cols, 0, [&](int j) { return j; }, c);
    const double* last = k == 1 ? p[1] : k == 2 ? p[2] : p[3];
    auto h = [](const double* q) {  // |q|^2 (exact here)
      double v, va;
      lift_fp(q, 0.0, v, va);
      return v;
    };
    const double hl = with_h ? h(last) : 0.0;
    double d[3][3] = {};
    double span = 0, hspan = 0;  // the largest coordinate and height differences
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i < k && j < k) {
          const bool hc = c[j] == 3;  // (h is the last column when present)
          d[i][j] = hc ? fp::sub(h(p[i]), hl) : fp::sub(p[i][c[j]], last[c[j]]);
          if (hc) hspan = fp::abs(d[i][j]) > hspan ? fp::abs(d[i][j]) : hspan;
          else span = fp::abs(d[i][j]) > span ? fp::abs(d[i][j]) : span;
        }
    if (!with_h && !(span <= kSmallOrientSpan)) return kUncertain;
    if (with_h && !(fp::mul(k == 3 ? fp::mul(span, span) : k == 2 ? span : 1.0, hspan) <= kSmallHeightProduct))
      return kUncertain;
    const double det = k == 1 ? det_small<1>(d) : k == 2 ? det_small<2>(d) : det_small<3>(d);
    return (det > 0) - (det < 0);
  }
};

// The SoS walk of a certified tie in the small-integer stage (N = 4: orient3d_sos's table;
// N = 5: the lift walk over integer points).
template <int N>
GDEL_HD int small_tie(const double* const* p, const std::int64_t* ids) {
  LiftedRows R;
  const int swaps = sorted_rows<N>(p, nullptr, ids, false, R);
  SmallMinor minor{R, N == 5};
  int v;  // as the exact forms (lift_sos_degenerate, orient3d_sos)
  if constexpr (N == 5) v = lift_walk(minor);
  else v = sos_table_walk(false, minor);
  return (swaps & 1) ? v : negate_sign(v);
}
}  // namespace detail

// orient3d_sos's sign, or kUncertain where the small-integer stage does not decide it.
// Every coordinate must be a multiple of 1/4 (see above).
GDEL_HD inline int orient3d_sos_small(const double* a, const double* b, const double* c, const double* d,
                                      std::int64_t ia, std::int64_t ib, std::int64_t ic, std::int64_t id) {
  FilterValue fv;
  const int s = orient3d_filter(a, b, c, d, &fv);
  if (s != kUncertain) return s;
  if (!(fv.span <= kSmallOrientSpan)) return kUncertain;
  if (fv.det != 0) return fv.det > 0 ? 1 : -1;
  const double* p[4] = {a, b, c, d};
  const std::int64_t ids[4] = {ia, ib, ic, id};
  return detail::small_tie<4>(p, ids);
}

// insphere_lift_sos's sign, or kUncertain where the small-integer stage does not decide
// it. Every coordinate must be an integer (see above).
GDEL_HD inline int insphere_lift_sos_small(const double* a, const double* b, const double* c, const double* d,
                                           const double* e, std::int64_t ia, std::int64_t ib, std::int64_t ic,
                                           std::int64_t id, std::int64_t ie) {
  FilterValue fv;
  const int s = insphere_filter(a, b, c, d, e, &fv);
  if (s != kUncertain) return s;
  const double* p[5] = {a, b, c, d, e};
  if (fv.span <= kSmallInsphereSpan) {
    if (fv.det != 0) return fv.det > 0 ? 1 : -1;
  } else {  // zero only as five points of one sphere about the origin
    double h[5], ha;
    for (int i = 0; i < 5; ++i) {
      const double* q = p[i];
      if (!(fp::abs(q[0]) <= kSmallSphereCoord && fp::abs(q[1]) <= kSmallSphereCoord &&
            fp::abs(q[2]) <= kSmallSphereCoord))
        return kUncertain;
      detail::lift_fp(q, 0.0, h[i], ha);
    }
    if (!(h[0] == h[1] && h[0] == h[2] && h[0] == h[3] && h[0] == h[4])) return kUncertain;
  }
  const std::int64_t ids[5] = {ia, ib, ic, id, ie};
  return detail::small_tie<5>(p, ids);
}

// ---------------------------------------------------------------------------------------
// Points of the integer stage
// ---------------------------------------------------------------------------------------

// True when every coordinate of p times `scale` is an integer with |x| <= 2^23 and w (the
// point's weight, 0 when unweighted) times scale^2 an integer with |w| <= 2^46: the integer
// stage's condition (minors.hpp) at scale 1 (integers) or kQuarterScale (multiples of 1/4).
// When every point of a set passes at one of the two scales, every exact evaluation over
// points of that set only (each predicate here, every SoS minor of theirs) is done in
// 128-bit integers and never touches the work buffer, so callers may pass work = nullptr
// for them and never get kUncertain (flip::Geo's exact forms do, with Geo::int_points /
// Geo::int_all).
inline constexpr double kQuarterScale = detail::kIntQuarter;
GDEL_HD inline bool integer_point(const double* p, double w = 0.0, double scale = 1.0) {
  std::int64_t q[4];
  return detail::int_point(p, w, scale, 15u, q);
}

// ---------------------------------------------------------------------------------------
// orient3d
// ---------------------------------------------------------------------------------------

// Exact sign of det[b-a, c-a, d-a]; work: kOrient3dWork doubles.
template <class Work>
GDEL_HD int orient3d_exact(const double* a, const double* b, const double* c,
                           const double* d, Work work) {
  const detail::LiftedRows R{{a, b, c, d, nullptr}, {0.0, 0.0, 0.0, 0.0, 0.0}};
  return detail::orient3d_exact_rows(R, work);
}

template <class Work>
GDEL_HD int orient3d(const double* a, const double* b, const double* c, const double* d,
                     Work work) {
  const int s = orient3d_filter(a, b, c, d);
  return s != kUncertain ? s : orient3d_exact(a, b, c, d, work);
}

// Never 0; ia..id: distinct original indices.
template <class Work>
GDEL_HD int orient3d_sos(const double* a, const double* b, const double* c,
                         const double* d, std::int64_t ia, std::int64_t ib,
                         std::int64_t ic, std::int64_t id, Work work) {
  const int s = orient3d(a, b, c, d, work);
  if (s != 0) return s;
  const double* p[4] = {a, b, c, d};
  const std::int64_t ids[4] = {ia, ib, ic, id};
  detail::LiftedRows R;
  const int swaps = detail::sorted_rows<4>(p, nullptr, ids, false, R);
  const int v = detail::sos_walk<4>(R, false, work);  // perturbed det4 of sorted rows
  return (swaps & 1) ? v : detail::negate_sign(v);    // orient3d = -det4(original)
}

// orient3d(p0, p1, p2, p3) with the point at position kpos replaced by the exact centroid
// K = (q0 + q1 + q2 + q3) / 4 of four points, which need not be a double: a kernel point
// for a first tetrahedron that holds no double (docs/gflip3d.md). K is perturbed as in
// orient3d_sos, as a point of index ids[kpos]. The determinant is linear in K's row
// (K, 1) = sum_i (q_i, 1) / 4, so its value and every SoS minor with K's row are sums of
// the four with q_i in K's place: each evaluated exactly, summed as expansions. Never 0.
// p[kpos] is not read. Work: kPredicateWork doubles (a scratch is required). flip::Geo
// uses it for ∞ when gFlip3D's first tetrahedron holds no double (Geo::k_centroid).
namespace detail {
// Sign of sum_i det[(q, 1)] over the rows rr[0..k] and columns cc[0..k) with sorted row kr
// replaced by q_i.
template <int K>
GDEL_HD int centroid_minor_sign(const LiftedRows& R, const int* rr, const int* cc, int kr, const double* const* q,
                                double* work) {
  constexpr int cap = 4 * det_len(K, 1);
  double* acc = work;
  double* next = acc + cap;
  double* term = next + cap;  // det_work(K, 1) doubles
  int len = 0;
  for (int i = 0; i < 4; ++i) {
    LiftedRows Ri = R;
    Ri.p[kr] = q[i];
    const int tl = det_ones_exact<K>(Ri, rr, cc, false, term);
    len = ex::sum(len, acc, tl, term, next);
    double* t = acc;
    acc = next;
    next = t;
  }
  return ex::sign(len, acc);
}
static_assert(8 * det_len(3, 1) + det_work(3, 1) <= static_cast<int>(kPredicateWork));

struct CentroidMinor {
  const LiftedRows& R;
  int kr;
  const double* const* q;
  double* work;
  GDEL_HD int operator()(unsigned rows, unsigned cols) const {
    int rr[5], k = 0;
    for (int r = 0; r < 4; ++r)
      if (rows >> r & 1u) rr[k++] = r;
    if (!(rows >> kr & 1u)) return minor_sign(R, rr, cols, false, work);
    int cc[4];
    switch (mask_columns(cols, cc)) {
      case 1: return centroid_minor_sign<1>(R, rr, cc, kr, q, work);
      case 2: return centroid_minor_sign<2>(R, rr, cc, kr, q, work);
      default: return centroid_minor_sign<3>(R, rr, cc, kr, q, work);
    }
  }
};
}  // namespace detail

// The filter of orient3d_centroid_sos: the sign on which the four terms' filters agree
// (each certain and non-zero), else kUncertain.
GDEL_HD inline int orient3d_centroid_filter(const double* const p[4], int kpos, const double* const q[4]) {
  int agree = 0;
  for (int i = 0; i < 4 && agree != kUncertain; ++i) {
    const double* r[4] = {p[0], p[1], p[2], p[3]};
    r[kpos] = q[i];
    const int f = orient3d_filter(r[0], r[1], r[2], r[3]);
    agree = (f == kUncertain || f == 0 || (agree != 0 && f != agree)) ? kUncertain : f;
  }
  return agree;
}

GDEL_HD inline int orient3d_centroid_sos(const double* const p[4], int kpos, const double* const q[4],
                                         const std::int64_t ids[4], double* work) {
  const int agree = orient3d_centroid_filter(p, kpos, q);
  if (agree != kUncertain) return agree;
  const double* pp[4] = {p[0], p[1], p[2], p[3]};
  pp[kpos] = q[0];  // (a placeholder: the sorted row of K is replaced in every minor)
  detail::LiftedRows R;
  const int swaps = detail::sorted_rows<4>(pp, nullptr, ids, false, R);
  int kr = 0;  // K's sorted row: its index's rank
  for (int i = 0; i < 4; ++i) kr += ids[i] < ids[kpos];
  const int rr[4] = {0, 1, 2, 3};
  const int cc[3] = {0, 1, 2};
  int v = detail::centroid_minor_sign<3>(R, rr, cc, kr, q, work);  // the exact value (raw, sorted rows)
  if (v == 0) {
    detail::CentroidMinor minor{R, kr, q, work};
    v = detail::sos_table_walk(false, minor);  // perturbed det4 of sorted rows
  }
  return (swaps & 1) ? v : detail::negate_sign(v);  // orient3d = -det4(original)
}

// ---------------------------------------------------------------------------------------
// insphere
// ---------------------------------------------------------------------------------------

// Exact insphere sign; work: kInsphereWork doubles.
template <class Work>
GDEL_HD int insphere_exact(const double* a, const double* b, const double* c,
                           const double* d, const double* e, Work work) {
  const detail::LiftedRows R{{a, b, c, d, e}, {0.0, 0.0, 0.0, 0.0, 0.0}};
  return detail::lifted_exact_rows(R, false, work);
}

template <class Work>
GDEL_HD int insphere(const double* a, const double* b, const double* c, const double* d,
                     const double* e, Work work) {
  const int s = insphere_filter(a, b, c, d, e);
  return s != kUncertain ? s : insphere_exact(a, b, c, d, e, work);
}

template <class Work>
GDEL_HD int insphere_sos(const double* a, const double* b, const double* c,
                         const double* d, const double* e, std::int64_t ia,
                         std::int64_t ib, std::int64_t ic, std::int64_t id,
                         std::int64_t ie, Work work) {
  const int s = insphere(a, b, c, d, e, work);
  if (s != 0) return s;
  const double* p[5] = {a, b, c, d, e};
  const std::int64_t ids[5] = {ia, ib, ic, id, ie};
  return detail::lifted_sos_degenerate(p, nullptr, ids, false, work);
}

// tied (optional): set to true when the unperturbed sign is 0 (the perturbation decided).
template <class Work>
GDEL_HD int insphere_lift_sos(const double* a, const double* b, const double* c,
                              const double* d, const double* e, std::int64_t ia,
                              std::int64_t ib, std::int64_t ic, std::int64_t id,
                              std::int64_t ie, Work work, bool* tied = nullptr) {
  const int s = insphere(a, b, c, d, e, work);
  if (s != 0) return s;
  if (tied) *tied = true;  // (the caller's count of exact ties)
  const double* p[5] = {a, b, c, d, e};
  const std::int64_t ids[5] = {ia, ib, ic, id, ie};
  return detail::lift_sos_degenerate(p, nullptr, ids, false, work);
}

// ---------------------------------------------------------------------------------------
// power (weighted insphere)
// ---------------------------------------------------------------------------------------

// Exact power-test sign; work: kPowerWork doubles.
template <class Work>
GDEL_HD int power_exact(const double* a, const double* b, const double* c, const double* d,
                        const double* e, double wa, double wb, double wc, double wd,
                        double we, Work work) {
  const detail::LiftedRows R{{a, b, c, d, e}, {wa, wb, wc, wd, we}};
  return detail::lifted_exact_rows(R, true, work);
}

template <class Work>
GDEL_HD int power(const double* a, const double* b, const double* c, const double* d,
                  const double* e, double wa, double wb, double wc, double wd, double we,
                  Work work) {
  const int s = power_filter(a, b, c, d, e, wa, wb, wc, wd, we);
  return s != kUncertain ? s : power_exact(a, b, c, d, e, wa, wb, wc, wd, we, work);
}

template <class Work>
GDEL_HD int power_sos(const double* a, const double* b, const double* c, const double* d,
                      const double* e, double wa, double wb, double wc, double wd,
                      double we, std::int64_t ia, std::int64_t ib, std::int64_t ic,
                      std::int64_t id, std::int64_t ie, Work work) {
  const int s = power(a, b, c, d, e, wa, wb, wc, wd, we, work);
  if (s != 0) return s;
  const double* p[5] = {a, b, c, d, e};
  const double w[5] = {wa, wb, wc, wd, we};
  const std::int64_t ids[5] = {ia, ib, ic, id, ie};
  return detail::lifted_sos_degenerate(p, w, ids, true, work);
}

template <class Work>
GDEL_HD int power_lift_sos(const double* a, const double* b, const double* c,
                           const double* d, const double* e, double wa, double wb,
                           double wc, double wd, double we, std::int64_t ia,
                           std::int64_t ib, std::int64_t ic, std::int64_t id,
                           std::int64_t ie, Work work) {
  const int s = power(a, b, c, d, e, wa, wb, wc, wd, we, work);
  if (s != 0) return s;
  const double* p[5] = {a, b, c, d, e};
  const double w[5] = {wa, wb, wc, wd, we};
  const std::int64_t ids[5] = {ia, ib, ic, id, ie};
  return detail::lift_sos_degenerate(p, w, ids, true, work);
}

// ---------------------------------------------------------------------------------------
// Lifted minors (the SoS building blocks, exposed for testing and for callers that need a
// projected orientation): sign of det[[q_0, 1]; ...; [q_k, 1]] where q_i holds the columns
// of `mask` (kColX | kColY | kColZ | kColH, in that order) of the lifted point
// (p_i, |p_i|^2 - w_i); k = popcount(mask) in 1..4 and p[0..k] are the k+1 points.
// w may be nullptr (all weights 0). This is the raw determinant: mask xyz gives
// -orient3d, mask xyzh gives -power. Work: kMinorWork doubles for k <= 3, kPowerWork for 4.
// ---------------------------------------------------------------------------------------

GDEL_HD inline int lifted_minor_filter(const double* const* p, const double* w, unsigned mask) {
  detail::LiftedRows R{{nullptr, nullptr, nullptr, nullptr, nullptr}, {0.0, 0.0, 0.0, 0.0, 0.0}};
  int cols[4];
  const int k = detail::mask_columns(mask, cols);
  for (int i = 0; i <= k; ++i) {
    R.p[i] = p[i];
    R.w[i] = w ? w[i] : 0.0;
  }
  const int rows[5] = {0, 1, 2, 3, 4};
  switch (k) {
    case 1: return detail::det_ones_filter<1>(R, rows, cols);
    case 2: return detail::det_ones_filter<2>(R, rows, cols);
    case 3: return detail::det_ones_filter<3>(R, rows, cols);
    case 4: {
      const int s = power_filter(R.p[0], R.p[1], R.p[2], R.p[3], R.p[4], R.w[0], R.w[1], R.w[2], R.w[3], R.w[4]);
      return s == kUncertain ? s : -s;
    }
    default: return kUncertain;
  }
}

GDEL_HD inline int lifted_minor_exact(const double* const* p, const double* w, unsigned mask,
                                      double* work) {
  detail::LiftedRows R{{nullptr, nullptr, nullptr, nullptr, nullptr}, {0.0, 0.0, 0.0, 0.0, 0.0}};
  int cols[4];
  const int k = detail::mask_columns(mask, cols);
  for (int i = 0; i <= k; ++i) {
    R.p[i] = p[i];
    R.w[i] = w ? w[i] : 0.0;
  }
  const bool weighted = w != nullptr;
  const int rows[5] = {0, 1, 2, 3, 4};
  switch (k) {
    case 1: return detail::det_ones_exact_sign<1>(R, rows, cols, weighted, work);
    case 2: return detail::det_ones_exact_sign<2>(R, rows, cols, weighted, work);
    case 3: return detail::det_ones_exact_sign<3>(R, rows, cols, weighted, work);
    case 4: return detail::det_ones_exact_sign<4>(R, rows, cols, weighted, work);
    default: return 0;
  }
}

GDEL_HD inline int lifted_minor(const double* const* p, const double* w, unsigned mask,
                                double* work) {
  const int s = lifted_minor_filter(p, w, mask);
  return s != kUncertain ? s : lifted_minor_exact(p, w, mask, work);
}

// orient2d of the projection on coordinates (i, j), i != j in 0..2:
// sign det[[a_i, a_j, 1]; [b_i, b_j, 1]; [c_i, c_j, 1]]. Work: kMinorWork doubles.
GDEL_HD inline int orient2d_proj(const double* a, const double* b, const double* c, int i, int j,
                                 double* work) {
  if (i == j) return 0;
  const double* p[3] = {a, b, c};
  const int s = lifted_minor(p, nullptr, (1u << i) | (1u << j), work);
  return i < j ? s : -s;
}

}  // namespace gdel::geom
