// On general-position inputs the exact Delaunay triangulation is unique: gdel3d's tet
// set must equal CGAL's exactly (sorted canonical tet lists), for gdel3d (Auto) and gstar4d.
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
    auto ref = gdel::oracle::cgal_delaunay(pts);
    auto same_as_cgal = [&](const gdel::Triangulation& x) {
      std::vector<gdel::oracle::Tet> mine(x.tets.size() / 4);
      for (std::size_t i = 0; i < mine.size(); ++i)
        for (int k = 0; k < 4; ++k) mine[i][k] = x.tets[4 * i + k];
      ASSERT_EQ(mine.size(), ref.size());
      EXPECT_TRUE(gdel::canonical(mine) == gdel::canonical(ref));
    };
    auto t = gdel::delaunay(pts, o);  // Algorithm::Auto (gdel3d)
    same_as_cgal(t);
    o.algorithm = gdel::Algorithm::gstar4d;  // gStar4D: the same tets, by star splaying
    const auto s = gdel::delaunay(pts, o);
    EXPECT_EQ(s.stats.certificate_fallbacks, 0);
    same_as_cgal(s);
    // and the gFlip3D result alone differs only where it reported failed vertices
    o.algorithm = gdel::Algorithm::gflip3d;
    auto f = gdel::delaunay(pts, o);
    if (f.failed_vertices.empty()) {
      EXPECT_EQ(f.num_tets(), t.num_tets());
    }
  }
}
