#include "common/gdel3d_cases.hpp"
TEST(GDel3DCpu, AllGenerators) { gdel::test::gdel3d_generator_cases(gdel::Backend::Cpu, 4000); }
TEST(GDel3DCpu, Degenerate) { gdel::test::gdel3d_degenerate_cases(gdel::Backend::Cpu); }
TEST(GDel3DCpu, LargerSphereAndGrid) {
  for (auto d : {gdel::gen::Distribution::Sphere, gdel::gen::Distribution::Grid}) {
    auto pts = gdel::gen::generate(d, 30000, 77);
    gdel::Options o;
    o.backend = gdel::Backend::Cpu;
    gdel::test::expect_exact_delaunay(pts, gdel::delaunay(pts, o), gdel::Backend::Cpu);
  }
}
