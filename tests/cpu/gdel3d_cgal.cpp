// On general-position inputs the exact Delaunay triangulation is unique: gdel3d's tet
// set must equal CGAL's exactly (sorted canonical tet lists), on both CPU paths.
#include <gtest/gtest.h>

#include "gdel/delaunay.hpp"
#include "gen/generators.hpp"
#include "oracle/cgal_oracle.hpp"

TEST(GDel3DCgal, SameTetsAsCgalOnGeneralPosition) {
  using gdel::gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Ball}) {
    SCOPED_TRACE(std::string(gdel::gen::to_string(d)));
    auto pts = gdel::gen::generate(d, 20000, 99);
    gdel::Options o;
    o.backend = gdel::Backend::Cpu;
    auto t = gdel::delaunay(pts, o);
    std::vector<gdel::oracle::Tet> mine(t.tets.size() / 4);
    for (std::size_t i = 0; i < mine.size(); ++i)
      for (int k = 0; k < 4; ++k) mine[i][k] = t.tets[4 * i + k];
    auto ref = gdel::oracle::cgal_delaunay(pts);
    ASSERT_EQ(mine.size(), ref.size());
    EXPECT_TRUE(gdel::canonical(mine) == gdel::canonical(ref));
    // and the gFlip3D result alone differs only where it reported failed vertices
    o.algorithm = gdel::Algorithm::gflip3d;
    auto f = gdel::delaunay(pts, o);
    if (f.failed_vertices.empty()) {
      EXPECT_EQ(f.num_tets(), t.num_tets());
    }
  }
}
