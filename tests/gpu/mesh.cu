#include "common/mesh_cases.hpp"
TEST(MeshGpu, SlotsAdjacencyCompaction) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::tet_mesh_cases(ctx, /*gather=*/false);
  gdel::test::tet_mesh_cases(ctx, /*gather=*/true);
}
