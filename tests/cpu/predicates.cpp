// Tests of src/geometry: expansion arithmetic, filter constants, the exact predicates
// against GMP on random / near-degenerate / degenerate inputs, simulation of simplicity
// (both perturbations) against brute-force GMP evaluations, contraction regressions, and
// the search for a double point inside a tetrahedron (interior_point) against GMP.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "cpu/predicates_oracle.hpp"
#include "geometry/expansion.hpp"
#include "geometry/filters_simd.hpp"
#include "geometry/interior_point.hpp"
#include "geometry/predicates.hpp"

using namespace gdel::geom;
using gdel_test::Case;
using gdel_test::Generator;
using gdel_test::Oracle;

namespace {

// ---------------------------------------------------------------------------------------
// Parallel driver and failure bookkeeping
// ---------------------------------------------------------------------------------------
struct Failures {
  std::atomic<long> count{0};
  std::mutex mu;
  std::vector<std::string> first;
  void add(const std::string& msg) {
    if (count.fetch_add(1) < 20) {
      std::lock_guard<std::mutex> lock(mu);
      first.push_back(msg);
    }
  }
  void report(const char* what) {
    for (const auto& m : first) ADD_FAILURE() << what << ": " << m;
    EXPECT_EQ(count.load(), 0) << what;
  }
};

int num_threads() {
  const unsigned h = std::thread::hardware_concurrency();
  return h == 0 ? 2 : static_cast<int>(h);
}

template <class F>
void run_parallel(long n, F f) {  // f(thread, begin, end)
  const int t = num_threads();
  std::vector<std::thread> th;
  for (int i = 0; i < t; ++i) {
    const long b = n * i / t, e = n * (i + 1) / t;
    th.emplace_back([=, &f] { f(i, b, e); });
  }
  for (auto& x : th) x.join();
}

std::string describe(const Case& k, int n) {
  char buf[1024];
  std::string s;
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "(%a,%a,%a; w=%a; id=%lld) ", k.p[i][0], k.p[i][1], k.p[i][2],
                  k.w[i], static_cast<long long>(k.id[i]));
    s += buf;
  }
  return s;
}

// ---------------------------------------------------------------------------------------
// Calls on a Case (optionally permuted)
// ---------------------------------------------------------------------------------------
Case permuted(const Case& k, const int* perm, int n) {
  Case r = k;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) r.p[i][c] = k.p[perm[i]][c];
    r.w[i] = k.w[perm[i]];
    r.id[i] = k.id[perm[i]];
  }
  return r;
}

int parity(const int* perm, int n) {
  int inv = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) inv += perm[i] > perm[j];
  return inv & 1;
}

enum class Pred { O3Sos, InsSos, InsLift, PowSos, PowLift };

template <class Work>
int call(Pred p, const Case& k, Work w) {
  switch (p) {
    case Pred::O3Sos:
      return orient3d_sos(k.p[0], k.p[1], k.p[2], k.p[3], k.id[0], k.id[1], k.id[2], k.id[3], w);
    case Pred::InsSos:
      return insphere_sos(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.id[0], k.id[1], k.id[2],
                          k.id[3], k.id[4], w);
    case Pred::InsLift:
      return insphere_lift_sos(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.id[0], k.id[1],
                               k.id[2], k.id[3], k.id[4], w);
    case Pred::PowSos:
      return power_sos(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.w[0], k.w[1], k.w[2], k.w[3],
                       k.w[4], k.id[0], k.id[1], k.id[2], k.id[3], k.id[4], w);
    case Pred::PowLift:
      return power_lift_sos(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.w[0], k.w[1], k.w[2],
                            k.w[3], k.w[4], k.id[0], k.id[1], k.id[2], k.id[3], k.id[4], w);
  }
  return 0;
}

// Exact comparison of an expansion's value with an mpq.
mpq_class value(int n, const double* e) {
  mpq_class s = 0;
  for (int i = 0; i < n; ++i) s += mpq_class(e[i]);
  return s;
}

bool nonoverlapping_increasing(int n, const double* e) {
  for (int i = 0; i + 1 < n; ++i) {
    if (e[i] == 0.0 || e[i + 1] == 0.0) return false;  // zero-eliminated
    // |e[i]| must be below the lowest set bit of e[i+1]
    const double lsb = std::ldexp(1.0, gdel_test::low_exp(e[i + 1]));
    if (!(std::fabs(e[i]) < lsb)) return false;
  }
  return true;
}

// Random double with a random exponent in [lo, hi].
double rand_double(Generator& g, int lo, int hi) {
  return std::ldexp(g.uniform(0.5, 1.0), g.integer(lo, hi)) * ((g.rng()() & 1) ? 1 : -1);
}

}  // namespace

// =========================================================================================
// Expansion arithmetic
// =========================================================================================
TEST(Expansion, ErrorFreeTransformationsAreExact) {
  Generator g(1);
  for (int t = 0; t < 200000; ++t) {
    const double a = rand_double(g, -300, 300), b = rand_double(g, -300, 300);
    double x, y;
    ex::two_product(a, b, x, y);
    ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(a) * mpq_class(b)) << a << " " << b;
    ASSERT_EQ(x, a * b);
    ASSERT_EQ(y, std::fma(a, b, -x));
    const double c = rand_double(g, -60, 60), d = rand_double(g, -60, 60);
    ex::two_sum(c, d, x, y);
    ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(c) + mpq_class(d));
    ASSERT_EQ(x, c + d);
    ex::two_diff(c, d, x, y);
    ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(c) - mpq_class(d));
    ASSERT_EQ(x, c - d);
    const double big = std::fabs(c) >= std::fabs(d) ? c : d, small = big == c ? d : c;
    ex::fast_two_sum(big, small, x, y);
    ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(c) + mpq_class(d));
    double hi, lo;
    ex::split(a, hi, lo);
    ASSERT_EQ(hi + lo, a);
    for (double v : {hi, lo}) {  // each half has at most 26 significant bits
      if (v == 0.0) continue;
      int ex_;
      const auto m = static_cast<unsigned long long>(std::ldexp(std::fabs(std::frexp(v, &ex_)), 53));
      ASSERT_LE(64 - __builtin_clzll(m) - __builtin_ctzll(m), 26) << a;
    }
  }
}

TEST(Expansion, SumScaleProductMatchGmp) {
  Generator g(2);
  std::vector<double> e(64), f(64), h(8192), w(8192);
  for (int t = 0; t < 20000; ++t) {
    // build expansions by accumulating random doubles of wide exponent spread
    auto build = [&](std::vector<double>& out) {
      int n = 0;
      const int terms = g.integer(0, 6);
      std::vector<double> tmp(64);
      for (int i = 0; i < terms; ++i) {
        const double v = rand_double(g, -80, 80);
        const int m = ex::sum(n, out.data(), 1, &v, tmp.data());
        std::copy(tmp.begin(), tmp.begin() + m, out.begin());
        n = m;
      }
      return n;
    };
    const int ne = build(e), nf = build(f);
    ASSERT_TRUE(nonoverlapping_increasing(ne, e.data()));
    const mpq_class ve = value(ne, e.data()), vf = value(nf, f.data());
    const int ns = ex::sum(ne, e.data(), nf, f.data(), h.data());
    ASSERT_LE(ns, ex::sum_len(ne, nf));
    ASSERT_TRUE(nonoverlapping_increasing(ns, h.data()));
    ASSERT_EQ(value(ns, h.data()), ve + vf);
    ASSERT_EQ(ex::sign(ns, h.data()), sgn(ve + vf));
    const double b = rand_double(g, -100, 100);
    const int nc = ex::scale(ne, e.data(), b, h.data());
    ASSERT_LE(nc, ex::scale_len(ne));
    ASSERT_TRUE(nonoverlapping_increasing(nc, h.data()));
    ASSERT_EQ(value(nc, h.data()), ve * mpq_class(b));
    const int np = ex::product(ne, e.data(), nf, f.data(), h.data(), w.data());
    ASSERT_LE(np, ex::product_len(ne, nf));
    ASSERT_TRUE(nonoverlapping_increasing(np, h.data()));
    ASSERT_EQ(value(np, h.data()), ve * vf);
    // in-place accumulation (sum with h + flen == e)
    ex::Accumulator acc(h.data(), ne + nf + ne);
    acc.add(ne, e.data());
    acc.add(nf, f.data());
    acc.add(ne, e.data());
    const int na = acc.finish();
    ASSERT_EQ(value(na, h.data()), 2 * ve + vf);
    ASSERT_TRUE(nonoverlapping_increasing(na, h.data()));
  }
}

// =========================================================================================
// Filter constants: inequality (*) of filter_bounds.hpp, checked in exact arithmetic
// =========================================================================================
TEST(FilterBounds, CoefficientsSatisfyDerivedInequality) {
  const mpq_class u(mpz_class(1), mpz_class(1) << 53);
  const mpq_class rho(1, 8);
  for (int n : {1, 4, 5, 8, 12, 16, 17}) {
    const mpq_class c(bounds::coefficient(n));
    ASSERT_EQ(c, mpq_class(4 * n + 1, 1) * mpq_class(mpz_class(1), mpz_class(1) << 55));
    const mpq_class gamma = n * u / (1 - n * u);
    const mpq_class rhs = gamma * (1 + rho * u) / (1 - gamma) + rho * u;
    EXPECT_GE(c * (1 - u), rhs) << "N = " << n;
  }
  // Thresholds: T >= G * 2^-1075 / (rho u) with the G bounds of filter_bounds.hpp.
  const double e2 = bounds::kFilterCoordMaxExp;
  EXPECT_GE(std::log2(bounds::kOrient3dThreshold), (e2 + 4) - 1075 + 3 + 53);
  EXPECT_GE(std::log2(bounds::kInsphereThreshold), (3 * e2 + 11) - 1075 + 3 + 53);
  EXPECT_GE(std::log2(bounds::kPowerThreshold), (3 * e2 + 11) - 1075 + 3 + 53);
  EXPECT_GE(std::log2(bounds::kMinorThreshold), (2 * e2 + 8) - 1075 + 3 + 53);
}

TEST(FilterBounds, UncertainOnOverflowNanAndUnderflow) {
  const double inf = INFINITY, nan = NAN;
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
  const double bad[3] = {inf, 0, 0}, nn[3] = {nan, 0, 0};
  EXPECT_EQ(orient3d_filter(o, x, y, z), 1);
  EXPECT_EQ(orient3d_filter(o, x, y, bad), kUncertain);
  EXPECT_EQ(orient3d_filter(o, x, y, nn), kUncertain);
  const double h[3] = {0x1p600, 0, 0}, hy[3] = {0, 0x1p600, 0}, hz[3] = {0, 0, 0x1p600};
  EXPECT_EQ(orient3d_filter(o, h, hy, hz), kUncertain);  // 2^1800 overflows
  const double t = 0x1p-300;
  const double tx[3] = {t, 0, 0}, ty[3] = {0, t, 0}, tz[3] = {0, 0, t};
  EXPECT_EQ(orient3d_filter(o, tx, ty, tz), kUncertain);  // permanent 2^-900 < 2^-815
  const double c[3] = {0.25, 0.25, 0.25}, far[3] = {5, 5, 5};
  EXPECT_EQ(insphere_filter(o, x, y, z, c), 1);
  EXPECT_EQ(insphere_filter(o, x, y, z, far), -1);
  EXPECT_EQ(insphere_filter(o, x, y, z, nn), kUncertain);
  const double s = 0x1p-90;
  const double sx[3] = {s, 0, 0}, sy[3] = {0, s, 0}, sz[3] = {0, 0, s}, sc[3] = {s / 4, s / 4, s / 4};
  EXPECT_EQ(insphere_filter(o, sx, sy, sz, sc), kUncertain);  // permanent ~2^-450 < 2^-408
  std::vector<double> work(kPredicateWork);
  EXPECT_EQ(insphere(o, sx, sy, sz, sc, work.data()), 1);  // the exact stage decides
  EXPECT_EQ(power_filter(o, x, y, z, c, 0, 0, 0, 0, nan), kUncertain);
  EXPECT_EQ(power_filter(o, x, y, z, c, 0, 0, 0, 0, inf), kUncertain);
}

// insphere_filter4 and orient3d_filter4 (the CPU backend's cavity search and walk test
// several tets in SIMD lanes) answer as insphere_filter and orient3d_filter, lane by lane
// and for every lane count, on random, near-degenerate and degenerate cases and at the
// filters' limits (NaN, infinity, overflow, underflow), and every sign they give is the
// exact one.
TEST(FilterBounds, SimdFiltersAnswerAsTheScalarFilters) {
  Generator g(77);
  Oracle o;
  long compared = 0, uncertain = 0, mismatches = 0, signs = 0, wrong = 0;
  const double specials[] = {NAN, INFINITY, -INFINITY, 0x1p600, 0x1p-300, 0x1p-90, 0.0};
  for (long t = 0; t < 200000; ++t) {
    Case k[4];
    for (int j = 0; j < 4; ++j) {
      const int sel = static_cast<int>((t + j) % 8);
      k[j] = sel < 3 ? g.degenerate(static_cast<int>(t)) : g.random(sel == 3 ? 0x1p198 : sel == 4 ? 0x1p-120 : 1.0);
      if (t % 97 == 0) k[j].p[g.integer(0, 3)][g.integer(0, 2)] = specials[g.integer(0, 6)];
    }
    const double* pts[4][4];
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) pts[j][i] = k[j].p[i];
    const double* e = k[0].p[4];  // the four tests share their fifth point, as in a cavity search
    for (int n = 1; n <= 4; ++n) {
      int out[4] = {7, 7, 7, 7};
      insphere_filter4(pts, e, n, out);
      for (int j = 0; j < n; ++j) {
        const int want = insphere_filter(pts[j][0], pts[j][1], pts[j][2], pts[j][3], e);
        ++compared;
        uncertain += want == kUncertain;
        if (out[j] != want && ++mismatches <= 10)
          ADD_FAILURE() << "lane " << j << " of " << n << ": " << out[j] << " vs " << want << " " << describe(k[j], 4);
        if (n == 4 && t % 97 != 0 && out[j] != kUncertain) {  // a sign is the exact one (GMP)
          Case c = k[j];
          for (int d = 0; d < 3; ++d) c.p[4][d] = e[d];
          o.load(c, 5, false);
          ++signs;
          if (out[j] != o.lifted() && ++wrong <= 10) ADD_FAILURE() << "lane " << j << ": not the exact sign " << describe(c, 5);
        }
      }
      // orient3d over (t[j][0], t[j][1], t[j][2], e)
      const double* tri[4][3];
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i) tri[j][i] = pts[j][i];
      int o3[4] = {7, 7, 7, 7};
      orient3d_filter4(tri, e, n, o3);
      for (int j = 0; j < n; ++j) {
        const int want = orient3d_filter(tri[j][0], tri[j][1], tri[j][2], e);
        ++compared;
        uncertain += want == kUncertain;
        if (o3[j] != want && ++mismatches <= 10)
          ADD_FAILURE() << "orient3d lane " << j << " of " << n << ": " << o3[j] << " vs " << want << " " << describe(k[j], 3);
        if (n == 4 && t % 97 != 0 && o3[j] != kUncertain) {
          Case c = k[j];
          for (int d = 0; d < 3; ++d) c.p[3][d] = e[d];
          o.load(c, 4, false);
          ++signs;
          if (o3[j] != o.orient3d() && ++wrong <= 10) ADD_FAILURE() << "orient3d lane " << j << ": not the exact sign " << describe(c, 4);
        }
      }
    }
  }
  std::printf("[simd filters] %ld lanes compared, %ld uncertain; %ld signs checked against GMP\n", compared,
              uncertain, signs);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(uncertain, compared / 100);  // the degenerate families reach the uncertain answers
}

// =========================================================================================
// Sign conventions and geometric meaning
// =========================================================================================
TEST(Predicates, SignConventions) {
  std::vector<double> w(kPredicateWork);
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  const double in[3] = {0.25, 0.25, 0.25}, out[3] = {2, 2, 2};
  EXPECT_EQ(orient3d(a, b, c, d, w.data()), 1);  // det[b-a, c-a, d-a] = det(I) = 1
  EXPECT_EQ(orient3d(a, c, b, d, w.data()), -1);
  EXPECT_EQ(insphere(a, b, c, d, in, w.data()), 1);
  EXPECT_EQ(insphere(a, b, c, d, out, w.data()), -1);
  EXPECT_EQ(insphere(a, c, b, d, in, w.data()), -1);  // flips with the tet's orientation
  EXPECT_EQ(insphere(a, b, c, d, d, w.data()), 0);
  EXPECT_EQ(insphere_exact(a, b, c, d, in, w.data()), 1);
  EXPECT_EQ(orient3d_exact(a, b, c, d, w.data()), 1);
  // power: equal weights = insphere; a heavy e is in conflict even outside the sphere;
  // a heavy vertex pushes e out of conflict.
  EXPECT_EQ(power(a, b, c, d, out, 5, 5, 5, 5, 5, w.data()), -1);
  EXPECT_EQ(power(a, b, c, d, out, 0, 0, 0, 0, 100, w.data()), 1);
  EXPECT_EQ(power(a, b, c, d, in, 0, 0, 0, 0, -10, w.data()), -1);
  EXPECT_EQ(power_exact(a, b, c, d, out, 0, 0, 0, 0, 100, w.data()), 1);
  // raw minors: mask xyz = -orient3d, mask xyzh = -power
  const double* p[5] = {a, b, c, d, in};
  const double ws[5] = {0, 0, 0, 0, 1};
  EXPECT_EQ(lifted_minor(p, nullptr, kColX | kColY | kColZ, w.data()), -1);
  EXPECT_EQ(lifted_minor(p, ws, kColX | kColY | kColZ | kColH, w.data()), -1);
  EXPECT_EQ(orient2d_proj(a, b, c, 0, 1, w.data()), 1);
  EXPECT_EQ(orient2d_proj(a, b, c, 1, 0, w.data()), -1);
  // lift SoS: five cospherical points, e with the largest index is outside
  const double e[3] = {1, 1, 0};  // on the sphere through a, b, c, d? |e - (.5,.5,.5)|^2 = .75
  EXPECT_EQ(insphere(a, b, c, d, e, w.data()), 0);
  EXPECT_EQ(insphere_lift_sos(a, b, c, d, e, 0, 1, 2, 3, 4, w.data()), -1);
  // ... and with a the largest index, e is inside: dP/dh_a = -orient3d(b,c,d,e)
  const int o = orient3d(b, c, d, e, w.data());
  ASSERT_NE(o, 0);
  EXPECT_EQ(insphere_lift_sos(a, b, c, d, e, 9, 1, 2, 3, 4, w.data()), -o);
}

// insphere against the circumcentre (rational solve) and power against the lifted plane.
TEST(Predicates, GeometricMeaning) {
  Generator g(3);
  std::vector<double> work(kPredicateWork);
  for (int t = 0; t < 4000; ++t) {
    Case k = t % 2 ? g.random() : g.degenerate(t);
    mpq_class P[5][3], W[5];
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) P[i][c] = k.p[i][c];
      W[i] = k.w[i];
    }
    // Plane through lifted a..d: h = alpha . p + delta, i.e. solve for (alpha, delta):
    // 2 alpha . (p_i - p_0) = ... use the circumcentre form: centre C, radius^2 R solve
    // |p_i - C|^2 - w_i = R for i = 0..3 (power sphere):
    // 2 (p_i - p_0).C = |p_i|^2 - |p_0|^2 - w_i + w_0.
    mpq_class A[3][4];
    for (int i = 0; i < 3; ++i) {
      mpq_class rhs = 0;
      for (int c = 0; c < 3; ++c) {
        A[i][c] = 2 * (P[i + 1][c] - P[0][c]);
        rhs += P[i + 1][c] * P[i + 1][c] - P[0][c] * P[0][c];
      }
      A[i][3] = rhs - W[i + 1] + W[0];
    }
    // Cramer
    auto det3 = [](mpq_class m[3][3]) -> mpq_class {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    mpq_class m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = A[i][j];
    const mpq_class D = det3(m);
    if (D == 0) continue;
    mpq_class C[3];
    for (int c = 0; c < 3; ++c) {
      mpq_class mc[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) mc[i][j] = j == c ? A[i][3] : A[i][j];
      C[c] = det3(mc) / D;
    }
    auto pw = [&](int i) -> mpq_class {  // power distance of point i to the sphere (C, R): |p-C|^2 - w
      mpq_class s = -W[i];
      for (int c = 0; c < 3; ++c) s += (P[i][c] - C[c]) * (P[i][c] - C[c]);
      return s;
    };
    const int o = orient3d(k.p[0], k.p[1], k.p[2], k.p[3], work.data());
    ASSERT_NE(o, 0);
    // e in conflict iff its power distance is below that of the tet's vertices
    const int expect_pow = sgn(pw(0) - pw(4)) * o;
    const int got_pow = power(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.w[0], k.w[1], k.w[2],
                              k.w[3], k.w[4], work.data());
    ASSERT_EQ(got_pow, expect_pow) << describe(k, 5);
    if (k.w[0] == 0 && k.w[1] == 0 && k.w[2] == 0 && k.w[3] == 0 && k.w[4] == 0) {
      ASSERT_EQ(insphere(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], work.data()), expect_pow);
    }
  }
}

// =========================================================================================
// Sorting network
// =========================================================================================
TEST(Predicates, SortingNetworkParity) {
  int perm5[5] = {0, 1, 2, 3, 4};
  do {
    std::int64_t idx[5];
    int pp[5] = {0, 1, 2, 3, 4};
    for (int i = 0; i < 5; ++i) idx[i] = 10 * perm5[i] - 7;
    const int swaps = detail::sort_network<5>(idx, pp);
    for (int i = 0; i < 4; ++i) ASSERT_LT(idx[i], idx[i + 1]);
    for (int i = 0; i < 5; ++i) ASSERT_EQ(idx[i], 10 * perm5[pp[i]] - 7);
    ASSERT_EQ(swaps & 1, parity(perm5, 5));
  } while (std::next_permutation(perm5, perm5 + 5));
  int perm4[4] = {0, 1, 2, 3};
  do {
    std::int64_t idx[4];
    int pp[4] = {0, 1, 2, 3};
    for (int i = 0; i < 4; ++i) idx[i] = perm4[i];
    const int swaps = detail::sort_network<4>(idx, pp);
    for (int i = 0; i < 3; ++i) ASSERT_LT(idx[i], idx[i + 1]);
    ASSERT_EQ(swaps & 1, parity(perm4, 4));
  } while (std::next_permutation(perm4, perm4 + 4));
}

// =========================================================================================
// Random cases: 10^6, every main predicate against GMP (threads across cases)
// =========================================================================================
TEST(Predicates, RandomCasesMatchGmp) {
  const long n = 1000000;
  Failures fail;
  std::atomic<long> uncertain_o3{0}, uncertain_ins{0}, uncertain_pow{0}, minors{0};
  const auto t0 = std::chrono::steady_clock::now();
  run_parallel(n, [&](int th, long b, long e) {
    Generator g(1000 + th);
    Oracle o;
    std::vector<double> work(kPredicateWork);
    long u3 = 0, ui = 0, up = 0, nm = 0;
    for (long t = b; t < e; ++t) {
      // mostly unit scale; some at the ends of the range
      const int sel = static_cast<int>(t % 16);
      const double s = sel == 0 ? 0x1p198 : sel == 1 ? 0x1p-120 : sel == 2 ? 1e6 : 1.0;
      const Case k = g.random(s);
      const double *pa = k.p[0], *pb = k.p[1], *pc = k.p[2], *pd = k.p[3], *pe = k.p[4];
      o.load(k, 5, false);
      const int x3 = o.orient3d();
      const int xi = o.lifted();
      const int r3 = orient3d(pa, pb, pc, pd, work.data());
      const int ri = insphere(pa, pb, pc, pd, pe, work.data());
      u3 += orient3d_filter(pa, pb, pc, pd) == kUncertain;
      ui += insphere_filter(pa, pb, pc, pd, pe) == kUncertain;
      if (r3 != x3) fail.add("orient3d " + describe(k, 4));
      if (ri != xi) fail.add("insphere " + describe(k, 5));
      o.load(k, 5, true);
      const int xp = o.lifted();
      const int rp = power(pa, pb, pc, pd, pe, k.w[0], k.w[1], k.w[2], k.w[3], k.w[4], work.data());
      up += power_filter(pa, pb, pc, pd, pe, k.w[0], k.w[1], k.w[2], k.w[3], k.w[4]) == kUncertain;
      if (rp != xp) fail.add("power " + describe(k, 5));
      if (t % 64 == 0) {  // exact stages alone
        if (orient3d_exact(pa, pb, pc, pd, work.data()) != x3) fail.add("orient3d_exact " + describe(k, 4));
        if (power_exact(pa, pb, pc, pd, pe, k.w[0], k.w[1], k.w[2], k.w[3], k.w[4], work.data()) != xp)
          fail.add("power_exact " + describe(k, 5));
        o.load(k, 5, false);
        if (insphere_exact(pa, pb, pc, pd, pe, work.data()) != xi) fail.add("insphere_exact " + describe(k, 5));
      }
      if (t % 8 == 0) {  // a lifted minor with a random column mask (1..3 columns)
        unsigned mask;
        do mask = static_cast<unsigned>(g.integer(1, 15));
        while (__builtin_popcount(mask) == 4);
        o.load(k, 5, true);
        const double* pts[5] = {pa, pb, pc, pd, pe};
        const int xm = o.minor(mask);
        if (lifted_minor(pts, k.w, mask, work.data()) != xm ||
            lifted_minor_exact(pts, k.w, mask, work.data()) != xm)
          fail.add("minor " + std::to_string(mask) + " " + describe(k, 4));
        ++nm;
      }
    }
    uncertain_o3 += u3;
    uncertain_ins += ui;
    uncertain_pow += up;
    minors += nm;
  });
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[random] %ld cases x {orient3d, insphere, power} + %ld minors, %.1f s; filter "
              "uncertain: orient3d %ld, insphere %ld, power %ld\n",
              n, minors.load(), sec, uncertain_o3.load(), uncertain_ins.load(), uncertain_pow.load());
  fail.report("random");
}

// =========================================================================================
// Near-degenerate and degenerate cases: all predicates, minors, SoS and lift-SoS
// =========================================================================================
TEST(Predicates, DegenerateCasesMatchGmpAndSosIsConsistent) {
  const long n = 200000;
  Failures fail;
  std::atomic<long> zeros_o3{0}, zeros_ins{0}, zeros_pow{0}, em_checked{0}, lift_deep{0}, no_scratch_walks{0};
  const auto t0 = std::chrono::steady_clock::now();
  run_parallel(n, [&](int th, long b, long e) {
    Generator g(5000 + th);
    Oracle o;
    std::vector<double> work(kPredicateWork);
    long z3 = 0, zi = 0, zp = 0, em = 0, deep = 0, free_walks = 0;
    for (long t = b; t < e; ++t) {
      const Case k = g.degenerate(static_cast<int>(t));
      const double *pa = k.p[0], *pb = k.p[1], *pc = k.p[2], *pd = k.p[3], *pe = k.p[4];
      const double* pts[5] = {pa, pb, pc, pd, pe};
      const double* W = k.w;
      // --- orient3d
      o.load(k, 4, false);
      const int x3 = o.orient3d();
      z3 += x3 == 0;
      const int f3 = orient3d_filter(pa, pb, pc, pd);
      if ((f3 != kUncertain && f3 != x3) || orient3d(pa, pb, pc, pd, work.data()) != x3 ||
          orient3d_exact(pa, pb, pc, pd, work.data()) != x3)
        fail.add("orient3d " + describe(k, 4));
      const int s3 = call(Pred::O3Sos, k, work.data());
      if (s3 == 0 || (x3 != 0 && s3 != x3)) fail.add("orient3d_sos " + describe(k, 4));
      if (x3 == 0 && (t % 4 == 0)) {
        ++em;
        if (s3 != o.em_sos(4, k.id)) fail.add("orient3d_sos brute force " + describe(k, 4));
      }
      // --- insphere
      o.load(k, 5, false);
      const int xi = o.lifted();
      zi += xi == 0;
      const int fi = insphere_filter(pa, pb, pc, pd, pe);
      if ((fi != kUncertain && fi != xi) || insphere(pa, pb, pc, pd, pe, work.data()) != xi ||
          insphere_exact(pa, pb, pc, pd, pe, work.data()) != xi)
        fail.add("insphere " + describe(k, 5));
      const int si = call(Pred::InsSos, k, work.data());
      const int li = call(Pred::InsLift, k, work.data());
      if (si == 0 || (xi != 0 && si != xi)) fail.add("insphere_sos " + describe(k, 5));
      if (li == 0 || (xi != 0 && li != xi)) fail.add("insphere_lift_sos " + describe(k, 5));
      if (xi == 0) {
        const int bl = o.lift_sos(k.id);
        if (li != bl) fail.add("insphere_lift_sos brute force " + describe(k, 5));
        if (t % 4 == 1) {
          ++em;
          if (si != o.em_sos(5, k.id)) fail.add("insphere_sos brute force " + describe(k, 5));
        }
      }
      // --- power
      o.load(k, 5, true);
      const int xp = o.lifted();
      zp += xp == 0;
      const int fp_ = power_filter(pa, pb, pc, pd, pe, W[0], W[1], W[2], W[3], W[4]);
      if ((fp_ != kUncertain && fp_ != xp) ||
          power(pa, pb, pc, pd, pe, W[0], W[1], W[2], W[3], W[4], work.data()) != xp ||
          power_exact(pa, pb, pc, pd, pe, W[0], W[1], W[2], W[3], W[4], work.data()) != xp)
        fail.add("power " + describe(k, 5));
      const int sp = call(Pred::PowSos, k, work.data());
      const int lp = call(Pred::PowLift, k, work.data());
      if (sp == 0 || (xp != 0 && sp != xp)) fail.add("power_sos " + describe(k, 5));
      if (lp == 0 || (xp != 0 && lp != xp)) fail.add("power_lift_sos " + describe(k, 5));
      if (xp == 0) {
        const int bl = o.lift_sos(k.id);
        if (lp != bl) fail.add("power_lift_sos brute force " + describe(k, 5));
        if (t % 4 == 2) {
          ++em;
          if (sp != o.em_sos(5, k.id)) fail.add("power_sos brute force " + describe(k, 5));
        }
        // all five cofactors zero -> the lift SoS went on to the position terms
        bool all_zero = true;
        for (int i = 0; i < 5 && all_zero; ++i) {
          const double* q[4];
          for (int a = 0, u = 0; a < 5; ++a)
            if (a != i) q[u++] = pts[a];
          all_zero = orient3d(q[0], q[1], q[2], q[3], work.data()) == 0;
        }
        deep += all_zero;
      }
      // --- equal weights: power == insphere, power_sos == insphere_sos
      {
        const double ww = W[0];
        if (power(pa, pb, pc, pd, pe, ww, ww, ww, ww, ww, work.data()) != xi ||
            power_sos(pa, pb, pc, pd, pe, ww, ww, ww, ww, ww, k.id[0], k.id[1], k.id[2], k.id[3],
                      k.id[4], work.data()) != si ||
            power_lift_sos(pa, pb, pc, pd, pe, ww, ww, ww, ww, ww, k.id[0], k.id[1], k.id[2],
                           k.id[3], k.id[4], work.data()) != li)
          fail.add("equal weights " + describe(k, 5));
      }
      // --- antisymmetry under a random permutation of (point, weight, index) triples
      {
        int perm[5] = {0, 1, 2, 3, 4};
        std::shuffle(perm, perm + 5, g.rng());
        const Case kp = permuted(k, perm, 5);
        const int sg = parity(perm, 5) ? -1 : 1;
        if (call(Pred::InsSos, kp, work.data()) != sg * si ||
            call(Pred::InsLift, kp, work.data()) != sg * li ||
            call(Pred::PowSos, kp, work.data()) != sg * sp ||
            call(Pred::PowLift, kp, work.data()) != sg * lp)
          fail.add("permutation (5) " + describe(k, 5));
        int perm4[4] = {0, 1, 2, 3};
        std::shuffle(perm4, perm4 + 4, g.rng());
        const Case kq = permuted(k, perm4, 4);
        if (call(Pred::O3Sos, kq, work.data()) != (parity(perm4, 4) ? -s3 : s3))
          fail.add("permutation (4) " + describe(k, 4));
        // an explicit odd permutation: one transposition
        const int i = g.integer(0, 4);
        int j = g.integer(0, 3);
        if (j >= i) ++j;
        int tr[5] = {0, 1, 2, 3, 4};
        std::swap(tr[i], tr[j]);
        const Case kt = permuted(k, tr, 5);
        if (call(Pred::InsSos, kt, work.data()) != -si || call(Pred::PowSos, kt, work.data()) != -sp ||
            call(Pred::InsLift, kt, work.data()) != -li || call(Pred::PowLift, kt, work.data()) != -lp)
          fail.add("transposition " + describe(k, 5));
      }
      // --- no scratch (work = nullptr): where every point (and weight) is of the integer
      // stage, all at scale 1 or all at the quarter scale, the same sign as with a scratch
      // (the SoS walks on detail::IntRows); elsewhere that sign or kUncertain, never another
      {
        auto of_stage = [&](int np, bool weighted) {
          for (const double sc : {1.0, kQuarterScale}) {
            bool all = true;
            for (int i = 0; i < np; ++i) all = all && integer_point(k.p[i], weighted ? W[i] : 0.0, sc);
            if (all) return true;
          }
          return false;
        };
        const Pred preds[5] = {Pred::O3Sos, Pred::InsSos, Pred::InsLift, Pred::PowSos, Pred::PowLift};
        const int with[5] = {s3, si, li, sp, lp};
        const int exact_with[3] = {x3, xi, xp};
        const int exact_without[3] = {orient3d_exact(pa, pb, pc, pd, nullptr),
                                      insphere_exact(pa, pb, pc, pd, pe, nullptr),
                                      power_exact(pa, pb, pc, pd, pe, W[0], W[1], W[2], W[3], W[4], nullptr)};
        for (int q = 0; q < 5; ++q) {
          const bool weighted = preds[q] == Pred::PowSos || preds[q] == Pred::PowLift;
          const bool stage = of_stage(preds[q] == Pred::O3Sos ? 4 : 5, weighted);
          const int without = call(preds[q], k, nullptr);  // (std::nullptr_t: the scratch-free instances)
          const int null_work = call(preds[q], k, static_cast<double*>(nullptr));  // (a null double*)
          if (stage ? without != with[q] : (without != with[q] && without != kUncertain))
            fail.add("no scratch, predicate " + std::to_string(q) + " " + describe(k, 5));
          if (null_work != without) fail.add("null scratch, predicate " + std::to_string(q) + " " + describe(k, 5));
          const int x = q == 0 ? x3 : (weighted ? xp : xi);
          free_walks += stage && x == 0;
          if (q == 0 || q == 2 || q == 4) {
            const int e = q / 2;
            if (stage ? exact_without[e] != exact_with[e]
                      : (exact_without[e] != exact_with[e] && exact_without[e] != kUncertain))
              fail.add("no scratch, exact " + std::to_string(e) + " " + describe(k, 5));
          }
        }
      }
      // --- lifted minors (all masks of 1..3 columns on the first k+1 points)
      if (t % 2 == 0) {
        o.load(k, 5, true);
        for (unsigned mask = 1; mask < 15; ++mask) {
          if (__builtin_popcount(mask) == 4) continue;
          const int xm = o.minor(mask);
          const int fm = lifted_minor_filter(pts, W, mask);
          if ((fm != kUncertain && fm != xm) || lifted_minor(pts, W, mask, work.data()) != xm ||
              lifted_minor_exact(pts, W, mask, work.data()) != xm)
            fail.add("minor " + std::to_string(mask) + " " + describe(k, 4));
        }
      }
    }
    zeros_o3 += z3;
    zeros_ins += zi;
    zeros_pow += zp;
    em_checked += em;
    lift_deep += deep;
    no_scratch_walks += free_walks;
  });
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[degenerate] %ld cases, %.1f s; exact zeros: orient3d %ld, insphere %ld, power %ld; "
              "E-M brute-force checks %ld; lift-SoS E-M fallbacks (5 coplanar, power) %ld; "
              "SoS walks without a scratch %ld\n",
              n, sec, zeros_o3.load(), zeros_ins.load(), zeros_pow.load(), em_checked.load(),
              lift_deep.load(), no_scratch_walks.load());
  EXPECT_GT(zeros_o3.load(), n / 10);
  EXPECT_GT(zeros_ins.load(), n / 10);
  EXPECT_GT(zeros_pow.load(), n / 10);
  EXPECT_GT(lift_deep.load(), 100);
  EXPECT_GT(no_scratch_walks.load(), n / 10);
  fail.report("degenerate");
}

// Hand-made exact degeneracies that walk deep into the SoS tables.
// =========================================================================================
// The integer stage (minors.hpp): taken exactly where its bounds hold, and exact there
// =========================================================================================
namespace {
template <int K>
bool int_stage(const gdel::geom::detail::LiftedRows& R, const int* cols, int& s) {
  const int rows[5] = {0, 1, 2, 3, 4};
  return gdel::geom::detail::det_ones_int<K>(R, rows, cols, s);
}
// f(R, mask, cols, kc) for every column mask 1..15 (kc columns cols[0..kc)) of the five
// points of k, with the oracle loaded (weighted) for o.minor(mask).
template <class F>
void for_each_minor(const Case& k, Oracle& o, F f) {
  const gdel::geom::detail::LiftedRows R{{k.p[0], k.p[1], k.p[2], k.p[3], k.p[4]},
                                         {k.w[0], k.w[1], k.w[2], k.w[3], k.w[4]}};
  o.load(k, 5, true);
  for (unsigned mask = 1; mask < 16; ++mask) {
    int cols[4];
    const int kc = gdel::geom::detail::mask_columns(mask, cols);
    f(R, mask, cols, kc);
  }
}
}  // namespace

TEST(Predicates, IntegerStageAppliesWithinItsBoundsAndMatchesGmp) {
  Generator g(4242);
  Oracle o;
  Failures fail;
  long taken = 0, refused = 0, zeros = 0;
  const auto coord_ok = [](double x) { return std::fabs(x) <= 0x1p23 && x == std::trunc(x); };
  const auto weight_ok = [](double w) { return std::fabs(w) <= 0x1p46 && w == std::trunc(w); };
  long quarters = 0;  // taken at the quarter scale only
  for (long t = 0; t < 60000; ++t) {
    // the integer family; every fourth case another family (fractions, huge, tiny: refused)
    const Case k = g.degenerate(t % 4 ? 9 : static_cast<int>(t / 4));
    for_each_minor(k, o, [&](const gdel::geom::detail::LiftedRows& R, unsigned mask, const int* cols, int kc) {
      // the entries at scale 1, or all of them times 4 (weights times 16)
      const auto entries_ok = [&](double sc) {
        bool e = true;
        for (int i = 0; i <= kc; ++i)
          for (int j = 0; j < kc; ++j) {
            if (cols[j] < 3) e = e && coord_ok(sc * k.p[i][cols[j]]);
            else
              e = e && coord_ok(sc * k.p[i][0]) && coord_ok(sc * k.p[i][1]) && coord_ok(sc * k.p[i][2]) &&
                  weight_ok(sc * sc * k.w[i]);
          }
        return e;
      };
      const bool at1 = entries_ok(1.0), at4 = entries_ok(4.0);
      const bool expect = at1 || at4;
      quarters += !at1 && at4;
      int s = 7;
      bool ok = false;
      switch (kc) {
        case 1: ok = int_stage<1>(R, cols, s); break;
        case 2: ok = int_stage<2>(R, cols, s); break;
        case 3: ok = int_stage<3>(R, cols, s); break;
        default: ok = int_stage<4>(R, cols, s); break;
      }
      if (ok != expect) fail.add("integer stage taken=" + std::to_string(ok) + " mask " + std::to_string(mask) + " " + describe(k, 5));
      if (!ok) {
        ++refused;
        return;
      }
      ++taken;
      const int x = o.minor(mask);
      zeros += x == 0;
      if (s != x) fail.add("integer stage sign, mask " + std::to_string(mask) + " " + describe(k, 5));
    });
  }
  std::printf("[integer stage] %ld minors taken (%ld zero, %ld at the quarter scale), %ld refused\n", taken, zeros,
              quarters, refused);
  // all outcomes occur, so the checks above have something to see
  EXPECT_GT(taken, 100000);
  EXPECT_GT(quarters, 10000);
  EXPECT_GT(zeros, 10000);
  EXPECT_GT(refused, 10000);
  fail.report("integer stage");
}

// =========================================================================================
// The small-integer stage (predicates.hpp: exact in binary64, for filter-stage code): where it
// answers, the exact SoS sign (GMP and the brute-force perturbations); it answers the
// lattice's ties, and refuses past its bounds
// =========================================================================================
namespace {
// The integer points of the sphere x^2 + y^2 + z^2 = d (radius about 1 000: neighbours
// farther apart than the insphere bound of 2^9 are common).
std::vector<std::array<double, 3>> sphere_lattice(long d) {
  std::vector<std::array<double, 3>> pts;
  const long r = static_cast<long>(std::sqrt(static_cast<double>(d)));
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y) {
      const long z2 = d - x * x - y * y;
      if (z2 < 0) continue;
      const long z = std::lround(std::sqrt(static_cast<double>(z2)));
      if (z * z != z2) continue;
      pts.push_back({double(x), double(y), double(z)});
      if (z != 0) pts.push_back({double(x), double(y), double(-z)});
    }
  return pts;
}
}  // namespace

TEST(Predicates, SmallIntegerStageMatchesGmpAndSos) {
  Generator g(777);
  Oracle o;
  Failures fail;
  std::vector<double> work(kPredicateWork);
  const auto sphere = sphere_lattice(1000001);
  ASSERT_GT(sphere.size(), 1000u);
  long o3_decided = 0, o3_ties = 0, o3_refused = 0, in_decided = 0, in_ties = 0, in_sphere = 0, in_refused = 0;
  for (long t = 0; t < 200000; ++t) {
    Case k;
    g.ids(k);
    const int fam = static_cast<int>(t % 5);
    // 0: a small box (ties everywhere); 1: the box of the grid generator, 512^3; 2: past
    // the bounds (differences up to 2^15, on one plane); 3: multiples of 1/4 (orient3d
    // only: ∞'s point K);
    // 4: integer points of one sphere, a random neighbourhood
    const int side = fam == 0 ? g.integer(1, 4) : fam == 1 ? 511 : fam == 2 ? (1 << 15) : 64;
    const std::size_t s0 = g.integer(0, static_cast<int>(sphere.size()) - 1);
    for (int i = 0; i < 5; ++i) {
      const std::size_t j = (s0 + static_cast<std::size_t>(g.integer(0, 400))) % sphere.size();
      for (int c = 0; c < 3; ++c) {
        k.p[i][c] = fam == 4 ? sphere[j][c] : fam == 2 && c == 2 ? 100000 : g.integer(0, side);
        if (fam == 3) k.p[i][c] *= 0.25;
      }
    }
    for (int i = 0; i < 5; ++i) k.w[i] = 0;
    // orient3d: the small stage against GMP (an exact 0: the brute-force E-M perturbation)
    o.load(k, 4, false);
    const int x3 = o.orient3d();
    const int s3 = orient3d_sos_small(k.p[0], k.p[1], k.p[2], k.p[3], k.id[0], k.id[1], k.id[2], k.id[3]);
    if (s3 == kUncertain) {
      ++o3_refused;
    } else {
      ++o3_decided;
      o3_ties += x3 == 0;
      const int want = x3 != 0 ? x3 : o.em_sos(4, k.id);
      if (s3 != want || s3 != call(Pred::O3Sos, k, work.data())) fail.add("orient3d_sos_small " + describe(k, 4));
    }
    if (fam == 3) continue;  // (insphere_lift_sos_small takes integers only)
    o.load(k, 5, false);
    const int xi = o.lifted();
    const int si = insphere_lift_sos_small(k.p[0], k.p[1], k.p[2], k.p[3], k.p[4], k.id[0], k.id[1], k.id[2],
                                           k.id[3], k.id[4]);
    if (si == kUncertain) {
      ++in_refused;
    } else {
      ++in_decided;
      in_ties += xi == 0;
      in_sphere += xi == 0 && fam == 4;
      const int want = xi != 0 ? xi : o.lift_sos(k.id);
      if (si != want || si != call(Pred::InsLift, k, work.data()))
        fail.add("insphere_lift_sos_small " + describe(k, 5));
    }
  }
  std::printf("[small-integer stage] orient3d %ld decided (%ld ties), %ld refused; insphere %ld decided (%ld ties, "
              "%ld on the sphere), %ld refused\n",
              o3_decided, o3_ties, o3_refused, in_decided, in_ties, in_sphere, in_refused);
  // every outcome occurs, so the checks above see something
  EXPECT_GT(o3_ties, 5000);
  EXPECT_GT(in_ties, 5000);
  EXPECT_GT(in_sphere, 1000);
  EXPECT_GT(o3_refused, 1000);
  EXPECT_GT(in_refused, 1000);
  fail.report("small-integer stage");
}

// The narrow form (int64 minors, one 128-bit step) and the 128-bit form of the integer
// stage, each against GMP, about the narrow form's limit of 2^20 (Generator::int_narrow_limit).
namespace {
struct NarrowTally {
  long narrow = 0, wide_only = 0, zero_column = 0, zeros = 0;
};
template <int K>
void check_int_forms(const gdel::geom::detail::LiftedRows& R, const int* cols, int expect, NarrowTally& n,
                     Failures& fail, const std::string& what) {
  namespace d = gdel::geom::detail;
  const int rows[5] = {0, 1, 2, 3, 4};
  std::int64_t q[K][K];
  if (!d::int_differences<K>(R, rows, cols, q)) {
    fail.add("integer stage refused " + what);
    return;
  }
  const auto sign = [](d::i128 v) { return (v > 0) - (v < 0); };
  if (sign(d::det_int_wide<K>(q)) != expect) fail.add("128-bit form " + what);
  d::i128 v = 7;
  if (d::det_int_narrow<K>(q, v)) {
    ++n.narrow;
    if (sign(v) != expect) fail.add("narrow form " + what);
  } else {
    ++n.wide_only;
  }
  bool zc = true;
  for (int i = 0; i < K; ++i) zc &= q[i][K - 1] == 0;
  n.zero_column += zc;
  int s = 7;
  if (!d::det_ones_int<K>(R, rows, cols, s) || s != expect) fail.add("det_ones_int " + what);
}
}  // namespace

TEST(Predicates, IntegerStageNarrowFormAtItsLimitsMatchesGmp) {
  Generator g(20261201);
  Oracle o;
  Failures fail;
  NarrowTally n;
  for (long t = 0; t < 40000; ++t) {
    const Case k = g.int_narrow_limit();
    for_each_minor(k, o, [&](const gdel::geom::detail::LiftedRows& R, unsigned mask, const int* cols, int kc) {
      const int x = o.minor(mask);
      n.zeros += x == 0;
      const std::string what = "mask " + std::to_string(mask) + " " + describe(k, 5);
      switch (kc) {
        case 1: check_int_forms<1>(R, cols, x, n, fail, what); break;
        case 2: check_int_forms<2>(R, cols, x, n, fail, what); break;
        case 3: check_int_forms<3>(R, cols, x, n, fail, what); break;
        default: check_int_forms<4>(R, cols, x, n, fail, what); break;
      }
    });
  }
  std::printf("[integer stage, narrow limit] narrow form %ld, 128-bit only %ld, zero last column %ld, "
              "exact zeros %ld\n", n.narrow, n.wide_only, n.zero_column, n.zeros);
  // both forms and the zero column occur often, so each check above has cases to see
  EXPECT_GT(n.narrow, 100000);
  EXPECT_GT(n.wide_only, 100000);
  EXPECT_GT(n.zero_column, 10000);
  EXPECT_GT(n.zeros, 10000);
  fail.report("integer stage narrow form");
}

TEST(Predicates, SosDeepDegeneracies) {
  Oracle o;
  std::vector<double> work(kPredicateWork);
  Generator g(7);
  const double base[3] = {0.375, -1.5, 3.0};
  for (int t = 0; t < 3000; ++t) {
    Case k;
    g.ids(k);
    const int mode = t % 5;
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) k.p[i][c] = base[c];
      k.w[i] = 0.5;
    }
    if (mode >= 1) k.p[g.integer(0, 4)][g.integer(0, 2)] += 1.0;  // one coordinate differs
    if (mode >= 2) k.p[g.integer(0, 4)][g.integer(0, 2)] -= 2.0;
    if (mode >= 3) k.w[g.integer(0, 4)] = 1.5;
    if (mode >= 4) {
      for (int i = 0; i < 5; ++i) k.p[i][2] = base[2];  // all coplanar z = const
    }
    const double *pa = k.p[0], *pb = k.p[1], *pc = k.p[2], *pd = k.p[3], *pe = k.p[4];
    o.load(k, 4, false);
    ASSERT_EQ(call(Pred::O3Sos, k, work.data()), o.em_sos(4, k.id)) << describe(k, 4);
    o.load(k, 5, false);
    ASSERT_EQ(call(Pred::InsSos, k, work.data()), o.em_sos(5, k.id)) << describe(k, 5);
    ASSERT_EQ(call(Pred::InsLift, k, work.data()), o.lift_sos(k.id)) << describe(k, 5);
    o.load(k, 5, true);
    ASSERT_EQ(call(Pred::PowSos, k, work.data()), o.em_sos(5, k.id)) << describe(k, 5);
    ASSERT_EQ(call(Pred::PowLift, k, work.data()), o.lift_sos(k.id)) << describe(k, 5);
    (void)pa, (void)pb, (void)pc, (void)pd, (void)pe;
  }
}

// =========================================================================================
// Contraction regressions
// =========================================================================================
namespace {

// What contraction makes of Dekker's product when it hits the split: c = s*v feeds both
// c - v and c - big, and a contracting compiler may turn both into FMAs. Then
// big = 2^27 v exactly and hi = fma(s, v, -big) = v: the split degenerates (lo = 0, hi has
// 53 bits), the partial products ahi*bhi are no longer exact and the error term is wrong.
// (Contracting only the partial-product chain happens to be harmless; the split is not.)
void contracted_two_product(double a, double b, double& x, double& y) {
  const double s = 134217729.0;
  auto split = [&](double v, double& hi, double& lo) {
    const double big = std::fma(s, v, -v);  // contracted (s*v) - v
    hi = std::fma(s, v, -big);              // contracted (s*v) - big
    lo = v - hi;
  };
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double r1 = x - ahi * bhi;
  const double r2 = r1 - alo * bhi;
  const double r3 = r2 - ahi * blo;
  y = alo * blo - r3;
}

// The filter expression det[b-a, c-a, d-a] with every "p*q - r*s" contracted.
double contracted_orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double mx = std::fma(vy, wz, -(vz * wy));
  const double my = std::fma(vz, wx, -(vx * wz));
  const double mz = std::fma(vx, wy, -(vy * wx));
  return std::fma(uz, mz, std::fma(uy, my, ux * mx));
}

}  // namespace

TEST(Contraction, TwoProductExactWhereContractedSplitFails) {
  Generator g(11);
  int contracted_wrong = 0;
  for (int t = 0; t < 100000; ++t) {
    const double a = rand_double(g, -200, 200), b = rand_double(g, -200, 200);
    double x, y, cx, cy;
    ex::two_product(a, b, x, y);
    ASSERT_EQ(x, a * b);
    ASSERT_EQ(y, std::fma(a, b, -x)) << a << " " << b;  // the exact rounding error
    contracted_two_product(a, b, cx, cy);
    contracted_wrong += cy != std::fma(a, b, -cx);
  }
  // The regression is meaningful: contraction breaks two_product on most inputs.
  EXPECT_GT(contracted_wrong, 1000);
  std::printf("[contraction] contracted two_product wrong on %d of 100000 inputs; ours exact\n",
              contracted_wrong);
}

TEST(Contraction, Orient3dExactWhereContractedDeterminantFails) {
  // c - a = 2 (b - a), d - a = e_z: the exact determinant is 0; contracted, the 2x2 minor
  // vx*wy... reduces to the rounding error of a product, which is not 0.
  const double a[3] = {0.0, 0.0, 0.0};
  const double b[3] = {0.1, 0.7, 0.0};
  const double c[3] = {0.2, 1.4, 0.0};
  const double d[3] = {0.0, 0.0, 1.0};
  const double e[3] = {0.3, 0.3, 0.3};
  ASSERT_NE(contracted_orient3d(a, b, c, d), 0.0);  // a contracting build would get a sign
  std::vector<double> w(kPredicateWork);
  EXPECT_EQ(orient3d(a, b, c, d, w.data()), 0);
  EXPECT_EQ(orient3d_exact(a, b, c, d, w.data()), 0);
  EXPECT_NE(orient3d_filter(a, b, c, d), 1);
  EXPECT_NE(orient3d_filter(a, b, c, d), -1);
  EXPECT_EQ(orient3d_sos(a, b, c, d, 0, 1, 2, 3, w.data()), -orient3d_sos(b, a, c, d, 1, 0, 2, 3, w.data()));
  Oracle o;
  const double* p[5] = {a, b, c, d, e};
  o.load(5, p, nullptr);
  EXPECT_EQ(insphere(a, b, c, d, e, w.data()), o.lifted());
}

// ---------------------------------------------------------------------------------------
// interior_point: a double point strictly inside a tetrahedron (gFlip3D's kernel point)
// ---------------------------------------------------------------------------------------
namespace {

// GMP: is q strictly inside the positive tet p (every face's orient3d with q in place of
// its opposite vertex > 0)?
int oracle_orient(const double* const p[4]) {
  const double* r[5] = {p[0], p[1], p[2], p[3], nullptr};
  Oracle o;
  o.load(4, r, nullptr);
  return o.orient3d();
}
bool oracle_inside(const double* const p[4], const double* q) {
  for (int i = 0; i < 4; ++i) {
    const double* r[4] = {p[0], p[1], p[2], p[3]};
    r[i] = q;
    if (oracle_orient(r) <= 0) return false;
  }
  return true;
}
// The search's answer, checked: a point it returns is inside (GMP) and in the exact range.
bool checked_interior_point(const double* const p[4]) {
  double k[3];
  if (!interior_point(p, k)) return false;
  for (double x : k) EXPECT_TRUE(coordinate_in_range(x)) << x;
  EXPECT_TRUE(oracle_inside(p, k)) << k[0] << " " << k[1] << " " << k[2];
  return true;
}

}  // namespace

TEST(InteriorPoint, SliversFromPropertyTestsAndATetWithoutInteriorDoubles) {
  const double e = std::ldexp(1.0, -126);
  // the two slivers whose rounded centroids miss their interiors (found by
  // tests/python/test_properties.py, sessions 39 and 54), in positive order
  const double a0[3] = {0, 0, 0}, a1[3] = {0, 0, e}, a2[3] = {0, 1, 0}, a3[3] = {1, 0, 1};
  const double b0[3] = {0, 0, 1}, b1[3] = {0, 1, 0}, b2[3] = {0, 1, -e}, b3[3] = {1, 0, 0};
  for (auto t : {std::array<const double*, 4>{a0, a1, a2, a3}, std::array<const double*, 4>{b0, b1, b2, b3}}) {
    if (oracle_orient(t.data()) < 0) std::swap(t[2], t[3]);
    ASSERT_GT(oracle_orient(t.data()), 0);
    double c[3];
    for (int d = 0; d < 3; ++d) c[d] = .25 * t[0][d] + .25 * t[1][d] + .25 * t[2][d] + .25 * t[3][d];
    EXPECT_FALSE(oracle_inside(t.data(), c));  // why the search exists
    EXPECT_TRUE(checked_interior_point(t.data()));
  }
  // four points one ulp apart around (1,1,1): no double inside
  const double u = std::ldexp(1.0, -52);
  const double c0[3] = {1, 1, 1}, c1[3] = {1 + u, 1, 1}, c2[3] = {1, 1 + u, 1}, c3[3] = {1, 1, 1 + u};
  const double* c[4] = {c0, c1, c2, c3};
  ASSERT_GT(oracle_orient(c), 0);
  EXPECT_FALSE(checked_interior_point(c));
  // outside the exact range (a subnormal coordinate): refused, not searched
  const double d0[3] = {0, 0, 0}, d1[3] = {1, 0, 0}, d2[3] = {0, 1, 0}, d3[3] = {0, 0, std::ldexp(1.0, -1070)};
  const double* d[4] = {d0, d1, d2, d3};
  double k[3];
  EXPECT_FALSE(interior_point(d, k));
}

TEST(InteriorPoint, FindsADoubleWheneverTheLatticeHasOne) {
  // Vertices on the lattice 1 + i 2^-52, i = 0..6, per coordinate: every double of that box
  // is a lattice point, so brute force over the 343 of them says whether any double lies
  // inside; the search must find one exactly when one exists.
  Generator g(2026);
  const double u = std::ldexp(1.0, -52);
  auto lattice = [&](int i) { return 1 + i * u; };
  int with = 0, without = 0;
  for (int trial = 0; trial < 250; ++trial) {
    double v[4][3];
    for (auto& x : v)
      for (double& y : x) y = lattice(g.integer(0, 6));
    const double* p[4] = {v[0], v[1], v[2], v[3]};
    const int o = oracle_orient(p);
    if (o == 0) continue;
    if (o < 0) std::swap(p[2], p[3]);
    bool any = false;
    for (int i = 0; i < 7 && !any; ++i)
      for (int j = 0; j < 7 && !any; ++j)
        for (int k = 0; k < 7 && !any; ++k) {
          const double q[3] = {lattice(i), lattice(j), lattice(k)};
          any = oracle_inside(p, q);
        }
    EXPECT_EQ(checked_interior_point(p), any) << "trial " << trial;
    (any ? with : without)++;
  }
  EXPECT_GT(with, 20);
  EXPECT_GT(without, 20);
  std::printf("[interior_point] lattice tets: %d with a double inside (all found), %d without\n", with, without);
}

TEST(InteriorPoint, RandomSliversAcrossScales) {
  // A triangle and a fourth point lifted off its plane by 2^-k, k = 10..140, in a random
  // direction: every answer is checked with GMP; slivers thicker than the doubles' spacing
  // near a vertex must be found.
  Generator g(7);
  int found = 0, total = 0;
  for (int trial = 0; trial < 400; ++trial) {
    double v[4][3];
    for (int i = 0; i < 3; ++i)
      for (double& y : v[i]) y = g.uniform(-1, 1);
    const double s = g.uniform(0.1, 0.8), t = g.uniform(0.1, 0.8) * (1 - s);
    const int k = g.integer(10, 140);
    for (int d = 0; d < 3; ++d)
      v[3][d] = v[0][d] + s * (v[1][d] - v[0][d]) + t * (v[2][d] - v[0][d]) + std::ldexp(g.uniform(-1, 1), -k);
    const double* p[4] = {v[0], v[1], v[2], v[3]};
    const int o = oracle_orient(p);
    if (o == 0) continue;
    if (o < 0) std::swap(p[2], p[3]);
    ++total;
    const bool f = checked_interior_point(p);
    found += f;
    if (k <= 40) {
      EXPECT_TRUE(f) << "trial " << trial << " k " << k;
    }
  }
  EXPECT_GT(found, total / 2);
  std::printf("[interior_point] random slivers: %d of %d with a point found\n", found, total);
}

// ---------------------------------------------------------------------------------------
// orient3d_centroid_sos: orient3d with one point the exact centroid of four others
// ---------------------------------------------------------------------------------------
TEST(Predicates, Orient3dWithAnExactCentroidMatchesGmp) {
  // gdel_test::centroid_cases: centroids off the doubles, half of them exactly on the
  // plane of the other three points (the perturbation decides), each with GMP's sign
  std::vector<double> w(kPredicateWork);
  int ties = 0, off_grid = 0;
  const std::vector<gdel_test::CentroidCase> cases = gdel_test::centroid_cases(4000, 55);
  for (std::size_t t = 0; t < cases.size(); ++t) {
    const gdel_test::CentroidCase& c = cases[t];
    const double* p[4] = {c.p[0], c.p[1], c.p[2], c.p[3]};
    const double* q[4] = {c.q[0], c.q[1], c.q[2], c.q[3]};
    const int got = orient3d_centroid_sos(p, c.kpos, q, c.id, w.data());
    ASSERT_EQ(got, c.want) << "case " << t << " kpos " << c.kpos;
    ASSERT_NE(got, 0);
    ties += c.tie;
    off_grid += c.off_grid;
  }
  EXPECT_GT(ties, 1000);  // the perturbation decided these
  EXPECT_GT(off_grid, 1000);
  std::printf("[centroid orient3d] 4000 cases as GMP: %d exact ties, %d with a centroid off the doubles\n", ties,
              off_grid);
}
