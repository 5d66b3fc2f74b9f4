// gStar4D stages 3-5 (src/star4d/star_stage.hpp) on their own, shared by the CPU and GPU
// test programs: from ANY working sets (good ones: k nearest neighbours; poor ones: a
// few random points) star splaying must reach exactly the triangulation that gdel3d
// computes (same symbolic perturbation, so the same tets even on degenerate input),
// with complete adjacency.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "common/gdel3d_cases.hpp"
#include "flip/gflip3d.hpp"
#include "mesh/canonical.hpp"
#include "star4d/star_stage.hpp"

namespace gdel::test {

enum class WorkingSets { Nearest, Random, NearestPlusRandom };

// Working sets by brute force: the k nearest points, or k random other points.
inline std::vector<std::int64_t> toy_working_sets(const std::vector<double>& pts, WorkingSets kind, int k,
                                                  std::vector<vid_t>& cand) {
  const std::int64_t n = static_cast<std::int64_t>(pts.size() / 3);
  std::vector<std::int64_t> off(n + 1, 0);
  cand.clear();
  std::mt19937_64 rng(99);
  for (std::int64_t v = 0; v < n; ++v) {
    std::vector<std::pair<double, vid_t>> d;
    if (kind != WorkingSets::Random) {
      for (std::int64_t u = 0; u < n; ++u) {
        if (u == v) continue;
        double s = 0;
        for (int c = 0; c < 3; ++c) s += (pts[3 * u + c] - pts[3 * v + c]) * (pts[3 * u + c] - pts[3 * v + c]);
        d.push_back({s, static_cast<vid_t>(u)});
      }
      std::partial_sort(d.begin(), d.begin() + std::min<std::int64_t>(k, n - 1), d.end());
      d.resize(static_cast<std::size_t>(std::min<std::int64_t>(k, n - 1)));
      if (kind == WorkingSets::NearestPlusRandom)
        for (int r = 0; r < 2; ++r) {
          const vid_t u = static_cast<vid_t>(rng() % n);
          bool dup = u == v;
          for (auto& e : d) dup = dup || e.second == u;
          if (!dup) d.push_back({0.0, u});
        }
    } else {
      while (static_cast<int>(d.size()) < std::min<std::int64_t>(k, n - 1)) {
        const vid_t u = static_cast<vid_t>(rng() % n);
        bool dup = u == v;
        for (auto& e : d) dup = dup || e.second == u;
        if (!dup) d.push_back({0.0, u});
      }
    }
    for (auto& e : d) cand.push_back(e.second);
    off[v + 1] = static_cast<std::int64_t>(cand.size());
  }
  return off;
}

// Runs stages 3-5 on distinct points (internal id = input id = SoS index).
template <class B>
std::vector<std::array<std::int64_t, 4>> star_stage_tets(const std::vector<double>& pts, WorkingSets kind, int k,
                                                         star4d::StarStageResult* res = nullptr,
                                                         std::vector<std::int32_t>* nbr_out = nullptr) {
  const std::int64_t n = static_cast<std::int64_t>(pts.size() / 3);
  par::Context<B> ctx;
  par::Buffer<double, B> P(ctx);
  std::vector<double> p1 = pts;
  p1.insert(p1.end(), {0.0, 0.0, 0.0});
  P.assign(p1.data(), p1.size());
  std::vector<std::int64_t> sid_h(n + 1);
  for (std::int64_t i = 0; i <= n; ++i) sid_h[i] = i;
  par::Buffer<std::int64_t, B> sid(ctx);
  sid.assign(sid_h.data(), sid_h.size());
  Stats st;
  flip::GFlip3D<B> seed(ctx, P, sid, n, flip::FlipConfig{}, st);
  vid_t t0[4];
  seed.first_tetrahedron(t0);  // sets the kernel point (slot n)
  const flip::Geo g{P.data(), sid.data(), static_cast<vid_t>(n)};
  std::vector<vid_t> cand_h;
  auto off_h = toy_working_sets(pts, kind, k, cand_h);
  par::Buffer<std::int64_t, B> off(ctx);
  off.assign(off_h.data(), off_h.size());
  par::Buffer<vid_t, B> cand(ctx);
  cand.assign(cand_h.data(), std::max<std::size_t>(cand_h.size(), 1));
  star4d::StarStage<B> stage(ctx, g, n);
  stage.splay(off.data(), cand.data());
  par::Buffer<vid_t, B> tv(ctx);
  par::Buffer<std::int32_t, B> tn(ctx);
  stage.extract(tv, tn);
  if (res) *res = stage.result();
  auto th = tv.to_host();
  std::vector<std::array<std::int64_t, 4>> tets(th.size() / 4);
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (int c = 0; c < 4; ++c) tets[i][c] = th[4 * i + c];
  if (nbr_out) *nbr_out = tn.to_host();
  return tets;
}

template <class B>
void star_stage_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Grid,
                         Distribution::Sphere, Distribution::Ball}) {
    auto pts = gen::generate(d, n, 2024);
    Options o;
    o.backend = b;
    Triangulation ref = delaunay(pts, o);
    if (ref.stats.distinct_points != static_cast<std::int64_t>(n)) continue;  // the helper needs distinct points
    std::vector<std::array<std::int64_t, 4>> want(ref.tets.size() / 4);
    for (std::size_t i = 0; i < want.size(); ++i)
      for (int c = 0; c < 4; ++c) want[i][c] = ref.tets[4 * i + c];
    canonicalize(want);
    for (auto [kind, k] : {std::pair{WorkingSets::Nearest, 8}, std::pair{WorkingSets::Random, 4}}) {
      SCOPED_TRACE(std::string(gen::to_string(d)) + (kind == WorkingSets::Nearest ? " nearest" : " random"));
      star4d::StarStageResult res;
      std::vector<std::int32_t> nbr;
      auto got = star_stage_tets<B>(pts, kind, k, &res, &nbr);
      Triangulation t;
      for (auto& x : got)
        for (int c = 0; c < 4; ++c) t.tets.push_back(static_cast<std::int32_t>(x[c]));
      t.neighbors = nbr;
      t.stats.algorithm = "gdel3d";  // expect_exact_delaunay's label check
      expect_exact_delaunay(pts, t, b);
      canonicalize(got);
      EXPECT_EQ(got, want) << "rounds " << res.splay.rounds << ", insertions " << res.splay.insertions;
    }
  }
}

}  // namespace gdel::test
