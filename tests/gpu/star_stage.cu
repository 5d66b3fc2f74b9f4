#include "common/star_stage_cases.hpp"
TEST(StarStageGpu, AnyWorkingSetsGiveTheDelaunayTriangulation) {
  gdel::test::star_stage_cases<gdel::par::Cuda>(gdel::Backend::Cuda, 1500);
}
