// Shared by tests/cpu/predicates.cpp and tests/gpu/predicates.cu: exact GMP oracles for
// the predicates of src/geometry and generators of random / near-degenerate / degenerate
// cases inside the documented exact range. Host-only code.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace gdel_test {

// ---------------------------------------------------------------------------------------
// A test case: up to five points, weights and distinct original indices.
// ---------------------------------------------------------------------------------------
struct Case {
  double p[5][3];
  double w[5];
  std::int64_t id[5];
};

// Exponent of the lowest set bit of a non-zero double (x = odd * 2^low_exp).
inline int low_exp(double x) {
  int e;
  const double m = std::frexp(x, &e);  // |m| in [0.5, 1)
  const auto mant = static_cast<std::int64_t>(std::ldexp(m, 53));
  const std::uint64_t u = static_cast<std::uint64_t>(mant < 0 ? -mant : mant);
  return e - 53 + __builtin_ctzll(u);
}

// x * 2^s as an integer (must be one).
inline mpz_class scaled(double x, int s) {
  if (x == 0.0) return 0;
  int e;
  const double m = std::frexp(x, &e);
  mpz_class z(static_cast<long>(std::ldexp(m, 53)));
  const int sh = e - 53 + s;
  if (sh >= 0) {
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), sh);
  } else {
    mpz_tdiv_q_2exp(z.get_mpz_t(), z.get_mpz_t(), -sh);  // exact by choice of s
  }
  return z;
}

// ---------------------------------------------------------------------------------------
// Oracle: exact integer evaluation after scaling every coordinate by 2^s and every weight
// by 2^(2s) (all signs here are invariant under that scaling).
// ---------------------------------------------------------------------------------------
class Oracle {
 public:
  // Loads n points (and weights) with a common scale; afterwards X[i][c] (c = 3: h) hold
  // the exact scaled coordinates and lifted heights.
  void load(int n, const double* const* p, const double* w) {
    n_ = n;
    int s = 0;
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c)
        if (p[i][c] != 0.0) s = std::max(s, -low_exp(p[i][c]));
      if (w && w[i] != 0.0) s = std::max(s, (-low_exp(w[i]) + 1) / 2);
    }
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) X[i][c] = scaled(p[i][c], s);
      X[i][3] = X[i][0] * X[i][0] + X[i][1] * X[i][1] + X[i][2] * X[i][2];
      if (w) X[i][3] -= scaled(w[i], 2 * s);
    }
  }
  void load(const Case& k, int n, bool weighted) {
    const double* p[5] = {k.p[0], k.p[1], k.p[2], k.p[3], k.p[4]};
    load(n, p, weighted ? k.w : nullptr);
  }

  // det[b-a, c-a, d-a] of loaded points 0..3.
  int orient3d() {
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) D_[i][c] = X[i + 1][c] - X[0][c];
    t_ = D_[0][0] * (D_[1][1] * D_[2][2] - D_[1][2] * D_[2][1]) -
         D_[0][1] * (D_[1][0] * D_[2][2] - D_[1][2] * D_[2][0]) +
         D_[0][2] * (D_[1][0] * D_[2][1] - D_[1][1] * D_[2][0]);
    return sgn(t_);
  }

  // -det4[(p_i - e, h_i - h_e)], i = 0..3, e = point 4 (insphere or power, as loaded).
  int lifted() {
    mpz_class r = lifted_value();
    return sgn(r);
  }
  mpz_class lifted_value() {
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c) M_[i][c] = X[i][c] - X[4][c];
    return -det(4);
  }

  // Raw det[[q_i, 1]] over the columns of mask (bit c: column c, 3 = h), rows 0..k.
  int minor(unsigned mask) {
    int cols[4], k = 0;
    for (int c = 0; c < 4; ++c)
      if (mask & (1u << c)) cols[k++] = c;
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; j < k; ++j) M_[i][j] = X[i][cols[j]];
      M_[i][k] = 1;
    }
    return sgn(det(k + 1));
  }

  // Determinant of M_[0..n)[0..n) by fraction-free Gaussian elimination (Bareiss).
  mpz_class det(int n) {
    int s = 1;
    mpz_class prev = 1;
    for (int k = 0; k + 1 < n; ++k) {
      if (M_[k][k] == 0) {
        int r = k + 1;
        while (r < n && M_[r][k] == 0) ++r;
        if (r == n) return 0;
        for (int j = 0; j < n; ++j) std::swap(M_[k][j], M_[r][j]);
        s = -s;
      }
      for (int i = k + 1; i < n; ++i) {
        for (int j = k + 1; j < n; ++j) {
          M_[i][j] = M_[i][j] * M_[k][k] - M_[i][k] * M_[k][j];
          mpz_divexact(M_[i][j].get_mpz_t(), M_[i][j].get_mpz_t(), prev.get_mpz_t());
        }
      }
      prev = M_[k][k];
    }
    return s > 0 ? mpz_class(M_[n - 1][n - 1]) : mpz_class(-M_[n - 1][n - 1]);
  }

  // Brute-force Edelsbrunner-Muecke sign of the perturbed predicate on the loaded points in
  // their ORIGINAL order (n = 4: orient3d, columns xyz; n = 5: insphere/power, columns
  // xyzh). Entry (i, c) is perturbed by eps^(2^(d*rank(i) + c)), rank = position of id[i]
  // in ascending order. Coefficient of a matching S = det of the matrix whose row i is
  // replaced by the unit vector e_c for each (i, c) in S (multilinearity in rows). Returns
  // the predicate's sign (-det(perturbed)), never 0.
  int em_sos(int n, const std::int64_t* id) {
    const int d = n - 1;
    int rank[5];
    for (int i = 0; i < n; ++i) {
      rank[i] = 0;
      for (int j = 0; j < n; ++j) rank[i] += id[j] < id[i];
    }
    const auto& order = matchings(n);
    for (const auto& S : order) {
      // rank-space matching -> original rows
      bool replaced[5] = {false, false, false, false, false};
      int unit_col[5];
      for (auto [r, c] : S) {
        int row = 0;
        while (rank[row] != r) ++row;
        replaced[row] = true;
        unit_col[row] = c;
      }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j <= d; ++j) {
          if (replaced[i]) {
            M_[i][j] = (j == unit_col[i]) ? 1 : 0;
          } else {
            M_[i][j] = j < d ? X[i][j] : mpz_class(1);
          }
        }
      const int s = sgn(det(n));
      if (s != 0) return -s;
    }
    return 0;  // not reached: the full matching of rows 0..d-1 has coefficient +-1
  }

  // Brute-force lifting-first perturbation (predicates.hpp): P(h + t e_i) - P(h) for each
  // i in decreasing index order (linear in h); if all vanish (five coplanar points), the
  // position perturbations x + d^(2^(3r+c)) in increasing exponent order, each first
  // alone and then with one height perturbation (decreasing index). Loaded n = 5.
  int lift_sos(const std::int64_t* id) {
    const mpz_class base = lifted_value();
    if (sgn(base) != 0) return sgn(base);
    int order[5] = {0, 1, 2, 3, 4};
    std::sort(order, order + 5, [&](int a, int b) { return id[a] > id[b]; });
    for (int k = 0; k < 5; ++k) {
      const int i = order[k];
      X[i][3] += 1;
      const mpz_class v = lifted_value();
      X[i][3] -= 1;
      const int s = sgn(v - base);
      if (s != 0) return s;
    }
    int rank[5];
    for (int i = 0; i < 5; ++i) {
      rank[i] = 0;
      for (int j = 0; j < 5; ++j) rank[i] += id[j] < id[i];
    }
    static const auto m3 = build(5, 3);
    for (const auto& S : m3) {
      int unit_col[5] = {-1, -1, -1, -1, -1};
      for (auto [r, c] : S) {
        int row = 0;
        while (rank[row] != r) ++row;
        unit_col[row] = c;
      }
      for (int e = -1; e < 5; ++e) {  // -1: the pure term; else the height of order[e]
        const int hrow = e < 0 ? -1 : order[e];
        if (hrow >= 0 && unit_col[hrow] >= 0) continue;
        for (int i = 0; i < 5; ++i)
          for (int j = 0; j < 5; ++j) {
            if (i == hrow) M_[i][j] = (j == 3) ? 1 : 0;
            else if (unit_col[i] >= 0) M_[i][j] = (j == unit_col[i]) ? 1 : 0;
            else M_[i][j] = j < 4 ? X[i][j] : mpz_class(1);
          }
        const int s = sgn(det(5));
        if (s != 0) return -s;
      }
    }
    return 0;  // not reached
  }

  mpz_class X[5][4];

 private:
  // All partial matchings (rank row -> column) of n rows and d = n-1 columns, sorted by
  // increasing exponent sum 2^(d r + c), i.e. decreasing magnitude; the empty one is
  // skipped (the unperturbed determinant).
  static const std::vector<std::vector<std::pair<int, int>>>& matchings(int n) {
    static const auto m4 = build(4, 3);
    static const auto m5 = build(5, 4);
    return n == 4 ? m4 : m5;
  }
  static std::vector<std::vector<std::pair<int, int>>> build(int n, int d) {
    std::vector<std::pair<std::uint64_t, std::vector<std::pair<int, int>>>> all;
    std::vector<std::pair<int, int>> cur;
    // recursive enumeration over rows
    auto rec = [&](auto&& self, int r, unsigned used, std::uint64_t expo) -> void {
      if (r == n) {
        if (!cur.empty()) all.push_back({expo, cur});
        return;
      }
      self(self, r + 1, used, expo);
      for (int c = 0; c < d; ++c) {
        if (used & (1u << c)) continue;
        cur.push_back({r, c});
        self(self, r + 1, used | (1u << c), expo + (std::uint64_t{1} << (d * r + c)));
        cur.pop_back();
      }
    };
    rec(rec, 0, 0u, 0);
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::vector<std::pair<int, int>>> out;
    for (auto& e : all) out.push_back(e.second);
    return out;
  }

  int n_ = 0;
  mpz_class D_[3][3], M_[5][5], t_;
};

// ---------------------------------------------------------------------------------------
// Case generators. All cases lie inside the documented exact range (predicates.hpp).
// ---------------------------------------------------------------------------------------
class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  std::mt19937_64& rng() { return rng_; }

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  // Distinct random indices (sometimes large, to exercise 64-bit ids).
  void ids(Case& k) {
    for (int i = 0; i < 5; ++i) {
      bool dup;
      do {
        k.id[i] = (rng_() & 1) ? static_cast<std::int64_t>(rng_() % 64)
                               : static_cast<std::int64_t>(rng_() >> 2);
        dup = false;
        for (int j = 0; j < i; ++j) dup |= k.id[j] == k.id[i];
      } while (dup);
    }
  }

  // Random points in [-s, s]^3 with full 53-bit significands; weights in [-s^2, s^2]/4.
  Case random(double s = 1.0) {
    Case k;
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) k.p[i][c] = in_range(uniform(-s, s));
      k.w[i] = w_in_range(uniform(-0.25, 0.25) * s * s);
    }
    ids(k);
    return k;
  }

  // One of several near-degenerate / degenerate families (see the switch).
  Case degenerate(int family) {
    Case k;
    ids(k);
    const int kind = family % kFamilies;
    switch (kind) {
      case 0: {  // points of the grid {0,1,2}^3 (many coplanar / cospherical / equal)
        const double sc = std::ldexp(1.0, integer(-40, 40));
        for (int i = 0; i < 5; ++i) {
          for (int c = 0; c < 3; ++c) k.p[i][c] = integer(0, 2) * sc;
          k.w[i] = integer(-2, 2) * sc * sc;
        }
        break;
      }
      case 1: {  // 2^-k multiples of small integers, with an offset
        const int e = integer(0, 60);
        const double off = integer(-1000, 1000);
        for (int i = 0; i < 5; ++i) {
          for (int c = 0; c < 3; ++c) k.p[i][c] = off + std::ldexp(integer(-4, 4), -e);
          k.w[i] = std::ldexp(integer(-4, 4), -2 * e);
        }
        break;
      }
      case 2: {  // points on the plane z = x + y (exact), weights on a lifted hyperplane
        for (int i = 0; i < 5; ++i) {
          const double x = std::ldexp(integer(-(1 << 20), 1 << 20), -20);
          const double y = std::ldexp(integer(-(1 << 20), 1 << 20), -20);
          k.p[i][0] = x;
          k.p[i][1] = y;
          k.p[i][2] = x + y;
          k.w[i] = std::ldexp(integer(-(1 << 20), 1 << 20), -20);
        }
        break;
      }
      case 3: {  // integer points on a common sphere, translated and scaled by powers of 2
        const auto& sph = sphere_points();
        const double sc = std::ldexp(1.0, integer(-100, 100));
        const double ox = integer(-64, 64), oy = integer(-64, 64), oz = integer(-64, 64);
        for (int i = 0; i < 5; ++i) {
          const auto& q = sph[rng_() % sph.size()];
          k.p[i][0] = (q[0] + ox) * sc;
          k.p[i][1] = (q[1] + oy) * sc;
          k.p[i][2] = (q[2] + oz) * sc;
          k.w[i] = 0.0;
        }
        break;
      }
      case 4: {  // weighted-degenerate: lifted points on a common hyperplane h = l(p)
        const double a = integer(-8, 8), b = integer(-8, 8), c = integer(-8, 8), d = integer(-64, 64);
        for (int i = 0; i < 5; ++i) {
          for (int t = 0; t < 3; ++t) k.p[i][t] = integer(-50, 50);
          const double h = a * k.p[i][0] + b * k.p[i][1] + c * k.p[i][2] + d;
          const double sq = k.p[i][0] * k.p[i][0] + k.p[i][1] * k.p[i][1] + k.p[i][2] * k.p[i][2];
          k.w[i] = sq - h;  // exact: small integers
        }
        break;
      }
      case 5: {  // huge magnitudes (~1e60), grid structure kept
        const double sc = std::ldexp(1.0, integer(150, 197));
        for (int i = 0; i < 5; ++i) {
          for (int c = 0; c < 3; ++c) k.p[i][c] = integer(-3, 3) * sc;
          k.w[i] = integer(-3, 3) * sc * sc;
        }
        break;
      }
      case 6: {  // tiny magnitudes (~1e-45), grid structure kept
        const double sc = std::ldexp(1.0, integer(-150, -120));
        for (int i = 0; i < 5; ++i) {
          for (int c = 0; c < 3; ++c) k.p[i][c] = integer(-3, 3) * sc;
          k.w[i] = integer(-3, 3) * sc * sc;
        }
        break;
      }
      case 7: {  // random huge / tiny full-significand points
        const bool huge = rng_() & 1;
        k = random(huge ? std::ldexp(1.0, 199) : std::ldexp(1.0, -130));
        ids(k);
        break;
      }
      case 8: {  // duplicates and collinear points
        const double sc = std::ldexp(1.0, integer(-20, 20));
        const double dx = integer(-3, 3) * sc, dy = integer(-3, 3) * sc, dz = integer(-3, 3) * sc;
        for (int i = 0; i < 5; ++i) {
          const int t = integer(0, 3);
          k.p[i][0] = 1.0 + t * dx;
          k.p[i][1] = -2.0 + t * dy;
          k.p[i][2] = 0.5 + t * dz;
          k.w[i] = integer(0, 2) * sc;
        }
        break;
      }
      case 9: {  // integers at the integer stage's limits (minors.hpp): |x| <= 2^23,
                 // |w| <= 2^46, and just past; then (one case in three) the same divided
                 // by 4 (weights by 16): its quarter scale
        const double X = 0x1p23, W = 0x1p46;
        const bool quarter = integer(0, 2) == 0;
        switch (integer(0, 2)) {
          case 0: {  // cospherical lattice points, scaled and moved to large coordinates
            const auto& sph = sphere_points();  // radius sqrt(2925) < 55
            const double m = integer(1, 150000);
            const double lim = X - 55.0 * m;
            const double ox = std::floor(uniform(-lim, lim)), oy = std::floor(uniform(-lim, lim)),
                         oz = std::floor(uniform(-lim, lim));
            const double w = (rng_() & 1) ? 0.0 : static_cast<double>(integer(-1000, 1000)) * 0x1p36;
            for (int i = 0; i < 5; ++i) {
              const auto& q = sph[rng_() % sph.size()];
              k.p[i][0] = q[0] * m + ox;
              k.p[i][1] = q[1] * m + oy;
              k.p[i][2] = q[2] * m + oz;
              k.w[i] = w;  // equal weights: the power test is the insphere test
            }
            break;
          }
          case 1: {  // coordinates and weights from the extremes (coplanar, collinear, equal)
            const double xs[] = {0.0, 1.0, -1.0, X - 1.0, X, -X, X + 1.0, -X - 1.0, X + 2.0};
            const double ws[] = {0.0, 1.0, W - 1.0, W, -W, W + 1.0, -W - 2.0, 3.0 * W};
            for (int i = 0; i < 5; ++i) {
              for (int c = 0; c < 3; ++c) k.p[i][c] = xs[rng_() % 9 < 7 ? rng_() % 6 : 6 + rng_() % 3];
              k.w[i] = ws[rng_() % 8];
            }
            break;
          }
          default: {  // lifted points on a common hyperplane, large integers
            const double a = integer(-8, 8), b = integer(-8, 8), c = integer(-8, 8);
            const double d = static_cast<double>(integer(-(1 << 30), 1 << 30)) * 0x1p14;
            for (int i = 0; i < 5; ++i) {
              for (int t = 0; t < 3; ++t) k.p[i][t] = static_cast<double>(integer(-(1 << 22), 1 << 22));
              const double h = a * k.p[i][0] + b * k.p[i][1] + c * k.p[i][2] + d;
              const double sq = k.p[i][0] * k.p[i][0] + k.p[i][1] * k.p[i][1] + k.p[i][2] * k.p[i][2];
              k.w[i] = sq - h;  // exact: integers below 2^53
            }
            break;
          }
        }
        if (quarter) {  // exact: powers of two; the ties stay ties (every minor scales by a positive constant)
          for (int i = 0; i < 5; ++i) {
            for (int c = 0; c < 3; ++c) k.p[i][c] *= 0.25;
            k.w[i] *= 0.0625;
          }
        }
        break;
      }
      default: {  // a degenerate family above, then one coordinate nudged by one ulp
        k = degenerate(integer(0, kFamilies - 2));
        const int i = integer(0, 4), c = integer(0, 2);
        const double to = (rng_() & 1) ? INFINITY : -INFINITY;
        const double v = std::nextafter(k.p[i][c], to);
        if (v != 0.0 && std::fabs(v) >= 0x1p-152 && std::fabs(v) <= 0x1p200) k.p[i][c] = v;
        if (rng_() & 1) k.w[i] = w_in_range(std::nextafter(k.w[i], to));
        break;
      }
    }
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) k.p[i][c] = in_range(k.p[i][c]);
      k.w[i] = w_in_range(k.w[i]);
    }
    return k;
  }
  static constexpr int kFamilies = 11;

  // Integer cases about the integer stage's narrow form (minors.hpp, kIntNarrowMax = 2^20):
  // coordinate differences to the last point of exactly +-2^20 and +-(2^20 - 1), or just
  // past (2^20 + 1, 2^20 + 2), in sign patterns that make the 3x3 minors large (up to
  // 4 * 2^60), at offsets that keep every coordinate within 2^23; weights at +-2^46 or 0, so
  // that the height column reaches the stage's 2^49. One case in four has its points on a
  // sphere about the origin (coordinate permutations and sign changes of one vector of
  // about 2^19, unweighted): equal heights, the height column all zero. Not part of
  // degenerate(): the families' streams stay as they were.
  Case int_narrow_limit() {
    Case k;
    ids(k);
    const double N = 0x1p20;
    if (integer(0, 3) == 0) {
      const double v[3] = {std::floor(N / 2) + integer(-2, 2), static_cast<double>(integer(0, 1 << 19)),
                           static_cast<double>(integer(0, 3))};
      for (int i = 0; i < 5; ++i) {
        int perm[3] = {0, 1, 2};
        std::shuffle(perm, perm + 3, rng_);
        for (int c = 0; c < 3; ++c) k.p[i][c] = (rng_() & 1 ? 1.0 : -1.0) * v[perm[c]];
        k.w[i] = 0.0;
      }
      return k;
    }
    const double steps[] = {N, N - 1.0, N + 1.0, N + 2.0};
    const double lim = 0x1p23 - 4.0 * N;
    double o[3];
    for (double& x : o) x = std::floor(uniform(-lim, lim));
    const bool past = integer(0, 2) == 0;  // otherwise every difference within 2^20
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double step = steps[past ? integer(0, 3) : integer(0, 1)];
        const int pick = integer(0, 4);  // -step, 0, +step mostly; a small difference sometimes
        const double d = pick == 0 ? -step : pick <= 2 ? step : pick == 3 ? 0.0 : static_cast<double>(integer(-3, 3));
        k.p[i][c] = i == 4 ? o[c] : o[c] + d;
      }
      const int wp = integer(0, 3);
      k.w[i] = wp == 0 ? 0x1p46 : wp == 1 ? -0x1p46 : wp == 2 ? 0.0 : static_cast<double>(integer(-1000, 1000));
    }
    return k;
  }

  static double in_range(double x) {
    const double a = std::fabs(x);
    return (a != 0.0 && (a < 0x1p-152 || a > 0x1p200)) ? 0.0 : x;
  }
  static double w_in_range(double w) {
    const double a = std::fabs(w);
    return (a != 0.0 && (a < 0x1p-356 || a > 0x1p400)) ? 0.0 : w;
  }

  // Integer points on the sphere x^2 + y^2 + z^2 = 2925 (many representations).
  static const std::vector<std::array<int, 3>>& sphere_points() {
    static const std::vector<std::array<int, 3>> pts = [] {
      std::vector<std::array<int, 3>> v;
      const int r2 = 2925;
      for (int x = -54; x <= 54; ++x)
        for (int y = -54; y <= 54; ++y) {
          const int z2 = r2 - x * x - y * y;
          if (z2 < 0) continue;
          const int z = static_cast<int>(std::lround(std::sqrt(static_cast<double>(z2))));
          if (z * z != z2) continue;
          v.push_back({x, y, z});
          if (z != 0) v.push_back({x, y, -z});
        }
      return v;
    }();
    return pts;
  }

 private:
  std::mt19937_64 rng_;
};


// ---------------------------------------------------------------------------------------
// orient3d_centroid_sos's cases: orient3d of p with p[kpos] the exact centroid of q[0..3]
// ---------------------------------------------------------------------------------------
struct CentroidCase {
  double p[4][3];
  double q[4][3];
  int kpos;
  std::int64_t id[4];
  int want;       // GMP: the perturbed sign
  bool tie;       // the unperturbed value is 0
  bool off_grid;  // the centroid is not a double
};

// GMP: the perturbed orient3d of p with p[kpos] := (q0 + q1 + q2 + q3) / 4 exactly. All
// rows are scaled by 2^(s+2), K's row as the sum of the q_i scaled by 2^s (an integer).
inline int oracle_centroid_orient(const CentroidCase& k, bool& tie) {
  int s = 0;
  auto widen = [&](const double* x) {
    for (int c = 0; c < 3; ++c)
      if (x[c] != 0.0) s = std::max(s, -low_exp(x[c]));
  };
  for (int i = 0; i < 4; ++i) {
    if (i != k.kpos) widen(k.p[i]);
    widen(k.q[i]);
  }
  Oracle o;
  const double* r[5] = {k.p[0], k.p[1], k.p[2], k.p[3], nullptr};
  r[k.kpos] = k.q[0];
  o.load(4, r, nullptr);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      if (i != k.kpos) {
        o.X[i][c] = scaled(k.p[i][c], s + 2);
      } else {
        o.X[i][c] = 0;
        for (int j = 0; j < 4; ++j) o.X[i][c] += scaled(k.q[j][c], s);
      }
    }
  const int v = o.orient3d();
  tie = v == 0;
  return v != 0 ? v : o.em_sos(4, k.id);
}

// The q's x carries bits 2^-60 below small integers (the centroid is then not a double),
// and every second case puts p's other three points on the plane z = K's z (a double):
// exact ties that the perturbation decides.
inline std::vector<CentroidCase> centroid_cases(int n, std::uint64_t seed) {
  Generator g(seed);
  std::vector<CentroidCase> out(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) {
    CentroidCase& k = out[static_cast<std::size_t>(t)];
    int isum = 0, ksum = 0;
    for (auto& x : k.q) {
      const int ii = g.integer(-8, 8), kk = g.integer(0, 3);
      isum += ii, ksum += kk;
      x[0] = ii + std::ldexp(static_cast<double>(kk), -60);
      x[1] = g.uniform(-1, 1);
      x[2] = g.integer(-8, 8);
    }
    const double kz = (k.q[0][2] + k.q[1][2] + k.q[2][2] + k.q[3][2]) / 4;
    const bool flat = t % 2 == 0;
    for (auto& x : k.p) {
      x[0] = g.integer(-4, 4) * (t % 3 == 0 ? 1.0 : g.uniform(0.5, 1));
      x[1] = t % 5 == 0 ? k.q[0][1] : g.uniform(-1, 1);
      x[2] = flat ? kz : g.integer(-8, 8);
    }
    k.kpos = g.integer(0, 3);
    Case ids;
    g.ids(ids);
    for (int i = 0; i < 4; ++i) k.id[i] = ids.id[i];
    k.off_grid = isum != 0 && ksum != 0;  // (isum + ksum 2^-60) / 4 spans more than 53 bits
    k.want = oracle_centroid_orient(k, k.tie);
  }
  return out;
}

}  // namespace gdel_test
