// grid_dual_examples [OUT_DIR]: the examples of docs/grid.md ("Negative results") on the CPU
// backend, one JSON file each (OUT_DIR/grid-<name>.json, default: the current folder) and
// OUT_DIR/grid-summary.json (every example's figures, the cube's triangulation count, and
// the Kuhn tets' corners: corner k of tet j is kuhn_corners[j][k] = dx + 2·dy + 4·dz).
// scripts/grid-dual-examples.py runs it and draws the pictures. Prints a table; exits 1
// when a figure differs from the documented one (examples/grid_dual_examples.hpp).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "grid_dual_examples.hpp"

namespace {

using namespace gdel;
using namespace gdel::examples;

// The items, each written by f, separated by sep.
template <class C, class F>
std::string join(const C& items, F f, const char* sep = ", ") {
  std::string o;
  for (const auto& x : items) o += (o.empty() ? "" : sep) + f(x);
  return o;
}

template <class C, class F>
std::string array(const C& items, F f) {
  return '[' + join(items, f) + ']';
}

template <class T>
std::string ids(const T& t) {
  return array(t, [](auto v) { return std::to_string(v); });
}

std::string quoted(const std::string& s) { return '"' + s + '"'; }

std::string same(const std::string& s) { return s; }

std::string figures_json(const Figures& f) {
  auto field = [&](const auto& k) { return quoted(k.first) + ": " + std::to_string(f.*k.second); };
  return '{' + join(kFigureFields, field) + '}';
}

std::string flag_names(std::uint8_t b) {
  static const char* names[8] = {"flat",      "inverted",           "folded",      "open_facet", "overshared_facet",
                                 "overlapping_facet", "cospherical_pair", "non_delaunay_pair"};
  std::vector<std::string> v;
  for (int i = 0; i < 8; ++i)
    if ((b >> i) & 1) v.push_back(quoted(names[i]));
  return array(v, same);
}

std::string example_json(const Example& ex, const Analysis& r) {
  std::ostringstream o;
  char buf[96];
  o << "{\n  \"name\": " << quoted(ex.name) << ",\n  \"title\": " << quoted(ex.title)
    << ",\n  \"kind\": " << quoted(ex.kind) << ",\n  \"W\": " << ex.W << ",\n";
  std::vector<std::string> pts;
  for (std::size_t i = 0; i < ex.xyz.size() / 3; ++i) {
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", ex.xyz[3 * i], ex.xyz[3 * i + 1], ex.xyz[3 * i + 2]);
    pts.push_back(buf);
  }
  o << "  \"sites\": " << array(pts, same) << ",\n";
  o << "  \"colouring\": " << ids(ex.site) << ",\n";
  o << "  \"region_pieces\": " << ids(r.pieces) << ",\n";
  o << "  \"detached_voxels\": " << ids(r.detached) << ",\n";
  std::vector<std::string> tets;
  for (std::size_t u = 0; u < r.tets.size(); ++u)
    tets.push_back("{\"sites\": " + ids(r.tets[u]) + ", \"orientation\": " + std::to_string(r.orientation[u]) +
                   ", \"grid_tets\": " + array(r.occurrences[u], [](const GridTet& g) { return ids(g); }) +
                   ", \"empty_sphere\": " + (r.empty_sphere[u] ? "true" : "false") +
                   ", \"flags\": " + flag_names(r.flags[u]) + "}");
  o << "  \"tets\": [\n    " << join(tets, same, ",\n    ") << "\n  ],\n";
  o << "  \"delaunay_unique\": " << (r.dt_unique ? "true" : "false") << ",\n";
  o << "  \"empty_sphere_tets\": " << array(r.dt, [](const Tet& t) { return ids(t); }) << ",\n";
  o << "  \"hull_facets\": " << array(r.hull, [](const Tri& t) { return ids(t); }) << ",\n";
  o << "  \"off_hull_facets\": " << array(r.off_hull, [](const Tri& t) { return ids(t); }) << ",\n";
  o << "  \"vertex_blocks\": " << array(r.blocks, [](const VertexBlock& b) {
         return "{\"corner\": " + ids(b.corner) + ", \"colours\": " + ids(b.colour) +
                ", \"distinct\": " + std::to_string(b.colours) + ", \"kuhn\": " + array(b.kuhn, [](const auto& t) {
                  return t[0] < 0 ? std::string("null") : ids(t);
                }) + "}";
       }) << ",\n";
  o << "  \"figures\": " << figures_json(r.figures) << ",\n";
  o << "  \"expected\": " << figures_json(ex.expect) << "\n}\n";
  return o.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  par::Context<par::Cpu> ctx;
  const std::int64_t cube = cube_triangulations();
  const std::string kuhn = array(std::array{0, 1, 2, 3, 4, 5}, [](int j) {
    return array(std::array{0, 1, 2, 3}, [&](int k) { return std::to_string(grid::kuhn_corner(j, k)); });
  });
  bool drift = false;
  std::vector<std::string> summary;
  std::printf("%-15s", "example");
  for (const auto& f : kFigureFields) std::printf(" %s", f.first);
  std::printf("\n");
  for (const Example& ex : grid_dual_examples(ctx)) {
    const Analysis r = analyse(ctx, ex);
    const std::string path = dir + "/grid-" + ex.name + ".json";
    std::ofstream(path) << example_json(ex, r);
    std::printf("%-15s", ex.name.c_str());
    for (const auto& f : kFigureFields)
      std::printf(" %*lld", int(std::string(f.first).size()), static_cast<long long>(r.figures.*f.second));
    std::printf("\n");
    if (!(r.figures == ex.expect)) {
      std::fprintf(stderr, "%s: figures differ from the documented ones (examples/grid_dual_examples.hpp)\n",
                   ex.name.c_str());
      drift = true;
    }
    summary.push_back("{\"name\": " + quoted(ex.name) + ", \"title\": " + quoted(ex.title) +
                      ", \"figures\": " + figures_json(r.figures) + "}");
  }
  std::ofstream(dir + "/grid-summary.json")
      << "{\"cube_triangulations\": " << cube << ",\n \"kuhn_corners\": " << kuhn
      << ",\n \"examples\": [\n  "
      << join(summary, same, ",\n  ") << "\n]}\n";
  std::printf("triangulations of the unit cube's 8 corners: %lld\n", (long long)cube);
  return drift ? 1 : 0;
}
