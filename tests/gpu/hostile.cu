#include "common/expect_error.hpp"
#include "common/gflip_cases.hpp"
#include "common/hostile_cases.hpp"
#include "gdel/device_memory.hpp"
#include "gdel/regular.hpp"
#include "parallel/device_pool.hpp"

#include <cuda_runtime.h>

#include <thread>
TEST(HostileGpu, PeersReportedFailures) { gdel::test::hostile_cases(gdel::Backend::Cuda); }
// With canonical_order both backends give bitwise identical arrays (issue 8: determinism).
TEST(HostileGpu, SameArraysAsTheCpuBackend) {
  for (const auto& s : gdel::test::hostile_sets()) {
    SCOPED_TRACE(s.name);
    for (auto a : {gdel::Algorithm::gdel3d, gdel::Algorithm::gstar4d}) {
      gdel::Options o;
      o.canonical_order = true;
      o.algorithm = a;
      o.backend = gdel::Backend::Cpu;
      const auto c = gdel::delaunay(s.pts, o);
      o.backend = gdel::Backend::Cuda;
      const auto g = gdel::delaunay(s.pts, o);
      EXPECT_EQ(c.tets, g.tets);
      EXPECT_EQ(c.neighbors, g.neighbors);
    }
  }
}
// gDel3D issue 6: 2*10^7 points crashed the original (26-bit tet ids).
TEST(HostileGpu, TwentyMillionPoints) {
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 20000000, 6);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  const auto t = gdel::delaunay(pts, o);
  gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
}
// Device memory: a shortage raises OutOfDeviceMemory naming needed and free bytes, leaks
// nothing (the next call in the process succeeds), and fallback_to_cpu answers on the CPU.
TEST(HostileGpu, OutOfDeviceMemoryIsCleanAndRecoverable) {
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 200000, 8);
  std::vector<double> w(200000, 0.0);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.canonical_order = true;
  o.device_memory_limit = std::size_t(4) << 20;  // 4 MiB: far too little
  if (auto e = gdel::test::expect_error<gdel::OutOfDeviceMemory>([&] { (void)gdel::delaunay(pts, o); },
                                                                 {"device_memory_limit"})) {
    EXPECT_GT(e->needed, 0u);
  }
  EXPECT_THROW(gdel::regular(pts, w, o), gdel::OutOfDeviceMemory);
  o.device_memory_limit = 0;
  const auto ok = gdel::delaunay(pts, o);  // same process, full device: succeeds
  gdel::test::expect_exact_delaunay(pts, ok, gdel::Backend::Cuda);
  o.device_memory_limit = std::size_t(4) << 20;
  o.fallback_to_cpu = true;
  const auto f = gdel::delaunay(pts, o);
  EXPECT_EQ(f.stats.backend.rfind("cpu (fallback", 0), 0u) << f.stats.backend;
  EXPECT_EQ(f.tets, ok.tets);
  const auto r = gdel::regular(pts, w, o);
  EXPECT_EQ(r.stats.backend.rfind("cpu (fallback", 0), 0u) << r.stats.backend;
}
// The memory estimate (gdel::estimated_device_bytes) is checked before any work: a limit
// just under it fails at once, naming the estimate; a limit just over it lets the run
// start. On 10^6 uniform points the estimate is within a factor of 2 of the measured
// peak, for gdel3d and gstar4d (bench/RESULTS.md has the per-point figures).
TEST(HostileGpu, MemoryEstimateIsCheckedBeforeStarting) {
  const std::int64_t n = 1000000;
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, static_cast<std::size_t>(n), 8);
  for (auto a : {gdel::Algorithm::gdel3d, gdel::Algorithm::gstar4d}) {
    gdel::Options o;
    o.backend = gdel::Backend::Cuda;
    o.algorithm = a;
    const std::size_t est = gdel::estimated_device_bytes(n, a);
    o.device_memory_limit = est - 1;
    if (auto e = gdel::test::expect_error<gdel::OutOfDeviceMemory>([&] { (void)gdel::delaunay(pts, o); }, {"estimated"},
                                                                   "a limit one byte under the estimate")) {
      EXPECT_EQ(e->needed, est);
    }
    o.device_memory_limit = 0;
    const auto t = gdel::delaunay(pts, o);
    std::printf("%s: estimate %zu bytes, measured peak %lld bytes\n", gdel::to_string(a), est,
                static_cast<long long>(t.stats.peak_bytes));
    EXPECT_LE(static_cast<double>(t.stats.peak_bytes), 2.0 * static_cast<double>(est));
    EXPECT_GE(2.0 * static_cast<double>(t.stats.peak_bytes), static_cast<double>(est));
  }
  std::vector<double> w(static_cast<std::size_t>(n), 0.0);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.device_memory_limit = gdel::estimated_device_bytes(n, gdel::Algorithm::Auto, true) - 1;
  EXPECT_THROW(gdel::regular(pts, w, o), gdel::OutOfDeviceMemory);
}
// Device memory kept between calls (gdel/device_memory.hpp), read on the shared pool
// itself (par::kept_pool_bytes) and on the driver: keep_device_memory(0) leaves the
// pool empty (also after the earlier tests of a GDEL_DEVICE_POOL=keep run) and a call
// then does not touch it; with no bound a call leaves at least half its peak reserved
// there and nothing in use, the next calls (two at once included) reuse it and give the
// same triangulation; a bound trims the pool under it, at once and after each call;
// release_device_memory() empties it and the driver gets that memory back; the setting
// stays until keep_device_memory(0).
TEST(HostileGpu, KeptDeviceMemoryIsBoundedAndReleased) {
  const std::size_t before = gdel::kept_device_memory_bound();
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 1000000, 9);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.canonical_order = true;
  auto pool = [] { return gdel::par::kept_pool_bytes(0); };
  auto free_now = [] {
    std::size_t f = 0, t = 0;
    EXPECT_EQ(cudaMemGetInfo(&f, &t), cudaSuccess);
    return static_cast<double>(f);
  };
  gdel::keep_device_memory(0);
  EXPECT_EQ(pool().used, 0u);
  EXPECT_EQ(pool().reserved, 0u);
  const auto ref = gdel::delaunay(pts, o);
  gdel::test::expect_exact_delaunay(pts, ref, gdel::Backend::Cuda);
  const double peak = static_cast<double>(ref.stats.peak_bytes);
  EXPECT_EQ(pool().reserved, 0u);  // a pool of the call's own

  gdel::keep_device_memory(~std::size_t(0));
  EXPECT_EQ(gdel::kept_device_memory_bound(), ~std::size_t(0));
  const auto a = gdel::delaunay(pts, o);
  const gdel::par::PoolBytes after_a = pool();
  EXPECT_GE(static_cast<double>(after_a.reserved), 0.5 * peak) << "peak " << peak;
  EXPECT_EQ(after_a.used, 0u);
  const auto b = gdel::delaunay(pts, o);
  EXPECT_LE(static_cast<double>(pool().reserved), 1.5 * static_cast<double>(after_a.reserved));
  EXPECT_EQ(a.tets, ref.tets);
  EXPECT_EQ(b.tets, ref.tets);
  EXPECT_EQ(b.neighbors, ref.neighbors);
  {  // two calls at once on the shared pool
    gdel::Triangulation t1, t2;
    std::thread th([&] { t1 = gdel::delaunay(pts, o); });
    t2 = gdel::delaunay(pts, o);
    th.join();
    EXPECT_EQ(t1.tets, ref.tets);
    EXPECT_EQ(t2.tets, ref.tets);
    EXPECT_EQ(pool().used, 0u);
  }
  const std::size_t bound = std::size_t(128) << 20;
  gdel::keep_device_memory(bound);  // trims now
  EXPECT_LE(pool().reserved, bound);
  const auto c = gdel::delaunay(pts, o);  // and after the call
  EXPECT_EQ(c.tets, ref.tets);
  EXPECT_LE(pool().reserved, bound);

  gdel::keep_device_memory(~std::size_t(0));
  (void)gdel::delaunay(pts, o);
  const double kept = static_cast<double>(pool().reserved), free_kept = free_now();
  EXPECT_GE(kept, 0.5 * peak);
  gdel::release_device_memory();
  EXPECT_EQ(pool().reserved, 0u);
  EXPECT_GE(free_now(), free_kept + 0.5 * kept);  // the driver has it back
  EXPECT_EQ(gdel::kept_device_memory_bound(), ~std::size_t(0));  // the setting stays
  (void)gdel::delaunay(pts, o);
  EXPECT_GE(static_cast<double>(pool().reserved), 0.5 * peak);
  gdel::keep_device_memory(0);
  EXPECT_EQ(pool().reserved, 0u);
  gdel::keep_device_memory(before);
}
// GDEL_POOL_PRIME=1 (a study: the call's pool maps the memory estimate at once) changes
// no flip and no output (gflip3d on the flip studies' inputs), and no prime is made past
// a device_memory_limit (the precheck refuses first).
TEST(HostileGpu, PoolPrimeChangesNothing) {
  gdel::test::knob_same_output_cases(gdel::Backend::Cuda, 200000, "GDEL_POOL_PRIME", "1");
  auto pts = gdel::gen::generate(gdel::gen::Distribution::Uniform, 300000, 10);
  gdel::Options o;
  o.backend = gdel::Backend::Cuda;
  o.device_memory_limit = std::size_t(4) << 20;
  ASSERT_EQ(::setenv("GDEL_POOL_PRIME", "1", 1), 0);
  EXPECT_THROW((void)gdel::delaunay(pts, o), gdel::OutOfDeviceMemory);
  o.device_memory_limit = 0;
  const auto t = gdel::delaunay(pts, o);
  ::unsetenv("GDEL_POOL_PRIME");
  gdel::test::expect_exact_delaunay(pts, t, gdel::Backend::Cuda);
}
