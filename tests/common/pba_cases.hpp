// gStar4D stages 1-2 cases (digital Voronoi by PBA, working sets), written once over the
// backend tag and instantiated by tests/cpu/pba.cpp (Cpu) and tests/gpu/pba.cu (Cuda).
//
// PBA is checked against a brute-force nearest-site search on the host (the assigned
// site's squared voxel distance equals the minimum; ties may go either way). Working
// sets are checked for their contract (sorted, unique, no self pair, symmetric, at
// least min(K, n-1) candidates, missing points paired with their owner), against an
// independent host grid scan (every grid pair present, every other pair a pumped one),
// and for quality: the share of exact Delaunay edges they contain.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gdel/delaunay.hpp"
#include "gen/generators.hpp"
#include "sort/point_sort.hpp"
#include "star4d/pba.hpp"
#include "star4d/working_sets.hpp"

namespace gdel::test {

using I64 = std::int64_t;

template <class B>
constexpr Backend backend_of() {
  return B::is_device ? Backend::Cuda : Backend::Cpu;
}

inline I64 vox_d2(const std::int32_t* a, int x, int y, int z) {
  const I64 dx = a[0] - x, dy = a[1] - y, dz = a[2] - z;
  return dx * dx + dy * dy + dz * dz;
}

// Host reference for a site set: the owner (smallest id) of each occupied voxel, and the
// minimum squared distance from each voxel to a site (brute force over all sites).
struct ColouringReference {
  int W = 0;
  std::vector<std::int32_t> owner;
  std::vector<I64> best;
};

inline ColouringReference colouring_reference(int W, const std::vector<std::int32_t>& vox) {
  ColouringReference r;
  r.W = W;
  const I64 n = static_cast<I64>(vox.size() / 3);
  const I64 W3 = I64(W) * W * W;
  r.owner.assign(static_cast<std::size_t>(W3), -1);
  auto vidx = [&](I64 i) { return (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i]; };
  for (I64 i = n - 1; i >= 0; --i) r.owner[vidx(i)] = static_cast<std::int32_t>(i);
  std::vector<std::int32_t> sites;
  for (I64 i = 0; i < n; ++i)
    if (r.owner[vidx(i)] == i) sites.push_back(static_cast<std::int32_t>(i));
  r.best.assign(static_cast<std::size_t>(W3), -1);
  if (sites.empty()) return r;
  for (int z = 0; z < W; ++z)
    for (int y = 0; y < W; ++y)
      for (int x = 0; x < W; ++x) {
        I64 b = INT64_MAX;
        for (std::int32_t t : sites) b = std::min(b, vox_d2(&vox[3 * I64(t)], x, y, z));
        r.best[(I64(z) * W + y) * W + x] = b;
      }
  return r;
}

// Host check of a colouring: every voxel holds a site (the smallest id of the points in
// its voxel) whose squared distance is the minimum over all sites; a site's own voxel
// holds it; with no site, every voxel holds -1.
inline void expect_exact_colouring(const ColouringReference& r, const std::vector<std::int32_t>& vox,
                                   const std::vector<std::int32_t>& site) {
  const int W = r.W;
  const I64 n = static_cast<I64>(vox.size() / 3);
  const I64 W3 = I64(W) * W * W;
  ASSERT_EQ(static_cast<I64>(site.size()), W3);
  auto vidx = [&](I64 i) { return (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i]; };
  if (n == 0) {
    for (I64 k = 0; k < W3; ++k) ASSERT_EQ(site[k], -1) << k;
    return;
  }
  I64 bad = 0;
  for (int z = 0; z < W; ++z)
    for (int y = 0; y < W; ++y)
      for (int x = 0; x < W; ++x) {
        const I64 k = (I64(z) * W + y) * W + x;
        const std::int32_t s = site[k];
        if (s < 0 || s >= n || r.owner[vidx(s)] != s) {
          if (bad++ < 5) ADD_FAILURE() << "voxel (" << x << "," << y << "," << z << ") holds " << s << ", not a site";
          continue;
        }
        if (r.owner[k] >= 0 && s != r.owner[k]) {
          if (bad++ < 5) ADD_FAILURE() << "site voxel (" << x << "," << y << "," << z << ") not coloured by its owner";
          continue;
        }
        const I64 d = vox_d2(&vox[3 * I64(s)], x, y, z);
        if (d != r.best[k] && bad++ < 5)
          ADD_FAILURE() << "voxel (" << x << "," << y << "," << z << "): site " << s << " at d2 " << d
                        << ", nearest site at d2 " << r.best[k];
      }
  EXPECT_EQ(bad, 0);
}

inline void expect_exact_colouring(int W, const std::vector<std::int32_t>& vox, const std::vector<std::int32_t>& site) {
  expect_exact_colouring(colouring_reference(W, vox), vox, site);
}

template <class B>
std::vector<std::int32_t> run_pba(par::Context<B>& ctx, int W, const std::vector<std::int32_t>& vox,
                                  star4d::PbaBands bands) {
  par::Buffer<std::int32_t, B> v(ctx);
  v.assign(vox);
  auto g = star4d::pba_colour(ctx, W, v.data(), static_cast<I64>(vox.size() / 3), bands);
  return g.to_host();
}

inline std::vector<star4d::PbaBands> band_configs(int W) {
  return {{1, 1, 2}, {1, 1, 1}, {2, 2, 2}, {4, 3, 5}, {3, 8, 7}, {W, W, W}, {1000, 1000, 1000}};
}

// A named set of site voxels on a W grid.
struct SiteSet {
  std::string name;
  int W;
  std::vector<std::int32_t> vox;
};

inline std::vector<SiteSet> pba_site_sets() {
  std::vector<SiteSet> sets;
  std::mt19937_64 rng(2024);
  auto uni = [&](int W, int n, const char* name) {
    SiteSet s{name, W, {}};
    for (int i = 0; i < 3 * n; ++i) s.vox.push_back(static_cast<std::int32_t>(rng() % W));
    sets.push_back(s);
  };
  uni(32, 40, "random W32 n40");
  uni(64, 300, "random W64 n300");
  uni(50, 200, "random W50 n200 (W not a power of two)");
  uni(37, 1500, "random W37 n1500 (dense, collisions)");
  uni(29, 3, "random W29 n3 (sparse)");
  {
    SiteSet s{"clustered W48", 48, {}};
    const int centre[4][3] = {{8, 9, 10}, {40, 12, 30}, {24, 24, 24}, {5, 44, 44}};
    for (int i = 0; i < 400; ++i) {
      const int* c = centre[i % 4];
      for (int a = 0; a < 3; ++a) {
        // sum of uniforms: a cluster a few voxels wide, clamped to the grid
        int d = static_cast<int>(rng() % 5) + static_cast<int>(rng() % 5) - 4;
        s.vox.push_back(std::clamp(c[a] + d, 0, 47));
      }
    }
    sets.push_back(s);
  }
  sets.push_back({"single site W33", 33, {3, 30, 17}});
  sets.push_back({"single site W1", 1, {0, 0, 0}});
  sets.push_back({"two sites W2", 2, {0, 0, 0, 1, 1, 1}});
  sets.push_back({"no site W5", 5, {}});
  {
    SiteSet s{"line along z W40", 40, {}};
    for (int i = 0; i < 12; ++i) s.vox.insert(s.vox.end(), {5, 7, static_cast<std::int32_t>(rng() % 40)});
    sets.push_back(s);
  }
  {
    SiteSet s{"line along x W40", 40, {}};
    for (int i = 0; i < 12; ++i) s.vox.insert(s.vox.end(), {static_cast<std::int32_t>(rng() % 40), 20, 39});
    sets.push_back(s);
  }
  {
    SiteSet s{"diagonal line W41", 41, {}};
    for (int t = 0; t < 41; t += 3) s.vox.insert(s.vox.end(), {t, t, t});
    sets.push_back(s);
  }
  {
    SiteSet s{"plane z=10 W36", 36, {}};
    for (int i = 0; i < 60; ++i)
      s.vox.insert(s.vox.end(), {static_cast<std::int32_t>(rng() % 36), static_cast<std::int32_t>(rng() % 36), 10});
    sets.push_back(s);
  }
  {
    SiteSet s{"plane x=0 W36", 36, {}};
    for (int i = 0; i < 60; ++i)
      s.vox.insert(s.vox.end(), {0, static_cast<std::int32_t>(rng() % 36), static_cast<std::int32_t>(rng() % 36)});
    sets.push_back(s);
  }
  {
    // equidistant ties everywhere: a regular lattice of sites
    SiteSet s{"lattice W30", 30, {}};
    for (int z = 1; z < 30; z += 7)
      for (int y = 1; y < 30; y += 7)
        for (int x = 1; x < 30; x += 7) s.vox.insert(s.vox.end(), {x, y, z});
    sets.push_back(s);
  }
  return sets;
}

template <class B>
void pba_brute_force_cases(par::Context<B>& ctx) {
  for (const SiteSet& s : pba_site_sets()) {
    const ColouringReference ref = colouring_reference(s.W, s.vox);
    for (const star4d::PbaBands& b : band_configs(s.W)) {
      SCOPED_TRACE(s.name + " bands " + std::to_string(b.m1) + "," + std::to_string(b.m2) + "," + std::to_string(b.m3));
      expect_exact_colouring(ref, s.vox, run_pba(ctx, s.W, s.vox, b));
    }
  }
}

// The same colouring whatever the band counts (deterministic, and ties resolved the same
// way is NOT required; distances are): compare distance fields between band settings on
// a larger grid, where the brute force would be slow.
template <class B>
void pba_band_agreement_cases(par::Context<B>& ctx) {
  const int W = 80;
  std::mt19937_64 rng(99);
  std::vector<std::int32_t> vox;
  for (int i = 0; i < 3 * 2000; ++i) vox.push_back(static_cast<std::int32_t>(rng() % W));
  auto ref = run_pba(ctx, W, vox, {1, 1, 2});
  // spot-check the reference by brute force on a sample of voxels
  {
    std::vector<std::int32_t> owner(static_cast<std::size_t>(W) * W * W, -1);
    const I64 n = static_cast<I64>(vox.size() / 3);
    auto vidx = [&](I64 i) { return (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i]; };
    for (I64 i = n - 1; i >= 0; --i) owner[vidx(i)] = static_cast<std::int32_t>(i);
    for (int q = 0; q < 3000; ++q) {
      const int x = static_cast<int>(rng() % W), y = static_cast<int>(rng() % W), z = static_cast<int>(rng() % W);
      I64 best = INT64_MAX;
      for (I64 i = 0; i < n; ++i) best = std::min(best, vox_d2(&vox[3 * i], x, y, z));
      const std::int32_t s = ref[(I64(z) * W + y) * W + x];
      ASSERT_GE(s, 0);
      EXPECT_EQ(owner[vidx(s)], s);
      EXPECT_EQ(vox_d2(&vox[3 * I64(s)], x, y, z), best);
    }
  }
  auto dist = [&](const std::vector<std::int32_t>& g) {
    std::vector<I64> d(g.size());
    for (int z = 0; z < W; ++z)
      for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
          const I64 k = (I64(z) * W + y) * W + x;
          d[k] = vox_d2(&vox[3 * I64(g[k])], x, y, z);
        }
    return d;
  };
  const auto dref = dist(ref);
  for (star4d::PbaBands b : {star4d::PbaBands{2, 4, 8}, star4d::PbaBands{8, 16, 3}, star4d::PbaBands{5, 7, 80}}) {
    SCOPED_TRACE(std::to_string(b.m1) + "," + std::to_string(b.m2) + "," + std::to_string(b.m3));
    auto g = run_pba(ctx, W, vox, b);
    EXPECT_TRUE(dist(g) == dref);
    EXPECT_EQ(run_pba(ctx, W, vox, b), g);  // deterministic
  }
}

inline void bbox(const std::vector<double>& pts, double lo[3], double hi[3]) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = 1e300;
    hi[a] = -1e300;
  }
  for (std::size_t i = 0; i < pts.size(); i += 3)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], pts[i + a]);
      hi[a] = std::max(hi[a], pts[i + a]);
    }
}

// Quantization and the W rule on real points.
template <class B>
void digital_voronoi_cases(par::Context<B>& ctx) {
  // the rule
  const std::size_t big = std::size_t(1) << 40;
  EXPECT_EQ(star4d::choose_grid_size(0, big), star4d::kMinGrid);
  EXPECT_EQ(star4d::choose_grid_size(3000, big, 4.0), 23);       // 23^3 = 12167 > 12000 >= 22^3
  EXPECT_EQ(star4d::choose_grid_size(1000000, big, 4.0), 159);   // 159^3 = 4019679
  EXPECT_EQ(star4d::choose_grid_size(1000000, big, 1.0), 101);   // 100^3 = 10^6 is not above 10^6
  EXPECT_EQ(star4d::choose_grid_size(1000000000, std::size_t(8) * 100 * 100 * 100, 4.0), 100);  // memory cap
  EXPECT_EQ(star4d::choose_grid_size(I64(1) << 40, big * 1024, 4.0), star4d::kMaxGrid);

  for (auto d : {gen::Distribution::Uniform, gen::Distribution::Gaussian, gen::Distribution::ThinShell}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, 1500, 11);
    double lo[3], hi[3];
    bbox(pts, lo, hi);
    par::Buffer<double, B> X(ctx);
    X.assign(pts);
    star4d::PbaOptions o;
    o.memory_budget = big;
    auto dv = star4d::digital_voronoi(ctx, X.data(), 1500, lo, hi, o);
    EXPECT_EQ(dv.W, star4d::choose_grid_size(1500, big));
    EXPECT_EQ(dv.W, 23);  // default 8 voxels per point: 23^3 = 12167 > 12000 >= 22^3
    EXPECT_EQ(dv.stats.W, dv.W);
    auto vox = dv.voxel.to_host();
    ASSERT_EQ(vox.size(), pts.size());
    for (std::size_t i = 0; i < vox.size(); ++i) {
      ASSERT_GE(vox[i], 0);
      ASSERT_LT(vox[i], dv.W);
      // same quantization on the host: floor((p - origin) * scale), clamped
      const double f = (pts[i] - dv.origin[i % 3]) * dv.scale;
      const int v = f >= dv.W ? dv.W - 1 : (f > 0 ? static_cast<int>(f) : 0);
      ASSERT_EQ(vox[i], v);
    }
    expect_exact_colouring(dv.W, vox, dv.site.to_host());
    EXPECT_GT(dv.stats.sites, 0);
    EXPECT_LE(dv.stats.sites, 1500);
    // explicit W, several bands
    o.grid = 41;
    o.bands = {2, 3, 4};
    auto dv2 = star4d::digital_voronoi(ctx, X.data(), 1500, lo, hi, o);
    EXPECT_EQ(dv2.W, 41);
    expect_exact_colouring(41, dv2.voxel.to_host(), dv2.site.to_host());
  }
}

// ---------------------------------------------------------------------------------
// Working sets
// ---------------------------------------------------------------------------------

// Independent host grid scan: Kuhn tets as the 6 monotone paths 000 -> 111 (one per
// permutation of the axes), 4 distinct colours -> the 6 edge pairs; plus missing pairs.
inline std::set<std::pair<int, int>> host_grid_pairs(int W, const std::vector<std::int32_t>& site,
                                                      const std::vector<std::int32_t>& vox) {
  std::set<std::pair<int, int>> E;
  auto at = [&](int x, int y, int z) { return site[(I64(z) * W + y) * W + x]; };
  std::array<int, 3> perm = {0, 1, 2};
  std::vector<std::array<int, 3>> perms;
  do perms.push_back(perm);
  while (std::next_permutation(perm.begin(), perm.end()));
  for (int z = 0; z + 1 < W; ++z)
    for (int y = 0; y + 1 < W; ++y)
      for (int x = 0; x + 1 < W; ++x)
        for (const auto& p : perms) {
          int c[4];
          int o[3] = {0, 0, 0};
          c[0] = at(x, y, z);
          for (int s = 0; s < 3; ++s) {
            o[p[s]] = 1;
            c[s + 1] = at(x + o[0], y + o[1], z + o[2]);
          }
          bool distinct = true;
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) distinct = distinct && c[a] != c[b];
          if (!distinct) continue;
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) E.insert({std::min(c[a], c[b]), std::max(c[a], c[b])});
        }
  const I64 n = static_cast<I64>(vox.size() / 3);
  for (I64 i = 0; i < n; ++i) {
    const std::int32_t o = at(vox[3 * i], vox[3 * i + 1], vox[3 * i + 2]);
    if (o != i) E.insert({std::min<int>(i, o), std::max<int>(i, o)});
  }
  return E;
}

// Contract checks; returns the lists.
inline void expect_working_set_contract(I64 n, int K, const std::vector<I64>& off, const std::vector<vid_t>& ids,
                                        const std::vector<std::int32_t>& vox, int W,
                                        const std::vector<std::int32_t>& site) {
  ASSERT_EQ(static_cast<I64>(off.size()), n + 1);
  ASSERT_EQ(off[0], 0);
  ASSERT_EQ(off[n], static_cast<I64>(ids.size()));
  auto has = [&](I64 i, vid_t j) { return std::binary_search(ids.begin() + off[i], ids.begin() + off[i + 1], j); };
  const I64 need = std::min<I64>(K, n - 1);
  for (I64 i = 0; i < n; ++i) {
    ASSERT_LE(off[i], off[i + 1]);
    ASSERT_GE(off[i + 1] - off[i], need) << "point " << i;
    for (I64 t = off[i]; t < off[i + 1]; ++t) {
      ASSERT_GE(ids[t], 0);
      ASSERT_LT(ids[t], n);
      ASSERT_NE(ids[t], i) << "self pair";
      if (t > off[i]) {
        ASSERT_LT(ids[t - 1], ids[t]) << "unsorted or duplicate in list " << i;
      }
      ASSERT_TRUE(has(ids[t], static_cast<vid_t>(i))) << "not symmetric: " << i << " -> " << ids[t];
    }
    const std::int32_t o = site[(I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i]];
    if (o != i) {
      EXPECT_TRUE(has(i, o)) << "missing point " << i << " lacks its owner " << o;
    }
  }
}

// Grid pairs all present; every other pair was pumped by one of its ends.
inline void expect_matches_host_scan(I64 n, int K, const std::vector<I64>& off, const std::vector<vid_t>& ids,
                                     const std::set<std::pair<int, int>>& E) {
  std::vector<I64> degE(static_cast<std::size_t>(n), 0);
  for (auto [a, b] : E) {
    ++degE[a];
    ++degE[b];
  }
  const I64 need = std::min<I64>(K, n - 1);
  std::set<std::pair<int, int>> O;
  for (I64 i = 0; i < n; ++i)
    for (I64 t = off[i]; t < off[i + 1]; ++t)
      if (i < ids[t]) O.insert({static_cast<int>(i), ids[t]});
  for (auto& e : E) EXPECT_TRUE(O.count(e)) << "grid pair " << e.first << "," << e.second << " lost";
  for (auto& e : O)
    if (!E.count(e)) {
      EXPECT_TRUE(degE[e.first] < need || degE[e.second] < need) << "unexplained pair " << e.first << "," << e.second;
    }
}

template <class B>
void working_set_cases(par::Context<B>& ctx) {
  struct Case {
    std::string name;
    std::vector<double> pts;
    int grid;
    int K;
  };
  std::vector<Case> cases;
  cases.push_back({"uniform 2000 auto W", gen::uniform(2000, 3), 0, 8});
  cases.push_back({"uniform 2000 W 10 (coarse: many missing)", gen::uniform(2000, 4), 10, 8});
  cases.push_back({"gaussian 1500 W 31 K 20", gen::generate(gen::Distribution::Gaussian, 1500, 5), 31, 20});
  cases.push_back({"thin shell 1500", gen::generate(gen::Distribution::ThinShell, 1500, 6), 0, 8});
  {
    std::vector<double> line;  // collinear points: the grid scan finds nothing; pumping only
    for (int i = 0; i < 50; ++i) line.insert(line.end(), {0.1 * i, 0.2 * i, 0.3 * i});
    cases.push_back({"line 50", line, 0, 8});
  }
  {
    std::vector<double> plane;
    for (int i = 0; i < 400; ++i) plane.insert(plane.end(), {double(i % 20), double(i / 20), 0.5});
    cases.push_back({"plane grid 400", plane, 0, 8});
  }
  cases.push_back({"5 points", gen::uniform(5, 7), 0, 8});
  cases.push_back({"9 points", gen::uniform(9, 8), 0, 8});
  cases.push_back({"1 point", gen::uniform(1, 9), 0, 8});
  cases.push_back({"2 points K 0", gen::uniform(2, 9), 0, 0});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const I64 n = static_cast<I64>(c.pts.size() / 3);
    double lo[3], hi[3];
    bbox(c.pts, lo, hi);
    par::Buffer<double, B> X(ctx);
    X.assign(c.pts);
    star4d::PbaOptions po;
    po.grid = c.grid;
    auto dv = star4d::digital_voronoi(ctx, X.data(), n, lo, hi, po);
    star4d::WorkingSetOptions wo;
    wo.min_candidates = c.K;
    auto ws = star4d::working_sets(ctx, dv, wo);
    auto off = ws.offsets.to_host();
    auto ids = ws.ids.to_host();
    auto vox = dv.voxel.to_host();
    auto site = dv.site.to_host();
    expect_working_set_contract(n, c.K, off, ids, vox, dv.W, site);
    if (::testing::Test::HasFatalFailure()) return;
    auto E = host_grid_pairs(dv.W, site, vox);
    expect_matches_host_scan(n, c.K, off, ids, E);
    EXPECT_EQ(ws.stats.directed_pairs, static_cast<I64>(ids.size()));
    EXPECT_EQ(ws.stats.raw_pairs, ws.stats.grid_pairs + ws.stats.missing_points);
    EXPECT_GE(ws.stats.unique_pairs, static_cast<I64>(E.size()) - 0);
    // deterministic
    auto ws2 = star4d::working_sets(ctx, dv, wo);
    EXPECT_EQ(ws2.offsets.to_host(), off);
    EXPECT_EQ(ws2.ids.to_host(), ids);
  }
}

// Share of the exact Delaunay edges of 10^4 uniform points that the working sets hold
// (default W rule and K). Returns the share; asserts it above a measured bound.
template <class B>
double working_set_quality_case(par::Context<B>& ctx, double bound) {
  const I64 n = 10000;
  auto pts = gen::uniform(static_cast<std::size_t>(n), 12345);
  Options o;
  o.backend = backend_of<B>();
  Triangulation t = delaunay(pts, o);
  std::set<std::pair<int, int>> dt;
  for (std::size_t k = 0; k < t.tets.size(); k += 4)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const int u = t.tets[k + a], v = t.tets[k + b];
        dt.insert({std::min(u, v), std::max(u, v)});
      }
  double lo[3], hi[3];
  bbox(pts, lo, hi);
  par::Buffer<double, B> X(ctx);
  X.assign(pts);
  auto dv = star4d::digital_voronoi(ctx, X.data(), n, lo, hi);
  auto ws = star4d::working_sets(ctx, dv);
  auto off = ws.offsets.to_host();
  auto ids = ws.ids.to_host();
  I64 found = 0;
  for (auto [a, b] : dt)
    if (std::binary_search(ids.begin() + off[a], ids.begin() + off[a + 1], b)) ++found;
  const double share = static_cast<double>(found) / static_cast<double>(dt.size());
  std::printf("[quality] n=%lld W=%d: %lld of %zu Delaunay edges in the working sets (%.4f); %lld directed pairs "
              "(%.2f per point, Delaunay %.2f), missing %lld, pumped points %lld\n",
              static_cast<long long>(n), dv.W, static_cast<long long>(found), dt.size(), share,
              static_cast<long long>(ids.size()), double(ids.size()) / n, 2.0 * dt.size() / n,
              static_cast<long long>(ws.stats.missing_points), static_cast<long long>(ws.stats.pumped_points));
  EXPECT_GT(share, bound);
  return share;
}

// Timing of stages 1-2 on uniform points (default W), printed; for the docs. The points
// are Hilbert-sorted first, as gStar4D's internal points are (site ids are then spatially
// coherent, which the voxel look-ups of PBA and the scans profit from).
template <class B>
void pba_timing_case(par::Context<B>& ctx, I64 n) {
  auto raw = gen::uniform(static_cast<std::size_t>(n), 777);
  double lo[3], hi[3];
  bbox(raw, lo, hi);
  par::Buffer<double, B> X(ctx);
  X.assign(raw);
  {
    par::Buffer<I64, B> order(ctx, static_cast<std::size_t>(n));
    sort::hilbert_order(ctx, X.data(), n, lo, hi, order.data());
    auto o = order.to_host();
    std::vector<double> pts(raw.size());
    for (I64 k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) pts[3 * k + a] = raw[3 * o[k] + a];
    X.assign(pts);
  }
  for (int rep = 0; rep < 2; ++rep) {
    const std::size_t base = ctx.memory().current();
    ctx.memory().reset_peak();
    auto dv = star4d::digital_voronoi(ctx, X.data(), n, lo, hi);
    const std::size_t peak_pba = ctx.memory().peak() - base;
    const std::size_t held = ctx.memory().current();
    ctx.memory().reset_peak();
    auto ws = star4d::working_sets(ctx, dv);
    const std::size_t peak_ws = ctx.memory().peak() - held;
    const auto& p = dv.stats;
    const auto& w = ws.stats;
    std::printf("[timing %s] n=%lld W=%d sites=%lld PBA %.3f s (quantize %.3f seed %.3f ph1 %.3f ph2 %.3f ph3 %.3f "
                "transpose %.3f) peak %.1f MB (context %.1f MB) | working sets %.3f s (missing %.3f scan %.3f sort "
                "%.3f csr %.3f pump %.3f) peak above stage 1 %.1f MB; missing %lld raw %lld unique %lld pumped "
                "%lld/%lld directed %lld (%.2f/pt)\n",
                B::name, static_cast<long long>(n), dv.W, static_cast<long long>(p.sites), p.t_total, p.t_quantize,
                p.t_seed, p.t_phase1, p.t_phase2, p.t_phase3, p.t_transpose, p.peak_bytes / 1e6, peak_pba / 1e6,
                w.t_total, w.t_missing, w.t_scan, w.t_sort, w.t_csr, w.t_pump, peak_ws / 1e6, static_cast<long long>(w.missing_points),
                static_cast<long long>(w.raw_pairs), static_cast<long long>(w.unique_pairs),
                static_cast<long long>(w.pumped_points), static_cast<long long>(w.pumped_pairs),
                static_cast<long long>(w.directed_pairs), double(w.directed_pairs) / n);
  }
}

}  // namespace gdel::test
