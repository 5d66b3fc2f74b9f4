// Inputs and corruptions for the verifier tests, shared by the CPU (CGAL) and GPU
// test programs.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"

namespace gdel::test {

using Tet = std::array<int, 4>;

inline std::vector<std::int32_t> flatten(const std::vector<Tet>& t) {
  std::vector<std::int32_t> f;
  f.reserve(t.size() * 4);
  for (auto& x : t) f.insert(f.end(), x.begin(), x.end());
  return f;
}

inline int exact_orient(const std::vector<double>& p, int a, int b, int c, int d) {
  std::vector<double> work(geom::kPredicateWork);
  return geom::orient3d_exact(&p[3 * a], &p[3 * b], &p[3 * c], &p[3 * d], work.data());
}
inline int exact_insphere(const std::vector<double>& p, const Tet& t, int e) {
  std::vector<double> work(geom::kPredicateWork);
  return geom::insphere_exact(&p[3 * t[0]], &p[3 * t[1]], &p[3 * t[2]], &p[3 * t[3]], &p[3 * e], work.data());
}

// Freudenthal (Kuhn) triangulation of the k x k x k cube grid: a valid Delaunay
// triangulation with many cospherical ties (each cube's 8 corners).
inline void kuhn_grid(int k, std::vector<double>& pts, std::vector<Tet>& tets) {
  const int s = k + 1;
  pts.clear();
  tets.clear();
  for (int z = 0; z < s; ++z)
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) pts.insert(pts.end(), {double(x), double(y), double(z)});
  auto id = [s](int x, int y, int z) { return x + s * (y + s * z); };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int z = 0; z < k; ++z)
    for (int y = 0; y < k; ++y)
      for (int x = 0; x < k; ++x)
        for (auto& p : perms) {
          int c[3] = {x, y, z};
          Tet t;
          t[0] = id(c[0], c[1], c[2]);
          for (int j = 0; j < 3; ++j) {
            c[p[j]]++;
            t[j + 1] = id(c[0], c[1], c[2]);
          }
          if (exact_orient(pts, t[0], t[1], t[2], t[3]) < 0) std::swap(t[2], t[3]);
          tets.push_back(t);
        }
}

// Applies one 2-3 flip to an interior facet whose two tets form a strictly convex
// double pyramid and whose facet is strictly locally Delaunay: the result is a
// valid triangulation with non-locally-Delaunay facets. Returns false if none found.
inline bool flip_one_facet(const std::vector<double>& p, std::vector<Tet>& tets) {
  // index facets by sorted triple
  struct F {
    std::array<int, 3> key;
    int tet, face;
  };
  std::vector<F> fs;
  for (int t = 0; t < int(tets.size()); ++t)
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> k = {tets[t][face_vertex(i, 0)], tets[t][face_vertex(i, 1)], tets[t][face_vertex(i, 2)]};
      std::sort(k.begin(), k.end());
      fs.push_back({k, t, i});
    }
  std::sort(fs.begin(), fs.end(), [](const F& a, const F& b) { return a.key < b.key; });
  for (std::size_t j = 0; j + 1 < fs.size(); ++j) {
    if (fs[j].key != fs[j + 1].key) continue;
    const Tet t1 = tets[fs[j].tet], t2 = tets[fs[j + 1].tet];
    const int d = t1[fs[j].face], e = t2[fs[j + 1].face];
    const int a = t1[face_vertex(fs[j].face, 0)], b = t1[face_vertex(fs[j].face, 1)],
              c = t1[face_vertex(fs[j].face, 2)];
    // (a,b,c,d) positive. New tets (a,b,e,d), (b,c,e,d), (c,a,e,d) must be positive.
    Tet n1 = {a, b, e, d}, n2 = {b, c, e, d}, n3 = {c, a, e, d};
    if (exact_orient(p, n1[0], n1[1], n1[2], n1[3]) <= 0 || exact_orient(p, n2[0], n2[1], n2[2], n2[3]) <= 0 ||
        exact_orient(p, n3[0], n3[1], n3[2], n3[3]) <= 0)
      continue;
    if (exact_insphere(p, t1, e) >= 0) continue;  // want a strictly LD facet, so the flip breaks it
    int lo = std::min(fs[j].tet, fs[j + 1].tet), hi = std::max(fs[j].tet, fs[j + 1].tet);
    tets.erase(tets.begin() + hi);
    tets.erase(tets.begin() + lo);
    tets.push_back(n1);
    tets.push_back(n2);
    tets.push_back(n3);
    return true;
  }
  return false;
}

enum class Corruption { None, FlipFacet, RemoveTet, InvertTet, DuplicateTet, LeaveOutPoint };

// Returns false if the corruption could not be applied to this input.
inline bool corrupt(Corruption c, std::vector<double>& p, std::vector<Tet>& tets, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  if (tets.empty()) return false;
  std::size_t k = rng() % tets.size();
  switch (c) {
    case Corruption::None: return true;
    case Corruption::FlipFacet: return flip_one_facet(p, tets);
    case Corruption::RemoveTet: tets.erase(tets.begin() + static_cast<long>(k)); return true;
    case Corruption::InvertTet: std::swap(tets[k][0], tets[k][1]); return true;
    case Corruption::DuplicateTet: tets.push_back(tets[k]); return true;
    case Corruption::LeaveOutPoint: {
      // a new point strictly inside tet k (its centroid is exact enough: it is only
      // required to be distinct and inside the hull)
      double c3[3] = {0, 0, 0};
      for (int v : tets[k])
        for (int a = 0; a < 3; ++a) c3[a] += p[3 * v + a] / 4;
      p.insert(p.end(), c3, c3 + 3);
      return true;
    }
  }
  return false;
}

}  // namespace gdel::test
