#include "common/mesh_cases.hpp"
TEST(MeshCpu, SlotsAdjacencyCompaction) {
  gdel::par::Context<gdel::par::Cpu> ctx;
  gdel::test::tet_mesh_cases(ctx, /*gather=*/false);
  gdel::test::tet_mesh_cases(ctx, /*gather=*/true);
}
