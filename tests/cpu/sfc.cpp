// Space-filling-curve keys (src/sort/sfc.hpp): quantization robustness, Morton
// interleaving, Hilbert bijection and face adjacency of consecutive cells.
#include "sort/sfc.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

namespace {

using gdel::sfc::kMaxCoord;
using gdel::sfc::Quantizer;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Compile-time checks: the functions are constexpr and agree on small cases.
static_assert(gdel::sfc::spread3(0b111) == 0b001001001);
static_assert(gdel::sfc::compact3(0b001001001) == 0b111);
static_assert(gdel::sfc::morton_key(1, 0, 0) == 4 && gdel::sfc::morton_key(0, 1, 0) == 2 &&
              gdel::sfc::morton_key(0, 0, 1) == 1);
static_assert(gdel::sfc::morton_key(kMaxCoord, kMaxCoord, kMaxCoord) == gdel::sfc::kMaxKey);
static_assert(gdel::sfc::hilbert_key(0, 0, 0) == 0);

TEST(SfcMorton, SpreadCompactRoundTrip) {
  std::mt19937 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t v = rng() & kMaxCoord;
    const std::uint64_t s = gdel::sfc::spread3(v);
    EXPECT_EQ(s & ~0x1249249249249249ull, 0u);
    EXPECT_EQ(gdel::sfc::compact3(s), v);
  }
  // Bits above 21 are ignored.
  EXPECT_EQ(gdel::sfc::spread3(0xFFFFFFFFu), gdel::sfc::spread3(kMaxCoord));
}

TEST(SfcMorton, KeyRoundTripAndBitLayout) {
  std::mt19937 rng(11);
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t x = rng() & kMaxCoord, y = rng() & kMaxCoord, z = rng() & kMaxCoord;
    const std::uint64_t k = gdel::sfc::morton_key(x, y, z);
    EXPECT_LT(k, std::uint64_t{1} << 63);
    std::uint32_t c[3];
    gdel::sfc::morton_decode(k, c);
    EXPECT_EQ(c[0], x);
    EXPECT_EQ(c[1], y);
    EXPECT_EQ(c[2], z);
    // Reference interleaving, one bit at a time: bit i of x -> 3i+2, y -> 3i+1, z -> 3i.
    std::uint64_t ref = 0;
    for (int b = 0; b < 21; ++b) {
      ref |= std::uint64_t((x >> b) & 1) << (3 * b + 2);
      ref |= std::uint64_t((y >> b) & 1) << (3 * b + 1);
      ref |= std::uint64_t((z >> b) & 1) << (3 * b);
    }
    EXPECT_EQ(k, ref);
  }
}

// All cells of an n^3 grid (n = 2^levels), sorted by Hilbert key.
std::vector<std::array<std::uint32_t, 3>> cells_in_hilbert_order(int levels, int key_levels) {
  const std::uint32_t n = 1u << levels;
  std::vector<std::pair<std::uint64_t, std::array<std::uint32_t, 3>>> v;
  for (std::uint32_t x = 0; x < n; ++x)
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t z = 0; z < n; ++z) v.push_back({gdel::sfc::hilbert_key(x, y, z, key_levels), {x, y, z}});
  std::sort(v.begin(), v.end());
  // Keys must be exactly 0 .. n^3-1 (a bijection onto the first n^3 keys).
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i].first, i) << "levels " << levels << " key_levels " << key_levels;
  std::vector<std::array<std::uint32_t, 3>> out;
  for (auto& p : v) out.push_back(p.second);
  return out;
}

void expect_face_adjacent_walk(const std::vector<std::array<std::uint32_t, 3>>& cells) {
  ASSERT_FALSE(cells.empty());
  EXPECT_EQ(cells.front(), (std::array<std::uint32_t, 3>{0, 0, 0}));
  for (std::size_t i = 1; i < cells.size(); ++i) {
    int d = 0;
    for (int a = 0; a < 3; ++a) d += std::abs(int(cells[i][a]) - int(cells[i - 1][a]));
    ASSERT_EQ(d, 1) << "step " << i;
  }
}

TEST(SfcHilbert, BijectionAndAdjacencySmallCubes) {
  for (int levels = 1; levels <= 5; ++levels) {
    SCOPED_TRACE(levels);
    // The curve on exactly `levels` levels ...
    expect_face_adjacent_walk(cells_in_hilbert_order(levels, levels));
    // ... and the corner cube of the full 21-level curve: keys 0 .. 8^levels-1.
    expect_face_adjacent_walk(cells_in_hilbert_order(levels, gdel::sfc::kBits));
  }
}

TEST(SfcHilbert, Grid8And16Explicit) {
  const auto c8 = cells_in_hilbert_order(3, 3);
  ASSERT_EQ(c8.size(), 512u);
  expect_face_adjacent_walk(c8);
  const auto c16 = cells_in_hilbert_order(4, 4);
  ASSERT_EQ(c16.size(), 4096u);
  expect_face_adjacent_walk(c16);
}

TEST(SfcHilbert, AlignedKeyBlocksAreAlignedCubes) {
  // Self-similarity, which a mere face-adjacent snake lacks: for every k, the keys
  // [j*8^k, (j+1)*8^k) cover one aligned cube of side 2^k.
  const auto cells = cells_in_hilbert_order(4, 4);
  for (int k = 1; k <= 3; ++k) {
    const std::size_t block = std::size_t{1} << (3 * k);
    const std::uint32_t side = 1u << k;
    for (std::size_t j = 0; j < cells.size(); j += block) {
      std::uint32_t lo[3] = {~0u, ~0u, ~0u}, hi[3] = {0, 0, 0};
      for (std::size_t i = j; i < j + block; ++i)
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], cells[i][a]);
          hi[a] = std::max(hi[a], cells[i][a]);
        }
      for (int a = 0; a < 3; ++a) {
        ASSERT_EQ(lo[a] % side, 0u) << "k " << k << " block " << j / block;
        ASSERT_EQ(hi[a] - lo[a], side - 1) << "k " << k << " block " << j / block;
      }
    }
  }
}

TEST(SfcHilbert, DecodeRoundTrip) {
  std::mt19937 rng(3);
  for (int levels : {1, 2, 5, 13, 21}) {
    const std::uint32_t m = (1u << levels) - 1u;
    for (int i = 0; i < 20000; ++i) {
      const std::uint32_t x = rng() & m, y = rng() & m, z = rng() & m;
      const std::uint64_t k = gdel::sfc::hilbert_key(x, y, z, levels);
      ASSERT_LT(k, std::uint64_t{1} << (3 * levels));
      std::uint32_t c[3];
      gdel::sfc::hilbert_decode(k, c, levels);
      ASSERT_EQ(c[0], x);
      ASSERT_EQ(c[1], y);
      ASSERT_EQ(c[2], z);
    }
  }
}

TEST(SfcHilbert, ConsecutiveKeysAdjacentAtFullDepth) {
  // Random stretches of the full 21-level curve: decode key and key+1, check that
  // the cells share a face, and that the keys stay below 2^63.
  std::mt19937_64 rng(5);
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t k = rng() % gdel::sfc::kMaxKey;  // k+1 <= kMaxKey
    std::uint32_t a[3], b[3];
    gdel::sfc::hilbert_decode(k, a);
    gdel::sfc::hilbert_decode(k + 1, b);
    int d = 0;
    for (int t = 0; t < 3; ++t) d += std::abs(int(a[t]) - int(b[t]));
    ASSERT_EQ(d, 1) << "key " << k;
    ASSERT_EQ(gdel::sfc::hilbert_key(a[0], a[1], a[2]), k);
  }
  std::uint32_t last[3];
  gdel::sfc::hilbert_decode(gdel::sfc::kMaxKey, last);
  EXPECT_EQ(gdel::sfc::hilbert_key(last[0], last[1], last[2]), gdel::sfc::kMaxKey);
}

TEST(SfcQuantize, InsideBoxAndEnds) {
  const Quantizer q = Quantizer::from_box(0, 0, 0, 1, 2, 4, /*uniform=*/false);
  EXPECT_EQ(q.axis(0, 0.0), 0u);
  EXPECT_EQ(q.axis(0, 1.0), kMaxCoord);
  EXPECT_EQ(q.axis(1, 2.0), kMaxCoord);
  EXPECT_EQ(q.axis(2, 4.0), kMaxCoord);
  EXPECT_EQ(q.axis(0, 0.5), 1u << 20);
  EXPECT_EQ(q.axis(1, 1.0), 1u << 20);
  EXPECT_EQ(q.axis(2, 1.0), 1u << 19);
  // Uniform: the largest extent (4) on every axis.
  const Quantizer u = Quantizer::from_box(0, 0, 0, 1, 2, 4);
  EXPECT_EQ(u.axis(0, 1.0), 1u << 19);
  EXPECT_EQ(u.axis(1, 2.0), 1u << 20);
  EXPECT_EQ(u.axis(2, 4.0), kMaxCoord);
}

TEST(SfcQuantize, ClampsMonotonically) {
  const Quantizer q = Quantizer::from_box(-1, -1, -1, 3, 3, 3);
  EXPECT_EQ(q.axis(0, -1e300), 0u);
  EXPECT_EQ(q.axis(0, -kInf), 0u);
  EXPECT_EQ(q.axis(0, -1.0000001), 0u);
  EXPECT_EQ(q.axis(0, 3.0000001), kMaxCoord);
  EXPECT_EQ(q.axis(0, 1e300), kMaxCoord);
  EXPECT_EQ(q.axis(0, kInf), kMaxCoord);
  EXPECT_EQ(q.axis(0, kNaN), 0u);
  EXPECT_EQ(q.axis(0, -std::numeric_limits<double>::max()), 0u);
  EXPECT_EQ(q.axis(0, std::numeric_limits<double>::max()), kMaxCoord);
  // A sweep across and beyond the box, including values one ulp apart, never
  // decreases and uses the full range.
  std::vector<double> vs = {-kInf, -1e308, -5.0};
  for (int i = 0; i <= 100000; ++i) vs.push_back(-2.0 + 6.0 * i / 100000.0);
  for (double v = -1.0, n = 0; n < 1000; ++n) vs.push_back(v = std::nextafter(v, 10.0));
  for (double v = 3.0, n = 0; n < 1000; ++n) vs.push_back(v = std::nextafter(v, -10.0));
  vs.push_back(1e308);
  vs.push_back(kInf);
  std::sort(vs.begin(), vs.end());
  std::uint32_t prev = 0;
  for (double v : vs) {
    const std::uint32_t c = q.axis(1, v);
    ASSERT_LE(c, kMaxCoord);
    ASSERT_GE(c, prev) << v;
    prev = c;
  }
  EXPECT_EQ(prev, kMaxCoord);
}

TEST(SfcQuantize, DegenerateBoxes) {
  // Zero extent on z: every z maps to 0, the other axes are unaffected.
  const Quantizer flat = Quantizer::from_box(0, 0, 5, 1, 1, 5);
  for (double z : {-kInf, -1.0, 5.0, 7.0, kInf, kNaN}) EXPECT_EQ(flat.axis(2, z), 0u);
  EXPECT_EQ(flat.axis(0, 1.0), kMaxCoord);
  EXPECT_EQ(flat.axis(1, 0.5), 1u << 20);
  const Quantizer flat_nonuniform = Quantizer::from_box(0, 0, 5, 1, 1, 5, false);
  EXPECT_EQ(flat_nonuniform.axis(2, 5.0), 0u);
  EXPECT_EQ(flat_nonuniform.axis(0, 1.0), kMaxCoord);
  // A single point: everything to cell 0.
  const Quantizer point = Quantizer::from_box(2, 2, 2, 2, 2, 2);
  for (int a = 0; a < 3; ++a)
    for (double v : {-kInf, 0.0, 2.0, 3.0, kInf, kNaN}) EXPECT_EQ(point.axis(a, v), 0u);
  // Inverted, NaN and infinite boxes are degenerate too.
  const Quantizer inverted = Quantizer::from_box(1, 1, 1, 0, 0, 0);
  EXPECT_EQ(inverted.axis(0, 0.5), 0u);
  const Quantizer nan_box = Quantizer::from_box(kNaN, 0, 0, 1, kNaN, 1);
  EXPECT_EQ(nan_box.axis(0, 0.5), 0u);
  EXPECT_EQ(nan_box.axis(1, 0.5), 0u);
  EXPECT_EQ(nan_box.axis(2, 1.0), kMaxCoord);
  const Quantizer inf_box = Quantizer::from_box(-kInf, 0, 0, kInf, 1, 1);
  EXPECT_EQ(inf_box.axis(0, 0.5), 0u);
  EXPECT_EQ(inf_box.axis(1, 0.5), 1u << 20);
  // The widest finite box does not overflow.
  const double big = std::numeric_limits<double>::max();
  const Quantizer wide = Quantizer::from_box(-big, -big, -big, big, big, big);
  EXPECT_EQ(wide.axis(0, -big), 0u);
  EXPECT_GE(wide.axis(0, 0.0), (1u << 20) - 1);  // the middle, up to rounding of the scale
  EXPECT_LE(wide.axis(0, 0.0), 1u << 20);
  EXPECT_EQ(wide.axis(0, big), kMaxCoord);
  // A subnormal extent still separates lo from anything above it.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const Quantizer sub = Quantizer::from_box(0, 0, 0, 4 * tiny, 4 * tiny, 4 * tiny);
  EXPECT_EQ(sub.axis(0, 0.0), 0u);
  EXPECT_LE(sub.axis(0, 2 * tiny), kMaxCoord);
  EXPECT_EQ(sub.axis(0, 1.0), kMaxCoord);
}

TEST(SfcKeys, PointKeysFollowCells) {
  const Quantizer q = Quantizer::from_box(0, 0, 0, 1, 1, 1);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    std::uint32_t c[3];
    q(x, y, z, c);
    EXPECT_EQ(gdel::sfc::morton_key(q, x, y, z), gdel::sfc::morton_key(c[0], c[1], c[2]));
    EXPECT_EQ(gdel::sfc::hilbert_key(q, x, y, z), gdel::sfc::hilbert_key(c[0], c[1], c[2]));
  }
  // NaN points get a valid key (cell 0 on that axis), never UB.
  EXPECT_EQ(gdel::sfc::hilbert_key(q, kNaN, kNaN, kNaN), 0u);
}

}  // namespace
