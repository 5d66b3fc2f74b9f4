// gDel3D cases shared by the CPU and GPU test programs: the exact Delaunay
// triangulation (gFlip3D + star-splaying repair) of every generator passes every check
// of the exact verifier, has no flat tet, and is the same on every run.
#pragma once

#include <gtest/gtest.h>

#include "common/gflip_cases.hpp"

namespace gdel::test {

inline void expect_exact_delaunay(const std::vector<double>& pts, const Triangulation& t, Backend b) {
  auto r = verify(pts, t.tets, {}, b);
  SCOPED_TRACE(r.summary());
  SCOPED_TRACE(t.stats.to_string());
  EXPECT_EQ(t.stats.algorithm, "gdel3d");
  EXPECT_TRUE(r.delaunay());
  EXPECT_EQ(r.non_delaunay_facets, 0);
  EXPECT_EQ(r.degenerate_tets, 0);  // no flat tets in the output contract
  EXPECT_TRUE(t.failed_vertices.empty());
  expect_flip_output_valid(pts, t, b);  // structure and neighbour checks
}

inline void gdel3d_generator_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Grid,
                         Distribution::Sphere, Distribution::Ball, Distribution::SkewLines}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    const std::size_t nn = d == Distribution::SkewLines ? std::min<std::size_t>(n / 10, 400) : n;
    auto pts = gen::generate(d, nn, 4321);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    Triangulation t = delaunay(pts, o);
    expect_exact_delaunay(pts, t, b);
    // deterministic across runs (degenerate inputs included)
    Triangulation t2 = delaunay(pts, o);
    EXPECT_EQ(t.tets, t2.tets);
    EXPECT_EQ(t.neighbors, t2.neighbors);
  }
}

// Degenerate configurations the repair must handle: cospherical and coplanar subsets.
inline void gdel3d_degenerate_cases(Backend b) {
  Options o;
  o.backend = b;
  // cube corners + centre; 3x3x3 grid; points on two parallel planes; many coplanar
  // points on the hull with one apex
  std::vector<std::vector<double>> sets;
  {
    std::vector<double> cube;
    for (int i = 0; i < 8; ++i) cube.insert(cube.end(), {double(i & 1), double((i >> 1) & 1), double(i >> 2)});
    cube.insert(cube.end(), {0.5, 0.5, 0.5});
    sets.push_back(cube);
  }
  {
    std::vector<double> g;
    for (int i = 0; i < 27; ++i) g.insert(g.end(), {double(i % 3), double((i / 3) % 3), double(i / 9)});
    sets.push_back(g);
  }
  {
    std::vector<double> two;
    for (int i = 0; i < 200; ++i) two.insert(two.end(), {double(i % 10), double((i / 10) % 10), double(i / 100)});
    sets.push_back(two);
  }
  {
    std::vector<double> pyr;
    for (int i = 0; i < 400; ++i) pyr.insert(pyr.end(), {double(i % 20), double(i / 20), 0.0});
    pyr.insert(pyr.end(), {7.3, 9.1, 5.0});
    sets.push_back(pyr);
  }
  for (auto& s : sets) {
    SCOPED_TRACE(s.size() / 3);
    expect_exact_delaunay(s, delaunay(s, o), b);
  }
}

}  // namespace gdel::test
