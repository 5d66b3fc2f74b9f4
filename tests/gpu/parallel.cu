#include "common/parallel_cases.hpp"

TEST(ParallelGpu, Primitives) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::parallel_layer_cases(ctx);
}
TEST(ParallelGpu, Team) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::team_cases(ctx);
}
TEST(ParallelGpu, Buffers) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::buffer_cases(ctx);
}
TEST(ParallelGpu, OutOfMemoryIsReportedAndRecoverable) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  std::size_t huge = std::size_t(1) << 50;  // 1 PiB
  using CharBuf = gdel::par::Buffer<char, gdel::par::Cuda>;
  EXPECT_THROW(CharBuf(ctx, huge), gdel::OutOfDeviceMemory);
  gdel::par::Buffer<int, gdel::par::Cuda> ok(ctx, 1000);  // the context still works
  ok.memset(0);
  EXPECT_EQ(ok.get(999), 0);
}
TEST(ParallelGpu, UniqueManyRuns) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::unique_cases(ctx);
}
TEST(ParallelGpu, DistinctHilbertOrder) {
  gdel::par::Context<gdel::par::Cuda> ctx;
  gdel::test::distinct_order_cases(ctx);
}
