// Peers measured by the benchmark in the same process, on the same points.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gdel::bench {

struct PeerResult {
  bool available = false;
  double seconds = 0;
  std::int64_t tets = 0;  // finite cells
  std::string note;
};

// CGAL Delaunay_triangulation_3 (Epick), insertion of all points with spatial sort;
// parallel = CGAL::Parallel_tag with TBB on all host threads. Unavailable when the
// benchmark was built without CGAL.
PeerResult cgal_delaunay(const std::vector<double>& xyz, bool parallel);
// CGAL Regular_triangulation_3 (Epick) of weighted points (weight = squared radius), same
// insertion and parallelism; tets = finite cells, note = hidden (redundant) point count.
PeerResult cgal_regular(const std::vector<double>& xyz, const std::vector<double>& w, bool parallel);
bool cgal_built();

}  // namespace gdel::bench
