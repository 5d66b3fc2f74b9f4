// The documented examples of docs/grid.md ("Negative results"): small colourings of a W³
// grid, their raw duals under the grid perturbation (grid/dual.hpp) and brute-force facts
// about them. Shared by the example program (examples/grid_dual_examples.cpp, which writes
// them as JSON for scripts/grid-dual-examples.py) and the test that pins their figures
// (tests/cpu/grid_examples.cpp), so the documented numbers cannot drift.
//
//   std::vector<Example> grid_dual_examples<B>(ctx)   the examples, colourings filled in
//   Analysis analyse<B>(ctx, example)                 the dual and the brute-force facts
//   Example::expect                                   the documented figures
//   std::int64_t cube_triangulations()                triangulations of the unit cube's corners
//
// Brute force (host, exact predicates): the site tets with an empty circumsphere (no site
// strictly inside; when no such sphere has a fifth site on it, `dt_unique`, they are the
// sites' Delaunay triangulation), the convex hull's facets (facets of exactly one of those
// tets; only when dt_unique), the digital regions' face-connected pieces, and the 2×2×2
// blocks of voxels with 5 or more colours ("digital Voronoi vertices" of degree > 4).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "geometry/predicates.hpp"
#include "grid/dual.hpp"
#include "grid/kuhn.hpp"
#include "parallel/backend.hpp"
#include "star4d/pba.hpp"

namespace gdel::examples {

using Tet = std::array<std::int32_t, 4>;  // site ids, ascending
using Tri = std::array<std::int32_t, 3>;  // site ids, ascending
using GridTet = std::array<int, 4>;       // voxel of cube corner 000 (x, y, z), Kuhn tet j

// The figures each example documents: the dual's counts (grid::DualStats without the
// time) and the brute-force ones (-1: not defined, see below).
struct Figures {
  std::int64_t grid_tets = 0, tets = 0, flat = 0, inverted = 0, folded = 0;
  std::int64_t open_facets = 0, overshared_facets = 0, overlapping_facets = 0;
  std::int64_t cospherical_pairs = 0, non_delaunay_pairs = 0;
  std::int64_t empty_sphere_tets = 0;  // site tets whose circumsphere holds no site strictly inside
  std::int64_t dual_empty_sphere = 0;  // dual tets among them
  std::int64_t hull_facets = 0;        // facets of the sites' convex hull (-1: no unique DT)
  std::int64_t off_hull_facets = 0;    // open dual facets that are not hull facets (-1: idem)
  std::int64_t split_regions = 0;      // sites whose digital region has > 1 face-connected piece
  std::int64_t vertex_blocks = 0;      // 2×2×2 blocks of voxels with 5 or more colours
  bool operator==(const Figures&) const = default;
};

// Every figure with its name (JSON keys, test messages).
inline constexpr std::pair<const char*, std::int64_t Figures::*> kFigureFields[] = {
    {"grid_tets", &Figures::grid_tets},
    {"tets", &Figures::tets},
    {"flat", &Figures::flat},
    {"inverted", &Figures::inverted},
    {"folded", &Figures::folded},
    {"open_facets", &Figures::open_facets},
    {"overshared_facets", &Figures::overshared_facets},
    {"overlapping_facets", &Figures::overlapping_facets},
    {"cospherical_pairs", &Figures::cospherical_pairs},
    {"non_delaunay_pairs", &Figures::non_delaunay_pairs},
    {"empty_sphere_tets", &Figures::empty_sphere_tets},
    {"dual_empty_sphere", &Figures::dual_empty_sphere},
    {"hull_facets", &Figures::hull_facets},
    {"off_hull_facets", &Figures::off_hull_facets},
    {"split_regions", &Figures::split_regions},
    {"vertex_blocks", &Figures::vertex_blocks},
};

// Figures from a list in kFigureFields order (the examples' tables below).
inline Figures figures(std::initializer_list<std::int64_t> v) {
  Figures f;
  std::size_t i = 0;
  for (std::int64_t x : v) f.*kFigureFields[i++].second = x;
  return f;
}

struct Example {
  std::string name;   // the files are grid-<name>.json and docs/img/grid-<name>.png
  std::string title;  // one line
  std::string kind;   // "pba": star4d::digital_voronoi of the sites; "hand-made"
  int W = 0;
  std::vector<double> xyz;         // the sites, 3 coordinates per id
  std::vector<std::int32_t> site;  // the colouring: W³ ids, index (z·W + y)·W + x
  Figures expect;                  // the documented figures (tests/cpu/grid_examples.cpp)
};

// One 2×2×2 block of voxels with 5 or more distinct colours (a digital Voronoi vertex of
// degree > 4) and its 6 Kuhn tets (site ids in kuhn_corner order; -1 where the Kuhn tet
// is not 4-coloured).
struct VertexBlock {
  int corner[3] = {0, 0, 0};  // voxel of corner 000
  std::int32_t colour[8] = {};
  int colours = 0;
  std::array<std::array<std::int32_t, 4>, 6> kuhn{};
};

struct Analysis {
  grid::DualStats stats;
  std::vector<Tet> tets;             // distinct dual tets
  std::vector<std::uint8_t> flags;   // grid::DualTetFlag bits per dual tet
  std::vector<int> orientation;      // exact orient3d of each dual tet (ascending ids)
  std::vector<std::vector<GridTet>> occurrences;  // the grid tets dualizing each dual tet
  std::vector<bool> empty_sphere;    // each dual tet has an empty circumsphere
  std::vector<Tet> dt;               // the site tets with an empty circumsphere
  bool dt_unique = true;             // no fifth site on an empty sphere: dt is the Delaunay triangulation
  std::vector<Tri> hull, off_hull;   // (dt_unique only) hull facets; open dual facets off the hull
  std::vector<int> pieces;           // face-connected pieces of each site's region
  std::vector<std::int64_t> detached;  // voxels not in the piece holding their site's voxel
  std::vector<VertexBlock> blocks;
  Figures figures;
};

namespace detail {

inline const double* pt(const std::vector<double>& xyz, std::int32_t i) { return xyz.data() + 3 * std::size_t(i); }

inline int orient(const std::vector<double>& xyz, const Tet& t) {
  double work[geom::kPredicateWork];
  return geom::orient3d(pt(xyz, t[0]), pt(xyz, t[1]), pt(xyz, t[2]), pt(xyz, t[3]), work);
}

// The site tets whose circumsphere holds no site strictly inside, by brute force; false
// when some such sphere has a fifth site on it (else they are the Delaunay triangulation).
inline bool empty_sphere_tets(const std::vector<double>& xyz, std::vector<Tet>& dt) {
  const std::int32_t n = static_cast<std::int32_t>(xyz.size() / 3);
  double work[geom::kPredicateWork];
  bool unique = true;
  for (std::int32_t a = 0; a < n; ++a)
    for (std::int32_t b = a + 1; b < n; ++b)
      for (std::int32_t c = b + 1; c < n; ++c)
        for (std::int32_t d = c + 1; d < n; ++d) {
          Tet t{a, b, c, d};
          const int s = orient(xyz, t);
          if (s == 0) continue;
          bool empty = true, on = false;
          for (std::int32_t e = 0; e < n && empty; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            const int i = s * geom::insphere(pt(xyz, a), pt(xyz, b), pt(xyz, c), pt(xyz, d), pt(xyz, e), work);
            empty = i <= 0;
            on = on || i == 0;
          }
          if (!empty) continue;
          unique = unique && !on;
          dt.push_back(t);
        }
  return unique;
}

// The facets of `tets` (ascending triples) with how many of the tets hold each.
inline std::map<Tri, int> facet_counts(const std::vector<Tet>& tets, const std::vector<bool>& skip) {
  std::map<Tri, int> f;
  for (std::size_t u = 0; u < tets.size(); ++u) {
    if (skip[u]) continue;
    for (int i = 0; i < 4; ++i) {
      Tri t{};
      for (int k = 0, c = 0; k < 4; ++k)
        if (k != i) t[c++] = tets[u][k];
      ++f[t];
    }
  }
  return f;
}

// Face-connected pieces of every site's region; `detached` gets the voxels outside the
// piece that holds the site's own voxel (home[i]: voxel index of site i).
inline std::vector<int> region_pieces(const std::vector<std::int32_t>& site, int W,
                                      const std::vector<std::int64_t>& home, std::vector<std::int64_t>& detached) {
  std::vector<int> pieces(home.size(), 0);
  std::vector<char> seen(site.size(), 0);
  std::vector<std::int64_t> stack;
  auto flood = [&](std::int64_t v0, bool at_home) {
    if (seen[v0] || site[v0] < 0) return;
    ++pieces[site[v0]];
    seen[v0] = 1;
    stack.push_back(v0);
    while (!stack.empty()) {
      const std::int64_t v = stack.back();
      stack.pop_back();
      if (!at_home) detached.push_back(v);
      const int c[3] = {int(v % W), int((v / W) % W), int(v / (std::int64_t(W) * W))};
      for (int a = 0; a < 3; ++a)
        for (int d = -1; d <= 1; d += 2) {
          int q[3] = {c[0], c[1], c[2]};
          q[a] += d;
          if (q[a] < 0 || q[a] >= W) continue;
          const std::int64_t w = (std::int64_t(q[2]) * W + q[1]) * W + q[0];
          if (!seen[w] && site[w] == site[v0]) seen[w] = 1, stack.push_back(w);
        }
    }
  };
  for (std::size_t i = 0; i < home.size(); ++i)
    if (site[home[i]] == std::int32_t(i)) flood(home[i], true);
  for (std::int64_t v = 0; v < std::int64_t(site.size()); ++v) flood(v, false);
  std::sort(detached.begin(), detached.end());
  return pieces;
}

// Calls f(x, y, z, colours[8], Kuhn mask) for every cube of voxels (corner 000 at voxel
// x, y, z; colours and mask as grid/dual.hpp reads them).
template <class F>
void for_each_cube(const std::vector<std::int32_t>& site, int W, F f) {
  const std::int64_t w1 = W - 1;
  for (std::int64_t c = 0; c < w1 * w1 * w1; ++c) {
    std::int32_t col[8];
    grid::dual_detail::cube_colours(site.data(), W, c, col);
    f(int(c % w1), int((c / w1) % w1), int(c / (w1 * w1)), col, grid::coloured_kuhn_tets(col, -1));
  }
}

inline std::vector<VertexBlock> vertex_blocks(const std::vector<std::int32_t>& site, int W) {
  std::vector<VertexBlock> out;
  for_each_cube(site, W, [&](int x, int y, int z, const std::int32_t* col, int mask) {
    VertexBlock b;
    b.corner[0] = x, b.corner[1] = y, b.corner[2] = z;
    std::copy(col, col + 8, b.colour);
    b.colours = static_cast<int>(std::set<std::int32_t>(col, col + 8).size());
    if (b.colours < 5) return;
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 4; ++k) b.kuhn[j][k] = (mask >> j) & 1 ? col[grid::kuhn_corner(j, k)] : -1;
    out.push_back(b);
  });
  return out;
}

// The grid tets (4-coloured Kuhn tets: cube corner x, y, z and Kuhn index j) that dualize
// each site tet.
inline std::map<Tet, std::vector<GridTet>> grid_tet_occurrences(const std::vector<std::int32_t>& site, int W) {
  std::map<Tet, std::vector<GridTet>> occ;
  for_each_cube(site, W, [&](int x, int y, int z, const std::int32_t* col, int mask) {
    for (int j = 0; j < 6; ++j) {
      if (!((mask >> j) & 1)) continue;
      Tet t{};
      for (int k = 0; k < 4; ++k) t[k] = col[grid::kuhn_corner(j, k)];
      std::sort(t.begin(), t.end());
      occ[t].push_back({x, y, z, j});
    }
  });
  return occ;
}

}  // namespace detail

// The number of triangulations of the 8 corners of the unit cube (all of them Delaunay:
// the corners are cospherical), by brute force over sets of corner tets: a set of
// positively oriented tets inside the cube whose facets off the cube's faces are each held
// by 0 or 2 of them on opposite sides has a winding number constant inside the cube; with
// total volume 1 it is 1 everywhere, i.e. the tets triangulate the cube.
inline std::int64_t cube_triangulations() {
  auto corner = [](int k, int a) { return (k >> a) & 1; };
  // det[b−a, c−a, d−a] of four corners (6 × the signed volume)
  auto det = [&](int a, int b, int c, int d) {
    int m[3][3];
    const int p[3] = {b, c, d};
    for (int r = 0; r < 3; ++r)
      for (int x = 0; x < 3; ++x) m[r][x] = corner(p[r], x) - corner(a, x);
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  std::vector<std::array<int, 4>> tets;  // ascending corners, non-flat
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int c = b + 1; c < 8; ++c)
        for (int d = c + 1; d < 8; ++d)
          if (det(a, b, c, d) != 0) tets.push_back({a, b, c, d});
  auto on_cube_face = [&](int x, int y, int z) {
    for (int a = 0; a < 3; ++a)
      if (corner(x, a) == corner(y, a) && corner(y, a) == corner(z, a)) return true;
    return false;
  };
  // uses of facet (a, b, c) by tets with their fourth vertex on its positive / negative
  // side: two tets glue there iff the sides differ
  std::vector<std::array<int, 2>> use(512, {0, 0});
  auto slot = [&](const std::array<int, 4>& t, int i) -> int& {
    int f[3], c = 0;
    for (int k = 0; k < 4; ++k)
      if (k != i) f[c++] = t[k];
    return use[f[0] * 64 + f[1] * 8 + f[2]][det(f[0], f[1], f[2], t[i]) > 0 ? 0 : 1];
  };
  auto facets_ok = [&] {
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        for (int c = b + 1; c < 8; ++c) {
          const auto& u = use[a * 64 + b * 8 + c];
          if (on_cube_face(a, b, c) ? u[0] + u[1] > 1 : u[0] != u[1]) return false;
        }
    return true;
  };
  std::int64_t count = 0;
  auto dfs = [&](auto&& self, std::size_t from, int vol6) -> void {
    if (vol6 == 6) {
      count += facets_ok() ? 1 : 0;
      return;
    }
    for (std::size_t t = from; t < tets.size(); ++t) {
      const auto& v = tets[t];
      const int d = std::abs(det(v[0], v[1], v[2], v[3]));
      bool ok = vol6 + d <= 6;
      for (int i = 0; i < 4 && ok; ++i) ok = slot(v, i) == 0;  // never two tets on one side
      if (!ok) continue;
      for (int i = 0; i < 4; ++i) ++slot(v, i);
      self(self, t + 1, vol6 + d);
      for (int i = 0; i < 4; ++i) --slot(v, i);
    }
  };
  dfs(dfs, 0, 0);
  return count;
}

// The dual of the example's colouring and the brute-force facts.
template <class B>
Analysis analyse(par::Context<B>& ctx, const Example& ex) {
  Analysis r;
  const std::int32_t n = static_cast<std::int32_t>(ex.xyz.size() / 3);
  {
    par::Buffer<std::int32_t, B> s(ctx);
    s.assign(ex.site);
    par::Buffer<double, B> x(ctx);
    x.assign(ex.xyz);
    grid::Dual<B> d = grid::dual_of_colouring(ctx, s.data(), ex.W, x.data());
    r.stats = d.stats;
    const std::vector<std::uint64_t> hi = d.hi.to_host(), lo = d.lo.to_host();
    r.flags = d.flags.to_host();
    for (std::size_t u = 0; u < hi.size(); ++u)
      r.tets.push_back({std::int32_t(hi[u] >> 32), std::int32_t(hi[u] & 0xffffffffu), std::int32_t(lo[u] >> 32),
                        std::int32_t(lo[u] & 0xffffffffu)});
  }
  const std::map<Tet, std::vector<GridTet>> occ = detail::grid_tet_occurrences(ex.site, ex.W);
  r.dt_unique = detail::empty_sphere_tets(ex.xyz, r.dt);
  const std::set<Tet> dts(r.dt.begin(), r.dt.end());
  std::vector<bool> flat(r.tets.size());
  for (std::size_t u = 0; u < r.tets.size(); ++u) {
    r.orientation.push_back(detail::orient(ex.xyz, r.tets[u]));
    r.occurrences.push_back(occ.count(r.tets[u]) ? occ.at(r.tets[u]) : std::vector<GridTet>{});
    r.empty_sphere.push_back(dts.count(r.tets[u]) > 0);
    flat[u] = r.orientation.back() == 0;
  }
  if (r.dt_unique) {
    for (auto& [f, c] : detail::facet_counts(r.dt, std::vector<bool>(r.dt.size(), false)))
      if (c == 1) r.hull.push_back(f);
    const std::set<Tri> hs(r.hull.begin(), r.hull.end());
    for (auto& [f, c] : detail::facet_counts(r.tets, flat))
      if (c == 1 && !hs.count(f)) r.off_hull.push_back(f);
  }
  std::vector<std::int64_t> home;
  for (std::int32_t i = 0; i < n; ++i) {
    std::int64_t v = 0;
    for (int a = 2; a >= 0; --a) v = v * ex.W + static_cast<std::int64_t>(std::floor(ex.xyz[3 * std::size_t(i) + a]));
    home.push_back(v);
  }
  r.pieces = detail::region_pieces(ex.site, ex.W, home, r.detached);
  r.blocks = detail::vertex_blocks(ex.site, ex.W);

  Figures& f = r.figures;
  const grid::DualStats& s = r.stats;
  f.grid_tets = s.grid_tets, f.tets = s.tets, f.flat = s.flat, f.inverted = s.inverted, f.folded = s.folded;
  f.open_facets = s.open_facets, f.overshared_facets = s.overshared_facets;
  f.overlapping_facets = s.overlapping_facets, f.cospherical_pairs = s.cospherical_pairs;
  f.non_delaunay_pairs = s.non_delaunay_pairs;
  f.empty_sphere_tets = static_cast<std::int64_t>(r.dt.size());
  f.dual_empty_sphere = std::count(r.empty_sphere.begin(), r.empty_sphere.end(), true);
  f.hull_facets = r.dt_unique ? static_cast<std::int64_t>(r.hull.size()) : -1;
  f.off_hull_facets = r.dt_unique ? static_cast<std::int64_t>(r.off_hull.size()) : -1;
  f.split_regions = std::count_if(r.pieces.begin(), r.pieces.end(), [](int p) { return p > 1; });
  f.vertex_blocks = static_cast<std::int64_t>(r.blocks.size());
  return r;
}

// The colouring of sites given in grid units ([0, W)³, voxel = floor of the coordinates)
// by the real digital Voronoi code (star4d PBA).
template <class B>
std::vector<std::int32_t> pba_colouring(par::Context<B>& ctx, int W, const std::vector<double>& xyz) {
  par::Buffer<double, B> x(ctx);
  x.assign(xyz);
  const double lo[3] = {0, 0, 0}, hi[3] = {double(W), double(W), double(W)};
  star4d::PbaOptions po;
  po.grid = W;
  return star4d::digital_voronoi(ctx, x.data(), static_cast<std::int64_t>(xyz.size() / 3), lo, hi, po).site.to_host();
}

// The examples. Sites are in grid units (voxel = floor of the coordinates); the "pba"
// ones are coloured by star4d::digital_voronoi, the sites found by a random search over
// multiples of 1/16 for the phenomenon named (docs/grid.md).
template <class B>
std::vector<Example> grid_dual_examples(par::Context<B>& ctx) {
  // figures: grid_tets tets flat inverted folded open_facets overshared_facets
  //          overlapping_facets cospherical_pairs non_delaunay_pairs empty_sphere_tets
  //          dual_empty_sphere hull_facets off_hull_facets split_regions vertex_blocks
  std::vector<Example> out;
  auto pba = [&](std::string name, std::string title, int W, std::vector<double> xyz, Figures expect) {
    Example e{std::move(name), std::move(title), "pba", W, std::move(xyz), {}, expect};
    e.site = pba_colouring(ctx, W, e.xyz);
    out.push_back(std::move(e));
  };
  // (a) negative result 1: a digital Voronoi colouring whose dual folds
  pba("folds", "9 points, 8^3 grid: the dual has inverted, folded and overlapping site tets", 8,
      {0.875, 2.8125, 4.3125, 3.3125, 6.4375, 3.5,    6.25,   7,      4.8125, 3.25,  3.375,  4.8125, 4.9375, 2.6875,
       1.5,   5.9375, 7.125,  3.6875, 5.75,   7.25,   5.5,    4.1875, 3.6875, 6.9375, 3.4375, 2.4375, 5.875},
      figures({16, 14, 0, 2, 1, 12, 0, 4, 0, 2, 14, 9, 12, 0, 0, 2}));
  // (b) negative result 2 and the grid perturbation: one 2×2×2 block of 8 colours
  std::vector<double> lattice, perturbed;
  const double dx[24] = {-1, -2, 2,  2,  -2, 0,  0,  2,  2, 2, -1, -2, -1, 2, 0, -1,
                         -2, -1, 1,  1,  -1, -1, 0,  -1};
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a) {
      lattice.push_back(((k >> a) & 1) + 0.5);
      perturbed.push_back(lattice.back() + dx[3 * k + a] / 16.0);
    }
  pba("vertex-lattice", "8 sites at the centres of a 2x2x2 block: cospherical, 74 triangulations; Kuhn picks 6 tets", 2,
      lattice, figures({6, 6, 0, 0, 0, 12, 0, 0, 6, 0, 58, 6, -1, -1, 0, 1}));
  pba("vertex", "the same block with the sites moved: Kuhn's 6 tets are valid but not the Delaunay ones", 2, perturbed,
      figures({6, 6, 0, 0, 0, 12, 0, 0, 0, 1, 6, 4, 12, 2, 0, 1}));
  // (c) topology: a facet in three site tets; a Delaunay tet no grid tet dualizes
  pba("overshared", "7 points, 6^3 grid: a spurious folded site tet, one facet in three tets", 6,
      {3.25, 2.125, 1.5,    0.75,   5.3125, 4.25,  1.125, 0.5, 2.75, 3,   3.1875,
       5.3125, 4.875, 2,    2.3125, 5.3125, 4,     1.125, 2.9375, 1.5, 5},
      figures({9, 8, 0, 1, 1, 9, 1, 2, 0, 0, 7, 7, 10, 1, 0, 1}));
  pba("split", "6 points, 8^3 grid: a digital region in two pieces, a spurious folded tet, a facet in three tets", 8,
      {4.625, 3.25, 2.4375, 5.4375, 4.8125, 4.9375, 2.1875, 2.875, 5.625, 4.625, 1.125, 7.1875, 4.125, 1.5625, 1.5625,
       3.6875, 1, 0.875},
      figures({6, 5, 0, 1, 1, 7, 1, 2, 0, 0, 5, 4, 8, 3, 1, 0}));
  pba("missing", "6 points, 8^3 grid: the dual misses one Delaunay tet (its boundary is not the hull)", 8,
      {2.9375, 7.25, 2.5625, 3.9375, 2.0625, 6, 3.125, 7.25, 6.75, 4.5, 7.25, 1.5625, 5.375, 7.25, 2.0625, 3, 0.625,
       6.6875},
      figures({4, 4, 0, 0, 0, 8, 0, 0, 0, 0, 5, 4, 8, 2, 0, 0}));
  // (d) the positive case
  pba("valid", "8 points, 8^3 grid: the dual is the Delaunay triangulation", 8,
      {6.125, 3.625, 4.5625, 1.5625, 3.4375, 5.25,   3.5,    1.1875, 3.375,  6.5625, 5.5625, 4.4375,
       1.8125, 2,    2.75,   6.375,  7.25,   6.625,  5.1875, 7.1875, 5.25,   2.9375, 4.1875, 2.375},
      figures({6, 6, 0, 0, 0, 12, 0, 0, 0, 0, 6, 6, 12, 0, 0, 1}));
  return out;
}

}  // namespace gdel::examples
