// The documented examples of docs/grid.md (examples/grid_dual_examples.hpp): every figure
// as documented, so the numbers and pictures in the docs cannot drift from the code.
#include <gtest/gtest.h>

#include "../../examples/grid_dual_examples.hpp"

namespace {

using namespace gdel;

TEST(GridDualExamplesCpu, DocumentedFigures) {
  par::Context<par::Cpu> ctx;
  const auto examples = examples::grid_dual_examples(ctx);
  ASSERT_EQ(examples.size(), 7u);
  for (const examples::Example& ex : examples) {
    SCOPED_TRACE(ex.name);
    const examples::Analysis r = examples::analyse(ctx, ex);
    for (const auto& [name, field] : examples::kFigureFields) EXPECT_EQ(r.figures.*field, ex.expect.*field) << name;
    // the per-tet flags agree with the counts they refine
    auto tets_with = [&](std::uint8_t bit) {
      return std::count_if(r.flags.begin(), r.flags.end(), [&](std::uint8_t f) { return (f & bit) != 0; });
    };
    EXPECT_EQ(tets_with(grid::kDualFlat), r.stats.flat);
    EXPECT_EQ(tets_with(grid::kDualInverted), r.stats.inverted);
    EXPECT_EQ(tets_with(grid::kDualFolded), r.stats.folded);
    EXPECT_EQ(tets_with(grid::kDualOversharedFacet) > 0, r.stats.overshared_facets > 0);
    EXPECT_EQ(tets_with(grid::kDualOverlappingFacet) > 0, r.stats.overlapping_facets > 0);
    EXPECT_EQ(tets_with(grid::kDualNonDelaunayPair) > 0, r.stats.non_delaunay_pairs > 0);
    // the orientation flags agree with the exact orientation computed on the host
    for (std::size_t u = 0; u < r.tets.size(); ++u)
      EXPECT_EQ((r.flags[u] & grid::kDualFlat) != 0, r.orientation[u] == 0);
  }
}

// The unit cube's 8 corners have 74 triangulations (De Loera, Rambau, Santos,
// "Triangulations", 2010): the brute force behind the "vertex-lattice" example.
TEST(GridDualExamplesCpu, CubeTriangulations) { EXPECT_EQ(examples::cube_triangulations(), 74); }

}  // namespace
