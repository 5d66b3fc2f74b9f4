#include "common/gdel3d_cases.hpp"
TEST(GDel3DGpu, AllGenerators) { gdel::test::gdel3d_generator_cases(gdel::Backend::Cuda, 20000); }
// 10^4 points: 24 990 001 tets
TEST(GDel3DGpu, SkewLines) { gdel::test::gdel3d_skew_lines_case(gdel::Backend::Cuda, 10000); }
TEST(GDel3DGpu, Degenerate) { gdel::test::gdel3d_degenerate_cases(gdel::Backend::Cuda); }
// Issue 4's sizes: every generator but the skew lines (SkewLines above) at 10^4, 10^5, 10^6.
TEST(GDel3DGpu, AllGeneratorsAtScale) { gdel::test::gdel3d_scale_cases(gdel::Backend::Cuda, {10000, 100000, 1000000}); }
TEST(GDel3DGpu, HostBuiltStarsSameResult) { gdel::test::gdel3d_host_star_case(gdel::Backend::Cuda); }
TEST(GDel3DGpu, FlipFlopSameAsRebuild) { gdel::test::gdel3d_flipflop_case(gdel::Backend::Cuda); }
TEST(GDel3DGpu, IntegerInputWithoutScratchSameResult) { gdel::test::gdel3d_exact_tiers_case(gdel::Backend::Cuda); }
