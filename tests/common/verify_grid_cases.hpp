// Verifier cases that need no oracle (Kuhn grid triangulations and corruptions),
// run on a given backend and compared with the CPU backend's report.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "common/verify_cases.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/regular.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"

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
  EXPECT_EQ(a.duplicate_vertices, b.duplicate_vertices);
  EXPECT_EQ(a.locate_failures, b.locate_failures);
  EXPECT_EQ(a.redundant_points, b.redundant_points);
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

// The verifier's facet, hull-edge and edge sorts run in chunks by vertex range
// (GDEL_VERIFY_CHUNK items each): with tiny chunks (dozens of chunks, chunks
// larger than the cap where one vertex has many items) every count must be the
// same as with one chunk, on valid, corrupted and regular inputs.
class ChunkEnv {
 public:
  explicit ChunkEnv(const char* items) { setenv("GDEL_VERIFY_CHUNK", items, 1); }
  ~ChunkEnv() { unsetenv("GDEL_VERIFY_CHUNK"); }
};
inline void expect_chunked_same(std::span<const double> pts, const std::vector<std::int32_t>& tets,
                                std::span<const double> w, Backend backend) {
  const VerifyReport whole = verify(pts, tets, w, backend);
  for (const char* items : {"1", "97", "1000"}) {
    ChunkEnv env(items);
    SCOPED_TRACE(std::string("GDEL_VERIFY_CHUNK=") + items);
    expect_same_report(verify(pts, tets, w, backend), whole);
  }
}
inline void chunked_cases(Backend backend) {
  std::vector<double> pts;
  std::vector<Tet> tets;
  kuhn_grid(6, pts, tets);
  expect_chunked_same(pts, flatten(tets), {}, backend);
  for (Corruption k : {Corruption::RemoveTet, Corruption::InvertTet, Corruption::DuplicateTet,
                       Corruption::LeaveOutPoint}) {
    auto p2 = pts;
    auto t2 = tets;
    ASSERT_TRUE(corrupt(k, p2, t2, 3));
    expect_chunked_same(p2, flatten(t2), {}, backend);
  }
  // a gdel triangulation with a large hull (points on a sphere)
  const std::vector<double> sp = gen::generate(gen::Distribution::Sphere, 3000, 7);
  const Triangulation t = delaunay(sp);
  const VerifyReport r = verify(sp, t.tets, {}, backend);
  EXPECT_TRUE(r.delaunay()) << r.summary();
  EXPECT_GT(r.hull_facets, 1000);
  expect_chunked_same(sp, t.tets, {}, backend);
  // regular: redundant points are located through the facet adjacency
  const std::vector<double> up = gen::generate(gen::Distribution::Uniform, 2000, 11);
  std::vector<double> w(up.size() / 3);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ud(0.0, 0.01);
  for (double& x : w) x = ud(rng);
  const RegularTriangulation rt = regular(up, w);
  const VerifyReport rr = verify(up, rt.tets, w, backend);
  EXPECT_TRUE(rr.delaunay()) << rr.summary();
  EXPECT_GT(rr.redundant_points, 0);
  expect_chunked_same(up, rt.tets, w, backend);
}

}  // namespace gdel::test
