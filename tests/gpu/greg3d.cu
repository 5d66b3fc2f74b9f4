#include "common/greg3d_cases.hpp"
TEST(GReg3DGpu, GeneratorsAndWeightScales) { gdel::test::greg3d_generator_cases(gdel::Backend::Cuda, 20000); }
TEST(GReg3DGpu, EqualWeightsGiveDelaunay) { gdel::test::greg3d_equal_weights_case(gdel::Backend::Cuda, 20000); }
TEST(GReg3DGpu, MoleculeGridDuplicatesAndErrors) { gdel::test::greg3d_special_cases(gdel::Backend::Cuda); }
TEST(GReg3DGpu, MillionPoints) {
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 1000000, 6);
  for (double scale : {0.3, 3.0}) {
    auto w = gdel::test::random_weights(1000000, 1.0, scale, 7);
    gdel::Options o;
    o.backend = gdel::Backend::Cuda;
    auto r = gdel::regular(pts, w, o);
    gdel::test::expect_exact_regular(pts, w, r, gdel::Backend::Cuda);
  }
}
