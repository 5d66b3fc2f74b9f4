// On general-position weighted inputs the regular triangulation is unique: gReg3D's tet
// set and redundant set must equal CGAL's Regular_triangulation_3 exactly.
#include <gtest/gtest.h>

#include "common/greg3d_cases.hpp"
#include "oracle/cgal_oracle.hpp"

TEST(GReg3DCgal, SameTetsAndRedundantPointsAsCgal) {
  using gdel::gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::Ball}) {
    auto pts = gdel::gen::generate(d, 5000, 42);
    const double extent = d == Distribution::Gaussian ? 0.6 : 1.0;
    for (double scale : {0.3, 3.0, 30.0}) {
      SCOPED_TRACE(std::string(gdel::gen::to_string(d)) + " weight scale " + std::to_string(scale));
      auto w = gdel::test::random_weights(5000, extent, scale, 17, -0.5);
      gdel::Options o;
      o.backend = gdel::Backend::Cpu;
      auto r = gdel::regular(pts, w, o);
      std::vector<gdel::oracle::Tet> mine(r.tets.size() / 4);
      for (std::size_t i = 0; i < mine.size(); ++i)
        for (int k = 0; k < 4; ++k) mine[i][k] = r.tets[4 * i + k];
      auto ref = gdel::oracle::cgal_regular(pts, w);
      EXPECT_EQ(std::vector<int>(r.redundant.begin(), r.redundant.end()), ref.redundant);
      ASSERT_EQ(mine.size(), ref.tets.size());
      EXPECT_TRUE(gdel::canonical(mine) == gdel::canonical(ref.tets));
    }
  }
}
