#include "common/model_cases.hpp"
TEST(ModelsGpu, ScannedModelsGiveValidTriangulations) { gdel::test::model_cases(gdel::Backend::Cuda); }
