// Options::initial = grid on the CUDA backend, through the public API only (a GPU test
// program that instantiates the library's internal templates itself risks nvcc's
// per-translation-unit lambda tables: api/cuda_backend.cu).
#include "common/grid_cases.hpp"
TEST(GridInitialGpu, AllGenerators) { gdel::test::grid_initial_generator_cases(gdel::Backend::Cuda, 20000); }
// The same grid, sites, dual counts and tets on both backends.
TEST(GridInitialGpu, SameAsCpu) {
  for (auto d : {gdel::gen::Distribution::Uniform, gdel::gen::Distribution::Gaussian,
                 gdel::gen::Distribution::ThinShell}) {
    auto pts = gdel::gen::generate(d, 200000, 9);
    gdel::Options o;
    o.initial = gdel::Initial::grid;
    o.canonical_order = true;
    o.backend = gdel::Backend::Cuda;
    gdel::Triangulation g = gdel::delaunay(pts, o);
    o.backend = gdel::Backend::Cpu;
    gdel::Triangulation c = gdel::delaunay(pts, o);
    SCOPED_TRACE(g.stats.to_string());
    EXPECT_EQ(g.stats.grid_fallbacks, 0);
    EXPECT_EQ(g.stats.grid_sites, c.stats.grid_sites);
    EXPECT_EQ(g.stats.dual_tets, c.stats.dual_tets);
    EXPECT_EQ(g.stats.dual_inverted, c.stats.dual_inverted);
    EXPECT_EQ(g.stats.dual_overlapping_facets, c.stats.dual_overlapping_facets);
    EXPECT_EQ(g.stats.dual_delaunay_tets, c.stats.dual_delaunay_tets);
    EXPECT_EQ(g.tets, c.tets);
  }
}
// 10^6 uniform points from the grid start: exact, and the same tets as the default start.
TEST(GridInitialGpu, MillionPoints) {
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 1000000, 5);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.canonical_order = true;
  o.initial = gdel::Initial::grid;
  gdel::Triangulation t = gdel::delaunay(pts, o);
  EXPECT_EQ(t.stats.grid_fallbacks, 0) << t.stats.to_string();
  gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
  o.initial = gdel::Initial::Default;
  EXPECT_EQ(t.tets, gdel::delaunay(pts, o).tets);
}
