// Tests of the deterministic point generators (src/gen).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "common/expect_error.hpp"
#include "gdel/errors.hpp"
#include "gen/generators.hpp"

namespace gdel::gen {
namespace {

using Triple = std::array<double, 3>;

std::vector<Triple> triples(const std::vector<double>& xyz) {
  std::vector<Triple> t(xyz.size() / 3);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  return t;
}

// Number of points equal to an earlier one (== on every coordinate).
std::size_t count_repeats(const std::vector<double>& xyz) {
  auto t = triples(xyz);
  std::sort(t.begin(), t.end());
  std::size_t repeats = 0;
  for (std::size_t i = 1; i < t.size(); ++i) repeats += t[i] == t[i - 1];
  return repeats;
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// FNV-1a over the bytes of the doubles (little-endian byte order of the bit patterns, so
// the value does not depend on the host byte order).
std::uint64_t fingerprint(const std::vector<double>& v) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (double d : v) {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    for (int b = 0; b < 8; ++b) {
      h ^= (u >> (8 * b)) & 0xFF;
      h *= 0x100000001b3ull;
    }
  }
  return h;
}

std::size_t test_size(Distribution d) { return d == Distribution::SkewLines ? 2001 : 20000; }

TEST(Generators, NamesRoundTrip) {
  for (Distribution d : kAllDistributions) {
    EXPECT_EQ(parse_distribution(to_string(d)), d);
    std::string upper(to_string(d));
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_EQ(parse_distribution(upper), d);
  }
  EXPECT_EQ(to_string(Distribution::ThinShell), "thin_shell");
  EXPECT_EQ(to_string(Distribution::SkewLines), "skew_lines");
  test::expect_error<InvalidInput>([] { parse_distribution("cube"); }, {"'cube'", "thin_shell", "skew_lines"});
  EXPECT_THROW(parse_distribution(""), InvalidInput);
  EXPECT_THROW(parse_distribution("uniform "), InvalidInput);
}

TEST(Generators, CountsDeterminismAndDistinctness) {
  for (Distribution d : kAllDistributions) {
    SCOPED_TRACE(std::string(to_string(d)));
    const std::size_t n = test_size(d);
    const auto a = generate(d, n, 7);
    const auto b = generate(d, n, 7);
    const auto c = generate(d, n, 8);
    ASSERT_EQ(a.size(), 3 * n);
    ASSERT_EQ(c.size(), 3 * n);
    EXPECT_TRUE(bitwise_equal(a, b)) << "same seed, different output";
    EXPECT_FALSE(bitwise_equal(a, c)) << "different seeds, same output";
    EXPECT_EQ(count_repeats(a), 0u);
    for (double v : a) EXPECT_TRUE(std::isfinite(v));
    EXPECT_TRUE(generate(d, 0, 7).empty());
    EXPECT_EQ(generate(d, 1, 7).size(), 3u);
    // A prefix property is not promised, but small sizes must work and stay distinct.
    for (std::size_t small : {2, 3, 4, 5, 17}) {
      const auto s = generate(d, small, 3);
      EXPECT_EQ(s.size(), 3 * small);
      EXPECT_EQ(count_repeats(s), 0u);
    }
  }
}

// Golden fingerprints: the output must be bit-identical on every platform and compiler.
// A change here means every stored benchmark input changes too; do it deliberately.
TEST(Generators, GoldenFingerprints) {
  struct Golden {
    Distribution d;
    std::uint64_t fp;
  };
  const Golden golden[] = {
      {Distribution::Uniform, 0x775886f01c2e5b83ull},
      {Distribution::Gaussian, 0x6c3cb61738d94186ull},
      {Distribution::Ball, 0x95fccd50774db201ull},
      {Distribution::ThinShell, 0x2dbee257f3d06826ull},
      {Distribution::Grid, 0x35115d18f33ce25dull},
      {Distribution::Sphere, 0xe5a1be4979cff978ull},
      {Distribution::SkewLines, 0x6bb37c0a62f5df8dull},
  };
  for (const auto& g : golden) {
    const std::uint64_t fp = fingerprint(generate(g.d, 1000, 42));
    EXPECT_EQ(fp, g.fp) << to_string(g.d) << ": 0x" << std::hex << fp;
  }
  EXPECT_EQ(fingerprint(weights(1000, 42, 2.0)), 0x07bc0468c598a4f2ull) << std::hex << fingerprint(weights(1000, 42, 2.0));
}

TEST(Generators, UniformInUnitCube) {
  const auto p = uniform(50000, 1);
  for (double v : p) {
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    ASSERT_EQ(v * 0x1.0p53, std::floor(v * 0x1.0p53));  // a multiple of 2^-53
  }
  double mean = 0;
  for (double v : p) mean += v;
  mean /= static_cast<double>(p.size());
  EXPECT_NEAR(mean, 0.5, 0.01);
}

TEST(Generators, GaussianMoments) {
  const auto p = gaussian(100000, 3);
  for (int k = 0; k < 3; ++k) {
    double s = 0, s2 = 0;
    const double n = static_cast<double>(p.size() / 3);
    for (std::size_t i = k; i < p.size(); i += 3) s += p[i];
    const double mean = s / n;
    for (std::size_t i = k; i < p.size(); i += 3) s2 += (p[i] - mean) * (p[i] - mean);
    const double sigma = std::sqrt(s2 / n);
    EXPECT_NEAR(mean, kGaussianMean, 0.002) << "coordinate " << k;
    EXPECT_NEAR(sigma, kGaussianSigma, 0.002) << "coordinate " << k;
  }
  // Tails: about 4.55% of the coordinates lie beyond 2 sigma, 0.27% beyond 3 sigma.
  std::size_t beyond2 = 0, beyond3 = 0;
  for (double v : p) {
    beyond2 += std::fabs(v - kGaussianMean) > 2 * kGaussianSigma;
    beyond3 += std::fabs(v - kGaussianMean) > 3 * kGaussianSigma;
  }
  EXPECT_NEAR(static_cast<double>(beyond2) / static_cast<double>(p.size()), 0.0455, 0.004);
  EXPECT_NEAR(static_cast<double>(beyond3) / static_cast<double>(p.size()), 0.0027, 0.001);
}

TEST(Generators, BallAndShellRadii) {
  const auto b = ball(50000, 5);
  double max_r = 0;
  std::size_t inner = 0;
  for (std::size_t i = 0; i < b.size(); i += 3) {
    const long double dx = b[i] - kBallCentre, dy = b[i + 1] - kBallCentre, dz = b[i + 2] - kBallCentre;
    const double r = static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz));
    max_r = std::max(max_r, r);
    inner += r < kBallRadius * 0.7937005259840998;  // radius enclosing half of the volume
  }
  EXPECT_LE(max_r, kBallRadius * (1 + 1e-15));
  EXPECT_GT(max_r, kBallRadius * 0.999);
  EXPECT_NEAR(static_cast<double>(inner) / static_cast<double>(b.size() / 3), 0.5, 0.01);

  const auto s = thin_shell(50000, 5);
  double lo = 1, hi = 0;
  double octant[8] = {};
  for (std::size_t i = 0; i < s.size(); i += 3) {
    const long double dx = s[i] - 0.5L, dy = s[i + 1] - 0.5L, dz = s[i + 2] - 0.5L;
    const double r = static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    octant[(dx > 0) + 2 * (dy > 0) + 4 * (dz > 0)] += 1;
  }
  EXPECT_GE(lo, kShellInner - 1e-15);
  EXPECT_LE(hi, kShellOuter + 1e-15);
  EXPECT_LT(lo, kShellInner + 1e-5);
  EXPECT_GT(hi, kShellOuter - 1e-5);
  for (double o : octant) EXPECT_NEAR(o / static_cast<double>(s.size() / 3), 0.125, 0.01);  // directions spread evenly
}

TEST(Generators, GridIntegralInRange) {
  const std::size_t n = 100000;
  const auto g = grid(n, 9);
  ASSERT_EQ(g.size(), 3 * n);
  for (double v : g) {
    ASSERT_EQ(v, std::floor(v));
    ASSERT_GE(v, 0.0);
    ASSERT_LE(v, static_cast<double>(kGridSide - 1));
  }
  EXPECT_EQ(count_repeats(g), 0u);
  // The 1/512 variant is the same points, exactly scaled.
  const auto u = grid(n, 9, 1.0 / 512);
  ASSERT_EQ(u.size(), g.size());
  for (std::size_t i = 0; i < g.size(); ++i) ASSERT_EQ(u[i], g[i] / 512);
  EXPECT_THROW(grid(std::size_t{512} * 512 * 512 + 1, 1), InvalidInput);
  EXPECT_THROW(grid(10, 1, 0.0), InvalidInput);
  EXPECT_THROW(grid(10, 1, std::nan("")), InvalidInput);
}

TEST(Generators, SphereClosedFormMatchesEnumeration) {
  for (std::uint64_t d = 1; d <= 1501; d += 2) {
    ASSERT_EQ(sphere_point_count(d), detail::sphere_point_count_formula(d)) << "d = " << d;
  }
  for (std::uint64_t d : {3465u, 15015u, 45045u}) {  // products of many small primes
    EXPECT_EQ(sphere_point_count(d), detail::sphere_point_count_formula(d)) << "d = " << d;
  }
  EXPECT_THROW(sphere_point_count(4), InvalidInput);
  EXPECT_THROW(sphere_point_count(0), InvalidInput);
}

TEST(Generators, SpherePointsExactlyCospherical) {
  for (std::size_t n : {1, 2, 3, 4, 5, 10, 100, 1000, 5000, 30000}) {
    SCOPED_TRACE(n);
    const std::uint64_t d = sphere_radius(n);
    ASSERT_EQ(d % 2, 1u);
    ASSERT_GE(sphere_point_count(d), n);
    const auto p = sphere(n, 11);
    ASSERT_EQ(p.size(), 3 * n);
    EXPECT_EQ(count_repeats(p), 0u);
    const auto d2 = static_cast<__int128>(d) * static_cast<__int128>(d);
    for (std::size_t i = 0; i < p.size(); i += 3) {
      __int128 sum = 0;
      for (int k = 0; k < 3; ++k) {
        const double v = p[i + k];
        ASSERT_EQ(v, std::floor(v));
        ASSERT_LE(std::fabs(v), static_cast<double>(d));
        const auto c = static_cast<__int128>(static_cast<std::int64_t>(v));
        sum += c * c;
      }
      ASSERT_TRUE(sum == d2) << "point " << i / 3 << " is off the sphere of radius " << d;
      // The same holds in double arithmetic: every quantity is an exact double.
      ASSERT_EQ(p[i] * p[i] + p[i + 1] * p[i + 1] + p[i + 2] * p[i + 2], static_cast<double>(d * d));
    }
  }
}

TEST(Generators, SphereRadiusIsSmallest) {
  for (std::size_t n : {1, 3, 9, 50, 200, 1000}) {
    const std::uint64_t d = sphere_radius(n);
    for (std::uint64_t e = 1; e < d; e += 2) {
      ASSERT_LT(sphere_point_count(e), n) << "n = " << n << ": radius " << e << " < " << d << " suffices";
    }
  }
  EXPECT_EQ(sphere_radius(2), 1u);  // (+-1, 0, 0)
}

TEST(Generators, SkewLines) {
  for (std::size_t n : {2, 3, 10, 1001}) {
    SCOPED_TRACE(n);
    const auto p = skew_lines(n, 13);
    ASSERT_EQ(p.size(), 3 * n);
    EXPECT_EQ(count_repeats(p), 0u);
    const std::size_t first = (n + 1) / 2;
    for (std::size_t i = 0; i < n; ++i) {
      const double* q = &p[3 * i];
      const double t = i < first ? q[0] : q[1];
      if (i < first) {  // on the line (t, 0, 0)
        ASSERT_EQ(q[1], 0.0);
        ASSERT_EQ(q[2], 0.0);
      } else {          // on the line (0, t, 1)
        ASSERT_EQ(q[0], 0.0);
        ASSERT_EQ(q[2], 1.0);
      }
      ASSERT_GE(t, 0.0);
      ASSERT_LT(t, 1.0);
      ASSERT_EQ(t * 0x1.0p32, std::floor(t * 0x1.0p32));  // exactly representable grid
    }
    // Collinearity by exact cross products within each line: every coordinate is a multiple
    // of 2^-32 in [0,1], so each product and difference below is exact in long double.
    auto collinear = [&](std::size_t a, std::size_t b, std::size_t c) {
      long double u[3], v[3];
      for (int k = 0; k < 3; ++k) {
        u[k] = static_cast<long double>(p[3 * b + k]) - p[3 * a + k];
        v[k] = static_cast<long double>(p[3 * c + k]) - p[3 * a + k];
      }
      return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0;
    };
    for (std::size_t i = 2; i < first; ++i) ASSERT_TRUE(collinear(0, 1, i));
    for (std::size_t i = first + 2; i < n; ++i) ASSERT_TRUE(collinear(first, first + 1, i));
  }
}

TEST(Generators, Weights) {
  const auto w = weights(100000, 17, 0.25);
  ASSERT_EQ(w.size(), 100000u);
  double mean = 0;
  for (double v : w) {
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 0.25);
    mean += v;
  }
  EXPECT_NEAR(mean / static_cast<double>(w.size()), 0.125, 0.002);
  EXPECT_TRUE(bitwise_equal(w, weights(100000, 17, 0.25)));
  EXPECT_FALSE(bitwise_equal(w, weights(100000, 18, 0.25)));
  EXPECT_TRUE(weights(0, 1, 1.0).empty());
  EXPECT_THROW(weights(10, 1, 0.0), InvalidInput);
  EXPECT_THROW(weights(10, 1, -1.0), InvalidInput);
  EXPECT_THROW(weights(10, 1, std::nan("")), InvalidInput);
  EXPECT_THROW(weights(10, 1, INFINITY), InvalidInput);
  // Different streams: the weights are not the x coordinates of uniform() for the seed.
  const auto u = uniform(10, 17);
  const auto w1 = weights(10, 17, 1.0);
  EXPECT_NE(u[0], w1[0]);
}

TEST(Generators, RejectsTooManyPoints) {
  const std::size_t too_many = std::size_t{1} << 31;
  for (Distribution d : kAllDistributions) EXPECT_THROW(generate(d, too_many, 1), InvalidInput) << to_string(d);
  EXPECT_THROW(weights(too_many, 1, 1.0), InvalidInput);
  EXPECT_THROW(generate(static_cast<Distribution>(99), 10, 1), InvalidInput);
}

}  // namespace
}  // namespace gdel::gen
