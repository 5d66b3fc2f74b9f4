#include "common/greg3d_cases.hpp"
TEST(GReg3DCpu, GeneratorsAndWeightScales) { gdel::test::greg3d_generator_cases(gdel::Backend::Cpu, 1500); }
TEST(GReg3DCpu, EqualWeightsGiveDelaunay) { gdel::test::greg3d_equal_weights_case(gdel::Backend::Cpu, 1500); }
TEST(GReg3DCpu, MoleculeGridDuplicatesAndErrors) { gdel::test::greg3d_special_cases(gdel::Backend::Cpu); }
