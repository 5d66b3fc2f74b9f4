#include "common/star_stage_cases.hpp"
TEST(StarStageCpu, AnyWorkingSetsGiveTheDelaunayTriangulation) {
  gdel::test::star_stage_cases<gdel::par::Cpu>(gdel::Backend::Cpu, 1000);
}
