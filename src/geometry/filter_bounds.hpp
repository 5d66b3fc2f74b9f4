// Error bounds of gdel's floating-point filters, derived here once for all filters.
//
// Notation: u = 2^-53 (unit roundoff of binary64, round to nearest), gamma_n = n u / (1 - n u).
//
// 1. Rounding (no underflow). A filter evaluates a determinant D by a fixed expression tree
//    of +, -, * over "leaves" (coordinate differences, weight differences, squares of
//    coordinates, ...). Expanding the tree, the exact D is a signed sum of monomials,
//    D = sum_j s_j m_j, and the computed value is D^ = sum_j s_j m_j (1 + t_j) where
//    |t_j| <= gamma_{n_j} and n_j is the number of roundings on the path of monomial j
//    (Higham, Accuracy and Stability of Numerical Algorithms, Lemma 3.1; every operation
//    obeys fl(x op y) = (x op y)(1 + d), |d| <= u). With N = max_j n_j:
//        |D^ - D| <= gamma_N * P,    P = sum_j |m_j|   (the exact permanent).
//    The filter evaluates the permanent P^ with the same tree on absolute values (+ instead
//    of -), so P^ = sum_j |m_j| (1 + t'_j), |t'_j| <= gamma_N, hence P <= P^ / (1 - gamma_N).
//
// 2. Underflow. Additions and subtractions are exact when their result is subnormal, so only
//    products can underflow: fl(x*y) = xy(1 + d) + e with |e| <= eta = 2^-1075. An error e
//    made at a product node reaches D^ multiplied by the factors above that node. If G
//    bounds the sum over product nodes of those factors (derived per filter from the
//    documented input magnitude bound |coordinate| <= 2^200, |weight| <= 2^400), the total
//    underflow error in D^ (and in P^) is at most E = G eta (1 + O(u)). A filter returns
//    kUncertain when P^ < T with T = G eta / (rho u), rho = 1/8, so that E <= rho u P^.
//    Inputs inside the documented exact range never underflow at all (every intermediate
//    is a multiple of 2^-1020, see predicates.hpp); T only protects smaller inputs.
//
// 3. Decision. With both effects, |D^ - D| <= gamma_N (1 + rho u) P^ / (1 - gamma_N) + rho u P^.
//    The bound actually compared is fl(c P^) >= c P^ (1 - u) (P^ >= T keeps c P^ normal), so
//    the sign of D^ is certain when |D^| > fl(c P^) provided
//        c (1 - u) >= gamma_N (1 + rho u) / (1 - gamma_N) + rho u.          (*)
//    We take c_N = (N + 1/4) u = (4N + 1) 2^-55 (exact in binary64). Since
//    gamma_N / (1 - gamma_N) = N u / (1 - 2 N u), the right side of (*) is
//    N u + (1/8) u + O(N^2 u^2) while the left is N u + (1/4) u - O(N u^2); the margin u/8
//    exceeds the O(u^2) terms for every N < 2^20. The test suite checks (*) exactly in
//    rational arithmetic for every N used (tests/cpu/predicates.cpp, FilterBounds).
//
// 4. Overflow / NaN. Every intermediate of D^ is bounded in magnitude by the matching
//    intermediate of P^ (|fl(x - y)| <= fl(|x| + |y|), |fl(xy)| = fl(|x||y|)), so P^ finite
//    implies D^ finite and not NaN; a NaN or infinite input makes P^ NaN or infinite. Every
//    filter therefore returns kUncertain unless T <= P^ <= DBL_MAX (false for NaN).
//
// 5. A cheaper bound first (insphere and power filters). Rounding to nearest is monotone
//    (x <= x' implies fl(x) <= fl(x')), so evaluating P^'s tree on nonnegative leaves each
//    at least the original leaf gives B^ >= P^. The filters first evaluate it with every
//    leaf replaced by the largest of its kind (max |x_i|, max |y_i|, max |z_i|, max lift):
//    three products and five additions instead of the permanent's 29 operations. Sections
//    3 and 4 hold with B^ in place of P^: |D^ - D| <= gamma_N P + E with
//    P <= (P^ + E) / (1 - gamma_N) <= (B^ + E) / (1 - gamma_N); when B^ >= T (P^ may be
//    smaller) E <= G eta (1 + O(u)) = rho u T (1 + O(u)) <= rho u B^ (1 + O(u)), inside
//    the margin of (*); and B^ finite implies P^ finite. When B^ cannot decide, P^ is
//    computed and decides as before: the same signs, only sooner. B^ exceeds P^ by a small
//    factor (at most 4 * 3 * 2 = 24 for the insphere tree, typically 3-8).
//
// Rounding counts N and underflow bounds G of the filters (e2 = 200):
//   orient3d    det[b-a, c-a, d-a]: differences 1, 2x2 product 1 + subtraction 1, outer
//               product 1, two additions -> N = 8 (Shewchuk derives 7 + O(u) with a
//               tighter argument). G: 6 inner products times an outer difference
//               <= 2^(e2+1), plus 3 outer products: G <= 12 * 2^e2 + 3 <= 2^(e2+4)
//               -> T = 2^(e2+4) * 2^-1075 / (2^-3 * 2^-53) = 2^(e2-1015) = 2^-815.
//   insphere    translated to e, lift l = |p - e|^2: l carries 2 (squared difference) + 1
//               (square) + 2 (additions) = 5; the 3x3 minor of differences carries 8 (as
//               orient3d); product 1; the four terms are added pairwise, 2 -> N = 16
//               (Shewchuk: 16 + O(u)). G: 12 inner products (each used by 2 of the 3x3
//               minors) times |z| |l| <= 2^(e2+1) * 12 * 2^(2 e2): 576 * 2^(3 e2); 12 squares
//               times a 3x3 minor <= 48 * 2^(3 e2): 576 * 2^(3 e2); the rest is of lower
//               order: G <= 2^(3 e2 + 11) -> T = 2^(3 e2 + 11 - 1019) = 2^-408.
//   power       l = |p - e|^2 - (w_p - w_e): the squares carry 6 (one more subtraction), the
//               weight difference 2 -> N = 6 + 8 + 1 + 2 = 17 (derived here; replaces the
//               (32 + 448 u) u estimate of gReg3D). |l| <= 14 * 2^(2 e2), G <= 1248 * 2^(3 e2)
//               (1 + O(u)) <= 2^(3 e2 + 11) -> T = 2^-408.
//   minors      generic filter of minors.hpp (differences to the last row; an h entry
//               carries 4 roundings inside h = ((x^2 + y^2) + z^2) - w plus 1 for the
//               difference): N = 1..12 as listed there. The largest G is that of the lifted
//               orient3 minor: 12 squares times a 2x2 minor <= 2^(2 e2 + 3) plus 6 inner
//               products times an h difference <= 2^(2 e2 + 3): G <= 2^(2 e2 + 8)
//               -> T = 2^(2 e2 + 8 - 1019) = 2^-611; one threshold 2^-600 is used for all.
#pragma once

#include "core/macros.hpp"

namespace gdel::geom::bounds {

inline constexpr double kUnitRoundoff = 0x1p-53;
inline constexpr double kMaxFinite = 0x1.fffffffffffffp+1023;  // DBL_MAX

// c_N = (N + 1/4) u, exact in binary64 for N < 2^50.
GDEL_HD constexpr double coefficient(int n) { return (4.0 * n + 1.0) * 0x1p-55; }

// Rounding counts of the three main filters (filters.hpp).
inline constexpr int kOrient3dRoundings = 8;
inline constexpr int kInsphereRoundings = 16;
inline constexpr int kPowerRoundings = 17;
// Largest rounding count of the generic minor filter (lifted orient3).
inline constexpr int kMinorMaxRoundings = 12;

// Underflow thresholds on the computed permanent (section 2 above).
inline constexpr double kOrient3dThreshold = 0x1p-815;
inline constexpr double kInsphereThreshold = 0x1p-408;
inline constexpr double kPowerThreshold = 0x1p-408;
inline constexpr double kMinorThreshold = 0x1p-600;

// Magnitude bounds the thresholds were derived for (= the exact range's upper ends).
inline constexpr int kFilterCoordMaxExp = 200;
inline constexpr int kFilterWeightMaxExp = 400;

}  // namespace gdel::geom::bounds
