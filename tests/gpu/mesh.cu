#include "common/mesh_cases.hpp"
TEST(MeshGpu, SlotsAdjacencyCompaction) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  for (bool gather : {false, true})
    for (bool whole : {false, true}) gdel::test::tet_mesh_cases(ctx, gather, whole);
}
