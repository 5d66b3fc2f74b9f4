// gStar4D cases shared by the CPU and GPU test programs: on every generator the result
// is the exact Delaunay triangulation (verifier), identical to gdel3d's (the same
// symbolic perturbation), reached by star splaying itself (no certificate fallback),
// and deterministic.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/gdel3d_cases.hpp"
#include "common/model_cases.hpp"
#include "io/io.hpp"

namespace gdel::test {

inline void gstar4d_generator_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::ThinShell, Distribution::Grid,
                         Distribution::Sphere, Distribution::Ball, Distribution::SkewLines}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    // (skew lines: Θ(n²) tets)
    const std::size_t nn = d == Distribution::SkewLines ? std::min<std::size_t>(n / 10, 400) : n;
    auto pts = gen::generate(d, nn, 4321);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    o.algorithm = Algorithm::gstar4d;
    Triangulation t = delaunay(pts, o);
    SCOPED_TRACE(t.stats.to_string());
    EXPECT_EQ(t.stats.algorithm, "gstar4d");
    EXPECT_EQ(t.stats.certificate_fallbacks, 0);
    t.stats.algorithm = "gdel3d";  // expect_exact_delaunay's label check
    expect_exact_delaunay(pts, t, b);
    o.algorithm = Algorithm::gdel3d;
    Triangulation ref = delaunay(pts, o);
    EXPECT_EQ(t.tets, ref.tets);
    EXPECT_EQ(t.neighbors, ref.neighbors);
    o.algorithm = Algorithm::gstar4d;
    Triangulation t2 = delaunay(pts, o);
    EXPECT_EQ(t.tets, t2.tets);
  }
}

// One measured gstar4d run per item of GDEL_MEASURE (comma-separated DIST:N, or a model
// file name in .deps/models), verified exactly; prints the times per stage and the
// splaying counts (GDEL_SPLAY_DEBUG=1 adds the largest star and the critical path).
inline void gstar4d_measure(Backend b) {
  const char* env = std::getenv("GDEL_MEASURE");
  std::stringstream items(env ? env : "grid:10000,sphere:10000");
  for (std::string item; std::getline(items, item, ',');) {
    SCOPED_TRACE(item);
    std::vector<double> pts;
    const auto colon = item.find(':');
    if (colon == std::string::npos) {
      pts = io::read_points(models_dir() / item).xyz;
    } else {
      const auto d = gen::parse_distribution(item.substr(0, colon));
      pts = gen::generate(d, static_cast<std::size_t>(std::stod(item.substr(colon + 1))), 4321);
    }
    Options o;
    o.backend = b;
    o.algorithm = Algorithm::gstar4d;
    Triangulation t = delaunay(pts, o);
    std::printf("== %s: %zu points, %.3f s\n%s\n", item.c_str(), pts.size() / 3, t.stats.seconds,
                t.stats.to_string().c_str());
    EXPECT_EQ(t.stats.certificate_fallbacks, 0);
    t.stats.algorithm = "gdel3d";  // expect_exact_delaunay's label check
    expect_exact_delaunay(pts, t, b);
  }
}

}  // namespace gdel::test
