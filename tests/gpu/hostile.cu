#include "common/hostile_cases.hpp"
TEST(HostileGpu, PeersReportedFailures) { gdel::test::hostile_cases(gdel::Backend::Cuda); }
// With canonical_order both backends give bitwise identical arrays (issue 8: determinism).
TEST(HostileGpu, SameArraysAsTheCpuBackend) {
  for (const auto& s : gdel::test::hostile_sets()) {
    SCOPED_TRACE(s.name);
    for (auto a : {gdel::Algorithm::gdel3d, gdel::Algorithm::gstar4d}) {
      gdel::Options o;
      o.canonical_order = true;
      o.algorithm = a;
      o.backend = gdel::Backend::Cpu;
      const auto c = gdel::delaunay(s.pts, o);
      o.backend = gdel::Backend::Cuda;
      const auto g = gdel::delaunay(s.pts, o);
      EXPECT_EQ(c.tets, g.tets);
      EXPECT_EQ(c.neighbors, g.neighbors);
    }
  }
}
// gDel3D issue 6: 2*10^7 points crashed the original (26-bit tet ids).
TEST(HostileGpu, TwentyMillionPoints) {
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 20000000, 6);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  const auto t = gdel::delaunay(pts, o);
  gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
}
