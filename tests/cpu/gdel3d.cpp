#include "common/gdel3d_cases.hpp"
TEST(GDel3DCpu, AllGenerators) { gdel::test::gdel3d_generator_cases(gdel::Backend::Cpu, 4000); }
// 2000 points: 998 001 tets, 6.6 s on 2 cores with one point per round (about 15 s with the
// rounds and the repair; 4000 points: 4 M tets, 65 s then)
TEST(GDel3DCpu, SkewLines) { gdel::test::gdel3d_skew_lines_case(gdel::Backend::Cpu, 2000); }
TEST(GDel3DCpu, Degenerate) { gdel::test::gdel3d_degenerate_cases(gdel::Backend::Cpu); }
TEST(GDel3DCpu, LargerSphereAndGrid) {
  for (auto d : {gdel::gen::Distribution::Sphere, gdel::gen::Distribution::Grid}) {
    auto pts = gdel::gen::generate(d, 30000, 77);
    gdel::Options o;
    o.backend = gdel::Backend::Cpu;
    gdel::test::expect_exact_delaunay(pts, gdel::delaunay(pts, o), gdel::Backend::Cpu);
  }
}
// Issue 4's sizes on the CPU backend: every generator but the skew lines at 10^4, 10^5 and
// 10^6 (about 5 minutes on 2 cores; the skew lines: SkewLines above).
TEST(GDel3DCpu, AllGeneratorsAtScale) { gdel::test::gdel3d_scale_cases(gdel::Backend::Cpu, {10000, 100000, 1000000}); }
TEST(GDel3DCpu, HostBuiltStarsSameResult) { gdel::test::gdel3d_host_star_case(gdel::Backend::Cpu); }
TEST(GDel3DCpu, FlipFlopSameAsRebuild) { gdel::test::gdel3d_flipflop_case(gdel::Backend::Cpu); }
TEST(GDel3DCpu, OnePointPerRoundOnThreads) { gdel::test::gdel3d_threads_case(gdel::Backend::Cpu); }
TEST(GDel3DCpu, IntegerInputWithoutScratchSameResult) { gdel::test::gdel3d_exact_tiers_case(gdel::Backend::Cpu); }
