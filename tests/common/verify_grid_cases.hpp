// Verifier cases that need no oracle (Kuhn grid triangulations and corruptions),
// run on a given backend and compared with the CPU backend's report.
#pragma once

#include <gtest/gtest.h>

#include "common/verify_cases.hpp"
#include "gdel/verify.hpp"

namespace gdel::test {

inline void expect_same_report(const VerifyReport& a, const VerifyReport& b) {
  EXPECT_EQ(a.distinct_points, b.distinct_points);
  EXPECT_EQ(a.vertices_used, b.vertices_used);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.facets, b.facets);
  EXPECT_EQ(a.hull_facets, b.hull_facets);
  EXPECT_EQ(a.euler, b.euler);
  EXPECT_EQ(a.degenerate_tets, b.degenerate_tets);
  EXPECT_EQ(a.inverted_tets, b.inverted_tets);
  EXPECT_EQ(a.overshared_facets, b.overshared_facets);
  EXPECT_EQ(a.same_side_facets, b.same_side_facets);
  EXPECT_EQ(a.hull_open_edges, b.hull_open_edges);
  EXPECT_EQ(a.hull_reflex_edges, b.hull_reflex_edges);
  EXPECT_EQ(a.unused_points, b.unused_points);
  EXPECT_EQ(a.non_delaunay_facets, b.non_delaunay_facets);
  EXPECT_EQ(a.cospherical_facets, b.cospherical_facets);
  EXPECT_EQ(a.valid(), b.valid());
  EXPECT_EQ(a.delaunay(), b.delaunay());
}

inline void kuhn_grid_cases(Backend backend) {
  std::vector<double> pts;
  std::vector<Tet> tets;
  kuhn_grid(12, pts, tets);
  auto r = verify(pts, flatten(tets), {}, backend);
  EXPECT_TRUE(r.delaunay()) << r.summary();
  EXPECT_GT(r.cospherical_facets, 0);
  EXPECT_EQ(r.vertices_used, 13 * 13 * 13);
  expect_same_report(r, verify(pts, flatten(tets), {}, Backend::Cpu));
  for (Corruption k : {Corruption::RemoveTet, Corruption::InvertTet, Corruption::DuplicateTet,
                       Corruption::LeaveOutPoint}) {
    auto p2 = pts;
    auto t2 = tets;
    ASSERT_TRUE(corrupt(k, p2, t2, 5));
    auto a = verify(p2, flatten(t2), {}, backend);
    EXPECT_FALSE(a.valid()) << a.summary();
    expect_same_report(a, verify(p2, flatten(t2), {}, Backend::Cpu));
  }
  // Lift the grid slightly off the sphere ties: moving one interior vertex inward
  // along the diagonal keeps the triangulation valid but breaks Delaunay.
  auto p3 = pts;
  int v = 6 + 13 * (6 + 13 * 6);
  p3[3 * v] += 0.25;
  p3[3 * v + 1] += 0.25;
  p3[3 * v + 2] += 0.25;
  auto b = verify(p3, flatten(tets), {}, backend);
  EXPECT_TRUE(b.valid()) << b.summary();
  EXPECT_GT(b.non_delaunay_facets, 0);
  expect_same_report(b, verify(p3, flatten(tets), {}, Backend::Cpu));
}

}  // namespace gdel::test
