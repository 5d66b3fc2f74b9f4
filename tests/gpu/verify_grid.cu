#include "common/verify_grid_cases.hpp"
TEST(VerifyGpu, KuhnGridAndCorruptionsMatchCpu) { gdel::test::kuhn_grid_cases(gdel::Backend::Cuda); }
TEST(VerifyGpu, ChunkedSortsGiveTheSameReport) { gdel::test::chunked_cases(gdel::Backend::Cuda); }
