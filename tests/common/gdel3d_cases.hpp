// gDel3D cases shared by the CPU and GPU test programs: the exact Delaunay
// triangulation (gFlip3D + star-splaying repair) of every generator passes every check
// of the exact verifier, has no flat tet, and is the same on every run.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <cstdlib>
#include <utility>
#include <vector>

#include "common/gflip_cases.hpp"

namespace gdel::test {

inline void gdel3d_generator_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Grid,
                         Distribution::Sphere, Distribution::Ball, Distribution::SkewLines}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    const std::size_t nn = d == Distribution::SkewLines ? std::min<std::size_t>(n / 10, 400) : n;
    auto pts = gen::generate(d, nn, 4321);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    Triangulation t = delaunay(pts, o);
    expect_exact_delaunay(pts, t, b);
    // deterministic across runs (degenerate inputs included)
    Triangulation t2 = delaunay(pts, o);
    EXPECT_EQ(t.tets, t2.tets);
    EXPECT_EQ(t.neighbors, t2.neighbors);
    // the parallel rounds + repair give the same triangulation (on the CPU backend the
    // default inserts one point per round, with no repair; the GPU ignores cpu_rounds)
    o.cpu_rounds = true;
    Triangulation r = delaunay(pts, o);
    expect_exact_delaunay(pts, r, b);
    EXPECT_EQ(r.tets, t.tets);
    EXPECT_EQ(r.neighbors, t.neighbors);
  }
}

// Issue 4's sizes: every generator except the skew lines at each size of `sizes`, with the
// default options (Algorithm::Auto: gdel3d). The skew lines have Theta(n^2) tets (10^6
// points: 2.5e11 tets, terabytes of output for any program) and get their own closed-form
// test at the largest size that fits a test run.
inline void gdel3d_scale_cases(Backend b, std::initializer_list<std::size_t> sizes) {
  using gen::Distribution;
  for (std::size_t n : sizes)
    for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Grid,
                           Distribution::Sphere, Distribution::Ball}) {
      SCOPED_TRACE(std::string(gen::to_string(d)) + " " + std::to_string(n));
      auto pts = gen::generate(d, n, 2026);
      Options o;
      o.backend = b;
      Triangulation t = delaunay(pts, o);
      expect_exact_delaunay(pts, t, b);  // verifier: valid, every facet LD, all points used
    }
}

// The repair's host work on huge stars (on the CUDA backend: building the stars whose
// working sets exceed 48 points, and the splaying rounds' insertions into stars of over
// 96 triangles, at most 4 stars per host thread each time) gives the same triangulation
// as the in-kernel work: forced here for every star over 8 points and every insertion
// into a star of over 16 triangles (GDEL_HOST_STAR_MIN, no cap), on grid and sphere
// points; both host paths must have run. With a cap of 3 stars per build or round
// (GDEL_HOST_STAR_CAP) fewer stars go to the host, and the result is again the same;
// with the gate (GDEL_HOST_STAR_GATE) above every star, none goes, and again the same.
inline void gdel3d_host_star_case(Backend b) {
  for (auto d : {gen::Distribution::Grid, gen::Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, d == gen::Distribution::Grid ? 100000 : 10000, 31);
    Options o;
    o.backend = b;
    o.cpu_rounds = true;  // the rounds leave stars to repair, also on the CPU
    Triangulation base = delaunay(pts, o);
    ::setenv("GDEL_HOST_STAR_MIN", "8", 1);
    ::setenv("GDEL_HOST_STAR_CAP", "1000000000", 1);
    Triangulation host = delaunay(pts, o);
    ::setenv("GDEL_HOST_STAR_CAP", "3", 1);
    Triangulation capped = delaunay(pts, o);
    ::unsetenv("GDEL_HOST_STAR_CAP");
    // the gate above every star: the host path never runs, and the kernel, whose
    // threshold host_pick raises to the largest star, builds and serves them all
    ::setenv("GDEL_HOST_STAR_GATE", "1000000000", 1);
    Triangulation gated = delaunay(pts, o);
    ::unsetenv("GDEL_HOST_STAR_GATE");
    ::unsetenv("GDEL_HOST_STAR_MIN");
    EXPECT_GT(host.stats.stars_built_on_host, 0);
    EXPECT_GT(host.stats.host_star_insertions, 0);
    EXPECT_GT(capped.stats.stars_built_on_host, 0);
    EXPECT_LT(capped.stats.stars_built_on_host, host.stats.stars_built_on_host);
    EXPECT_EQ(gated.stats.stars_built_on_host, 0);
    EXPECT_EQ(gated.stats.host_star_insertions, 0);
    EXPECT_EQ(gated.stats.stars_built, host.stats.stars_built);
    expect_exact_delaunay(pts, host, b);
    expect_exact_delaunay(pts, capped, b);
    expect_exact_delaunay(pts, gated, b);
    EXPECT_EQ(host.tets, base.tets);
    EXPECT_EQ(host.neighbors, base.neighbors);
    EXPECT_EQ(capped.tets, base.tets);
    EXPECT_EQ(capped.neighbors, base.neighbors);
    EXPECT_EQ(gated.tets, base.tets);
    EXPECT_EQ(gated.neighbors, base.neighbors);
  }
}

// Integer input: the exact evaluations without a scratch (flip::Geo::int_points /
// int_all: the tiered fast/exact pass of gFlip3D, and the star splaying engine without
// a scratch) give the same triangulation as every evaluation with its scratch
// (GDEL_EXACT_TIERS=0), exactly Delaunay. Grid (ties) and sphere (all cospherical).
inline void gdel3d_exact_tiers_case(Backend b) {
  for (auto d : {gen::Distribution::Grid, gen::Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, d == gen::Distribution::Grid ? 100000 : 10000, 37);
    Options o;
    o.backend = b;
    o.cpu_rounds = true;  // the rounds and the repair, also on the CPU
    ::setenv("GDEL_EXACT_TIERS", "0", 1);
    const Triangulation off = delaunay(pts, o);
    ::unsetenv("GDEL_EXACT_TIERS");
    const Triangulation on = delaunay(pts, o);
    EXPECT_GT(on.stats.repair_failed_vertices, 0);  // the repair ran
    expect_exact_delaunay(pts, on, b);
    EXPECT_EQ(on.tets, off.tets);
    EXPECT_EQ(on.neighbors, off.neighbors);
  }
}

// One point per round (the CPU backend's default, flip/sequential.hpp) on several
// threads: each insertion is a transaction that is undone and deferred when it meets
// another thread's tets. Forced here with 4 threads, every round of over 64 points run in
// parallel, a conflict forced at every 50th tet taken, blocks kept for 4 points or
// released after each (GDEL_CPU_*): insertions must have been deferred, and the
// triangulation must be the one of a single thread and of the parallel rounds + repair,
// exactly Delaunay. gdel3d inserts by cavities; the forced run is repeated with split +
// flips (GDEL_CPU_INSERT=flip, gflip3d's way). Uniform, grid (exact ties) and sphere
// (cospherical) points.
inline void gdel3d_threads_case(Backend b) {
  for (auto d : {gen::Distribution::Uniform, gen::Distribution::Grid, gen::Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, 30000, 17);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    ::setenv("GDEL_CPU_THREADS", "1", 1);
    const Triangulation one = delaunay(pts, o);
    ::setenv("GDEL_CPU_THREADS", "4", 1);
    ::setenv("GDEL_CPU_PARALLEL_MIN", "64", 1);
    ::setenv("GDEL_CPU_FORCE_CONFLICT", "50", 1);
    const Triangulation four = delaunay(pts, o);
    ::setenv("GDEL_CPU_INSERT", "flip", 1);  // split + flips instead of the cavities (FlipConfig::cavity)
    const Triangulation four_flips = delaunay(pts, o);
    ::unsetenv("GDEL_CPU_INSERT");
    ::unsetenv("GDEL_CPU_FORCE_CONFLICT");
    const Triangulation natural = delaunay(pts, o);  // conflicts only where threads meet
    ::setenv("GDEL_CPU_HOLD", "1", 1);               // blocks released after every point
    const Triangulation hold1 = delaunay(pts, o);
    ::unsetenv("GDEL_CPU_HOLD");
    ::unsetenv("GDEL_CPU_PARALLEL_MIN");
    ::unsetenv("GDEL_CPU_THREADS");
    o.cpu_rounds = true;
    const Triangulation rounds = delaunay(pts, o);
    SCOPED_TRACE(four.stats.to_string());
    EXPECT_EQ(one.stats.points_deferred, 0);
    EXPECT_GT(four.stats.points_deferred, 0);
    EXPECT_EQ(four.stats.rounds, one.stats.rounds);  // every point inserted once
    expect_exact_delaunay(pts, four, b);
    expect_exact_delaunay(pts, natural, b);
    EXPECT_EQ(four.tets, one.tets);
    EXPECT_EQ(four.neighbors, one.neighbors);
    EXPECT_GT(four_flips.stats.points_deferred, 0);
    EXPECT_GT(four_flips.stats.flips23, 0);  // it flipped; the cavities do not
    EXPECT_EQ(four.stats.flips23 + four.stats.flips32, 0);
    EXPECT_EQ(four_flips.tets, one.tets);
    EXPECT_EQ(four_flips.neighbors, one.neighbors);
    EXPECT_EQ(natural.tets, one.tets);
    EXPECT_EQ(hold1.tets, one.tets);
    EXPECT_EQ(hold1.neighbors, one.neighbors);
    EXPECT_EQ(rounds.tets, one.tets);
    EXPECT_EQ(rounds.neighbors, one.neighbors);
  }
}

// Flip-Flop convexification of the failed stars (the default) and their rebuild by
// beneath-beyond insertion (GDEL_STAR_BUILD=rebuild) give the same triangulation: the
// convex star over a point set is unique. Flip-Flop must have made stars, and rebuilt none.
// With GDEL_FLIPFLOP_STEPS=0 every star takes the fallback (the rebuild after Flip-Flop
// gave up): the same triangulation again.
inline void gdel3d_flipflop_case(Backend b) {
  for (auto d : {gen::Distribution::Uniform, gen::Distribution::ThinShell, gen::Distribution::Grid,
                 gen::Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    auto pts = gen::generate(d, d == gen::Distribution::Sphere ? 20000 : 100000, 41);
    Options o;
    o.backend = b;
    o.canonical_order = true;  // the stars' triangles come in a different order
    o.cpu_rounds = true;       // the rounds leave stars to repair, also on the CPU
    Triangulation ff = delaunay(pts, o);
    EXPECT_GT(ff.stats.stars_flipflop, 0);
    EXPECT_EQ(ff.stats.stars_flipflop + ff.stats.stars_rebuilt, ff.stats.stars_built);
    EXPECT_EQ(ff.stats.stars_rebuilt, 0);
    ::setenv("GDEL_STAR_BUILD", "rebuild", 1);
    Triangulation rb = delaunay(pts, o);
    ::unsetenv("GDEL_STAR_BUILD");
    EXPECT_EQ(rb.stats.stars_flipflop, 0);
    EXPECT_EQ(rb.stats.stars_rebuilt, rb.stats.stars_built);
    expect_exact_delaunay(pts, ff, b);
    EXPECT_EQ(ff.tets, rb.tets);
    EXPECT_EQ(ff.neighbors, rb.neighbors);
    ::setenv("GDEL_FLIPFLOP_STEPS", "0", 1);
    Triangulation fb = delaunay(pts, o);
    ::unsetenv("GDEL_FLIPFLOP_STEPS");
    EXPECT_EQ(fb.stats.stars_flipflop, 0);
    EXPECT_EQ(fb.stats.stars_rebuilt, fb.stats.stars_built);
    EXPECT_EQ(ff.tets, fb.tets);
    EXPECT_EQ(ff.neighbors, fb.neighbors);
  }
}

// Two skew lines (gen::skew_lines: a points on the x axis at z = 0, b on the line x = 0,
// z = 1): the Delaunay triangulation is unique and known. No sphere holds 3 points of a
// line, so no 5 points are cospherical, and a tet with 3 points on one line is flat: the
// tets are exactly the (a-1)(b-1) joins of an edge between consecutive points of one line
// with an edge between consecutive points of the other, Theta(n^2) of them. The flip
// chains this input needs are the serial worst case of gFlip3D.
inline void gdel3d_skew_lines_case(Backend b, std::size_t n) {
  auto pts = gen::skew_lines(n, 99);
  Options o;
  o.backend = b;
  Triangulation t = delaunay(pts, o);
  expect_exact_delaunay(pts, t, b);
  // rank of each point along its line
  std::vector<std::pair<double, std::size_t>> la, lb;
  for (std::size_t i = 0; i < n; ++i) (pts[3 * i + 2] == 0.0 ? la : lb).push_back({pts[3 * i] + pts[3 * i + 1], i});
  std::sort(la.begin(), la.end());
  std::sort(lb.begin(), lb.end());
  std::vector<std::int64_t> rank(n), line(n);
  for (std::size_t r = 0; r < la.size(); ++r) rank[la[r].second] = std::int64_t(r), line[la[r].second] = 0;
  for (std::size_t r = 0; r < lb.size(); ++r) rank[lb[r].second] = std::int64_t(r), line[lb[r].second] = 1;
  ASSERT_EQ(t.num_tets(), std::int64_t((la.size() - 1) * (lb.size() - 1)));
  std::int64_t bad = 0;
  for (std::int64_t k = 0; k < t.num_tets(); ++k) {
    std::int64_t r[2][2], c[2] = {0, 0};
    for (int j = 0; j < 4; ++j) {
      const auto v = static_cast<std::size_t>(t.tets[std::size_t(4 * k + j)]);
      if (c[line[v]] < 2) r[line[v]][c[line[v]]] = rank[v];
      ++c[line[v]];
    }
    const bool ok = c[0] == 2 && c[1] == 2 && std::abs(r[0][0] - r[0][1]) == 1 && std::abs(r[1][0] - r[1][1]) == 1;
    bad += ok ? 0 : 1;
  }
  EXPECT_EQ(bad, 0) << "tets that are not the join of two consecutive-point edges";
}

// Degenerate configurations the repair must handle: cospherical and coplanar subsets.
inline void gdel3d_degenerate_cases(Backend b) {
  Options o;
  o.backend = b;
  // cube corners + centre; 3x3x3 grid; points on two parallel planes; many coplanar
  // points on the hull with one apex
  std::vector<std::vector<double>> sets;
  {
    std::vector<double> cube;
    for (int i = 0; i < 8; ++i) cube.insert(cube.end(), {double(i & 1), double((i >> 1) & 1), double(i >> 2)});
    cube.insert(cube.end(), {0.5, 0.5, 0.5});
    sets.push_back(cube);
  }
  {
    std::vector<double> g;
    for (int i = 0; i < 27; ++i) g.insert(g.end(), {double(i % 3), double((i / 3) % 3), double(i / 9)});
    sets.push_back(g);
  }
  {
    std::vector<double> two;
    for (int i = 0; i < 200; ++i) two.insert(two.end(), {double(i % 10), double((i / 10) % 10), double(i / 100)});
    sets.push_back(two);
  }
  {
    std::vector<double> pyr;
    for (int i = 0; i < 400; ++i) pyr.insert(pyr.end(), {double(i % 20), double(i / 20), 0.0});
    pyr.insert(pyr.end(), {7.3, 9.1, 5.0});
    sets.push_back(pyr);
  }
  for (auto& s : sets) {
    SCOPED_TRACE(s.size() / 3);
    expect_exact_delaunay(s, delaunay(s, o), b);
  }
}

}  // namespace gdel::test
