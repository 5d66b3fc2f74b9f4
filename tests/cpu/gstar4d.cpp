#include "common/gstar4d_cases.hpp"
TEST(GStar4DCpu, AllGenerators) { gdel::test::gstar4d_generator_cases(gdel::Backend::Cpu, 1500); }
