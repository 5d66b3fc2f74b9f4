// CGAL peer (compiled only when CGAL is found; see bench/CMakeLists.txt).
#include <chrono>
#include <utility>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>

#include "peers.hpp"

namespace gdel::bench {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Pt = K::Point_3;

template <class Tag>
PeerResult run(const std::vector<double>& xyz) {
  using Vb = CGAL::Triangulation_vertex_base_3<K>;
  using Cb = CGAL::Delaunay_triangulation_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, Tag>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<Pt> pts;
  pts.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) pts.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  PeerResult r;
  r.available = true;
  auto t0 = std::chrono::steady_clock::now();
  if constexpr (std::is_same_v<Tag, CGAL::Sequential_tag>) {
    DT dt(pts.begin(), pts.end());
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.tets = static_cast<std::int64_t>(dt.number_of_finite_cells());
  } else {
    // Lock grid over the bounding box, as CGAL's parallel examples do.
    CGAL::Bbox_3 box = CGAL::bbox_3(pts.begin(), pts.end());
    typename DT::Lock_data_structure locks(box, 50);
    DT dt(pts.begin(), pts.end(), &locks);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.tets = static_cast<std::int64_t>(dt.number_of_finite_cells());
  }
  return r;
}
template <class Tag>
PeerResult run_regular(const std::vector<double>& xyz, const std::vector<double>& w) {
  using Vb = CGAL::Regular_triangulation_vertex_base_3<K>;
  using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, Tag>;
  using RT = CGAL::Regular_triangulation_3<K, Tds>;
  using WP = K::Weighted_point_3;
  std::vector<WP> pts;
  pts.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) pts.emplace_back(Pt(xyz[i], xyz[i + 1], xyz[i + 2]), w[i / 3]);
  PeerResult r;
  r.available = true;
  auto t0 = std::chrono::steady_clock::now();
  auto finish = [&](const RT& rt) {
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.tets = static_cast<std::int64_t>(rt.number_of_finite_cells());
    r.note = "hidden " + std::to_string(pts.size() - rt.number_of_vertices());
  };
  if constexpr (std::is_same_v<Tag, CGAL::Sequential_tag>) {
    RT rt(pts.begin(), pts.end());
    finish(rt);
  } else {
    CGAL::Bbox_3 box;
    for (const WP& p : pts) box += p.point().bbox();
    typename RT::Lock_data_structure locks(box, 50);
    RT rt(pts.begin(), pts.end(), &locks);
    finish(rt);
  }
  return r;
}
}  // namespace

bool cgal_built() { return true; }

PeerResult cgal_regular(const std::vector<double>& xyz, const std::vector<double>& w, bool parallel) {
  if (!parallel) return run_regular<CGAL::Sequential_tag>(xyz, w);
#ifdef CGAL_LINKED_WITH_TBB
  return run_regular<CGAL::Parallel_tag>(xyz, w);
#else
  PeerResult r;
  r.note = "built without TBB";
  return r;
#endif
}

PeerResult cgal_delaunay(const std::vector<double>& xyz, bool parallel) {
  if (!parallel) return run<CGAL::Sequential_tag>(xyz);
#ifdef CGAL_LINKED_WITH_TBB
  return run<CGAL::Parallel_tag>(xyz);
#else
  PeerResult r;
  r.note = "built without TBB";
  return r;
#endif
}

}  // namespace gdel::bench
