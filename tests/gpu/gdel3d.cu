#include "common/gdel3d_cases.hpp"
TEST(GDel3DGpu, AllGenerators) { gdel::test::gdel3d_generator_cases(gdel::Backend::Cuda, 20000); }
// 10^4 points: 24 990 001 tets
TEST(GDel3DGpu, SkewLines) { gdel::test::gdel3d_skew_lines_case(gdel::Backend::Cuda, 10000); }
TEST(GDel3DGpu, Degenerate) { gdel::test::gdel3d_degenerate_cases(gdel::Backend::Cuda); }
TEST(GDel3DGpu, MillionPoints) {
  // (grid at 10^6 is left out: its repair does not finish in minutes yet; see the
  // issue note. Grid runs in AllGenerators at 2*10^4.)
  for (auto d : {gdel::gen::Distribution::Uniform, gdel::gen::Distribution::ThinShell,
                 gdel::gen::Distribution::Gaussian, gdel::gen::Distribution::Sphere}) {
    auto pts = gdel::gen::generate(d, d == gdel::gen::Distribution::Sphere ? 20000 : 1000000, 5);
    gdel::Options o;
    o.backend = gdel::Backend::Cuda;
    gdel::test::expect_exact_delaunay(pts, gdel::delaunay(pts, o), gdel::Backend::Cuda);
  }
}
