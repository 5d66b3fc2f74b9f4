// Real scanned models (CGAL's demo data, fetched by scripts/fetch-models.sh into
// .deps/models): gFlip3D's output must be a valid triangulation of their convex hull,
// gDel3D's the exact Delaunay triangulation without flat tets, gStar4D's the same one.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

#include "common/gdel3d_cases.hpp"
#include "io/io.hpp"

namespace gdel::test {

inline std::filesystem::path models_dir() {
  if (const char* d = std::getenv("GDEL_MODELS_DIR")) return d;
  return std::filesystem::path(GDEL_SOURCE_DIR) / ".deps" / "models";
}

inline void model_cases(Backend b) {
  const char* names[] = {"bunny00.off", "armadillo.off", "ChineseDragon-10kv.off", "blade.off", "building.ply",
                         "b9_training.ply"};
  for (const char* name : names) {
    SCOPED_TRACE(name);
    const auto path = models_dir() / name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing: run scripts/fetch-models.sh";
    auto pts = io::read_points(path).xyz;
    ASSERT_GE(pts.size(), 3000u);
    Options o;
    o.algorithm = Algorithm::gflip3d;
    o.backend = b;
    Triangulation t = delaunay(pts, o);
    expect_flip_output_valid(pts, t, b);
    o.algorithm = Algorithm::gdel3d;
    o.canonical_order = true;
    Triangulation d = delaunay(pts, o);
    expect_exact_delaunay(pts, d, b);
    // gStar4D: the same triangulation (same symbolic perturbation), by star splaying
    // itself (no certificate fallback)
    o.algorithm = Algorithm::gstar4d;
    Triangulation s = delaunay(pts, o);
    EXPECT_EQ(s.stats.certificate_fallbacks, 0) << s.stats.to_string();
    EXPECT_EQ(s.tets, d.tets);
  }
}

}  // namespace gdel::test
