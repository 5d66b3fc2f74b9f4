// A point with double coordinates strictly inside a tetrahedron, found with exact
// predicates only (host code). gFlip3D stores one inside its first tetrahedron as the
// kernel point that stands for the point at infinity (docs/gflip3d.md, first tetrahedron).
//
// The rounded centroid first (.25 p0 + .25 p1 + .25 p2 + .25 p3: on integer input a
// multiple of 1/4, which keeps gFlip3D's integer stage for it). Where that misses the
// interior (a sliver), a search fixes one coordinate at a time, over the six axis orders
// (a, b, c):
//  * a: the doubles next to each vertex's a-coordinate (two on each side) and the middle
//    of the a-range. Doubles are densest near the vertices' coordinates (and near 0),
//    where a sliver's cross-section still holds some.
//  * b, for a fixed a = s: the open b-range of the cross-section is (min, max) of the
//    b-values at s of the edges that span s (the cross-section's corners). "t lies above
//    edge PQ at s" is an exact orient2d of the projection on (a, b), so the first double
//    above the minimum and the last below the maximum are found by bisection over the
//    doubles' order. Candidates: two doubles inside each end, two on each side of every
//    edge's value at s (the corners, where the cross-section is thickest in c) and the
//    middle.
//  * c, for fixed (s, t): the line meets the open tetrahedron in the doubles above every
//    lower face and below every upper face (a face is lower where its outward side is
//    -c). The first double above all lower faces (bisection again, each step exact
//    orient3d) is inside iff any double on the line is: complete on each line.
// Every candidate is checked with exact orient3d against all four faces, and every
// coordinate stays in the predicates' exact range (0 or 2^-152 <= |x| <= 2^200,
// geometry/predicates.hpp), so the point is as good an input to the predicates as the
// vertices. A tetrahedron whose interior holds no double at all (four points one ulp apart)
// has no such point; the search says so by returning false.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/predicates.hpp"

namespace gdel::geom {

namespace detail {

// The doubles that coordinate_in_range accepts, numbered in increasing order: 0 is 0.0,
// +-1 are +-2^-152, and so on up to +-2^200 (no gaps: consecutive numbers are
// neighbouring doubles of the range).
inline constexpr std::int64_t kRangeBitsLo = std::bit_cast<std::int64_t>(0x1p-152);
inline std::int64_t range_rank(double x) {
  if (x == 0.0) return 0;
  const std::int64_t r = std::bit_cast<std::int64_t>(std::fabs(x)) - kRangeBitsLo + 1;
  return x < 0 ? -r : r;
}
inline double range_double(std::int64_t r) {
  if (r == 0) return 0.0;
  const double a = std::bit_cast<double>((r < 0 ? -r : r) - 1 + kRangeBitsLo);
  return r < 0 ? -a : a;
}
// The in-range double `steps` ranks above x (below for negative steps).
inline double range_step(double x, std::int64_t steps) { return range_double(range_rank(x) + steps); }

// Bisection over the in-range doubles of [lo, hi] for a predicate that is false then true:
// the first double where it holds, or false where it fails at hi.
template <class Pred>
bool first_true(double lo, double hi, Pred pred, double& out) {
  if (!pred(hi)) return false;
  std::int64_t a = range_rank(lo), b = range_rank(hi);
  if (pred(lo)) {
    out = lo;
    return true;
  }
  while (b - a > 1) {  // pred(a) false, pred(b) true
    const std::int64_t m = a + (b - a) / 2;
    (pred(range_double(m)) ? b : a) = m;
  }
  out = range_double(b);
  return true;
}

// ... and for one that is true then false: the last double where it holds.
template <class Pred>
bool last_true(double lo, double hi, Pred pred, double& out) {
  double f;
  if (!first_true(lo, hi, [&](double x) { return !pred(x); }, f)) {
    out = hi;
    return true;
  }
  if (f == lo) return false;
  out = range_step(f, -1);
  return true;
}

}  // namespace detail

// The rounded centroid .25 p0 + .25 p1 + .25 p2 + .25 p3 (the search's first candidate;
// gFlip3D's stored value for an exact-centroid kernel point).
inline void rounded_centroid(const double* const p[4], double k[3]) {
  for (int d = 0; d < 3; ++d) k[d] = .25 * p[0][d] + .25 * p[1][d] + .25 * p[2][d] + .25 * p[3][d];
}

// p[0..3] with orient3d(p0, p1, p2, p3) > 0, coordinates in the exact range. Writes k and
// returns true when the search finds a double point strictly inside (checked exactly).
inline bool interior_point(const double* const p[4], double k[3]) {
  std::vector<double> work(kPredicateWork);
  double* w = work.data();
  // Face i's test with q in place of vertex i: > 0 iff q lies on p_i's side of the face.
  auto face_sign = [&](int i, const double* q) {
    const double* r[4] = {p[0], p[1], p[2], p[3]};
    r[i] = q;
    return orient3d(r[0], r[1], r[2], r[3], w);
  };
  auto inside = [&](const double* q) {
    for (int d = 0; d < 3; ++d)
      if (!coordinate_in_range(q[d])) return false;
    for (int i = 0; i < 4; ++i)
      if (face_sign(i, q) <= 0) return false;
    return true;
  };
  double centroid[3];
  rounded_centroid(p, centroid);
  if (inside(centroid)) {
    for (int d = 0; d < 3; ++d) k[d] = centroid[d];
    return true;
  }
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      if (!coordinate_in_range(p[i][d])) return false;  // (the bisections' numbering needs it)
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = hi[d] = p[0][d];
    for (int i = 1; i < 4; ++i) lo[d] = std::min(lo[d], p[i][d]), hi[d] = std::max(hi[d], p[i][d]);
  }
  auto add_candidate = [](std::vector<double>& v, double x, double l, double h) {
    if (l < x && x < h && coordinate_in_range(x)) v.push_back(x);
  };
  auto middle = [](double l, double h) { return l / 2 + h / 2; };  // no overflow
  static constexpr int kOrders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& ord : kOrders) {
    const int a = ord[0], b = ord[1], c = ord[2];
    // The sign of face i's linear function's slope along c (its value at q is face_sign):
    // with q moved to the last place (3 - i transpositions), orient3d(r0, r1, r2, q) =
    // n . (q - r0), n = (r1 - r0) x (r2 - r0), whose c-component is the orient2d of the
    // projection on axes (c + 1, c + 2) mod 3.
    int slope[4];
    for (int i = 0; i < 4; ++i) {
      const double* r[3];
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != i) r[m++] = p[j];
      const int s = orient2d_proj(r[0], r[1], r[2], (c + 1) % 3, (c + 2) % 3, w);
      slope[i] = (3 - i) % 2 ? -s : s;
    }

    std::vector<double> sa;
    for (int i = 0; i < 4; ++i)
      for (int st : {-2, -1, 1, 2}) add_candidate(sa, detail::range_step(p[i][a], st), lo[a], hi[a]);
    add_candidate(sa, middle(lo[a], hi[a]), lo[a], hi[a]);
    std::sort(sa.begin(), sa.end());
    sa.erase(std::unique(sa.begin(), sa.end()), sa.end());

    for (const double s : sa) {
      // Edges P -> Q with P_a < Q_a spanning s; "t above PQ at s": orient2d on (a, b) > 0.
      int edges[6][2], ne = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (p[i][a] < p[j][a] && p[i][a] <= s && s <= p[j][a]) edges[ne][0] = i, edges[ne][1] = j, ++ne;
      double q[3];
      q[a] = s;
      q[c] = 0;
      auto side = [&](int e, double t) {
        q[b] = t;
        return orient2d_proj(p[edges[e][0]], p[edges[e][1]], q, a, b, w);
      };
      auto above_any = [&](double t) {
        for (int e = 0; e < ne; ++e)
          if (side(e, t) > 0) return true;
        return false;
      };
      auto below_any = [&](double t) {
        for (int e = 0; e < ne; ++e)
          if (side(e, t) < 0) return true;
        return false;
      };
      double tlo, thi;
      if (!detail::first_true(lo[b], hi[b], above_any, tlo) || !detail::last_true(lo[b], hi[b], below_any, thi) ||
          !(tlo <= thi))
        continue;
      std::vector<double> sb;
      for (int st : {0, 1}) sb.push_back(detail::range_step(tlo, st)), sb.push_back(detail::range_step(thi, -st));
      for (int e = 0; e < ne; ++e) {
        double t;
        if (detail::first_true(lo[b], hi[b], [&](double x) { return side(e, x) > 0; }, t))
          sb.push_back(t), sb.push_back(detail::range_step(t, 1));
        if (detail::last_true(lo[b], hi[b], [&](double x) { return side(e, x) < 0; }, t))
          sb.push_back(t), sb.push_back(detail::range_step(t, -1));
      }
      sb.push_back(middle(tlo, thi));
      std::sort(sb.begin(), sb.end());
      sb.erase(std::unique(sb.begin(), sb.end()), sb.end());

      for (const double t : sb) {
        if (t < tlo || t > thi || !coordinate_in_range(t)) continue;  // (a middle can fall below 2^-152)
        q[b] = t;
        auto above_lower = [&](double x) {
          q[c] = x;
          for (int i = 0; i < 4; ++i)
            if (slope[i] > 0 && face_sign(i, q) <= 0) return false;
          return true;
        };
        double z;
        if (!detail::first_true(lo[c], hi[c], above_lower, z)) continue;
        q[c] = z;
        if (inside(q)) {
          for (int d = 0; d < 3; ++d) k[d] = q[d];
          return true;
        }
      }
    }
  }
  return false;
}

}  // namespace gdel::geom
