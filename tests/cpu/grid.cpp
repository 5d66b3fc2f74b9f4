#include "common/grid_cases.hpp"
TEST(GridInitialCpu, AllGenerators) { gdel::test::grid_initial_generator_cases(gdel::Backend::Cpu, 3000); }
TEST(GridDualCpu, HandMadeColourings) { gdel::test::grid_dual_cases<gdel::par::Cpu>(); }
