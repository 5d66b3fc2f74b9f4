// CGAL as a test oracle: reference Delaunay and regular triangulations, returned as
// plain arrays of input indices in gdel's conventions, so tests can compare gdel's
// output with them exactly (after canonical()).
//
// This header includes no CGAL header; everything CGAL lives in cgal_oracle.cpp,
// which is compiled with -frounding-math (CGAL's interval filters need it).
//
// Conventions of the results:
//  * Only finite cells are returned; each tet (a,b,c,d) is positively oriented in
//    gdel's convention, orient3d(a,b,c,d) = sign det[b-a, c-a, d-a] > 0
//    (mesh/conventions.hpp), which is also CGAL's convention for its cells.
//  * The order of the tets is CGAL's cell order; use canonical() before comparing.
//  * Inputs whose points span fewer than 3 dimensions (fewer than 4 points, or all
//    coplanar) give an empty tet list.
//  * Exact duplicates: CGAL itself keeps one vertex per position and, when
//    inserting a range with info, overwrites that vertex's info with each later
//    copy, so the index it keeps depends on the spatial sort (and on thread timing
//    in parallel). The oracle makes this deterministic: among points with equal
//    coordinates (for cgal_regular: equal coordinates and equal weight) it passes
//    only the one with the LOWEST input index to CGAL. The other copies appear in
//    no tet (and, for cgal_regular, are listed as redundant).
//  * Input errors (size not a multiple of 3, weights of the wrong length, NaN or
//    infinite values) throw std::invalid_argument.
//  * parallel=true uses CGAL::Parallel_tag (TBB). If the oracle was built without
//    TBB, parallel=true throws std::runtime_error; cgal_parallel_available() tells.
#pragma once

#include <array>
#include <vector>

#include "mesh/canonical.hpp"

namespace gdel::oracle {

using Tet = std::array<int, 4>;

// Delaunay triangulation (CGAL Exact_predicates_inexact_constructions_kernel,
// points inserted with their index as vertex info by the range insert, which
// spatially sorts). xyz holds the points as x0,y0,z0,x1,y1,z1,...
std::vector<Tet> cgal_delaunay(const std::vector<double>& xyz, bool parallel = false);

struct RegularResult {
  std::vector<Tet> tets;       // finite cells, positively oriented
  std::vector<int> redundant;  // input indices that are no vertex (hidden points), ascending
};

// Regular (weighted Delaunay) triangulation with CGAL's Regular_triangulation_3;
// weights[i] is the weight of point i (squared radius; power distance
// |x - p|^2 - w). A point is redundant iff it is not a vertex of the result.
RegularResult cgal_regular(const std::vector<double>& xyz, const std::vector<double>& weights,
                           bool parallel = false);

// Whether the oracle was built with TBB (parallel=true supported).
bool cgal_parallel_available();

// Exact orientation of points a,b,c,d of xyz by CGAL::orientation (Epick, filtered
// exact): +1, 0 or -1 in gdel's convention, sign det[b-a, c-a, d-a].
int cgal_orientation(const std::vector<double>& xyz, int a, int b, int c, int d);

// Canonical comparison form of a tet list (see mesh/canonical.hpp).
using gdel::canonical;
using gdel::canonical_tet;

}  // namespace gdel::oracle
