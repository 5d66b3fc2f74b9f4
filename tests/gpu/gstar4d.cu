#include "common/gstar4d_cases.hpp"
TEST(GStar4DGpu, AllGenerators) { gdel::test::gstar4d_generator_cases(gdel::Backend::Cuda, 20000); }
TEST(GStar4DGpu, MillionPoints) {
  for (auto d : {gdel::gen::Distribution::Uniform, gdel::gen::Distribution::ThinShell,
                 gdel::gen::Distribution::Gaussian}) {
    auto pts = gdel::gen::generate(d, 1000000, 5);
    gdel::Options o;
    o.backend = gdel::Backend::Cuda;
    o.algorithm = gdel::Algorithm::gstar4d;
    gdel::Triangulation t = gdel::delaunay(pts, o);
    EXPECT_EQ(t.stats.certificate_fallbacks, 0) << t.stats.to_string();
    t.stats.algorithm = "gdel3d";
    gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
  }
}
