#include "common/model_cases.hpp"
TEST(ModelsCpu, ScannedModelsGiveValidTriangulations) { gdel::test::model_cases(gdel::Backend::Cpu); }
