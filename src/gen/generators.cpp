// Deterministic point generators; see generators.hpp for the guarantees.
#include "gen/generators.hpp"

// Bit-identical output needs every a*b+c rounded twice, never fused into an FMA. The
// project builds with -ffp-contract=off; these pragmas keep this file right in builds
// that do not (GCC's default is fast contraction, clang's is "on" within statements).
// (clang's -ffp-contract=fast overrides its pragma; GoldenFingerprints catches that.)
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "gdel/errors.hpp"

namespace gdel::gen {
namespace {

// ---------------------------------------------------------------------------------------
// Randomness
// ---------------------------------------------------------------------------------------

// SplitMix64 finaliser: used to derive the engine seed from (seed, stream) so that the
// different generators (and the weights) draw unrelated streams for one user seed.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Stream tags, one per generator.
enum Stream : std::uint64_t {
  kStreamUniform = 1,
  kStreamGaussian,
  kStreamBall,
  kStreamShell,
  kStreamGrid,
  kStreamSphere,
  kStreamSkew,
  kStreamWeights,
};

class Rng {
 public:
  Rng(std::uint64_t seed, Stream stream) : engine_(mix64(seed ^ mix64(stream))) {}

  std::uint64_t bits() { return engine_(); }

  // Uniform in [0,1): a multiple of 2^-53 (exact conversion of a 53-bit integer).
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Uniform in [-1,1): a multiple of 2^-52.
  double symmetric() { return static_cast<double>(engine_() >> 11) * 0x1.0p-52 - 1.0; }

  // Uniform integer in [0, bound), bound >= 1, without modulo bias (rejection of the
  // lowest 2^64 mod bound engine outputs).
  std::uint64_t below(std::uint64_t bound) {
    const std::uint64_t threshold = (0 - bound) % bound;  // 2^64 mod bound
    for (;;) {
      const std::uint64_t x = engine_();
      if (x >= threshold) return x % bound;
    }
  }

 private:
  std::mt19937_64 engine_;  // sequence fixed by the standard for a given seed
};

void check_count(std::size_t n, const char* what) {
  constexpr std::size_t kMax = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (n > kMax) {
    throw InvalidInput(std::string("gen::") + what + ": n = " + std::to_string(n) +
                       " exceeds the 2^31-1 points that int32 vertex ids allow");
  }
}

// ---------------------------------------------------------------------------------------
// Exact deduplication of points, in batches: hash every point, radix-sort the hashes
// (sequential memory traffic, unlike a hash table of 10^7 entries), compare exactly only
// the points whose hash occurs more than once, and drop every later copy of a point.
// ---------------------------------------------------------------------------------------

std::uint64_t point_hash(const double* p) {
  auto key = [](double v) { return std::bit_cast<std::uint64_t>(v + 0.0); };  // -0 -> +0
  return mix64(key(p[0]) ^ mix64(key(p[1]) ^ mix64(key(p[2]))));
}

// LSD radix sort, 6 passes of 11 bits.
void radix_sort(std::vector<std::uint64_t>& v) {
  std::vector<std::uint64_t> tmp(v.size());
  constexpr int kBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift < 64; shift += kBits) {
    std::fill(count.begin(), count.end(), 0);
    for (std::uint64_t x : v) ++count[(x >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (std::size_t& c : count) {
      const std::size_t k = c;
      c = sum;
      sum += k;
    }
    for (std::uint64_t x : v) tmp[count[(x >> shift) & (kBuckets - 1)]++] = x;
    v.swap(tmp);
  }
}

// Removes from xyz (triples) every point equal (==, so -0 == +0) to an earlier one,
// keeping the order of the rest. Returns the number removed.
std::size_t remove_duplicate_points(std::vector<double>& xyz) {
  const std::size_t n = xyz.size() / 3;
  std::vector<std::uint64_t> hashes(n);
  for (std::size_t i = 0; i < n; ++i) hashes[i] = point_hash(&xyz[3 * i]);
  std::vector<std::uint64_t> sorted = hashes;
  radix_sort(sorted);
  std::vector<std::uint64_t> repeated;  // hash values occurring more than once
  for (std::size_t i = 1; i < n; ++i) {
    if (sorted[i] == sorted[i - 1] && (repeated.empty() || repeated.back() != sorted[i])) {
      repeated.push_back(sorted[i]);
    }
  }
  if (repeated.empty()) return 0;
  // Points sharing a hash, grouped by hash in index order; compare them exactly.
  std::vector<std::pair<std::uint64_t, std::size_t>> group;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::binary_search(repeated.begin(), repeated.end(), hashes[i])) group.emplace_back(hashes[i], i);
  }
  std::sort(group.begin(), group.end());
  std::vector<bool> drop(n, false);
  for (auto a = group.begin(); a != group.end();) {
    const std::uint64_t h = a->first;
    const auto b = std::find_if(a, group.end(), [h](const auto& g) { return g.first != h; });
    for (auto j = a + 1; j != b; ++j) {
      const double* pj = &xyz[3 * j->second];
      for (auto i = a; i != j; ++i) {
        const double* pi = &xyz[3 * i->second];
        if (!drop[i->second] && pi[0] == pj[0] && pi[1] == pj[1] && pi[2] == pj[2]) {
          drop[j->second] = true;
          break;
        }
      }
    }
    a = b;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (drop[i]) continue;
    for (int k = 0; k < 3; ++k) xyz[3 * kept + k] = xyz[3 * i + k];
    ++kept;
  }
  xyz.resize(3 * kept);
  return n - kept;
}

// Draws points from `sample(rng, x, y, z)` until n distinct ones exist: draw the missing
// number, drop the repeats, again until none is missing (one round unless a repeat occurs).
template <class Sampler>
std::vector<double> distinct_points(std::size_t n, Rng& rng, Sampler&& sample) {
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  while (xyz.size() < 3 * n) {
    while (xyz.size() < 3 * n) {
      double x, y, z;
      sample(rng, x, y, z);
      xyz.insert(xyz.end(), {x, y, z});
    }
    remove_duplicate_points(xyz);
  }
  return xyz;
}

// `count` distinct integers of [0, range) in random order (count <= range).
std::vector<std::uint64_t> distinct_integers(std::size_t count, std::uint64_t range, Rng& rng) {
  std::vector<std::uint64_t> out;
  out.reserve(count);
  if (range <= (std::uint64_t{1} << 30)) {
    // Bitmap of the range (at most 128 MiB).
    std::vector<std::uint64_t> bits((range + 63) / 64, 0);
    auto test_and_set = [&](std::uint64_t v) {
      const std::uint64_t bit = std::uint64_t{1} << (v & 63);
      const bool was = (bits[v >> 6] & bit) != 0;
      bits[v >> 6] |= bit;
      return was;
    };
    if (count <= range / 2) {
      // Rejection: each draw succeeds with probability >= 1/2.
      while (out.size() < count) {
        const std::uint64_t v = rng.below(range);
        if (!test_and_set(v)) out.push_back(v);
      }
    } else {
      // Dense: mark the range - count values to leave out, collect the rest, shuffle.
      std::size_t excluded = 0;
      while (excluded < range - count) {
        if (!test_and_set(rng.below(range))) ++excluded;
      }
      for (std::uint64_t v = 0; v < range; ++v) {
        if ((bits[v >> 6] & (std::uint64_t{1} << (v & 63))) == 0) out.push_back(v);
      }
      for (std::size_t i = 0; i + 1 < out.size(); ++i) {  // Fisher-Yates
        std::swap(out[i], out[i + rng.below(out.size() - i)]);
      }
    }
    return out;
  }
  // Large range, count << range: hash set of the values drawn so far.
  std::size_t cap = 16;
  while (cap < 2 * count) cap <<= 1;
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // never drawn: values < range <= 2^64-1
  std::vector<std::uint64_t> slots(cap, kEmpty);
  while (out.size() < count) {
    const std::uint64_t v = rng.below(range);
    std::size_t h = static_cast<std::size_t>(mix64(v)) & (cap - 1);
    bool seen = false;
    while (slots[h] != kEmpty) {
      if (slots[h] == v) {
        seen = true;
        break;
      }
      h = (h + 1) & (cap - 1);
    }
    if (!seen) {
      slots[h] = v;
      out.push_back(v);
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// A deterministic natural logarithm (libm's log is not correctly rounded, so its last
// bit may differ between C libraries; this one uses only exact scaling, +, -, *, /).
// ---------------------------------------------------------------------------------------

// log(x) for finite x > 0, relative error a few ulp.
double det_log(double x) {
  int e = 0;
  double f = std::frexp(x, &e);  // x = f * 2^e, f in [0.5, 1): exact
  if (f < 0.70710678118654752440) {  // bring f into [sqrt(1/2), sqrt(2)): exact
    f *= 2.0;
    e -= 1;
  }
  // log f = 2 atanh(s), s = (f-1)/(f+1), |s| <= 3-2*sqrt(2) < 0.1716, s^2 < 0.02944.
  // The series 2(s + s^3/3 + s^5/5 + ...) truncated after s^25: the first omitted term is
  // below 2 * 0.1716 * 0.02944^13 / 27 < 1e-21, far under half an ulp of the result.
  const double s = (f - 1.0) / (f + 1.0);  // f - 1 is exact (Sterbenz)
  const double z = s * s;
  double poly = 1.0 / 25.0;
  for (int k = 11; k >= 0; --k) poly = poly * z + 1.0 / static_cast<double>(2 * k + 1);
  const double log_f = 2.0 * s * poly;
  // ln 2 split so that e * kLn2Hi is exact for |e| < 2^11.
  constexpr double kLn2Hi = 6.93147180369123816490e-01;  // 0x3FE62E42FEE00000
  constexpr double kLn2Lo = 1.90821492927058770002e-10;  // ln 2 - kLn2Hi
  const double de = static_cast<double>(e);
  return de * kLn2Hi + (de * kLn2Lo + log_f);
}

// ---------------------------------------------------------------------------------------
// Sphere points
// ---------------------------------------------------------------------------------------

using IPoint = std::array<std::int32_t, 3>;

std::uint64_t isqrt(std::uint64_t v) {
  auto r = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r;
}

// All distinct points of the quaternion construction for odd d, sorted.
std::vector<IPoint> sphere_points_all(std::uint64_t d) {
  const auto s = static_cast<std::int64_t>(isqrt(d));
  const auto dd = static_cast<std::int64_t>(d);
  // Representations k = p^2 + q^2 (all signs) for every k <= d, in CSR form.
  std::vector<std::uint32_t> start(d + 2, 0);
  for (std::int64_t p = -s; p <= s; ++p) {
    for (std::int64_t q = -s; q <= s; ++q) {
      const std::int64_t k = p * p + q * q;
      if (k <= dd) ++start[static_cast<std::size_t>(k) + 1];
    }
  }
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<std::array<std::int16_t, 2>> reps(start.back());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::int64_t p = -s; p <= s; ++p) {
      for (std::int64_t q = -s; q <= s; ++q) {
        const std::int64_t k = p * p + q * q;
        if (k <= dd) {
          reps[fill[static_cast<std::size_t>(k)]++] = {static_cast<std::int16_t>(p),
                                                       static_cast<std::int16_t>(q)};
        }
      }
    }
  }
  // The map (m,n,p,q) -> point is invariant under right multiplication by i:
  // (m,n,p,q) -> (-n,m,q,-p), an orbit of size 4. One representative per orbit: (m,n) with
  // m > 0, n >= 0, or m = n = 0 and p > 0, q >= 0. That leaves r4(d)/4 = 2 sigma(d) quadruples.
  std::vector<IPoint> pts;
  auto emit = [&](std::int64_t m, std::int64_t n, std::int64_t p, std::int64_t q) {
    const std::int64_t x = m * m + n * n - p * p - q * q;
    const std::int64_t y = 2 * (m * q + n * p);
    const std::int64_t z = 2 * (n * q - m * p);
    pts.push_back({static_cast<std::int32_t>(x), static_cast<std::int32_t>(y),
                   static_cast<std::int32_t>(z)});
  };
  for (std::int64_t m = 0; m <= s; ++m) {
    for (std::int64_t n = 0; m * m + n * n <= dd; ++n) {
      const auto r = static_cast<std::size_t>(dd - m * m - n * n);
      for (std::uint32_t i = start[r]; i < start[r + 1]; ++i) {
        const std::int64_t p = reps[i][0], q = reps[i][1];
        if (m > 0 || (n == 0 && p > 0 && q >= 0)) emit(m, n, p, q);
      }
    }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

// Smallest odd d whose construction gives >= n distinct points, with those points.
std::pair<std::uint64_t, std::vector<IPoint>> find_sphere(std::size_t n) {
  // The construction gives at most 2 sigma(d) points (r4(d) = 8 sigma(d) quadruples, four
  // per point at least), and exactly detail::sphere_point_count_formula(d) points (checked
  // against the enumeration by the tests for every odd d below a few thousand; should it
  // ever overestimate, the enumeration below still decides, so the result stays correct).
  // For odd d < 3*5*7*11*13*17*19*23 (> kSphereMaxRadius), d has at most 7 distinct prime
  // factors, so sigma(d)/d < prod_{p in 3..19} p/(p-1) < 2.924 and 2 sigma(d) < 5.85 d: no
  // d < n/6 can succeed. Scan the odd d >= n/6 in windows, sieving sigma(d) to skip hopeless ones.
  std::uint64_t lo = std::max<std::uint64_t>(1, n / 6) | 1;
  constexpr std::uint64_t kWindow = 1u << 15;  // odd numbers per window
  std::vector<std::uint64_t> sigma(kWindow);
  for (;;) {
    if (lo > kSphereMaxRadius) break;
    const std::uint64_t hi = lo + 2 * kWindow;  // window: lo, lo+2, ..., hi-2
    std::fill(sigma.begin(), sigma.end(), 0);
    for (std::uint64_t k = 1; k * k < hi; k += 2) {
      // Odd multiples m = k*q of k in the window with q >= k: add the divisors k and q.
      std::uint64_t q = std::max(k, (lo + k - 1) / k);
      if (q % 2 == 0) ++q;
      for (std::uint64_t m = k * q; m < hi; m += 2 * k, q += 2) {
        sigma[(m - lo) / 2] += (q == k) ? k : k + q;
      }
    }
    for (std::uint64_t i = 0; i < kWindow; ++i) {
      const std::uint64_t d = lo + 2 * i;
      if (d > kSphereMaxRadius) break;
      if (2 * sigma[i] < n) continue;
      if (detail::sphere_point_count_formula(d) < n) continue;
      auto pts = sphere_points_all(d);
      if (pts.size() >= n) return {d, std::move(pts)};
    }
    lo = hi;
  }
  throw InvalidInput("gen::sphere: n = " + std::to_string(n) +
                     " distinct points would need a radius above 2^26 (coordinates would "
                     "no longer square exactly in double)");
}

}  // namespace

std::uint64_t detail::sphere_point_count_formula(std::uint64_t d) {
  std::uint64_t count = 2;
  for (std::uint64_t p = 3; p * p <= d; p += 2) {
    if (d % p != 0) continue;
    std::uint64_t pa = 1;  // p^a, the full power of p in d
    while (d % p == 0) {
      d /= p;
      pa *= p;
    }
    count *= (p % 4 == 1) ? pa : (pa * p - 1) / (p - 1);  // p^a or sigma(p^a)
  }
  if (d > 1) count *= (d % 4 == 1) ? d : d + 1;
  return count;
}

// ---------------------------------------------------------------------------------------
// Names
// ---------------------------------------------------------------------------------------

std::string_view to_string(Distribution d) noexcept {
  switch (d) {
    case Distribution::Uniform: return "uniform";
    case Distribution::Gaussian: return "gaussian";
    case Distribution::Ball: return "ball";
    case Distribution::ThinShell: return "thin_shell";
    case Distribution::Grid: return "grid";
    case Distribution::Sphere: return "sphere";
    case Distribution::SkewLines: return "skew_lines";
  }
  return "unknown";
}

Distribution parse_distribution(std::string_view name) {
  auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; };
  std::string valid;
  for (Distribution d : kAllDistributions) {
    const std::string_view s = to_string(d);
    if (s.size() == name.size() &&
        std::equal(s.begin(), s.end(), name.begin(), [&](char a, char b) { return a == lower(b); })) {
      return d;
    }
    valid += valid.empty() ? "" : ", ";
    valid += s;
  }
  throw InvalidInput("unknown point distribution '" + std::string(name) + "'; valid: " + valid);
}

// ---------------------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------------------

std::vector<double> uniform(std::size_t n, std::uint64_t seed) {
  check_count(n, "uniform");
  Rng rng(seed, kStreamUniform);
  return distinct_points(n, rng, [](Rng& r, double& x, double& y, double& z) {
    x = r.unit();
    y = r.unit();
    z = r.unit();
  });
}

std::vector<double> gaussian(std::size_t n, std::uint64_t seed) {
  check_count(n, "gaussian");
  Rng rng(seed, kStreamGaussian);
  // Marsaglia's polar method: (u,v) uniform in the unit disc, then u*f and v*f with
  // f = sqrt(-2 ln(s)/s) are independent standard normals. The spare one is kept.
  bool have_spare = false;
  double spare = 0.0;
  auto normal = [&](Rng& r) {
    if (have_spare) {
      have_spare = false;
      return spare;
    }
    for (;;) {
      const double u = r.symmetric(), v = r.symmetric();
      const double s = u * u + v * v;
      if (s >= 1.0 || s == 0.0) continue;
      const double f = std::sqrt(-2.0 * det_log(s) / s);
      spare = v * f;
      have_spare = true;
      return u * f;
    }
  };
  return distinct_points(n, rng, [&](Rng& r, double& x, double& y, double& z) {
    x = kGaussianMean + kGaussianSigma * normal(r);
    y = kGaussianMean + kGaussianSigma * normal(r);
    z = kGaussianMean + kGaussianSigma * normal(r);
  });
}

std::vector<double> ball(std::size_t n, std::uint64_t seed) {
  check_count(n, "ball");
  Rng rng(seed, kStreamBall);
  return distinct_points(n, rng, [](Rng& r, double& x, double& y, double& z) {
    for (;;) {
      const double u = r.symmetric(), v = r.symmetric(), w = r.symmetric();
      if (u * u + v * v + w * w < 1.0) {
        x = kBallCentre + kBallRadius * u;
        y = kBallCentre + kBallRadius * v;
        z = kBallCentre + kBallRadius * w;
        return;
      }
    }
  });
}

std::vector<double> thin_shell(std::size_t n, std::uint64_t seed) {
  check_count(n, "thin_shell");
  Rng rng(seed, kStreamShell);
  return distinct_points(n, rng, [](Rng& r, double& x, double& y, double& z) {
    for (;;) {
      const double u = r.symmetric(), v = r.symmetric(), w = r.symmetric();
      const double s = u * u + v * v + w * w;
      // Uniform in the ball minus a tiny inner ball: the direction stays uniform and the
      // normalisation well conditioned.
      if (s >= 1.0 || s < 1e-4) continue;
      const double radius = kShellInner + (kShellOuter - kShellInner) * r.unit();
      const double scale = radius / std::sqrt(s);
      x = kBallCentre + scale * u;
      y = kBallCentre + scale * v;
      z = kBallCentre + scale * w;
      return;
    }
  });
}

std::vector<double> grid(std::size_t n, std::uint64_t seed, double scale) {
  check_count(n, "grid");
  constexpr std::uint64_t kCells = std::uint64_t{kGridSide} * kGridSide * kGridSide;
  if (n > kCells) {
    throw InvalidInput("gen::grid: n = " + std::to_string(n) + " exceeds the " +
                       std::to_string(kCells) + " points of the 512^3 grid");
  }
  if (!std::isfinite(scale) || scale <= 0.0) {
    throw InvalidInput("gen::grid: scale must be finite and positive");
  }
  Rng rng(seed, kStreamGrid);
  const std::vector<std::uint64_t> cells = distinct_integers(n, kCells, rng);
  std::vector<double> xyz(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t c = cells[i];
    xyz[3 * i + 0] = static_cast<double>(c % kGridSide) * scale;
    xyz[3 * i + 1] = static_cast<double>((c / kGridSide) % kGridSide) * scale;
    xyz[3 * i + 2] = static_cast<double>(c / (std::uint64_t{kGridSide} * kGridSide)) * scale;
  }
  return xyz;
}

std::size_t sphere_point_count(std::uint64_t d) {
  if (d == 0 || d % 2 == 0 || d > kSphereMaxRadius) {
    throw InvalidInput("gen::sphere_point_count: d must be odd, in [1, 2^26]");
  }
  return sphere_points_all(d).size();
}

std::uint64_t sphere_radius(std::size_t n) {
  check_count(n, "sphere");
  return find_sphere(n).first;
}

std::vector<double> sphere(std::size_t n, std::uint64_t seed) {
  check_count(n, "sphere");
  if (n == 0) return {};
  auto [d, pts] = find_sphere(n);
  (void)d;
  Rng rng(seed, kStreamSphere);
  for (std::size_t i = 0; i < n; ++i) {  // partial Fisher-Yates: a random n-subset
    std::swap(pts[i], pts[i + rng.below(pts.size() - i)]);
  }
  std::vector<double> xyz(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) xyz[3 * i + k] = static_cast<double>(pts[i][k]);
  }
  return xyz;
}

std::vector<double> skew_lines(std::size_t n, std::uint64_t seed) {
  check_count(n, "skew_lines");
  Rng rng(seed, kStreamSkew);
  const std::size_t first = (n + 1) / 2, second = n / 2;
  constexpr std::uint64_t kRange = std::uint64_t{1} << 32;
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (std::uint64_t j : distinct_integers(first, kRange, rng)) {
    xyz.insert(xyz.end(), {static_cast<double>(j) * 0x1.0p-32, 0.0, 0.0});
  }
  for (std::uint64_t j : distinct_integers(second, kRange, rng)) {
    xyz.insert(xyz.end(), {0.0, static_cast<double>(j) * 0x1.0p-32, 1.0});
  }
  return xyz;
}

std::vector<double> generate(Distribution d, std::size_t n, std::uint64_t seed) {
  switch (d) {
    case Distribution::Uniform: return uniform(n, seed);
    case Distribution::Gaussian: return gaussian(n, seed);
    case Distribution::Ball: return ball(n, seed);
    case Distribution::ThinShell: return thin_shell(n, seed);
    case Distribution::Grid: return grid(n, seed);
    case Distribution::Sphere: return sphere(n, seed);
    case Distribution::SkewLines: return skew_lines(n, seed);
  }
  throw InvalidInput("gen::generate: invalid Distribution value " +
                     std::to_string(static_cast<int>(d)));
}

std::vector<double> weights(std::size_t n, std::uint64_t seed, double max) {
  check_count(n, "weights");
  if (!std::isfinite(max) || max <= 0.0) {
    throw InvalidInput("gen::weights: max must be finite and > 0 (got " + std::to_string(max) + ")");
  }
  Rng rng(seed, kStreamWeights);
  const double below_max = std::nextafter(max, 0.0);
  std::vector<double> w(n);
  for (double& v : w) v = std::min(rng.unit() * max, below_max);
  return w;
}

}  // namespace gdel::gen
