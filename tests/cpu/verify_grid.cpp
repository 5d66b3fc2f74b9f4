#include "common/verify_grid_cases.hpp"
TEST(VerifyCpu, KuhnGridAndCorruptions) { gdel::test::kuhn_grid_cases(gdel::Backend::Cpu); }
TEST(VerifyCpu, ChunkedSortsGiveTheSameReport) { gdel::test::chunked_cases(gdel::Backend::Cpu); }
