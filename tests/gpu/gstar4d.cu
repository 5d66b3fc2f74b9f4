#include "common/gstar4d_cases.hpp"
TEST(GStar4DGpu, AllGenerators) { gdel::test::gstar4d_generator_cases(gdel::Backend::Cuda, 20000); }
// 10^6 points of every generator but the skew lines (Θ(n²) tets): the exact Delaunay
// triangulation by star splaying itself (no certificate fallback). The grid and the
// exactly cospherical sphere are the inputs whose hull stars were huge before ∞ joined
// every star (docs/gstar4d.md).
static void million(gdel::gen::Distribution d) {
  auto pts = gdel::gen::generate(d, 1000000, 5);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.algorithm = gdel::Algorithm::gstar4d;
  gdel::Triangulation t = gdel::delaunay(pts, o);
  std::printf("gstar4d %s 10^6: %.3f s\n%s\n", std::string(gdel::gen::to_string(d)).c_str(), t.stats.seconds, t.stats.to_string().c_str());
  EXPECT_EQ(t.stats.certificate_fallbacks, 0) << t.stats.to_string();
  t.stats.algorithm = "gdel3d";
  gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
}
TEST(GStar4DGpu, MillionPoints) {
  for (auto d : {gdel::gen::Distribution::Uniform, gdel::gen::Distribution::ThinShell,
                 gdel::gen::Distribution::Gaussian, gdel::gen::Distribution::Ball})
    million(d);
}
TEST(GStar4DGpu, MillionGridPoints) { million(gdel::gen::Distribution::Grid); }
TEST(GStar4DGpu, MillionSpherePoints) { million(gdel::gen::Distribution::Sphere); }
