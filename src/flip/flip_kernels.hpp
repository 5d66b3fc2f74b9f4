// Per-element functions of gFlip3D (host + device): point location inside a 1-4
// split, flip proposals, flip execution and history-DAG descent. Every decision
// comes in a fast form (filter; may answer "undecided") and an exact form (exact
// arithmetic + SoS), selected by the template flag Exact.
#pragma once

#include <cstdint>

#include "flip/geo.hpp"
#include "mesh/tet_mesh.hpp"

namespace gdel::flip {

using mesh::MeshView;
using mesh::Tet;

inline constexpr int kUndecidedResult = -2;

// ---------------------------------------------------------------------------
// 1-4 split: child i of tet o with new point p is (face i of o, p); its faces
// 0..2 are internal and face 3 is o's old face i. Child i's face k is shared with
// child face_vertex(i, k).
// ---------------------------------------------------------------------------
GDEL_HD inline void split_child_vertices(const vid_t o[4], vid_t p, int i, vid_t c[4]) {
  c[0] = o[face_vertex(i, 0)];
  c[1] = o[face_vertex(i, 1)];
  c[2] = o[face_vertex(i, 2)];
  c[3] = p;
}
// Face of child j that is shared with child i (i != j).
GDEL_HD inline int split_shared_face(int j, int i) {
  for (int k = 0; k < 3; ++k)
    if (face_vertex(j, k) == i) return k;
  return -1;
}

// Child of the split of o by p that contains q: 0..3, or kUndecidedResult.
template <bool Exact>
GDEL_HD int split_locate(const Geo& g, const vid_t o[4], vid_t p, vid_t q, double* work) {
  int c = 0;
  for (int step = 0; step < 6; ++step) {
    vid_t cv[4];
    split_child_vertices(o, p, c, cv);
    int exitk = -1;
    for (int k = 0; k < 3 && exitk < 0; ++k) {
      int s = g.orient<Exact>(cv[face_vertex(k, 0)], cv[face_vertex(k, 1)], cv[face_vertex(k, 2)], q, work);
      if (s == par::kUndecided) return kUndecidedResult;
      if (s < 0) exitk = k;
    }
    if (exitk < 0) return c;
    c = face_vertex(c, exitk);
  }
  // The walk among the 4 cones did not settle (cannot happen with consistent
  // predicates); decide by testing each child completely.
  for (int c2 = 0; c2 < 4; ++c2) {
    vid_t cv[4];
    split_child_vertices(o, p, c2, cv);
    bool in = true;
    for (int k = 0; k < 3 && in; ++k) {
      int s = g.orient<Exact>(cv[face_vertex(k, 0)], cv[face_vertex(k, 1)], cv[face_vertex(k, 2)], q, work);
      if (s == par::kUndecided) return kUndecidedResult;
      in = s > 0;
    }
    if (in) return c2;
  }
  return kUndecidedResult;
}

// ---------------------------------------------------------------------------
// Flip proposals. Encoding: -1 none; (1 << 4 | i << 2) 2-3 flip on face i;
// (2 << 4 | i << 2 | k) 3-2 flip of the edge shared by faces i and k.
// ---------------------------------------------------------------------------
GDEL_HD inline int prop_type(int p) { return p >> 4; }
GDEL_HD inline int prop_face(int p) { return (p >> 2) & 3; }
GDEL_HD inline int prop_other(int p) { return p & 3; }

GDEL_HD inline vid_t apex_of(const MeshView& m, fid_t o) {
  return o < 0 ? kNoVertex : m.tet[facet_tet(o)].v[facet_face(o)];
}

template <bool Exact>
GDEL_HD int propose_flip(const Geo& g, const MeshView& m, tid_t b, double* work) {
  if (!m.alive(b)) return -1;
  const Tet bt = m.tet[b];
  const vid_t* bv = bt.v;
  vid_t apex[4];
  for (int i = 0; i < 4; ++i) apex[i] = apex_of(m, m.opp[4 * std::int64_t(b) + i]);
  for (int i = 0; i < 4; ++i) {
    if (apex[i] == kNoVertex || (m.face_flags(b, i) & mesh::kInternal)) continue;
    int s = g.insphere<Exact>(bv, apex[i], work);
    if (s == par::kUndecided) return kUndecidedResult;
    if (s <= 0) continue;  // locally Delaunay
    const vid_t x = apex[i];
    // 3-2: the edge of face i opposite corner k has degree 3 iff face k's apex is x.
    for (int k = 0; k < 4; ++k) {
      if (k == i || apex[k] != x) continue;
      vid_t e[2];
      int ne = 0;
      for (int l = 0; l < 4; ++l)
        if (l != i && l != k) e[ne++] = bv[l];
      int s0 = g.orient<Exact>(bv[i], bv[k], x, e[0], work);
      int s1 = g.orient<Exact>(bv[i], bv[k], x, e[1], work);
      if (s0 == par::kUndecided || s1 == par::kUndecided) return kUndecidedResult;
      if (s0 != s1) return (2 << 4) | (i << 2) | k;
    }
    // 2-3: the segment from bv[i] to x crosses face i iff the three new tets are positive.
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      int sk = g.orient<Exact>(bv[face_vertex(i, k)], bv[face_vertex(i, (k + 1) % 3)], x, bv[i], work);
      if (sk == par::kUndecided) return kUndecidedResult;
      ok = sk > 0;
    }
    if (ok) return (1 << 4) | (i << 2);
    // not flippable now: try the other faces
  }
  return -1;
}

// Tets touched by a proposal (2 or 3); returns the count.
GDEL_HD inline int prop_tets(const MeshView& m, tid_t b, int prop, tid_t out[3]) {
  out[0] = b;
  out[1] = facet_tet(m.opp[4 * std::int64_t(b) + prop_face(prop)]);
  if (prop_type(prop) == 2) {
    out[2] = facet_tet(m.opp[4 * std::int64_t(b) + prop_other(prop)]);
    return 3;
  }
  return 2;
}

// ---------------------------------------------------------------------------
// Flip records (history DAG). type 1 (2-3): v = (c0, c1, c2, v, x), out[k] holds
// (c_k, c_k+1, x, v). type 2 (3-2): v = (r0, r1, r2, eA, eB), out[0] holds
// (r0, r1, r2, eA) (positive), out[1] holds (r1, r0, r2, eB). in = consumed slots.
// ---------------------------------------------------------------------------
struct FlipRec {
  std::int32_t type;
  vid_t v[5];
  tid_t in[3];
  tid_t out[3];
};

// Record of the flip proposed by b (type, vertices, not yet slots); a 3-2 record
// still needs order_32.
GDEL_HD inline void flip_outputs(const MeshView& m, tid_t b, int prop, FlipRec& r) {
  const Tet bt = m.tet[b];
  const vid_t* bv = bt.v;
  const int i = prop_face(prop);
  const vid_t x = apex_of(m, m.opp[4 * std::int64_t(b) + i]);
  r.type = prop_type(prop);
  if (r.type == 1) {
    for (int k = 0; k < 3; ++k) r.v[k] = bv[face_vertex(i, k)];
    r.v[3] = bv[i];
    r.v[4] = x;
    return;
  }
  const int k = prop_other(prop);
  int ne = 3;
  for (int l = 0; l < 4; ++l)
    if (l != i && l != k) r.v[ne++] = bv[l];
  r.v[0] = bv[i];
  r.v[1] = bv[k];
  r.v[2] = x;
}

// Orders a 3-2 record so that (r0, r1, r2, eA) is positive.
template <bool Exact>
GDEL_HD int order_32(const Geo& g, FlipRec& r, double* work) {
  int s = g.orient<Exact>(r.v[0], r.v[1], r.v[2], r.v[3], work);
  if (s == par::kUndecided) return kUndecidedResult;
  if (s < 0) {
    vid_t t = r.v[3];
    r.v[3] = r.v[4];
    r.v[4] = t;
  }
  return 0;
}

// The new tets of a complete record (see FlipRec); returns their number.
GDEL_HD inline int flip_new_tets(const FlipRec& r, vid_t nv[3][4]) {
  if (r.type == 1) {
    for (int k = 0; k < 3; ++k) {
      nv[k][0] = r.v[k];
      nv[k][1] = r.v[(k + 1) % 3];
      nv[k][2] = r.v[4];
      nv[k][3] = r.v[3];
    }
    return 3;
  }
  const int order[2][4] = {{0, 1, 2, 3}, {1, 0, 2, 4}};
  for (int a = 0; a < 2; ++a)
    for (int l = 0; l < 4; ++l) nv[a][l] = r.v[order[a][l]];
  return 2;
}

// True iff the 3 vertices f are all among the 4 of t.
GDEL_HD inline bool has_face(const vid_t* t, const vid_t* f) {
  int h = 0;
  for (int q = 0; q < 3; ++q)
    for (int z = 0; z < 4; ++z) h += (t[z] == f[q]);
  return h == 3;
}
// Local index of the vertex of t that is not in face f (t must hold f).
GDEL_HD inline int opposite_of_face(const vid_t* t, const vid_t* f) {
  int l = 0;
  for (int z = 0; z < 4; ++z) {
    bool in = false;
    for (int q = 0; q < 3; ++q) in = in || t[z] == f[q];
    if (!in) l = z;
  }
  return l;
}

// Builds the record of accepted flip f (proposer A[flp[f]]); false if undecided.
struct BuildFlipRecord {
  MeshView m;
  Geo g;
  const tid_t* A;
  const std::int64_t* flp;
  const std::int32_t* pp;
  FlipRec* rec;
  template <bool Exact>
  GDEL_HD bool run(std::int64_t f, double* work) const {
    const tid_t b = A[flp[f]];
    const int p = pp[flp[f]];
    FlipRec r;
    flip_outputs(m, b, p, r);
    if (r.type == 2 && order_32<Exact>(g, r, work) == kUndecidedResult) return false;
    tid_t ts[3];
    const int nt = prop_tets(m, b, p, ts);
    for (int l = 0; l < 3; ++l) r.in[l] = l < nt ? ts[l] : -1;
    rec[f] = r;
    return true;
  }
};

// Which output of flip record r contains q: 0..2, or kUndecidedResult.
template <bool Exact>
GDEL_HD int dag_child(const Geo& g, const FlipRec& r, vid_t q, double* work) {
  if (r.type == 1) {
    const vid_t v = r.v[3], x = r.v[4];
    int a0 = g.orient<Exact>(r.v[0], x, v, q, work);
    if (a0 == par::kUndecided) return kUndecidedResult;
    if (a0 > 0) {
      int a1 = g.orient<Exact>(r.v[1], x, v, q, work);
      if (a1 == par::kUndecided) return kUndecidedResult;
      return a1 < 0 ? 0 : 1;
    }
    int a2 = g.orient<Exact>(r.v[2], x, v, q, work);
    if (a2 == par::kUndecided) return kUndecidedResult;
    return a2 > 0 ? 2 : 1;
  }
  int s = g.orient<Exact>(r.v[0], r.v[1], r.v[2], q, work);
  if (s == par::kUndecided) return kUndecidedResult;
  return s > 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------
// Scores for choosing the point a tet inserts (floating point: a choice, not a
// decision; any value gives a valid algorithm).
// ---------------------------------------------------------------------------
GDEL_HD inline double orient_value(const double* a, const double* b, const double* c, const double* d) {
  double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
}
// Proportional to r^2 - |e - centre|^2 for a positive tet (positive inside).
GDEL_HD inline double insphere_value(const double* a, const double* b, const double* c, const double* d,
                                     const double* e) {
  double m[4][4];
  const double* p[4] = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    double x = p[i][0] - e[0], y = p[i][1] - e[1], z = p[i][2] - e[2];
    m[i][0] = x;
    m[i][1] = y;
    m[i][2] = z;
    m[i][3] = x * x + y * y + z * z;
  }
  auto det3 = [&](int r0, int r1, int r2, int c0, int c1, int c2) {
    return m[r0][c0] * (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) -
           m[r0][c1] * (m[r1][c0] * m[r2][c2] - m[r1][c2] * m[r2][c0]) +
           m[r0][c2] * (m[r1][c0] * m[r2][c1] - m[r1][c1] * m[r2][c0]);
  };
  // det of the 4x4 matrix, expanded along the lifted column
  double d4 = -m[0][3] * det3(1, 2, 3, 0, 1, 2) + m[1][3] * det3(0, 2, 3, 0, 1, 2) -
              m[2][3] * det3(0, 1, 3, 0, 1, 2) + m[3][3] * det3(0, 1, 2, 0, 1, 2);
  // Shewchuk's sign: positive inside for negatively oriented (in our convention) tets.
  return -d4;
}

}  // namespace gdel::flip
