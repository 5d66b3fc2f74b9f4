#include "common/parallel_cases.hpp"

#include <atomic>
#include <stdexcept>
#include <vector>

#include "parallel/host_threads.hpp"

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
// par::on_host_threads: every index once, on several threads; an exception in a job is
// rethrown after the join and stops the hand-out of the remaining indices.
TEST(ParallelCpu, OnHostThreads) {
  std::vector<std::atomic<int>> hits(1000);
  gdel::par::on_host_threads(hits.size(), [&](std::size_t i) { hits[i].fetch_add(1); }, 4);
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
  std::atomic<int> ran{0};
  EXPECT_THROW(gdel::par::on_host_threads(
                   100000,
                   [&](std::size_t i) {
                     ran.fetch_add(1);
                     if (i == 10) throw std::runtime_error("job 10");
                   },
                   2),
               std::runtime_error);
  EXPECT_LT(ran.load(), 100000);  // the rest was not handed out
  gdel::par::on_host_threads(0, [](std::size_t) { FAIL(); });
}
