#include "common/pba_cases.hpp"

using Ctx = gdel::par::Context<gdel::par::Cpu>;

TEST(PbaCpu, BruteForce) {
  Ctx ctx;
  gdel::test::pba_brute_force_cases(ctx);
}
TEST(PbaCpu, BandAgreement) {
  Ctx ctx;
  gdel::test::pba_band_agreement_cases(ctx);
}
TEST(PbaCpu, DigitalVoronoi) {
  Ctx ctx;
  gdel::test::digital_voronoi_cases(ctx);
}
TEST(WorkingSetsCpu, Contract) {
  Ctx ctx;
  gdel::test::working_set_cases(ctx);
}
TEST(WorkingSetsCpu, DelaunayEdgeShare) {
  Ctx ctx;
  gdel::test::working_set_quality_case(ctx, 0.68);  // measured 0.7193
}
// Timings for docs/gstar4d.md: --gtest_also_run_disabled_tests --gtest_filter='*Timing*'
TEST(PbaCpu, DISABLED_Timing) {
  Ctx ctx;
  for (long long n : {100000LL, 1000000LL}) gdel::test::pba_timing_case(ctx, n);
}
