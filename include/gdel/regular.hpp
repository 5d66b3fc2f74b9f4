// Regular (weighted Delaunay) triangulation: gReg3D (ALGORITHMS.md §6), the gStar4D
// pipeline with the power lifting |p|^2 - w, in which the stars of redundant points die.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gdel/delaunay.hpp"

namespace gdel {

struct RegularTriangulation {
  // 4 input point ids per tet, positively oriented; the vertices are the non-redundant
  // points. Ties (five points on one lifted hyperplane) are broken by the same symbolic
  // perturbation of the lifting as gdel::delaunay, so no tet is flat.
  std::vector<std::int32_t> tets;
  // 4 per tet: neighbours[4t+i] is the tet across the face opposite vertex i, -1 on the hull.
  std::vector<std::int32_t> neighbors;
  // Input ids of the points that are not vertices (redundant: their lifted point lies on
  // or above the lower hull of the others), ascending. Exact duplicates of a heavier
  // point are redundant too (see representative).
  std::vector<std::int32_t> redundant;
  // For each input point, the point that represents it: itself, or the heaviest point
  // with exactly the same coordinates (the smallest id among equally heavy ones).
  std::vector<std::int32_t> representative;
  // With Options::certificates: 5 input ids per entry of `redundant`, in that order, that
  // prove it redundant:
  //   (k, e, t0, t1, t2)   its star died: its lifted point lies in the lifted 4-simplex
  //                        of these five points (perturbed: strictly inside);
  //   (a, b, c, d, -1)     the output tet (a, b, c, d) holds it, and its lifted point is
  //                        not below the tet's lifted hyperplane (power test <= 0);
  //   (r, -1, -1, -1, -1)  an exact duplicate of the heavier (or equal, smaller id) point r.
  std::vector<std::int32_t> certificates;
  Stats stats;
  std::int64_t num_tets() const { return static_cast<std::int64_t>(tets.size() / 4); }
};

// points: 3n doubles; weights: n doubles (the squared radius of each point's sphere; any
// sign). Algorithm Auto or gstar4d (both: gReg3D); the result is certified by the exact
// verifier in regular mode. Throws InvalidInput (NaN/Inf, sizes, ranges, another
// algorithm), DegenerateInput (fewer than 4 distinct points, all coplanar),
// OutOfDeviceMemory, BackendUnavailable.
RegularTriangulation regular(std::span<const double> points, std::span<const double> weights,
                             const Options& options = {});

}  // namespace gdel
