// Parallel-layer test cases, written once over the backend tag and instantiated by
// tests/cpu/parallel.cpp (Cpu) and tests/gpu/parallel.cu (Cuda).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "parallel/atomic.hpp"
#include "parallel/primitives.hpp"
#include "parallel/team.hpp"
#include "sort/point_sort.hpp"

namespace gdel::test {

template <class B>
struct IsOdd {
  GDEL_HD bool operator()(std::int64_t x) const { return (x & 1) != 0; }
};

// par::team_run: a team's sums, selection and barrier (gFlip3D's small flip iterations
// rely on them) against the host, over sizes around the team's width (one and several
// chunks of 1 024 on the GPU).
template <class B>
void team_cases(par::Context<B>& ctx) {
  using namespace gdel::par;
  std::mt19937_64 rng(7);
  for (std::int64_t n : {0, 1, 1023, 1024, 1025, 5000}) {
    SCOPED_TRACE(n);
    std::vector<std::int64_t> h(static_cast<std::size_t>(n));
    for (auto& x : h) x = static_cast<std::int64_t>(rng() % 1000);
    Buffer<std::int64_t, B> a(ctx);
    a.assign(h);
    const std::size_t sz = static_cast<std::size_t>(n) + 1;
    Buffer<std::int64_t, B> scan(ctx, sz), mirror(ctx, sz), out(ctx, 2);
    Buffer<std::int32_t, B> idx(ctx, sz);
    const std::int64_t* ap = a.data();
    std::int64_t* sp = scan.data();
    std::int64_t* mp = mirror.data();
    std::int64_t* op = out.data();
    std::int32_t* ip = idx.data();
    auto third = [=] GDEL_LAMBDA(std::int64_t i) { return ap[i] % 3 == 0; };
    team_run(ctx, [=] GDEL_LAMBDA(const Team& tm) {
      // a whole exclusive scan, chunk by chunk
      std::int64_t base = 0;
      for (std::int64_t i0 = 0; i0 < n; i0 += tm.size()) {
        const std::int64_t i = i0 + tm.rank();
        std::int64_t total = 0;
        const std::int64_t at = tm.exclusive_sum(i < n ? ap[i] : 0, &total);
        if (i < n) sp[i] = base + at;
        base += total;
      }
      tm.sync();
      // each thread reads what others wrote before the barrier
      for (std::int64_t i = tm.rank(); i < n; i += tm.size()) mp[i] = sp[n - 1 - i];
      const std::int64_t k = team_select(tm, n, ip, third);
      if (tm.rank() == 0) {
        op[0] = base;
        op[1] = k;
      }
    });
    std::vector<std::int64_t> ref(h.size());
    std::exclusive_scan(h.begin(), h.end(), ref.begin(), std::int64_t(0));
    std::vector<std::int32_t> ridx;
    for (std::int64_t i = 0; i < n; ++i)
      if (h[static_cast<std::size_t>(i)] % 3 == 0) ridx.push_back(static_cast<std::int32_t>(i));
    const auto o = out.to_host();
    EXPECT_EQ(o[0], std::accumulate(h.begin(), h.end(), std::int64_t(0)));
    ASSERT_EQ(o[1], static_cast<std::int64_t>(ridx.size()));
    auto sh = scan.to_host(), mh = mirror.to_host();
    auto ih = idx.to_host();
    sh.resize(h.size());
    mh.resize(h.size());
    ih.resize(ridx.size());
    EXPECT_EQ(sh, ref);
    std::reverse(ref.begin(), ref.end());
    EXPECT_EQ(mh, ref);
    EXPECT_EQ(ih, ridx);
  }
}

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
    std::size_t k = select_indices(ctx, n, idx.data(), [=] GDEL_LAMBDA(std::int32_t i) { return (ap[i] % 3) == 0; });
    std::vector<std::int32_t> ridx;
    for (std::size_t i = 0; i < n; ++i)
      if (h[i] % 3 == 0) ridx.push_back(static_cast<std::int32_t>(i));
    ASSERT_EQ(k, ridx.size());
    auto ih = idx.to_host();
    ih.resize(k);
    EXPECT_EQ(ih, ridx);
    // the same selection with its count left on the backend, and loops cut by that count
    // below a bound the host knows (gFlip3D's iterations: one wait for several counts)
    {
      Buffer<std::int64_t, B> c(ctx, 1);
      std::int64_t* cp = c.data();
      Buffer<std::int32_t, B> idx2(ctx, n);
      select_indices_to(ctx, n, idx2.data(), cp, [=] GDEL_LAMBDA(std::int32_t i) { return (ap[i] % 3) == 0; });
      ASSERT_EQ(c.get(0), static_cast<std::int64_t>(k));
      auto ih2 = idx2.to_host();
      ih2.resize(k);
      EXPECT_EQ(ih2, ridx);
      for (std::int64_t bound : {static_cast<std::int64_t>(n), static_cast<std::int64_t>(n / 7)}) {
        Buffer<std::int8_t, B> hit(ctx, std::max<std::size_t>(n, 1));
        hit.memset(0);
        std::int8_t* hp = hit.data();
        parallel_for_counted(ctx, bound, cp, [=] GDEL_LAMBDA(std::int64_t i) { hp[i] += 1; });
        const auto hh = hit.to_host();
        const std::int64_t want = std::min<std::int64_t>(bound, static_cast<std::int64_t>(k));
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hh[i], static_cast<std::int64_t>(i) < want ? 1 : 0) << i;
      }
    }
    // a selection of mapped values (the map applied once, the kept values in index order)
    {
      Buffer<std::int64_t, B> c(ctx, 1);
      Buffer<std::int32_t, B> val(ctx, std::max<std::size_t>(n, 1));
      select_mapped_to(
          ctx, n, val.data(), c.data(),
          [=] GDEL_LAMBDA(std::int64_t i) { return (ap[i] % 3) == 0 ? static_cast<std::int32_t>(2 * i + 1) : std::int32_t(-1); },
          [=] GDEL_LAMBDA(std::int32_t v) { return v >= 0; });
      ASSERT_EQ(c.get(0), static_cast<std::int64_t>(k));
      auto vh = val.to_host();
      vh.resize(k);
      for (std::size_t j = 0; j < k; ++j) ASSERT_EQ(vh[j], 2 * ridx[j] + 1) << j;
    }
    // counting the same selection (to size an output exactly)
    EXPECT_EQ(count_indices(ctx, n, [=] GDEL_LAMBDA(std::int64_t i) { return (ap[i] % 3) == 0; }),
              static_cast<std::int64_t>(ridx.size()));
    EXPECT_EQ(count_indices(ctx, 0, [=] GDEL_LAMBDA(std::int64_t i) { return ap[i] >= 0; }), 0);

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

    // sort pairs on buffers: stable over the first m elements, the buffers' tails kept;
    // 20-bit keys take three radix passes on CUDA, so there the buffers take the sort's
    // alternate arrays
    {
      const std::size_t m = n, len = n + 3;
      std::vector<std::uint32_t> k2(len);
      for (auto& x : k2) x = static_cast<std::uint32_t>(rng() % 4096) << 8;  // ties in all 20 bits
      Buffer<std::uint32_t, B> k2b(ctx);
      k2b.assign(k2);
      Buffer<std::int32_t, B> v2b(ctx, len);
      sequence(ctx, v2b.data(), len, std::int32_t(0));
      sort_pairs(ctx, k2b, v2b, m, 20);
      std::vector<std::int32_t> p2(len);
      std::iota(p2.begin(), p2.end(), 0);
      std::stable_sort(p2.begin(), p2.begin() + static_cast<std::ptrdiff_t>(m),
                       [&](int x, int y) { return k2[x] < k2[y]; });
      std::vector<std::uint32_t> s2(len);
      for (std::size_t i = 0; i < len; ++i) s2[i] = k2[p2[i]];
      ASSERT_EQ(k2b.size(), len);
      ASSERT_EQ(v2b.size(), len);
      EXPECT_EQ(v2b.to_host(), p2);
      EXPECT_EQ(k2b.to_host(), s2);
    }

    // unique after sort
    std::size_t u = unique(ctx, kb.data(), n);
    std::vector<std::uint64_t> uk = sk;
    uk.erase(std::unique(uk.begin(), uk.end()), uk.end());
    ASSERT_EQ(u, uk.size());
    auto ukh = kb.to_host();
    ukh.resize(u);
    EXPECT_EQ(ukh, uk);

    // atomics: histogram with atomic_add, atomic_min per bucket, and the maximum per
    // bucket through atomic_raise (every item of a bucket on one address) and over all
    // items on one address
    Buffer<std::int32_t, B> hist(ctx, 64);
    hist.memset(0);
    Buffer<std::int64_t, B> mins(ctx, 64);
    fill(ctx, mins.data(), 64, std::int64_t(1) << 50);
    Buffer<std::int64_t, B> maxs(ctx, 65);
    fill(ctx, maxs.data(), 65, std::int64_t(-1));
    std::int32_t* hp = hist.data();
    std::int64_t* mp = mins.data();
    std::int64_t* xp = maxs.data();
    const std::uint64_t* kp = kb.data();
    (void)kp;
    parallel_for(ctx, static_cast<std::int64_t>(n), [=] GDEL_LAMBDA(std::int64_t i) {
      int bucket = static_cast<int>(ap[i] % 64);
      atomic_add(hp + bucket, 1);
      atomic_min(mp + bucket, ap[i]);
      atomic_raise(xp + bucket, ap[i]);
      atomic_raise(xp + 64, ap[i]);
    });
    std::vector<std::int32_t> rh(64, 0);
    std::vector<std::int64_t> rm(64, std::int64_t(1) << 50);
    std::vector<std::int64_t> rx(65, -1);
    for (auto x : h) {
      rh[x % 64]++;
      rm[x % 64] = std::min(rm[x % 64], x);
      rx[x % 64] = std::max(rx[x % 64], x);
      rx[64] = std::max(rx[64], x);
    }
    EXPECT_EQ(hist.to_host(), rh);
    EXPECT_EQ(mins.to_host(), rm);
    EXPECT_EQ(maxs.to_host(), rx);

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


// sort::distinct_hilbert_order against brute force: representatives (smallest index, or
// the heaviest with weights), each distinct point once, in key order and lexicographic
// order within a key. Inputs with many key ties: clusters far below the box's cell size
// (a huge range), with duplicates inside and outside the clusters.
template <class B>
void distinct_order_cases(par::Context<B>& ctx) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int variant = 0; variant < 6; ++variant) {
    SCOPED_TRACE(variant);
    const bool weighted = variant % 2 == 1;
    std::vector<double> X;
    auto push = [&](double x, double y, double z) { X.insert(X.end(), {x, y, z}); };
    const int n0 = variant < 2 ? 20000 : 3000;
    for (int i = 0; i < n0; ++i) {
      if (variant >= 4) push(std::ldexp(u(rng), -60), std::ldexp(u(rng), -60), 0.0);  // all in a few cells
      else if (variant >= 2 && i % 3 == 0) push(1.0 + std::ldexp(u(rng), -50), 2.0, std::ldexp(u(rng), -50));
      else push(u(rng), u(rng), u(rng));
    }
    push(1e9, -1e9, 1e9);  // the range
    push(-1e9, 1e9, -1e9);
    const std::size_t base = X.size() / 3;
    for (std::size_t i = 0; i < base / 4; ++i) {  // duplicates of random earlier points
      const std::size_t j = rng() % (X.size() / 3);
      push(X[3 * j], X[3 * j + 1], X[3 * j + 2]);
    }
    X[3 * 5] = -0.0;  // -0 equals +0
    X[3 * 6] = 0.0;
    X[3 * 6 + 1] = X[3 * 5 + 1];
    X[3 * 6 + 2] = X[3 * 5 + 2];
    const std::int64_t n = static_cast<std::int64_t>(X.size() / 3);
    std::vector<double> w(static_cast<std::size_t>(n));
    for (auto& x : w) x = static_cast<double>(rng() % 4);  // ties among the heaviest too
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = hi[a] = X[a];
      for (std::int64_t i = 0; i < n; ++i) {
        lo[a] = std::min(lo[a], X[3 * i + a]);
        hi[a] = std::max(hi[a], X[3 * i + a]);
      }
    }
    par::Buffer<double, B> Xd(ctx), Wd(ctx);
    Xd.assign(X);
    Wd.assign(w);
    par::Buffer<std::int64_t, B> rep(ctx, static_cast<std::size_t>(n)), order(ctx, static_cast<std::size_t>(n));
    const std::int64_t m = sort::distinct_hilbert_order(ctx, Xd.data(), n, lo, hi, rep.data(), order.data(),
                                                        weighted ? Wd.data() : nullptr);
    const auto rh = rep.to_host();
    auto oh = order.to_host();
    oh.resize(static_cast<std::size_t>(m));
    // brute force: groups of equal points by a lexicographic sort of the indices
    auto eq = [&](std::int64_t a, std::int64_t b) {
      return X[3 * a] == X[3 * b] && X[3 * a + 1] == X[3 * b + 1] && X[3 * a + 2] == X[3 * b + 2];
    };
    auto less = [&](std::int64_t a, std::int64_t b) {
      for (int k = 0; k < 3; ++k)
        if (X[3 * a + k] != X[3 * b + k]) return X[3 * a + k] < X[3 * b + k];
      return false;
    };
    std::vector<std::int64_t> idx(static_cast<std::size_t>(n));
    std::iota(idx.begin(), idx.end(), std::int64_t(0));
    std::stable_sort(idx.begin(), idx.end(), less);
    std::vector<std::int64_t> want(static_cast<std::size_t>(n)), reps;
    for (std::size_t s = 0; s < idx.size();) {
      std::size_t e = s + 1;
      while (e < idx.size() && eq(idx[s], idx[e])) ++e;
      std::int64_t best = idx[s];
      for (std::size_t j = s; j < e; ++j)
        if (weighted && w[static_cast<std::size_t>(idx[j])] > w[static_cast<std::size_t>(best)]) best = idx[j];
      for (std::size_t j = s; j < e; ++j) want[static_cast<std::size_t>(idx[j])] = best;
      reps.push_back(best);
      s = e;
    }
    ASSERT_EQ(m, static_cast<std::int64_t>(reps.size()));
    EXPECT_EQ(rh, want);
    std::vector<std::int64_t> sorted = oh;
    std::sort(sorted.begin(), sorted.end());
    std::sort(reps.begin(), reps.end());
    EXPECT_EQ(sorted, reps);  // each distinct point once, by its representative
    const sfc::Quantizer q = sfc::Quantizer::from_box(lo, hi);
    auto key = [&](std::int64_t i) { return sfc::hilbert_key(q, X[3 * i], X[3 * i + 1], X[3 * i + 2]); };
    std::int64_t ties = 0;
    for (std::size_t k = 1; k < oh.size(); ++k) {
      const auto a = key(oh[k - 1]), b = key(oh[k]);
      ASSERT_LE(a, b) << k;
      if (a == b) {
        ++ties;
        EXPECT_TRUE(less(oh[k - 1], oh[k])) << k;
      }
    }
    if (variant >= 2) {
      EXPECT_GT(ties, 100);  // the clusters share cells: the tie path ran
    }
  }
}

}  // namespace gdel::test
