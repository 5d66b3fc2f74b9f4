// Parallel-layer test cases, written once over the backend tag and instantiated by
// tests/cpu/parallel.cpp (Cpu) and tests/gpu/parallel.cu (Cuda).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "parallel/atomic.hpp"
#include "parallel/primitives.hpp"

namespace gdel::test {

template <class B>
struct IsOdd {
  GDEL_HD bool operator()(std::int64_t x) const { return (x & 1) != 0; }
};

template <class B>
void parallel_layer_cases(par::Context<B>& ctx) {
  using namespace gdel::par;
  std::mt19937_64 rng(42);
  // Sizes around block and tile boundaries.
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(255), std::size_t(257), std::size_t(100003),
                        std::size_t(1) << 20}) {
    SCOPED_TRACE(n);
    std::vector<std::int64_t> h(n);
    for (auto& x : h) x = static_cast<std::int64_t>(rng() % 1000003);
    Buffer<std::int64_t, B> a(ctx);
    a.assign(h);

    // exclusive / inclusive scan
    Buffer<std::int64_t, B> s(ctx, n);
    exclusive_scan(ctx, a.data(), s.data(), n);
    std::vector<std::int64_t> ref(n);
    std::exclusive_scan(h.begin(), h.end(), ref.begin(), std::int64_t(0));
    EXPECT_EQ(s.to_host(), ref);
    inclusive_scan(ctx, a.data(), s.data(), n);
    std::inclusive_scan(h.begin(), h.end(), ref.begin());
    EXPECT_EQ(s.to_host(), ref);

    // reductions
    EXPECT_EQ(reduce_sum(ctx, a.data(), n), std::accumulate(h.begin(), h.end(), std::int64_t(0)));
    EXPECT_EQ(reduce_max(ctx, a.data(), n, std::int64_t(-1)),
              n ? *std::max_element(h.begin(), h.end()) : std::int64_t(-1));
    EXPECT_EQ(reduce_min(ctx, a.data(), n, std::int64_t(1) << 40),
              n ? *std::min_element(h.begin(), h.end()) : std::int64_t(1) << 40);

    // compaction keeps order
    Buffer<std::int64_t, B> o(ctx, n);
    std::size_t m = copy_if(ctx, a.data(), o.data(), n, IsOdd<B>{});
    std::vector<std::int64_t> odd;
    std::copy_if(h.begin(), h.end(), std::back_inserter(odd), [](std::int64_t x) { return x & 1; });
    ASSERT_EQ(m, odd.size());
    auto oh = o.to_host();
    oh.resize(m);
    EXPECT_EQ(oh, odd);

    // indices selection
    const std::int64_t* ap = a.data();
    Buffer<std::int32_t, B> idx(ctx, n);
    std::size_t k = select_indices(ctx, n, idx.data(), [=] GDEL_HD(std::int32_t i) { return (ap[i] % 3) == 0; });
    std::vector<std::int32_t> ridx;
    for (std::size_t i = 0; i < n; ++i)
      if (h[i] % 3 == 0) ridx.push_back(static_cast<std::int32_t>(i));
    ASSERT_EQ(k, ridx.size());
    auto ih = idx.to_host();
    ih.resize(k);
    EXPECT_EQ(ih, ridx);
    // counting the same selection (to size an output exactly)
    EXPECT_EQ(count_indices(ctx, n, [=] GDEL_HD(std::int64_t i) { return (ap[i] % 3) == 0; }),
              static_cast<std::int64_t>(ridx.size()));
    EXPECT_EQ(count_indices(ctx, 0, [=] GDEL_HD(std::int64_t i) { return ap[i] >= 0; }), 0);

    // sort pairs is stable and sort keys sorts
    std::vector<std::uint64_t> keys(n);
    for (auto& x : keys) x = rng() % 64;  // many ties: stability matters
    Buffer<std::uint64_t, B> kb(ctx);
    kb.assign(keys);
    Buffer<std::int32_t, B> vb(ctx, n);
    sequence(ctx, vb.data(), n, std::int32_t(0));
    sort_pairs(ctx, kb.data(), vb.data(), n, 6);
    std::vector<std::int32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::stable_sort(perm.begin(), perm.end(), [&](int x, int y) { return keys[x] < keys[y]; });
    EXPECT_EQ(vb.to_host(), perm);
    std::vector<std::uint64_t> sk = keys;
    std::sort(sk.begin(), sk.end());
    EXPECT_EQ(kb.to_host(), sk);

    // unique after sort
    std::size_t u = unique(ctx, kb.data(), n);
    std::vector<std::uint64_t> uk = sk;
    uk.erase(std::unique(uk.begin(), uk.end()), uk.end());
    ASSERT_EQ(u, uk.size());
    auto ukh = kb.to_host();
    ukh.resize(u);
    EXPECT_EQ(ukh, uk);

    // atomics: histogram with atomic_add, atomic_min per bucket
    Buffer<std::int32_t, B> hist(ctx, 64);
    hist.memset(0);
    Buffer<std::int64_t, B> mins(ctx, 64);
    fill(ctx, mins.data(), 64, std::int64_t(1) << 50);
    std::int32_t* hp = hist.data();
    std::int64_t* mp = mins.data();
    const std::uint64_t* kp = kb.data();
    (void)kp;
    parallel_for(ctx, static_cast<std::int64_t>(n), [=] GDEL_HD(std::int64_t i) {
      int bucket = static_cast<int>(ap[i] % 64);
      atomic_add(hp + bucket, 1);
      atomic_min(mp + bucket, ap[i]);
    });
    std::vector<std::int32_t> rh(64, 0);
    std::vector<std::int64_t> rm(64, std::int64_t(1) << 50);
    for (auto x : h) {
      rh[x % 64]++;
      rm[x % 64] = std::min(rm[x % 64], x);
    }
    EXPECT_EQ(hist.to_host(), rh);
    EXPECT_EQ(mins.to_host(), rm);

    // counts -> offsets
    Buffer<std::int64_t, B> cnt(ctx, n + 1);
    cnt.assign(h.data(), n);
    cnt.resize(n + 1);
    std::int64_t total = counts_to_offsets(ctx, cnt.data(), n);
    EXPECT_EQ(total, std::accumulate(h.begin(), h.end(), std::int64_t(0)));
  }
}

// unique() on many small sorted arrays with runs of every length (the CPU version
// once relied on Thrust's in-place unique, which is racy on the OpenMP system).
template <class B>
void unique_cases(par::Context<B>& ctx) {
  std::mt19937 r(1);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + static_cast<int>(r() % 5000);
    std::vector<int> v(static_cast<std::size_t>(n));
    for (auto& x : v) x = static_cast<int>(r() % static_cast<unsigned>(n / 2 + 1)) - 1;
    par::Buffer<int, B> b(ctx);
    b.assign(v);
    par::sort_keys(ctx, b.data(), v.size());
    const std::size_t u = par::unique(ctx, b.data(), v.size());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    auto h = b.to_host();
    h.resize(u);
    ASSERT_EQ(h, v) << "trial " << trial << " n " << n;
  }
}

template <class B>
void buffer_cases(par::Context<B>& ctx) {
  using namespace gdel::par;
  std::size_t before = ctx.memory().current();
  {
    Buffer<int, B> b(ctx, 10);
    EXPECT_GE(ctx.memory().current(), before + 10 * sizeof(int));
    std::vector<int> h(10);
    std::iota(h.begin(), h.end(), 0);
    b.assign(h);
    b.resize(1000);  // growth keeps contents
    auto back = b.to_host();
    EXPECT_TRUE(std::equal(h.begin(), h.end(), back.begin()));
    EXPECT_EQ(b.get(7), 7);
    b.set(7, 70);
    EXPECT_EQ(b.get(7), 70);
    Buffer<int, B> moved(std::move(b));
    EXPECT_EQ(moved.size(), 1000u);
    EXPECT_EQ(b.size(), 0u);
    EXPECT_GE(ctx.memory().peak(), before + 1000 * sizeof(int));
  }
  EXPECT_EQ(ctx.memory().current(), before);  // everything returned
}

}  // namespace gdel::test
