// Stand-in when the benchmark is built without CGAL.
#include "peers.hpp"

namespace gdel::bench {
bool cgal_built() { return false; }
PeerResult cgal_delaunay(const std::vector<double>&, bool) {
  PeerResult r;
  r.note = "benchmark built without CGAL";
  return r;
}
PeerResult cgal_regular(const std::vector<double>&, const std::vector<double>&, bool) {
  PeerResult r;
  r.note = "benchmark built without CGAL";
  return r;
}
}  // namespace gdel::bench
