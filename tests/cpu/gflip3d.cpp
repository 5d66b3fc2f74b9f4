#include "common/gflip_cases.hpp"
TEST(GFlip3DCpu, AllGenerators) { gdel::test::gflip_generator_cases(gdel::Backend::Cpu, 4000); }
TEST(GFlip3DCpu, DegenerateAndHostileInput) { gdel::test::gflip_degenerate_cases(gdel::Backend::Cpu); }
