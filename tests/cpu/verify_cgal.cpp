// The verifier accepts CGAL's Delaunay triangulations of every generator and
// catches every corruption class (CPU backend; CGAL as the oracle).
#include <gtest/gtest.h>

#include "common/verify_cases.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"
#include "oracle/cgal_oracle.hpp"

using namespace gdel;
using gdel::test::Corruption;

namespace {

struct Case {
  gen::Distribution dist;
  std::size_t n;
};

class VerifyCgal : public ::testing::TestWithParam<Case> {};

TEST_P(VerifyCgal, AcceptsCgalAndCatchesCorruptions) {
  const Case c = GetParam();
  auto pts = gen::generate(c.dist, c.n, 7);
  auto tets = oracle::cgal_delaunay(pts);
  ASSERT_FALSE(tets.empty());
  auto r = verify(pts, test::flatten(tets), {}, Backend::Cpu);
  EXPECT_TRUE(r.delaunay()) << r.summary();
  EXPECT_EQ(r.vertices_used, r.distinct_points);
  EXPECT_EQ(r.euler, 1);

  for (Corruption k : {Corruption::FlipFacet, Corruption::RemoveTet, Corruption::InvertTet, Corruption::DuplicateTet,
                       Corruption::LeaveOutPoint}) {
    auto p2 = pts;
    auto t2 = tets;
    bool applied = test::corrupt(k, p2, t2, 11);
    if (k == Corruption::FlipFacet && !applied) continue;  // e.g. all facets cospherical
    ASSERT_TRUE(applied);
    auto r2 = verify(p2, test::flatten(t2), {}, Backend::Cpu);
    SCOPED_TRACE(r2.summary());
    switch (k) {
      case Corruption::FlipFacet:
        EXPECT_TRUE(r2.valid());
        EXPECT_GT(r2.non_delaunay_facets, 0);
        break;
      case Corruption::RemoveTet: EXPECT_FALSE(r2.valid()); break;
      case Corruption::InvertTet:
        EXPECT_FALSE(r2.valid());
        EXPECT_EQ(r2.inverted_tets, 1);
        break;
      case Corruption::DuplicateTet:
        EXPECT_FALSE(r2.valid());
        EXPECT_GT(r2.overshared_facets, 0);
        break;
      case Corruption::LeaveOutPoint:
        EXPECT_FALSE(r2.valid());
        EXPECT_EQ(r2.unused_points, 1);
        break;
      default: break;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Generators, VerifyCgal,
                         ::testing::Values(Case{gen::Distribution::Uniform, 20000},
                                           Case{gen::Distribution::Gaussian, 20000},
                                           Case{gen::Distribution::ThinShell, 20000},
                                           Case{gen::Distribution::Grid, 20000},
                                           Case{gen::Distribution::Sphere, 5000},
                                           Case{gen::Distribution::SkewLines, 400},
                                           Case{gen::Distribution::Ball, 5000}),
                         [](const auto& info) { return std::string(gen::to_string(info.param.dist)); });

TEST(VerifyCgal, RegularWeightedPointsAndRedundancy) {
  auto pts = gen::uniform(5000, 3);
  auto w = gen::weights(5000, 4, 0.001);
  auto reg = oracle::cgal_regular(pts, w);
  ASSERT_FALSE(reg.redundant.empty());
  auto r = verify(pts, test::flatten(reg.tets), w, Backend::Cpu);
  EXPECT_TRUE(r.delaunay()) << r.summary();
  EXPECT_EQ(r.redundant_points, static_cast<std::int64_t>(reg.redundant.size()));
  // The Delaunay triangulation of the same points is not regular for these weights.
  auto del = oracle::cgal_delaunay(pts);
  auto r2 = verify(pts, test::flatten(del), w, Backend::Cpu);
  EXPECT_TRUE(r2.valid());
  EXPECT_GT(r2.non_delaunay_facets, 0);
  // Dropping a non-redundant point from the regular triangulation's vertex set
  // (removing its tets) is caught.
  auto t3 = reg.tets;
  t3.erase(t3.begin());
  EXPECT_FALSE(verify(pts, test::flatten(t3), w, Backend::Cpu).valid());
}

TEST(VerifyCgal, DuplicatesAreMergedAndDegenerateDetected) {
  auto pts = gen::uniform(2000, 5);
  // exact duplicates of the first 10 points, and -0.0 vs 0.0
  for (int i = 0; i < 10; ++i) pts.insert(pts.end(), {pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]});
  auto tets = oracle::cgal_delaunay(pts);
  auto r = verify(pts, test::flatten(tets), {}, Backend::Cpu);
  EXPECT_TRUE(r.delaunay()) << r.summary();
  EXPECT_EQ(r.distinct_points, 2000);
  // Flat tet: four coplanar points.
  std::vector<double> q = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  auto rf = verify(q, std::vector<std::int32_t>{0, 1, 2, 3}, {}, Backend::Cpu);
  EXPECT_EQ(rf.degenerate_tets, 1);
  EXPECT_FALSE(rf.valid());
  // Bad ids.
  auto rb = verify(q, std::vector<std::int32_t>{0, 1, 2, 7}, {}, Backend::Cpu);
  EXPECT_EQ(rb.bad_index, 1);
}

}  // namespace
