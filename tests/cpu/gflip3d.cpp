#include "common/gflip_cases.hpp"
#include "common/nonoptimal_cases.hpp"
#include "common/geo_cases.hpp"
TEST(GFlip3DCpu, AllGenerators) { gdel::test::gflip_generator_cases(gdel::Backend::Cpu, 4000); }
TEST(GFlip3DCpu, DegenerateAndHostileInput) { gdel::test::gflip_degenerate_cases(gdel::Backend::Cpu); }
TEST(GFlip3DCpu, NonoptimalFlipsAllGenerators) { gdel::test::nonoptimal_generator_cases(gdel::Backend::Cpu, 2000); }
TEST(GFlip3DCpu, NonoptimalFlipsReduceStuckFacets) { gdel::test::nonoptimal_reduces_cases(gdel::Backend::Cpu); }
TEST(GFlip3DCpu, AutoUsesNonoptimalFlipsWhenFewAreStuck) { gdel::test::nonoptimal_auto_cases(gdel::Backend::Cpu); }
TEST(GFlip3DCpu, NonoptimalRoundsUnderIndependentSplits) { gdel::test::nonoptimal_each_round_cases(gdel::Backend::Cpu); }
TEST(GFlip3DCpu, LogFlushesChangeNothing) { gdel::test::gflip_log_flush_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, ScoreRaiseChangesNothing) { gdel::test::gflip_score_raise_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, DagStampChangesNothing) { gdel::test::gflip_dag_stamp_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, TeamLoopChangesNothing) { gdel::test::gflip_team_loop_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, SmallIterationPathsSameResult) { gdel::test::gflip_small_iteration_paths_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, SosOrderOnCosphericalInput) { gdel::test::gflip_sos_order_cases(gdel::Backend::Cpu, 20000); }
TEST(GFlip3DCpu, FlipCapPerIteration) { gdel::test::gflip_flip_cap_cases(gdel::Backend::Cpu, 6000, "64"); }
TEST(GFlip3DCpu, IndependentSplitsLeaveFewerStuckFacets) { gdel::test::gflip_independent_splits_cases(gdel::Backend::Cpu); }
TEST(GFlip3DCpu, ExactFormsWithoutScratchAndTieredPass) {
  gdel::test::geo_scratch_free_cases<gdel::par::Cpu>(0x1p21);  // Geo::int_points
  gdel::test::geo_scratch_free_cases<gdel::par::Cpu>(0x1p19);  // Geo::int_all
}
