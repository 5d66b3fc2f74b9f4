#include "common/pba_cases.hpp"

using Ctx = gdel::par::Context<gdel::par::Cuda>;

TEST(PbaGpu, BruteForce) {
  Ctx ctx;
  gdel::test::pba_brute_force_cases(ctx);
}
TEST(PbaGpu, BandAgreement) {
  Ctx ctx;
  gdel::test::pba_band_agreement_cases(ctx);
}
TEST(PbaGpu, DigitalVoronoi) {
  Ctx ctx;
  gdel::test::digital_voronoi_cases(ctx);
}
TEST(WorkingSetsGpu, Contract) {
  Ctx ctx;
  gdel::test::working_set_cases(ctx);
}
TEST(WorkingSetsGpu, DelaunayEdgeShare) {
  Ctx ctx;
  gdel::test::working_set_quality_case(ctx, 0.68);  // measured 0.7193 (CPU)
}
TEST(PbaGpu, Timing) {
  Ctx ctx;
  for (long long n : {100000LL, 1000000LL, 10000000LL}) gdel::test::pba_timing_case(ctx, n);
}
