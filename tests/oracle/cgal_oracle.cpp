// CGAL oracle: see cgal_oracle.hpp for the contract.
#include "oracle/cgal_oracle.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hidden_point_memory_policy.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace gdel::oracle {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using WPoint = K::Weighted_point_3;

// Delaunay: vertices carry the input index.
using DelVb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using DelCb = CGAL::Delaunay_triangulation_cell_base_3<K>;
template <class Concurrency>
using DelTr = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<DelVb, DelCb, Concurrency>>;

// Regular: vertices carry the input index; cells drop hidden points (we derive the
// redundant set from the vertices instead, which is cheaper and order-independent).
using RegVb = CGAL::Triangulation_vertex_base_with_info_3<int, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
using RegCb = CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>,
                                                      CGAL::Discard_hidden_points>;
template <class Concurrency>
using RegTr = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<RegVb, RegCb, Concurrency>>;

std::size_t checked_point_count(const std::vector<double>& xyz) {
  if (xyz.size() % 3 != 0)
    throw std::invalid_argument("gdel::oracle: xyz size " + std::to_string(xyz.size()) +
                                " is not a multiple of 3");
  if (xyz.size() / 3 > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::invalid_argument("gdel::oracle: too many points for int indices");
  for (std::size_t i = 0; i < xyz.size(); ++i)
    if (!std::isfinite(xyz[i]))
      throw std::invalid_argument("gdel::oracle: coordinate " + std::to_string(i % 3) + " of point " +
                                  std::to_string(i / 3) + " is not finite");
  return xyz.size() / 3;
}

// Indices of the points to hand to CGAL: one per group of equal keys, the lowest
// index of each group, in ascending index order. key(i) must be a tuple-like
// value compared with <, ==.
template <class KeyFn>
std::vector<int> lowest_index_of_equal(std::size_t n, KeyFn key) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto ka = key(a), kb = key(b);
    if (ka < kb) return true;
    if (kb < ka) return false;
    return a < b;
  });
  std::vector<int> keep;
  keep.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (i == 0 || key(order[i - 1]) < key(order[i])) keep.push_back(order[i]);
  std::sort(keep.begin(), keep.end());
  return keep;
}

auto point_key(const std::vector<double>& xyz) {
  // -0.0 and 0.0 compare equal, as they do geometrically.
  return [&xyz](int i) { return std::array<double, 3>{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; };
}

Point point_of(const std::vector<double>& xyz, int i) { return Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }

// Bounding box of the points, padded, for CGAL's spatial lock grid.
CGAL::Bbox_3 lock_box(const std::vector<double>& xyz) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const int a = static_cast<int>(i % 3);
    if (i < 3 || xyz[i] < lo[a]) lo[a] = xyz[i];
    if (i < 3 || xyz[i] > hi[a]) hi[a] = xyz[i];
  }
  double pad = 0;
  for (int a = 0; a < 3; ++a) pad = std::max(pad, hi[a] - lo[a]);
  pad = pad > 0 ? 0.01 * pad : 1.0;
  return CGAL::Bbox_3(lo[0] - pad, lo[1] - pad, lo[2] - pad, hi[0] + pad, hi[1] + pad, hi[2] + pad);
}

constexpr int kLockGridCellsPerAxis = 50;

template <class Tr>
std::vector<Tet> finite_tets(const Tr& tr) {
  std::vector<Tet> tets;
  if (tr.dimension() < 3) return tets;
  tets.reserve(tr.number_of_finite_cells());
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  return tets;
}

template <class Tr>
void fill(Tr& tr, const std::vector<double>& xyz, const std::vector<int>& keep) {
  std::vector<std::pair<Point, int>> pts;
  pts.reserve(keep.size());
  for (int i : keep) pts.emplace_back(point_of(xyz, i), i);
  tr.insert(pts.begin(), pts.end());  // range-with-info insert: spatial sort, then insert
}

template <class Tr>
void fill_weighted(Tr& tr, const std::vector<double>& xyz, const std::vector<double>& w,
                   const std::vector<int>& keep) {
  std::vector<std::pair<WPoint, int>> pts;
  pts.reserve(keep.size());
  for (int i : keep) pts.emplace_back(WPoint(point_of(xyz, i), w[i]), i);
  tr.insert(pts.begin(), pts.end());
}

template <class Tr>
RegularResult regular_result(const Tr& tr, std::size_t n) {
  RegularResult r;
  r.tets = finite_tets(tr);
  std::vector<char> is_vertex(n, 0);
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) is_vertex[v->info()] = 1;
  for (std::size_t i = 0; i < n; ++i)
    if (!is_vertex[i]) r.redundant.push_back(static_cast<int>(i));
  return r;
}

#ifndef CGAL_LINKED_WITH_TBB
[[noreturn]] void no_tbb() {
  throw std::runtime_error("gdel::oracle: parallel CGAL triangulation requested, but the oracle was built without TBB");
}
#endif

}  // namespace

bool cgal_parallel_available() {
#ifdef CGAL_LINKED_WITH_TBB
  return true;
#else
  return false;
#endif
}

std::vector<Tet> cgal_delaunay(const std::vector<double>& xyz, bool parallel) {
  const std::size_t n = checked_point_count(xyz);
  const std::vector<int> keep = lowest_index_of_equal(n, point_key(xyz));
  if (!parallel) {
    DelTr<CGAL::Sequential_tag> tr;
    fill(tr, xyz, keep);
    return finite_tets(tr);
  }
#ifdef CGAL_LINKED_WITH_TBB
  using Tr = DelTr<CGAL::Parallel_tag>;
  typename Tr::Lock_data_structure lock(lock_box(xyz), kLockGridCellsPerAxis);
  Tr tr(K(), &lock);
  fill(tr, xyz, keep);
  return finite_tets(tr);
#else
  no_tbb();
#endif
}

RegularResult cgal_regular(const std::vector<double>& xyz, const std::vector<double>& weights, bool parallel) {
  const std::size_t n = checked_point_count(xyz);
  if (weights.size() != n)
    throw std::invalid_argument("gdel::oracle: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(n) + " points");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(weights[i]))
      throw std::invalid_argument("gdel::oracle: weight of point " + std::to_string(i) + " is not finite");
  // Equal position and equal weight: keep the lowest index. Equal position with
  // different weights is left to CGAL (the larger weight wins, geometrically).
  const std::vector<int> keep = lowest_index_of_equal(n, [&](int i) {
    return std::array<double, 4>{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], weights[i]};
  });
  if (!parallel) {
    RegTr<CGAL::Sequential_tag> tr;
    fill_weighted(tr, xyz, weights, keep);
    return regular_result(tr, n);
  }
#ifdef CGAL_LINKED_WITH_TBB
  using Tr = RegTr<CGAL::Parallel_tag>;
  typename Tr::Lock_data_structure lock(lock_box(xyz), kLockGridCellsPerAxis);
  Tr tr(K(), &lock);
  fill_weighted(tr, xyz, weights, keep);
  return regular_result(tr, n);
#else
  no_tbb();
#endif
}

int cgal_orientation(const std::vector<double>& xyz, int a, int b, int c, int d) {
  const std::size_t n = xyz.size() / 3;
  for (int i : {a, b, c, d})
    if (i < 0 || static_cast<std::size_t>(i) >= n)
      throw std::out_of_range("gdel::oracle::cgal_orientation: index " + std::to_string(i) + " out of range");
  const CGAL::Orientation o = CGAL::orientation(point_of(xyz, a), point_of(xyz, b), point_of(xyz, c), point_of(xyz, d));
  return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0);
}

}  // namespace gdel::oracle
