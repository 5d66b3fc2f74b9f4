#include "common/gflip_cases.hpp"
#include "common/nonoptimal_cases.hpp"
#include "common/geo_cases.hpp"
TEST(GFlip3DGpu, AllGenerators) { gdel::test::gflip_generator_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, DegenerateAndHostileInput) { gdel::test::gflip_degenerate_cases(gdel::Backend::Cuda); }
TEST(GFlip3DGpu, NonoptimalFlipsAllGenerators) { gdel::test::nonoptimal_generator_cases(gdel::Backend::Cuda, 50000); }
TEST(GFlip3DGpu, NonoptimalFlipsReduceStuckFacets) { gdel::test::nonoptimal_reduces_cases(gdel::Backend::Cuda); }
TEST(GFlip3DGpu, AutoUsesNonoptimalFlipsWhenFewAreStuck) { gdel::test::nonoptimal_auto_cases(gdel::Backend::Cuda); }
TEST(GFlip3DGpu, NonoptimalRoundsUnderIndependentSplits) { gdel::test::nonoptimal_each_round_cases(gdel::Backend::Cuda); }
TEST(GFlip3DGpu, LogFlushesChangeNothing) { gdel::test::gflip_log_flush_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, ScoreRaiseChangesNothing) { gdel::test::gflip_score_raise_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, DagStampChangesNothing) { gdel::test::gflip_dag_stamp_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, TeamLoopChangesNothing) { gdel::test::gflip_team_loop_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, SmallIterationPathsSameResult) { gdel::test::gflip_small_iteration_paths_cases(gdel::Backend::Cuda, 100000); }
TEST(GFlip3DGpu, SosOrderOnCosphericalInput) { gdel::test::gflip_sos_order_cases(gdel::Backend::Cuda, 100000); }
TEST(GFlip3DGpu, FlipCapPerIteration) { gdel::test::gflip_flip_cap_cases(gdel::Backend::Cuda, 20000, "256"); }
TEST(GFlip3DGpu, IndependentSplitsLeaveFewerStuckFacets) { gdel::test::gflip_independent_splits_cases(gdel::Backend::Cuda); }
TEST(GFlip3DGpu, ExactFormsWithoutScratchAndTieredPass) {
  gdel::test::geo_scratch_free_cases<gdel::par::Cuda>(0x1p21);  // Geo::int_points
  gdel::test::geo_scratch_free_cases<gdel::par::Cuda>(0x1p19);  // Geo::int_all
}
