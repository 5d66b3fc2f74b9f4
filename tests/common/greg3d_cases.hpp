// gReg3D cases shared by the CPU and GPU test programs: gdel::regular's result passes
// every check of the exact verifier in regular mode (valid triangulation of the hull,
// every facet locally regular, every unused point redundant, no flat tet), its
// neighbours are complete, every redundancy certificate holds exactly, the star
// splaying converged without the certificate's retry, and the result is deterministic.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "gdel/errors.hpp"
#include "gdel/regular.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"
#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"

namespace gdel::test {

inline std::vector<std::array<std::int32_t, 4>> sorted_tets(const std::vector<std::int32_t>& t) {
  std::vector<std::array<std::int32_t, 4>> out(t.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < 4; ++k) out[i][k] = t[4 * i + k];
    std::sort(out[i].begin(), out[i].end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Sign of the raw lifted 5x5 determinant of points q[0..4] (power test convention).
inline int lifted_det(const std::vector<double>& P, const std::vector<double>& W, const std::int32_t* q) {
  std::vector<double> work(geom::kPredicateWork);
  auto p = [&](int i) { return P.data() + 3 * static_cast<std::size_t>(q[i]); };
  return geom::power(p(0), p(1), p(2), p(3), p(4), W[q[0]], W[q[1]], W[q[2]], W[q[3]], W[q[4]], work.data());
}

inline void expect_certificates(const std::vector<double>& P, const std::vector<double>& W,
                                const RegularTriangulation& r) {
  ASSERT_EQ(r.certificates.size(), 5 * r.redundant.size());
  std::vector<double> work(geom::kPredicateWork);
  auto p = [&](std::int32_t i) { return P.data() + 3 * static_cast<std::size_t>(i); };
  for (std::size_t j = 0; j < r.redundant.size(); ++j) {
    const std::int32_t s = r.redundant[j];
    const std::int32_t* c = r.certificates.data() + 5 * j;
    SCOPED_TRACE("redundant point " + std::to_string(s));
    if (c[1] < 0) {  // duplicate of a point at least as heavy
      ASSERT_GE(c[0], 0);
      EXPECT_EQ(P[3 * s], P[3 * c[0]]);
      EXPECT_EQ(P[3 * s + 1], P[3 * c[0] + 1]);
      EXPECT_EQ(P[3 * s + 2], P[3 * c[0] + 2]);
      EXPECT_GE(W[c[0]], W[s]);
    } else if (c[4] < 0) {  // the tet (c0..c3) holds s, whose lifted point is not below
      for (int f = 0; f < 4; ++f)
        EXPECT_GE(geom::orient3d(p(c[face_vertex(f, 0)]), p(c[face_vertex(f, 1)]), p(c[face_vertex(f, 2)]), p(s),
                                 work.data()),
                  0);
      EXPECT_LE(geom::power(p(c[0]), p(c[1]), p(c[2]), p(c[3]), p(s), W[c[0]], W[c[1]], W[c[2]], W[c[3]], W[s],
                            work.data()),
                0);
    } else {  // s inside the lifted 4-simplex c: on the side of each facet that holds the
              // opposite vertex (or on the facet: exact ties are allowed here)
      for (int f = 0; f < 5; ++f) {
        std::int32_t a[5], b[5];
        int k = 0;
        for (int i = 0; i < 5; ++i)
          if (i != f) a[k] = b[k] = c[i], ++k;
        a[4] = c[f];
        b[4] = s;
        const int so = lifted_det(P, W, a), ss = lifted_det(P, W, b);
        EXPECT_NE(so, 0);
        EXPECT_TRUE(ss == 0 || ss == so) << "facet " << f;
      }
    }
  }
}

inline void expect_exact_regular(const std::vector<double>& P, const std::vector<double>& W,
                                 const RegularTriangulation& r, Backend b) {
  auto rep = verify(P, r.tets, W, b);
  SCOPED_TRACE(rep.summary());
  SCOPED_TRACE(r.stats.to_string());
  EXPECT_EQ(r.stats.algorithm, "greg3d");
  EXPECT_TRUE(rep.valid());
  EXPECT_TRUE(rep.delaunay());
  EXPECT_EQ(rep.non_delaunay_facets, 0);
  EXPECT_EQ(rep.degenerate_tets, 0);
  EXPECT_EQ(rep.unused_points, 0);
  EXPECT_EQ(rep.locate_failures, 0);
  EXPECT_EQ(r.stats.certificate_fallbacks, 0);
  // redundant = exactly the input ids that are not vertices
  const std::size_t n = W.size();
  std::vector<char> used(n, 0);
  for (std::int32_t v : r.tets) used[static_cast<std::size_t>(v)] = 1;
  std::vector<std::int32_t> unused;
  for (std::size_t i = 0; i < n; ++i)
    if (!used[i]) unused.push_back(static_cast<std::int32_t>(i));
  EXPECT_EQ(r.redundant, unused);
  // neighbours: complete and mutual, -1 exactly on hull faces
  const std::size_t m = r.tets.size() / 4;
  ASSERT_EQ(r.neighbors.size(), 4 * m);
  std::map<std::array<std::int32_t, 3>, int> faces;
  std::int64_t bad = 0;
  for (std::size_t t = 0; t < m; ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<std::int32_t, 3> k = {r.tets[4 * t + face_vertex(f, 0)], r.tets[4 * t + face_vertex(f, 1)],
                                       r.tets[4 * t + face_vertex(f, 2)]};
      std::sort(k.begin(), k.end());
      ++faces[k];
      const std::int32_t u = r.neighbors[4 * t + f];
      if (u < 0) continue;
      bool back = false;
      for (int g = 0; g < 4; ++g) back = back || r.neighbors[4 * static_cast<std::size_t>(u) + g] == std::int32_t(t);
      if (!back) ++bad;
    }
  std::int64_t hull = 0, minus = 0;
  for (auto& [k, c] : faces) hull += c == 1;
  for (std::int32_t u : r.neighbors) minus += u < 0;
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(minus, hull);
  if (!r.certificates.empty() || r.redundant.empty()) expect_certificates(P, W, r);
}

// Weights: scale * h^2 * U(0, 1) with h the mean spacing (0: none redundant, larger: more).
inline std::vector<double> random_weights(std::size_t n, double extent, double scale, unsigned seed,
                                          double lo = 0.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, 1.0);
  const double h = extent / std::cbrt(static_cast<double>(n));
  std::vector<double> w(n);
  for (double& x : w) x = scale * h * h * u(rng);
  return w;
}

inline void greg3d_generator_cases(Backend b, std::size_t n) {
  using gen::Distribution;
  Options o;
  o.backend = b;
  o.certificates = true;
  for (Distribution d : {Distribution::Uniform, Distribution::Gaussian, Distribution::Ball, Distribution::Grid}) {
    if (d == Distribution::Grid) n = std::min<std::size_t>(n, 5000);  // (see gstar4d_cases.hpp)
    auto pts = gen::generate(d, n, 777);
    const double extent = d == Distribution::Grid ? 512.0 : d == Distribution::Gaussian ? 0.6 : 1.0;
    std::size_t last = 0;
    for (double scale : {0.0, 0.3, 3.0, 30.0}) {
      SCOPED_TRACE(std::string(gen::to_string(d)) + " weight scale " + std::to_string(scale));
      auto w = random_weights(n, extent, scale, 99);
      RegularTriangulation r = regular(pts, w, o);
      expect_exact_regular(pts, w, r, b);
      if (scale == 0.0) {
        EXPECT_TRUE(r.redundant.empty());
      }
      if (scale == 30.0) {
        EXPECT_GT(r.redundant.size(), n / 2);  // most hidden
      }
      EXPECT_GE(r.redundant.size(), last);
      last = r.redundant.size();
      RegularTriangulation r2 = regular(pts, w, o);  // deterministic
      EXPECT_EQ(r.tets, r2.tets);
      EXPECT_EQ(r.redundant, r2.redundant);
    }
  }
}

// All weights equal: exactly the Delaunay triangulation (same perturbation).
inline void greg3d_equal_weights_case(Backend b, std::size_t n) {
  using gen::Distribution;
  for (Distribution d : {Distribution::Uniform, Distribution::Grid, Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    // (exactly cospherical input: huge hull stars, one thread each; see gstar4d_cases.hpp)
    auto pts = gen::generate(d, d == gen::Distribution::Sphere ? std::min<std::size_t>(n, 500) : n, 31);
    std::vector<double> w(pts.size() / 3, 0.75);
    Options o;
    o.backend = b;
    RegularTriangulation r = regular(pts, w, o);
    expect_exact_regular(pts, w, r, b);
    Triangulation t = delaunay(pts, o);
    EXPECT_TRUE(r.redundant.empty());
    EXPECT_EQ(sorted_tets(r.tets), sorted_tets(t.tets));
  }
}

// Molecule-like input: atoms along a random chain (bond 1.5), radii of C/N/O/H-like
// sizes, weight = radius^2; most interior atoms' spheres overlap heavily.
inline std::vector<double> molecule(std::size_t n, unsigned seed, std::vector<double>& w) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 3);
  const double radii[4] = {1.7, 1.55, 1.52, 1.2};
  std::vector<double> P;
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    double d[3] = {g(rng), g(rng), g(rng)};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int a = 0; a < 3; ++a) x[a] += 1.5 * d[a] / l;
    // fold the chain back into a globule of radius ~ n^(1/3)
    const double rr = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), lim = 2.0 * std::cbrt(double(n));
    if (rr > lim)
      for (int a = 0; a < 3; ++a) x[a] *= lim / rr;
    P.insert(P.end(), {x[0], x[1], x[2]});
    const double r = radii[kind(rng)];
    w.push_back(r * r);
  }
  return P;
}

inline void greg3d_special_cases(Backend b) {
  Options o;
  o.backend = b;
  o.certificates = true;
  {
    SCOPED_TRACE("molecule");
    std::vector<double> w;
    auto P = molecule(3000, 5, w);
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
  }
  {
    SCOPED_TRACE("grid points with two weights");
    std::vector<double> P, w;
    for (int i = 0; i < 12 * 12 * 12; ++i) {
      P.insert(P.end(), {double(i % 12), double((i / 12) % 12), double(i / 144)});
      w.push_back((i * 7919) % 3 == 0 ? 0.3 : 0.0);
    }
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
  }
  {
    SCOPED_TRACE("cube corners hide a light centre");
    std::vector<double> P, w;
    for (int i = 0; i < 8; ++i) {
      P.insert(P.end(), {double(i & 1), double((i >> 1) & 1), double(i >> 2)});
      w.push_back(1.0);
    }
    P.insert(P.end(), {0.5, 0.5, 0.5});
    w.push_back(0.0);
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
    EXPECT_EQ(r.redundant, std::vector<std::int32_t>{8});
  }
  {
    SCOPED_TRACE("duplicates: the heaviest copy stays");
    auto P = gen::generate(gen::Distribution::Uniform, 500, 3);
    std::vector<double> w(500, 0.0);
    for (int src : {5, 7, 9}) P.insert(P.end(), {P[3 * src], P[3 * src + 1], P[3 * src + 2]});
    w.insert(w.end(), {1e-12, -1e-12, 0.0});
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
    EXPECT_EQ(r.redundant, (std::vector<std::int32_t>{5, 501, 502}));
    EXPECT_EQ(r.representative[5], 500);
    EXPECT_EQ(r.representative[501], 7);
    EXPECT_EQ(r.representative[502], 9);
  }
  {
    SCOPED_TRACE("four distinct points (one duplicate): a single tetrahedron, no 4-D star possible");
    const std::vector<double> P = {0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 0};  // found by hypothesis
    const std::vector<double> w(5, 0.0);
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
    EXPECT_EQ(r.num_tets(), 1);
    EXPECT_EQ(r.redundant, std::vector<std::int32_t>{1});
    Options d = o;
    d.algorithm = Algorithm::gstar4d;
    const Triangulation t = delaunay(P, d);
    EXPECT_EQ(t.num_tets(), 1);
    EXPECT_EQ(t.stats.certificate_fallbacks, 0);
    EXPECT_EQ(t.neighbors, std::vector<std::int32_t>(4, -1));
  }
  {
    SCOPED_TRACE("points on two planes one ulp apart: no double inside any tetrahedron");
    const double u = std::ldexp(1.0, -52);
    std::vector<double> P, w;
    for (int i = 0; i < 300; ++i) {
      P.insert(P.end(), {1 + u * (i & 1), std::ldexp(double((i * 37) % 101), -7), std::ldexp(double((i * 53) % 97), -7)});
      w.push_back(std::ldexp(double((i * 29) % 7), -12));  // (some points hidden)
    }
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
    EXPECT_EQ(r.stats.kernel_point_centroid, 1);  // ∞'s kernel point: the exact centroid
  }
  {
    SCOPED_TRACE("negative and mixed weights");
    auto P = gen::generate(gen::Distribution::Uniform, 2000, 8);
    auto w = random_weights(2000, 1.0, 10.0, 4, -1.0);
    RegularTriangulation r = regular(P, w, o);
    expect_exact_regular(P, w, r, b);
  }
  // bad input
  auto P = gen::generate(gen::Distribution::Uniform, 50, 1);
  EXPECT_THROW(regular(P, std::vector<double>(49, 0.0), o), InvalidInput);
  std::vector<double> w(50, 0.0);
  w[17] = std::nan("");
  EXPECT_THROW(regular(P, w, o), InvalidInput);
  w[17] = 0;
  {  // a weight that the coordinates' exact scaling (here 2^-133) would flush to zero
    auto Q = P;
    for (double& x : Q) x *= 1e100;
    std::vector<double> wq(50, 0.0);
    wq[3] = 1e-300;
    EXPECT_THROW(regular(Q, wq, o), InvalidInput);
    wq[3] = 0.0;
    EXPECT_NO_THROW(regular(Q, wq, o));
  }
  Options g = o;
  g.algorithm = Algorithm::gdel3d;
  EXPECT_THROW(regular(P, w, g), InvalidInput);
}

}  // namespace gdel::test
