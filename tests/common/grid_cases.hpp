// Options::initial = grid (src/grid, docs/grid.md), shared by the CPU and GPU test
// programs: on every generator gFlip3D's output from the grid start is a valid
// triangulation, gDel3D's is the exact Delaunay triangulation (the same tets as from the
// default start: one symbolic perturbation), both deterministic; the raw dual's exact
// classification on hand-made colourings (the documented negative results).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "common/gdel3d_cases.hpp"
#include "grid/dual.hpp"
#include "parallel/backend.hpp"

namespace gdel::test {

inline std::size_t grid_case_size(gen::Distribution d, std::size_t n) {
  using gen::Distribution;
  return d == Distribution::SkewLines ? std::min<std::size_t>(n / 10, 400) : n;
}

inline void grid_initial_generator_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : gen::kAllDistributions) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, grid_case_size(d, n), 4321);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    o.initial = Initial::grid;
    // gFlip3D from the grid: valid (failed vertices allowed)
    o.algorithm = Algorithm::gflip3d;
    Triangulation f = delaunay(pts, o);
    SCOPED_TRACE(f.stats.to_string());
    expect_flip_output_valid(pts, f, b);
    EXPECT_GT(f.stats.grid, 0);
    EXPECT_GT(f.stats.grid_sites, 0);
    EXPECT_GT(f.stats.dual_tets, 0);
    // the grid start is used on non-degenerate input, and said so in the stages
    const bool degenerate = d == Distribution::Grid || d == Distribution::Sphere || d == Distribution::SkewLines;
    if (!degenerate) {
      EXPECT_EQ(f.stats.grid_fallbacks, 0);
      EXPECT_GT(f.stats.dual_delaunay_tets, 0);
    }
    bool named = false;
    for (auto& [name, s] : f.stats.stages) named = named || name.rfind("grid initial", 0) == 0;
    EXPECT_TRUE(named);
    // gDel3D from the grid: exact, and the same triangulation as from the first tet
    o.algorithm = Algorithm::gdel3d;
    Triangulation t = delaunay(pts, o);
    expect_exact_delaunay(pts, t, b);
    Triangulation t2 = delaunay(pts, o);
    EXPECT_EQ(t.tets, t2.tets);
    EXPECT_EQ(t.neighbors, t2.neighbors);
    o.initial = Initial::Default;
    Triangulation ref = delaunay(pts, o);
    EXPECT_EQ(t.tets, ref.tets);
    EXPECT_EQ(ref.stats.grid_sites, 0);
  }
}

// The dual of a colouring given on the host (W³ site ids, x fastest) of host points.
template <class B>
grid::DualStats dual_stats(par::Context<B>& ctx, const std::vector<std::int32_t>& site, int W,
                           const std::vector<double>& xyz) {
  par::Buffer<std::int32_t, B> s(ctx);
  s.assign(site);
  par::Buffer<double, B> x(ctx);
  x.assign(xyz);
  return grid::dual_of_colouring(ctx, s.data(), W, x.data()).stats;
}

// Brute-force digital Voronoi colouring of W³ voxels (centres at integer coordinates) by
// sites at the given (integer or half-integer) coordinates: the nearest site, ties to the
// smaller id.
inline std::vector<std::int32_t> brute_colouring(int W, const std::vector<double>& xyz) {
  std::vector<std::int32_t> site(static_cast<std::size_t>(W) * W * W);
  const std::size_t n = xyz.size() / 3;
  for (int z = 0; z < W; ++z)
    for (int y = 0; y < W; ++y)
      for (int x = 0; x < W; ++x) {
        double best = 1e300;
        std::int32_t who = -1;
        for (std::size_t i = 0; i < n; ++i) {
          const double dx = xyz[3 * i] - x, dy = xyz[3 * i + 1] - y, dz = xyz[3 * i + 2] - z;
          const double d = dx * dx + dy * dy + dz * dz;
          if (d < best) best = d, who = static_cast<std::int32_t>(i);
        }
        site[(static_cast<std::size_t>(z) * W + y) * W + x] = who;
      }
  return site;
}

template <class B>
void grid_dual_cases() {
  par::Context<B> ctx;
  // One site per voxel of a 4³ grid, at the voxel centre; `fold`: the site of voxel
  // (1,1,1) moved to (2.25, 2.25, 2.25).
  const int W = 4;
  std::vector<std::int32_t> site;
  for (int i = 0; i < W * W * W; ++i) site.push_back(i);
  auto lattice = [&](bool fold) {
    std::vector<double> xyz;
    for (int z = 0; z < W; ++z)
      for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
          if (fold && x == 1 && y == 1 && z == 1) xyz.insert(xyz.end(), {2.25, 2.25, 2.25});
          else xyz.insert(xyz.end(), {double(x), double(y), double(z)});
        }
    return xyz;
  };
  // 1. the dual is the Kuhn triangulation of the lattice itself — valid, 6 tets per cube,
  //    every cube's 8 corners cospherical.
  {
    const std::vector<double> xyz = lattice(false);
    grid::DualStats s = dual_stats(ctx, site, W, xyz);
    EXPECT_EQ(s.grid_tets, 6 * 27);
    EXPECT_EQ(s.tets, 6 * 27);
    EXPECT_EQ(s.flat, 0);
    EXPECT_EQ(s.inverted, 0);
    EXPECT_EQ(s.folded, 0);
    EXPECT_EQ(s.overshared_facets, 0);
    EXPECT_EQ(s.overlapping_facets, 0);
    EXPECT_EQ(s.non_delaunay_pairs, 0);
    EXPECT_GT(s.cospherical_pairs, 0);
    // boundary of the 3×3×3 block of cubes: 6 faces × 9 squares × 2 triangles
    EXPECT_EQ(s.open_facets, 6 * 9 * 2);
  }
  // 2. the same sites with corner 000 of the middle cube pushed through the opposite
  //    corner's side: the map from grid to space folds (inverted dual tets, overlaps).
  {
    const std::vector<double> xyz = lattice(true);
    grid::DualStats s = dual_stats(ctx, site, W, xyz);
    EXPECT_EQ(s.tets, 6 * 27);
    EXPECT_GT(s.inverted, 0);
    EXPECT_GT(s.overlapping_facets + s.overshared_facets, 0);
  }
  // 3. a digital Voronoi colouring (brute force) of 3 × 3 × 3 grid: eight sites, one per
  //    corner octant, and a ninth near the centre: every count is reproducible.
  {
    const int W = 6;
    std::vector<double> xyz;
    for (int i = 0; i < 8; ++i) xyz.insert(xyz.end(), {i & 1 ? 4.0 : 1.0, i & 2 ? 4.0 : 1.0, i & 4 ? 4.0 : 1.0});
    xyz.insert(xyz.end(), {2.5, 2.5, 2.5});
    auto site = brute_colouring(W, xyz);
    grid::DualStats s = dual_stats(ctx, site, W, xyz);
    EXPECT_GT(s.tets, 0);
    EXPECT_EQ(s.grid_tets >= s.tets, true);
  }
}

}  // namespace gdel::test
