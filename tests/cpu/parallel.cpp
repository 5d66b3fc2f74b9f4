#include "common/parallel_cases.hpp"

TEST(ParallelCpu, Primitives) {
  gdel::par::Context<gdel::par::Cpu> ctx;
  gdel::test::parallel_layer_cases(ctx);
}
TEST(ParallelCpu, Buffers) {
  gdel::par::Context<gdel::par::Cpu> ctx;
  gdel::test::buffer_cases(ctx);
}
TEST(ParallelCpu, UniqueManyRuns) {
  gdel::par::Context<gdel::par::Cpu> ctx;
  gdel::test::unique_cases(ctx);
}
TEST(ParallelCpu, DistinctHilbertOrder) {
  gdel::par::Context<gdel::par::Cpu> ctx;
  gdel::test::distinct_order_cases(ctx);
}
