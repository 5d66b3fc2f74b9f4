#include "common/gflip_cases.hpp"
TEST(GFlip3DGpu, AllGenerators) { gdel::test::gflip_generator_cases(gdel::Backend::Cuda, 200000); }
TEST(GFlip3DGpu, DegenerateAndHostileInput) { gdel::test::gflip_degenerate_cases(gdel::Backend::Cuda); }
