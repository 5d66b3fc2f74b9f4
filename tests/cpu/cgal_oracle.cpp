// Tests of the CGAL oracle (tests/oracle/cgal_oracle.hpp) and of canonical()
// (src/mesh/canonical.hpp). The oracle is checked against independent exact GMP
// predicates: orientation of every tet, the empty-(power-)sphere property by brute
// force on small inputs and locally on larger ones, and the combinatorics (each
// face in at most two tets with opposite orientations, Euler characteristic 1, hull
// of a triangulated sphere).
#include "oracle/cgal_oracle.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "mesh/canonical.hpp"
#include "mesh/conventions.hpp"

namespace {

using gdel::oracle::Tet;

std::vector<double> random_points(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  for (auto& v : xyz) v = u(rng);
  return xyz;
}

// 8 corners of the unit cube (index = 4x + 2y + z) and its centre (index 8).
std::vector<double> cube_and_centre() {
  std::vector<double> xyz;
  for (int i = 0; i < 8; ++i) {
    xyz.push_back((i >> 2) & 1);
    xyz.push_back((i >> 1) & 1);
    xyz.push_back(i & 1);
  }
  xyz.insert(xyz.end(), {0.5, 0.5, 0.5});
  return xyz;
}

// ---------------------------------------------------------------------------
// Exact GMP predicates (independent of CGAL)
// ---------------------------------------------------------------------------

// The input as exact integers: every finite double is M * 2^(e-53) with an integer
// mantissa M, so scaling all coordinates by one power of two 2^K (and the weights by
// 2^2K, so power distances scale uniformly) makes them integers exactly. Both
// predicates below are invariant in sign under that scaling (orientation scales by
// 2^3K, the lifted determinant by 2^5K), and mpz arithmetic is much faster than mpq.
struct ExactPoints {
  std::vector<std::array<mpz_class, 3>> p;
  std::vector<mpz_class> w;

  ExactPoints(const std::vector<double>& xyz, const std::vector<double>* weights = nullptr) {
    const std::size_t n = xyz.size() / 3;
    int k = 0;  // fractional bits needed
    for (double v : xyz) k = std::max(k, fraction_bits(v));
    if (weights)
      for (double v : *weights) k = std::max(k, (fraction_bits(v) + 1) / 2);
    p.resize(n);
    w.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int a = 0; a < 3; ++a) p[i][a] = scaled(xyz[3 * i + a], k);
      w[i] = weights ? scaled((*weights)[i], 2 * k) : mpz_class(0);
    }
  }

  static int fraction_bits(double v) {
    if (v == 0.0) return 0;
    int e = 0;
    std::frexp(v, &e);  // v = f * 2^e, 0.5 <= |f| < 1
    return std::max(0, 53 - e);
  }

  // v * 2^k as an exact integer (k at least fraction_bits(v)).
  static mpz_class scaled(double v, int k) {
    if (v == 0.0) return 0;
    int e = 0;
    const double f = std::frexp(v, &e);
    mpz_class m(static_cast<long>(std::ldexp(f, 53)));  // exact 53-bit mantissa
    const int shift = e - 53 + k;
    EXPECT_GE(shift, 0);
    mpz_mul_2exp(m.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
    return m;
  }
};

int sign(const mpz_class& v) { return sgn(v); }

mpz_class det3(const mpz_class m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// sign det[b-a, c-a, d-a]: gdel's orient3d.
int orient_gmp(const ExactPoints& P, int a, int b, int c, int d) {
  mpz_class m[3][3];
  const int r[3] = {b, c, d};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = P.p[r[i]][k] - P.p[a][k];
  return sign(det3(m));
}

// +1 if e is strictly in conflict with the tet (a,b,c,d) (strictly inside its
// power sphere; for zero weights: inside its circumsphere), 0 if on it, -1 if not.
// Lifted determinant D with rows (p - a, |p - a|^2 - w_p + w_a), p = b, c, d, e.
// Writing A for the 3x3 block and o for the tet's orthocentre (relative to a),
// A o = l/2 gives D = det(A) * (|e - o|^2 - r^2 - w_e), r the orthoradius: so e is
// in conflict (below the lifted tet) iff D * orient(a,b,c,d) < 0.
int conflict_gmp(const ExactPoints& P, int a, int b, int c, int d, int e) {
  mpz_class m[4][4];
  const int r[4] = {b, c, d, e};
  for (int i = 0; i < 4; ++i) {
    mpz_class lift = 0;
    for (int k = 0; k < 3; ++k) {
      m[i][k] = P.p[r[i]][k] - P.p[a][k];
      lift += m[i][k] * m[i][k];
    }
    m[i][3] = lift - P.w[r[i]] + P.w[a];
  }
  mpz_class det = 0;
  for (int col = 0; col < 4; ++col) {
    mpz_class minor[3][3];
    for (int i = 1; i < 4; ++i)
      for (int k = 0, kk = 0; k < 4; ++k)
        if (k != col) minor[i - 1][kk++] = m[i][k];
    const mpz_class term = m[0][col] * det3(minor);
    if (col % 2 == 0)
      det += term;
    else
      det -= term;
  }
  return -sign(det) * orient_gmp(P, a, b, c, d);
}

TEST(GmpPredicates, Calibration) {
  // Unit tetrahedron: positively oriented; its circumcentre (.5,.5,.5) has R^2 = .75.
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25, 0.25, 0.25, 2, 2, 2, 1, 1, 0};
  const ExactPoints P(xyz);
  EXPECT_EQ(orient_gmp(P, 0, 1, 2, 3), 1);
  EXPECT_EQ(orient_gmp(P, 0, 2, 1, 3), -1);
  EXPECT_EQ(conflict_gmp(P, 0, 1, 2, 3, 4), 1);   // inside
  EXPECT_EQ(conflict_gmp(P, 0, 1, 2, 3, 5), -1);  // outside
  EXPECT_EQ(conflict_gmp(P, 0, 1, 2, 3, 6), 0);   // (1,1,0) is on the sphere
  EXPECT_EQ(conflict_gmp(P, 0, 2, 1, 3, 4), 1);   // independent of orientation
}

// ---------------------------------------------------------------------------
// Combinatorial checks
// ---------------------------------------------------------------------------

struct Topology {
  long vertices = 0, edges = 0, faces = 0, tets = 0;
  long hull_faces = 0, hull_vertices = 0;
  bool face_consistent = true;  // each face in 1 or 2 tets, opposite orientations when 2
  long euler() const { return vertices - edges + faces - tets; }
};

// Oriented face (a,b,c) rotated so the smallest index comes first (cyclic rotation
// keeps the orientation).
std::array<int, 3> oriented_face(int a, int b, int c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

Topology topology(const std::vector<Tet>& tets) {
  Topology t;
  t.tets = static_cast<long>(tets.size());
  std::set<int> verts;
  std::set<std::pair<int, int>> edges;
  std::map<std::array<int, 3>, std::vector<std::array<int, 3>>> faces;
  for (const Tet& tet : tets) {
    for (int v : tet) verts.insert(v);
    for (int e = 0; e < 6; ++e) {
      const int a = tet[gdel::edge_vertex(e, 0)], b = tet[gdel::edge_vertex(e, 1)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    for (int i = 0; i < 4; ++i) {
      const int a = tet[gdel::face_vertex(i, 0)], b = tet[gdel::face_vertex(i, 1)], c = tet[gdel::face_vertex(i, 2)];
      std::array<int, 3> key = {a, b, c};
      std::sort(key.begin(), key.end());
      faces[key].push_back(oriented_face(a, b, c));
    }
  }
  t.vertices = static_cast<long>(verts.size());
  t.edges = static_cast<long>(edges.size());
  t.faces = static_cast<long>(faces.size());
  std::set<int> hull_verts;
  for (const auto& [key, uses] : faces) {
    if (uses.size() == 1) {
      ++t.hull_faces;
      hull_verts.insert(key.begin(), key.end());
    } else if (uses.size() != 2 || uses[0] == uses[1]) {
      t.face_consistent = false;
    }
  }
  t.hull_vertices = static_cast<long>(hull_verts.size());
  return t;
}

void expect_positive_orientation(const std::vector<double>& xyz, const std::vector<Tet>& tets, bool with_gmp) {
  std::unique_ptr<ExactPoints> P;
  if (with_gmp) P = std::make_unique<ExactPoints>(xyz);
  for (const Tet& t : tets) {
    ASSERT_EQ(gdel::oracle::cgal_orientation(xyz, t[0], t[1], t[2], t[3]), 1);
    if (with_gmp) {
      ASSERT_EQ(orient_gmp(*P, t[0], t[1], t[2], t[3]), 1);
    }
  }
}

// No point of xyz (vertex of the tet or not) is strictly in conflict with any tet.
void expect_empty_spheres_brute_force(const std::vector<double>& xyz, const std::vector<Tet>& tets,
                                      const std::vector<double>* weights = nullptr) {
  const ExactPoints P(xyz, weights);
  const int n = static_cast<int>(xyz.size() / 3);
  for (const Tet& t : tets)
    for (int e = 0; e < n; ++e) {
      if (e == t[0] || e == t[1] || e == t[2] || e == t[3]) continue;
      ASSERT_LE(conflict_gmp(P, t[0], t[1], t[2], t[3], e), 0) << "point " << e << " in conflict";
    }
}

// Local Delaunay: across every interior face, the opposite vertex of the neighbour is
// not strictly inside the tet's sphere (with a valid triangulation, this implies the
// global property).
void expect_locally_delaunay(const std::vector<double>& xyz, const std::vector<Tet>& tets) {
  const ExactPoints P(xyz);
  std::map<std::array<int, 3>, std::vector<std::pair<int, int>>> faces;  // (tet, local vertex opposite)
  for (int ti = 0; ti < static_cast<int>(tets.size()); ++ti)
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> key = {tets[ti][gdel::face_vertex(i, 0)], tets[ti][gdel::face_vertex(i, 1)],
                                tets[ti][gdel::face_vertex(i, 2)]};
      std::sort(key.begin(), key.end());
      faces[key].push_back({ti, i});
    }
  for (const auto& [key, uses] : faces) {
    if (uses.size() != 2) continue;
    const Tet& t = tets[uses[0].first];
    const int e = tets[uses[1].first][uses[1].second];
    ASSERT_LE(conflict_gmp(P, t[0], t[1], t[2], t[3], e), 0);
  }
}

void expect_sane_triangulation(const std::vector<Tet>& tets, long expected_vertices) {
  const Topology t = topology(tets);
  EXPECT_EQ(t.vertices, expected_vertices);
  EXPECT_TRUE(t.face_consistent);
  EXPECT_EQ(t.euler(), 1);  // a triangulated ball
  EXPECT_EQ(t.hull_faces, 2 * t.hull_vertices - 4);  // a triangulated sphere
  // Each tet has 4 faces: 4T = 2 F_interior + F_hull.
  EXPECT_EQ(4 * t.tets, 2 * (t.faces - t.hull_faces) + t.hull_faces);
}

// ---------------------------------------------------------------------------
// Delaunay
// ---------------------------------------------------------------------------

TEST(CgalOracle, CubeCornersAndCentre) {
  const auto xyz = cube_and_centre();
  const auto tets = gdel::oracle::cgal_delaunay(xyz);
  // The centre is inside the circumsphere of every corner tet, so it is joined to
  // the 12 triangles of the 6 split square faces: exactly 12 tets, all with it.
  ASSERT_EQ(tets.size(), 12u);
  for (const Tet& t : tets) EXPECT_NE(std::find(t.begin(), t.end(), 8), t.end());
  expect_positive_orientation(xyz, tets, true);
  expect_empty_spheres_brute_force(xyz, tets);
  const Topology topo = topology(tets);
  EXPECT_EQ(topo.vertices, 9);
  EXPECT_EQ(topo.edges, 26);   // 12 cube edges + 6 face diagonals + 8 spokes
  EXPECT_EQ(topo.faces, 30);   // 12 hull + 18 interior
  EXPECT_EQ(topo.hull_faces, 12);
  EXPECT_TRUE(topo.face_consistent);
  EXPECT_EQ(topo.euler(), 1);
}

TEST(CgalOracle, RandomPointsSmallBruteForce) {
  const auto xyz = random_points(120, 1);
  const auto tets = gdel::oracle::cgal_delaunay(xyz);
  expect_positive_orientation(xyz, tets, true);
  expect_sane_triangulation(tets, 120);
  expect_empty_spheres_brute_force(xyz, tets);
}

TEST(CgalOracle, RandomPointsLarger) {
  const int n = 3000;
  const auto xyz = random_points(n, 2);
  const auto tets = gdel::oracle::cgal_delaunay(xyz);
  // Uniform points: about 6.5 tets per point (away from the boundary).
  EXPECT_GT(tets.size(), 5u * n);
  EXPECT_LT(tets.size(), 7u * n);
  expect_positive_orientation(xyz, tets, true);
  expect_sane_triangulation(tets, n);
  expect_locally_delaunay(xyz, tets);
}

TEST(CgalOracle, OrientationAgreesWithGmp) {
  // Integer grid points: many exactly coplanar quadruples, so all three signs occur.
  std::vector<double> xyz;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
  const auto rnd = random_points(20, 3);
  xyz.insert(xyz.end(), rnd.begin(), rnd.end());
  const ExactPoints P(xyz);
  const int n = static_cast<int>(xyz.size() / 3);
  std::mt19937 rng(4);
  int seen[3] = {0, 0, 0};
  for (int i = 0; i < 5000; ++i) {
    const int a = rng() % n, b = rng() % n, c = rng() % n, d = rng() % n;
    const int s = gdel::oracle::cgal_orientation(xyz, a, b, c, d);
    ASSERT_EQ(s, orient_gmp(P, a, b, c, d));
    ++seen[s + 1];
  }
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[1], 0);
  EXPECT_GT(seen[2], 0);
  EXPECT_THROW(gdel::oracle::cgal_orientation(xyz, 0, 1, 2, n), std::out_of_range);
}

TEST(CgalOracle, DuplicatesKeepLowestIndex) {
  auto xyz = random_points(200, 5);
  auto copy_point = [&](int from, int to) {
    for (int a = 0; a < 3; ++a) xyz[3 * to + a] = xyz[3 * from + a];
  };
  copy_point(3, 100);  // 100 duplicates 3: 3 is kept
  xyz.insert(xyz.end(), {xyz[3 * 17], xyz[3 * 17 + 1], xyz[3 * 17 + 2]});  // 200 duplicates 17
  xyz.insert(xyz.end(), {xyz[3 * 17], xyz[3 * 17 + 1], xyz[3 * 17 + 2]});  // 201 too
  const auto tets = gdel::oracle::cgal_delaunay(xyz);
  std::set<int> used;
  for (const Tet& t : tets) used.insert(t.begin(), t.end());
  EXPECT_EQ(used.size(), 199u);
  EXPECT_TRUE(used.count(3));
  EXPECT_TRUE(used.count(17));
  EXPECT_FALSE(used.count(100));
  EXPECT_FALSE(used.count(200));
  EXPECT_FALSE(used.count(201));
  expect_sane_triangulation(tets, 199);
  // Same tets as without the copies (index 100 removed: renumber its successors).
  std::vector<double> unique_xyz(xyz.begin(), xyz.begin() + 3 * 200);
  unique_xyz.erase(unique_xyz.begin() + 300, unique_xyz.begin() + 303);
  auto ref = gdel::oracle::cgal_delaunay(unique_xyz);
  for (Tet& t : ref)
    for (int& v : t)
      if (v >= 100) ++v;
  EXPECT_EQ(gdel::oracle::canonical(tets), gdel::oracle::canonical(ref));
  // Signed zeros are the same point.
  const std::vector<double> z = {0.0, 0.0, 0.0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -0.0, 0.0, -0.0};
  const auto zt = gdel::oracle::cgal_delaunay(z);
  ASSERT_EQ(zt.size(), 1u);
  EXPECT_EQ(gdel::canonical_tet(zt[0]), (Tet{0, 1, 2, 3}));
}

TEST(CgalOracle, DegenerateAndInvalidInput) {
  EXPECT_TRUE(gdel::oracle::cgal_delaunay({}).empty());
  EXPECT_TRUE(gdel::oracle::cgal_delaunay({0, 0, 0, 1, 0, 0, 0, 1, 0}).empty());  // 3 points
  std::vector<double> planar;
  for (int i = 0; i < 30; ++i) planar.insert(planar.end(), {double(i % 7), double(i / 7), 2.0});
  EXPECT_TRUE(gdel::oracle::cgal_delaunay(planar).empty());
  EXPECT_THROW(gdel::oracle::cgal_delaunay({0, 0}), std::invalid_argument);
  EXPECT_THROW(gdel::oracle::cgal_delaunay({0, 0, std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
  EXPECT_THROW(gdel::oracle::cgal_delaunay({0, 0, std::numeric_limits<double>::infinity()}), std::invalid_argument);
  EXPECT_THROW(gdel::oracle::cgal_regular({0, 0, 0}, {}), std::invalid_argument);
  EXPECT_THROW(gdel::oracle::cgal_regular({0, 0, 0}, {std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);
}

// ---------------------------------------------------------------------------
// canonical()
// ---------------------------------------------------------------------------

TEST(Canonical, StableUnderEvenPermutationsAndOrder) {
  const auto xyz = random_points(400, 6);
  const auto tets = gdel::oracle::cgal_delaunay(xyz);
  const auto ref = gdel::oracle::canonical(tets);
  ASSERT_EQ(ref.size(), tets.size());
  EXPECT_TRUE(std::is_sorted(ref.begin(), ref.end()));
  for (const Tet& c : ref) {
    EXPECT_EQ(c[0], *std::min_element(c.begin(), c.end()));
    EXPECT_LT(c[1], c[2]);
    EXPECT_LT(c[1], c[3]);
  }
  std::mt19937 rng(7);
  std::array<int, 4> perm = {0, 1, 2, 3};
  std::vector<std::array<int, 4>> even, odd;
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    (inversions % 2 ? odd : even).push_back(perm);
  } while (std::next_permutation(perm.begin(), perm.end()));
  ASSERT_EQ(even.size(), 12u);
  ASSERT_EQ(odd.size(), 12u);
  const ExactPoints P(xyz);
  for (const Tet& t : tets) {
    const Tet c = gdel::canonical_tet(t);
    EXPECT_EQ(orient_gmp(P, c[0], c[1], c[2], c[3]), 1);  // orientation kept
    for (const auto& p : even) {
      const Tet r = {t[p[0]], t[p[1]], t[p[2]], t[p[3]]};
      ASSERT_EQ(gdel::canonical_tet(r), c);
      ASSERT_EQ(gdel::tet_permutation_parity(t, r), 0);
    }
    for (const auto& p : odd) {
      const Tet r = {t[p[0]], t[p[1]], t[p[2]], t[p[3]]};
      ASSERT_NE(gdel::canonical_tet(r), c);
      ASSERT_EQ(gdel::tet_permutation_parity(t, r), 1);
    }
  }
  // Shuffling the list and rotating every tet by a random even permutation gives the
  // same canonical list.
  auto shuffled = tets;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  for (Tet& t : shuffled) {
    const auto& p = even[rng() % 12];
    t = {t[p[0]], t[p[1]], t[p[2]], t[p[3]]};
  }
  EXPECT_EQ(gdel::oracle::canonical(shuffled), ref);
  // One flipped tet makes the lists differ.
  std::swap(shuffled[0][2], shuffled[0][3]);
  EXPECT_NE(gdel::oracle::canonical(shuffled), ref);
  EXPECT_EQ(gdel::tet_permutation_parity(Tet{0, 1, 2, 3}, Tet{0, 1, 2, 4}), -1);
  // Other index types.
  static_assert(gdel::canonical_tet(std::array<long long, 4>{9, 3, 7, 5}) == std::array<long long, 4>{3, 5, 7, 9});
}

// ---------------------------------------------------------------------------
// Regular
// ---------------------------------------------------------------------------

TEST(CgalOracle, RegularEqualWeightsIsDelaunay) {
  const int n = 2000;
  const auto xyz = random_points(n, 8);
  const auto del = gdel::oracle::cgal_delaunay(xyz);
  for (double w : {0.0, 0.25, -3.0}) {
    const auto reg = gdel::oracle::cgal_regular(xyz, std::vector<double>(n, w));
    EXPECT_TRUE(reg.redundant.empty());
    EXPECT_EQ(gdel::oracle::canonical(reg.tets), gdel::oracle::canonical(del)) << "weight " << w;
  }
}

TEST(CgalOracle, RegularLowWeightInsideIsRedundant) {
  // Cube corners of weight 1 and the centre of weight 0: the corners' orthosphere has
  // squared radius 0.75 - 1 < 0 and the centre's power 0.25 exceeds its weight.
  const auto cube = cube_and_centre();
  std::vector<double> w(9, 1.0);
  w[8] = 0.0;
  const auto reg = gdel::oracle::cgal_regular(cube, w);
  EXPECT_EQ(reg.redundant, std::vector<int>{8});
  EXPECT_GE(reg.tets.size(), 5u);
  EXPECT_LE(reg.tets.size(), 6u);
  expect_positive_orientation(cube, reg.tets, true);
  const Topology topo = topology(reg.tets);
  EXPECT_EQ(topo.vertices, 8);
  EXPECT_EQ(topo.euler(), 1);
  EXPECT_TRUE(topo.face_consistent);
  expect_empty_spheres_brute_force(cube, reg.tets, &w);

  // Random points of weight 0 plus one point of weight -1 among them: hidden, and the
  // rest is the Delaunay triangulation of the others.
  const int n = 1000;
  auto xyz = random_points(n, 9);
  const auto del = gdel::oracle::cgal_delaunay(xyz);
  xyz.insert(xyz.end(), {0.5, 0.5, 0.5});
  std::vector<double> wr(n + 1, 0.0);
  wr[n] = -1.0;
  const auto reg2 = gdel::oracle::cgal_regular(xyz, wr);
  EXPECT_EQ(reg2.redundant, std::vector<int>{n});
  EXPECT_EQ(gdel::oracle::canonical(reg2.tets), gdel::oracle::canonical(del));
}

TEST(CgalOracle, RegularSamePositionLargerWeightWins) {
  const int n = 300;
  auto xyz = random_points(n, 10);
  const auto del = gdel::oracle::cgal_delaunay(xyz);
  // Index n: same position as 5, larger weight -> 5 is redundant and n replaces it.
  // Index n+1: same position as 7, smaller weight -> n+1 is redundant.
  // Index n+2: same position and weight as 9 -> the higher index (n+2) is dropped.
  for (int src : {5, 7, 9}) xyz.insert(xyz.end(), {xyz[3 * src], xyz[3 * src + 1], xyz[3 * src + 2]});
  std::vector<double> w(n + 3, 0.0);
  w[n] = 1e-12;  // tiny, so no other point is affected
  w[n + 1] = -1e-12;
  const auto reg = gdel::oracle::cgal_regular(xyz, w);
  EXPECT_EQ(reg.redundant, (std::vector<int>{5, n + 1, n + 2}));
  auto expected = del;
  for (Tet& t : expected)
    for (int& v : t)
      if (v == 5) v = n;
  EXPECT_EQ(gdel::oracle::canonical(reg.tets), gdel::oracle::canonical(expected));
}

TEST(CgalOracle, RegularRandomWeightsBruteForce) {
  const int n = 120;
  const auto xyz = random_points(n, 11);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 0.02);
  std::vector<double> w(n);
  for (double& v : w) v = u(rng);
  const auto reg = gdel::oracle::cgal_regular(xyz, w);
  // Some points are hidden at this weight range, but not most.
  EXPECT_GT(reg.redundant.size(), 0u);
  EXPECT_LT(reg.redundant.size(), static_cast<std::size_t>(n / 2));
  expect_positive_orientation(xyz, reg.tets, true);
  expect_sane_triangulation(reg.tets, n - static_cast<long>(reg.redundant.size()));
  std::set<int> used;
  for (const Tet& t : reg.tets) used.insert(t.begin(), t.end());
  for (int r : reg.redundant) EXPECT_FALSE(used.count(r));
  // Regular: no point (redundant ones included) lies below any lifted tet.
  expect_empty_spheres_brute_force(xyz, reg.tets, &w);
}

// ---------------------------------------------------------------------------
// Parallel
// ---------------------------------------------------------------------------

TEST(CgalOracle, ParallelEqualsSequential) {
  const int n = 20000;
  const auto xyz = random_points(n, 13);
  if (!gdel::oracle::cgal_parallel_available()) {
    EXPECT_THROW(gdel::oracle::cgal_delaunay(xyz, true), std::runtime_error);
    GTEST_SKIP() << "oracle built without TBB";
  }
  const auto seq = gdel::oracle::cgal_delaunay(xyz, false);
  const auto par = gdel::oracle::cgal_delaunay(xyz, true);
  expect_positive_orientation(xyz, par, false);
  EXPECT_EQ(gdel::oracle::canonical(par), gdel::oracle::canonical(seq));

  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0.0, 1e-4);
  std::vector<double> w(n);
  for (double& v : w) v = u(rng);
  const auto rseq = gdel::oracle::cgal_regular(xyz, w, false);
  const auto rpar = gdel::oracle::cgal_regular(xyz, w, true);
  EXPECT_EQ(rpar.redundant, rseq.redundant);
  expect_positive_orientation(xyz, rpar.tets, false);
  EXPECT_EQ(gdel::oracle::canonical(rpar.tets), gdel::oracle::canonical(rseq.tets));
}

}  // namespace
