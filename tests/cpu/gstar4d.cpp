#include "common/gstar4d_cases.hpp"
TEST(GStar4DCpu, AllGenerators) { gdel::test::gstar4d_generator_cases(gdel::Backend::Cpu, 10000); }
// Measurements on request: GDEL_MEASURE=grid:1e5,sphere:1e4,blade.off
TEST(GStar4DCpu, DISABLED_Measure) { gdel::test::gstar4d_measure(gdel::Backend::Cpu); }
