// The exact verifier: checks that a set of tetrahedra is a valid triangulation of
// the convex hull of the input points and that it is Delaunay (or regular, with
// weights), using exact predicates only (no symbolic perturbation: a tie is a tie).
// This is what `gdel check` runs.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "gdel/options.hpp"

namespace gdel {

struct VerifyReport {
  // sizes
  std::int64_t points = 0;           // input points
  std::int64_t distinct_points = 0;  // after merging exact duplicates
  std::int64_t tets = 0;
  std::int64_t vertices_used = 0;    // distinct vertex ids referenced by tets
  std::int64_t edges = 0;
  std::int64_t facets = 0;           // distinct facets
  std::int64_t hull_facets = 0;
  std::int64_t euler = 0;            // V - E + F - T; 1 for a triangulated 3-ball

  // validity failures (each must be 0 for a valid triangulation)
  std::int64_t bad_index = 0;           // tets with an out-of-range or repeated vertex id
  std::int64_t degenerate_tets = 0;     // zero volume
  std::int64_t inverted_tets = 0;       // negative orientation
  std::int64_t overshared_facets = 0;   // facets in more than 2 tets
  std::int64_t same_side_facets = 0;    // facets whose 2 tets lie on the same side (overlap)
  std::int64_t hull_open_edges = 0;     // hull edges not in exactly 2 hull facets of opposite direction
  std::int64_t hull_reflex_edges = 0;   // hull edges where the hull is not locally convex
  std::int64_t unused_points = 0;       // distinct points not in any tet (regular: and not redundant)
  std::int64_t duplicate_vertices = 0;  // groups of equal points with more than one used
  std::int64_t locate_failures = 0;     // regular: unused points that could not be located
  bool euler_ok = false;

  // Delaunay / regular property
  std::int64_t non_delaunay_facets = 0;  // interior facets whose opposite apex is strictly inside / in conflict
  std::int64_t cospherical_facets = 0;   // ties (allowed): apex exactly on the sphere / hyperplane
  std::int64_t redundant_points = 0;     // regular: unused points proven redundant

  // Work
  std::int64_t exact_evaluations = 0;  // predicate evaluations the float filter could not decide
  double seconds = 0;

  bool valid() const;     // a triangulation of the convex hull of the distinct points
  bool delaunay() const;  // valid() and every interior facet locally Delaunay / regular
  std::string summary() const;
};

// points: 3n doubles (x,y,z per point). tets: 4m vertex ids. weights: empty, or n
// weights (regular mode: power tests, and unused points must be redundant).
VerifyReport verify(std::span<const double> points, std::span<const std::int32_t> tets,
                    std::span<const double> weights = {}, Backend backend = Backend::Auto);

}  // namespace gdel
