// Per-element functions of gFlip3D (host + device): point location inside a 1-4
// split, flip proposals, flip execution and history-DAG descent. Every decision
// comes in a fast form (filter; may answer "undecided") and an exact form (exact
// arithmetic + SoS), selected by the template flag Exact.
#pragma once

#include <climits>
#include <cstdint>

#include "core/bits.hpp"
#include "flip/geo.hpp"
#include "mesh/tet_mesh.hpp"

namespace gdel::flip {

using mesh::MeshView;
using mesh::Tet;

inline constexpr int kUndecidedResult = -2;
// propose_flip: the tet has a face that is not locally Delaunay but no valid flip now
// (stuck). With independent splits it stays in the active set (GFlip3D::commit_flips)
// and is proposed again, this round and the next; otherwise it leaves like a tet with
// nothing to flip.
inline constexpr int kStuckResult = -3;

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
template <bool Exact, class Work>
GDEL_HD int split_locate(const Geo& g, const vid_t o[4], vid_t p, vid_t q, Work work) {
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

// Independent splits (FlipConfig::independent_splits): tet t, which holds uninserted
// points, leaves its point for a later round when a neighbour across any of its faces
// also holds points (best[u] != 0: insert_round's per-tet key) and comes first in a fixed
// order of tets: a multiplicative hash of the id, a bijection on 32 bits (not the id
// itself: slots follow the space-filling curve, so id order has few local minima and
// few tets would split per round). The splits of one round then share no face.
GDEL_HD inline bool split_defers(const MeshView& m, const std::uint64_t* best, tid_t t) {
  const std::uint32_t ht = static_cast<std::uint32_t>(t) * 0x9E3779B1u;
  for (int f = 0; f < 4; ++f) {
    const tid_t u = m.opp_tet(4 * std::int64_t(t) + f);
    if (u >= 0 && best[u] != 0 && static_cast<std::uint32_t>(u) * 0x9E3779B1u < ht) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// Flip proposals. Encoding: -1 none; (1 << 4 | i << 2) 2-3 flip on face i;
// (2 << 4 | i << 2 | k) 3-2 flip of the edge shared by faces i and k.
// ---------------------------------------------------------------------------
// The smallest finite vertex of tet t (∞'s id: inf): the points are in curve order, so
// tets sorted by it lie in space order (GFlip3D's tet sort and its active sets).
GDEL_HD inline vid_t smallest_finite_vertex(const Tet& t, vid_t inf) {
  vid_t lo = inf;
  for (int i = 0; i < 4; ++i) lo = (t.v[i] != inf && t.v[i] < lo) ? t.v[i] : lo;
  return lo;
}

GDEL_HD inline int prop_type(int p) { return p >> 4; }
GDEL_HD inline int prop_face(int p) { return (p >> 2) & 3; }
GDEL_HD inline int prop_other(int p) { return p & 3; }

GDEL_HD inline vid_t apex_of(const MeshView& m, fid_t o) {
  return o < 0 ? kNoVertex : m.tet[facet_tet(o)].v[facet_face(o)];
}
// The apex across face i of a tet (vertices bv) whose neighbour there is u: u's vertex
// off the shared face, found among its 4 vertices (one 16-byte load) without the
// neighbour's face index (a second, dependent-free but separate load in the hot loops).
GDEL_HD inline vid_t apex_in(const MeshView& m, tid_t u, const vid_t* bv, int i) {
  if (u < 0) return kNoVertex;
  const Tet ut = m.tet[u];
  const vid_t a = pick4(bv, face_vertex(i, 0)), c = pick4(bv, face_vertex(i, 1)), d = pick4(bv, face_vertex(i, 2));
  vid_t x = ut.v[3];
  for (int k = 0; k < 3; ++k)
    if (ut.v[k] != a && ut.v[k] != c && ut.v[k] != d) x = ut.v[k];
  return x;
}
// The same, u being the neighbour of tet b across face i.
GDEL_HD inline vid_t apex_across(const MeshView& m, tid_t b, const vid_t* bv, int i) {
  return apex_in(m, m.opp_tet(4 * std::int64_t(b) + i), bv, i);
}

// The edges of face i of tet bv that block its 2-3 flip with apex x across the face:
// bit k stands for the edge from corner face_vertex(i, k) to face_vertex(i, k+1) when
// the new tet (that edge, x, bv[i]) is not positive, i.e. the segment from bv[i] to x
// does not cross the face inside that edge. 0: the 2-3 flip is valid. Stops at the first
// blocking edge unless all_edges; kUndecidedResult when a test is undecided.
template <bool Exact, class Work>
GDEL_HD int flip23_blockers(const Geo& g, const vid_t* bv, int i, vid_t x, bool all_edges, Work work) {
  int mask = 0;
  for (int k = 0; k < 3 && (all_edges || mask == 0); ++k) {
    int sk = g.orient<Exact>(pick4(bv, face_vertex(i, k)), pick4(bv, face_vertex(i, (k + 1) % 3)), x, pick4(bv, i), work);
    if (sk == par::kUndecided) return kUndecidedResult;
    if (sk <= 0) mask |= 1 << k;
  }
  return mask;
}

// Non-locally-Delaunay face i of tet bv (apex[] = the apexes across bv's faces): its
// flip proposal, -1 when neither flip is valid (stuck), or kUndecidedResult.
template <bool Exact, class Work>
GDEL_HD int face_flip(const Geo& g, const vid_t* bv, const vid_t* apex, int i, Work work) {
  const vid_t x = pick4(apex, i), bi = pick4(bv, i);
  // 3-2: the edge of face i opposite corner k has degree 3 iff face k's apex is x.
  for (int k = 0; k < 4; ++k) {
    if (k == i || pick4(apex, k) != x) continue;
    const vid_t bk = pick4(bv, k), e0 = pick4(bv, other_corner(i, k, 0)), e1 = pick4(bv, other_corner(i, k, 1));
    int s0 = g.orient<Exact>(bi, bk, x, e0, work);
    int s1 = g.orient<Exact>(bi, bk, x, e1, work);
    if (s0 == par::kUndecided || s1 == par::kUndecided) return kUndecidedResult;
    if (s0 != s1) return (2 << 4) | (i << 2) | k;
  }
  // 2-3: the segment from bv[i] to x crosses face i iff the three new tets are positive.
  const int bl = flip23_blockers<Exact>(g, bv, i, x, false, work);
  if (bl == kUndecidedResult) return kUndecidedResult;
  return bl == 0 ? (1 << 4) | (i << 2) : -1;
}

// Calls f(bv, apex, i) for the faces i of tet b (vertices bv, apex[] across its faces)
// that have a neighbour, are not internal and are not locally Delaunay, in order, until
// f returns something other than -1; returns that value, -1, or kUndecidedResult.
// (All four apexes are loaded first, internal faces' too: loading those only for a tet
// with a face that is not locally Delaunay, which most active tets lack, made the large
// iterations' proposals slower, 104 -> 112 ms at 10^7, bench/RESULTS.md, session 62.)
// The loop runs over the faces to test, not over the four faces with the others
// skipped: a warp's lanes then run one insphere test each a step until the lane with
// the most faces is done (an active tet has 2.18 faces to test on average; at 10^6 a
// warp's tets took 3.37 steps by face index and take 2.81 so). The proposals' pass runs
// 7 % fewer instructions so, but not faster: it waits on its chain of dependent loads
// (bench/RESULTS.md, session 63).
template <bool Exact, class Work, class F>
GDEL_HD std::int64_t for_non_ld_faces(const Geo& g, const MeshView& m, tid_t b, Work work, F f) {
  if (!m.alive(b)) return -1;
  const Tet bt = m.tet[b];
  const vid_t* bv = bt.v;
  tid_t nt[4];
  std::uint8_t fl[4];
  m.get_adj(b, nt, fl);
  vid_t apex[4];
  unsigned todo = 0;  // the faces to test
  for (int i = 0; i < 4; ++i) {
    apex[i] = apex_in(m, nt[i], bv, i);
    if (nt[i] >= 0 && !(fl[i] & mesh::kInternal)) todo |= 1u << i;
  }
  for (; todo != 0; todo &= todo - 1) {
    const int i = lowest_bit(todo);
    const vid_t ai = pick4(apex, i);
    int s = g.insphere<Exact>(bv, ai, work);
    if (s == par::kUndecided) return kUndecidedResult;
    if (s <= 0) continue;  // locally Delaunay
    const std::int64_t r = f(bv, apex, i);
    if (r != -1) return r;
  }
  return -1;
}

// The flip tet b proposes: that of its first face with a valid flip (faces that are not
// flippable now are skipped); kStuckResult when it has non-locally-Delaunay faces but
// none is flippable, -1 when all its faces are locally Delaunay, or kUndecidedResult.
template <bool Exact, class Work>
GDEL_HD int propose_flip(const Geo& g, const MeshView& m, tid_t b, Work work) {
  bool stuck = false;
  const int r = static_cast<int>(for_non_ld_faces<Exact>(g, m, b, work, [&](const vid_t* bv, const vid_t* apex, int i) {
    const int f = face_flip<Exact>(g, bv, apex, i, work);
    stuck = stuck || f == -1;
    return std::int64_t(f);
  }));
  return r == -1 && stuck ? kStuckResult : r;
}

// propose_flip's exact form split by face (par::split_scratch_free, on integer input:
// work is nullptr there, Geo::int_all; the exact forms filter first): face i's part, -1
// when it has no neighbour, is internal or is locally Delaunay, else face_flip's flip or
// kStuckResult (-1 there), or kUndecidedResult. join_face_proposals makes propose_flip's
// answer from the four. The other faces' apexes are loaded only for a face that is not
// locally Delaunay.
template <class Work>
GDEL_HD std::int8_t face_proposal(const Geo& g, const MeshView& m, tid_t b, int i, Work work) {
  if (!m.alive(b)) return -1;
  const Tet bt = m.tet[b];
  const tid_t e = m.nraw[4 * std::int64_t(b) + i];  // (face i's neighbour and flag: one load)
  if (mesh::nb_flags(e) & mesh::kInternal) return -1;
  const vid_t x = apex_in(m, mesh::nb_tet(e), bt.v, i);
  if (x == kNoVertex) return -1;
  const int s = g.insphere<true>(bt.v, x, work);
  if (s == par::kUndecided) return kUndecidedResult;
  if (s <= 0) return -1;  // locally Delaunay
  tid_t nt[4];
  m.get_opp_tets(b, nt);
  vid_t apex[4];
  for (int k = 0; k < 4; ++k) apex[k] = k == i ? x : apex_in(m, nt[k], bt.v, k);
  const int f = face_flip<true>(g, bt.v, apex, i, work);
  return static_cast<std::int8_t>(f == -1 ? kStuckResult : f);
}
// The first face's flip in face order (kUndecidedResult if an undecided face comes
// first), else kStuckResult when some face is stuck, else -1: propose_flip's answer.
GDEL_HD inline int join_face_proposals(const std::int8_t* r) {
  bool stuck = false;
  for (int i = 0; i < 4; ++i) {
    if (r[i] >= 0 || r[i] == kUndecidedResult) return r[i];
    stuck = stuck || r[i] == kStuckResult;
  }
  return stuck ? kStuckResult : -1;
}

// ---------------------------------------------------------------------------
// Non-optimal flips (Options::nonoptimal_flips, docs/gflip3d.md): edge removal by ear
// cutting. A stuck facet F = (p, q, c) of tet B = (p, q, c, v), apex x across it, not
// locally Delaunay, whose 2-3 and 3-2 flips are both invalid, disappears with any of its
// three edges. Seen along an edge e = pq of F, the tets around e form a ring: B =
// (p, q, c, v), then (p, q, v, L2), ..., and back to B; ring vertices L = (c, v, L2, ...,
// L_{d-1}), d = e's degree. Removing e replaces the ring by the tets (p, t) and (q, t)
// for the triangles t of a triangulation of the ring polygon L; it is valid when every
// such tet is positive, i.e. every t's plane separates p from q with the ring's sense
// (exact). Such a triangulation is done by ear cuts: a 2-3 flip of a ring facet (p, q,
// L_j), between the ring's tets (p, q, L_{j-1}, L_j) and (p, q, L_j, L_{j+1}), cuts the
// ear L_{j-1} L_j L_{j+1} off the ring (its new tets: that triangle coned to p and to q,
// and (p, q, L_{j-1}, L_{j+1})), which lowers e's degree by one; it is valid when its
// three new tets are positive (exact, the normal 2-3 test) and usually not improving
// (the facet is locally Delaunay). Once 3 ring vertices are left, the normal 3-2 flip
// of e removes e, and F with it. Every ear of a valid triangulation but the one triangle
// that e's line crosses is a valid ear cut, so ears can be cut until that triangle is
// left. A tet proposes an ear only when a valid triangulation of the whole ring exists:
// found by dynamic programming over the ring's chains (exact tests on at most C(d, 3)
// triangles), and the ear proposed is the first valid one of that triangulation; so no
// flip is made towards a removal that would stop half-way, and the plan re-found on the
// reduced ring at the next step still exists. Rings through ∞ are left alone (every ring
// vertex is in some triangle, and a tet of ∞ made by an ear cut would carve the hull).
// ---------------------------------------------------------------------------
inline constexpr int kMaxRing = 16;  // rings of higher degree are left alone

// A packed non-optimal proposal: the tet that carries it and its code (as propose_flip's).
GDEL_HD inline std::int64_t pack_proposal(tid_t t, int code) { return (std::int64_t(t) << 8) | code; }
GDEL_HD inline tid_t proposal_tet(std::int64_t p) { return static_cast<tid_t>(p >> 8); }
GDEL_HD inline int proposal_code(std::int64_t p) { return static_cast<int>(p & 0xff); }

// Tet b's vertices (p, q, c, v) in this order are positively oriented (an even
// permutation of b's).
GDEL_HD inline bool same_orientation(const vid_t* bv, vid_t p, vid_t q, vid_t c, vid_t v) {
  const vid_t want[4] = {p, q, c, v};
  int pos[4] = {0, 0, 0, 0};
  for (int a = 0; a < 4; ++a)
    for (int l = 0; l < 4; ++l)
      if (bv[l] == want[a]) pos[a] = l;
  int inv = 0;
  for (int a = 0; a < 4; ++a)
    for (int z = a + 1; z < 4; ++z) inv += pos[a] > pos[z];
  return (inv & 1) == 0;
}

// The first ear cut of a removal of edge (p, q) of tet b, c being b's third vertex of the
// stuck facet (see above), as a packed proposal; -1 when no removal is possible;
// kUndecidedResult.
template <bool Exact, class Work>
GDEL_HD std::int64_t edge_removal_ear(const Geo& g, const MeshView& m, tid_t b, vid_t p, vid_t q, vid_t c,
                                      Work work) {
  if (p == g.inf || q == g.inf) return -1;
  vid_t L[kMaxRing];
  tid_t lt[kMaxRing];  // lt[j]: the ring's tet (p, q, L[j], L[j+1 mod d]); li[j]: its face opposite L[j]
  int li[kMaxRing];
  int n = 0;
  L[n++] = c;
  tid_t cur = b;
  for (;;) {
    const Tet ct = m.tet[cur];
    int iu = -1;
    vid_t w = kNoVertex;
    for (int l = 0; l < 4; ++l) {
      const vid_t z = ct.v[l];
      if (z == L[n - 1]) iu = l;
      else if (z != p && z != q) w = z;
    }
    if (iu < 0) return -1;
    lt[n - 1] = cur;
    li[n - 1] = iu;
    if (w == c) break;  // around e and back at b
    if (n == kMaxRing || w == g.inf || w == kNoVertex) return -1;
    L[n++] = w;
    const fid_t o = m.opp(4 * std::int64_t(cur) + iu);
    if (o < 0) return -1;
    cur = facet_tet(o);
  }
  if (n <= 3) return -1;  // degree 3: the normal 3-2 flip's case
  // (P, Q, L[j], L[j+1]) positive; a ring triangle (L[u], L[k], L[w]), u < k < w, is
  // valid when P lies on its negative side and Q on its positive side
  const bool pq = same_orientation(m.tet[b].v, p, q, c, L[1]);
  const vid_t P = pq ? p : q, Q = pq ? q : p;
  // ok[u] bit w: the chain L[u..w] closed by the chord (u, w) has a valid
  // triangulation, whose triangle on that chord is (u, pick[u][w], w)
  std::uint32_t ok[kMaxRing];
  std::uint8_t pick[kMaxRing][kMaxRing];
  for (int u = 0; u < n; ++u) ok[u] = u + 1 < n ? 1u << (u + 1) : 0u;
  for (int len = 2; len < n; ++len)
    for (int u = 0; u + len < n; ++u) {
      const int w = u + len;
      for (int k = u + 1; k < w; ++k) {
        if (!((ok[u] >> k) & 1u) || !((ok[k] >> w) & 1u)) continue;
        const int s0 = g.orient<Exact>(L[u], L[k], L[w], P, work);
        if (s0 == par::kUndecided) return kUndecidedResult;
        if (s0 >= 0) continue;
        const int s1 = g.orient<Exact>(L[u], L[k], L[w], Q, work);
        if (s1 == par::kUndecided) return kUndecidedResult;
        if (s1 <= 0) continue;
        ok[u] |= 1u << w;
        pick[u][w] = static_cast<std::uint8_t>(k);
        break;
      }
    }
  if (!((ok[0] >> (n - 1)) & 1u)) return -1;
  // the triangulation's triangles, chord by chord from (0, d-1); the first ear that is a
  // valid 2-3 flip (all but the one e's line crosses)
  std::uint8_t su[kMaxRing], sw[kMaxRing];
  int top = 0;
  su[top] = 0;
  sw[top++] = static_cast<std::uint8_t>(n - 1);
  while (top > 0) {
    --top;
    const int u = su[top], w = sw[top], k = pick[u][w];
    const int tip = (k == u + 1 && w == k + 1) ? k : (u == 0 && k == 1 && w == n - 1) ? 0 : (u == 0 && k == n - 2 && w == n - 1) ? n - 1 : -1;
    if (tip >= 0) {
      const int a = (tip + n - 1) % n;
      const vid_t V[4] = {P, Q, L[a], L[tip]};
      const int bl = flip23_blockers<Exact>(g, V, 2, L[(tip + 1) % n], false, work);
      if (bl == kUndecidedResult) return kUndecidedResult;
      if (bl == 0) return pack_proposal(lt[a], (1 << 4) | (li[a] << 2));
    }
    if (k - u >= 2) {
      su[top] = static_cast<std::uint8_t>(u);
      sw[top++] = static_cast<std::uint8_t>(k);
    }
    if (w - k >= 2) {
      su[top] = static_cast<std::uint8_t>(k);
      sw[top++] = static_cast<std::uint8_t>(w);
    }
  }
  return -1;
}

// Non-optimal proposal of tet b: for its first non-internal face that is not locally
// Delaunay and stuck, the next ear cut of the removal of one of the face's edges that
// block its 2-3 flip, or with other_edges, failing those, of one of its other edges.
// Returns a packed proposal, -1 (none, also when some face is normally flippable: the
// normal flip loop goes first), or kUndecidedResult.
template <bool Exact, class Work>
GDEL_HD std::int64_t propose_nonoptimal(const Geo& g, const MeshView& m, tid_t b, bool other_edges, Work work) {
  constexpr std::int64_t kNormal = -3;  // a face has a normal flip
  // (not const: nvcc 13 crashes on a const local whose initializer holds a lambda)
  std::int64_t r = for_non_ld_faces<Exact>(g, m, b, work, [&](const vid_t* bv, const vid_t* apex, int i) {
    const int p = face_flip<Exact>(g, bv, apex, i, work);
    if (p != -1) return p == kUndecidedResult ? std::int64_t(kUndecidedResult) : kNormal;
    const int bl = flip23_blockers<Exact>(g, bv, i, apex[i], true, work);
    if (bl == kUndecidedResult) return std::int64_t(kUndecidedResult);
    for (int pass = 0; pass < (other_edges ? 2 : 1); ++pass)
      for (int k = 0; k < 3; ++k) {
        if (((bl >> k) & 1) != (pass == 0 ? 1 : 0)) continue;
        const std::int64_t e = edge_removal_ear<Exact>(g, m, b, bv[face_vertex(i, k)], bv[face_vertex(i, (k + 1) % 3)],
                                                       bv[face_vertex(i, (k + 2) % 3)], work);
        if (e != -1) return e;  // a flip, or undecided
      }
    return std::int64_t(-1);
  });
  return r == kNormal ? -1 : r;
}

// Tets touched by a proposal (2 or 3); returns the count.
GDEL_HD inline int prop_tets(const MeshView& m, tid_t b, int prop, tid_t out[3]) {
  out[0] = b;
  out[1] = m.opp_tet(4 * std::int64_t(b) + prop_face(prop));
  if (prop_type(prop) == 2) {
    out[2] = m.opp_tet(4 * std::int64_t(b) + prop_other(prop));
    return 3;
  }
  return 2;
}

// The vote of tet b's proposal prop (>= 0) in its tets (GFlip3D::commit_flips): an atomic
// max of vstamp | INT_MAX - b, so that the smallest proposer wins each tet; `accepted`
// compares with the same value.
GDEL_HD inline std::uint64_t vote_value(std::uint64_t vstamp, tid_t b) {
  return vstamp | static_cast<std::uint64_t>(INT_MAX - b);
}
GDEL_HD inline void cast_vote(const MeshView& m, tid_t b, int prop, std::uint64_t* vote, std::uint64_t vstamp) {
  tid_t ts[3];
  const int nt = prop_tets(m, b, prop, ts);
  for (int l = 0; l < nt; ++l) par::atomic_max(vote + ts[l], vote_value(vstamp, b));
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
  const vid_t x = apex_across(m, b, bv, i);
  r.type = prop_type(prop);
  if (r.type == 1) {
    for (int k = 0; k < 3; ++k) r.v[k] = pick4(bv, face_vertex(i, k));
    r.v[3] = pick4(bv, i);
    r.v[4] = x;
    return;
  }
  const int k = prop_other(prop);
  r.v[3] = pick4(bv, other_corner(i, k, 0));
  r.v[4] = pick4(bv, other_corner(i, k, 1));
  r.v[0] = pick4(bv, i);
  r.v[1] = pick4(bv, k);
  r.v[2] = x;
}

// Orders a 3-2 record so that (r0, r1, r2, eA) is positive.
template <bool Exact, class Work>
GDEL_HD int order_32(const Geo& g, FlipRec& r, Work work) {
  int s = g.orient<Exact>(r.v[0], r.v[1], r.v[2], r.v[3], work);
  if (s == par::kUndecided) return kUndecidedResult;
  if (s < 0) {
    vid_t t = r.v[3];
    r.v[3] = r.v[4];
    r.v[4] = t;
  }
  return 0;
}

// New tet a of a complete record of type Type (1: 2-3, 2: 3-2; see FlipRec).
template <int Type>
GDEL_HD inline void flip_new_tet(const FlipRec& r, int a, vid_t nv[4]) {
  if constexpr (Type == 1) {
    nv[0] = r.v[a];
    nv[1] = r.v[(a + 1) % 3];
    nv[2] = r.v[4];
    nv[3] = r.v[3];
  } else {
    nv[0] = r.v[a];
    nv[1] = r.v[1 - a];
    nv[2] = r.v[2];
    nv[3] = r.v[3 + a];
  }
}
// The new tets of a complete record; returns their number.
GDEL_HD inline int flip_new_tets(const FlipRec& r, vid_t nv[3][4]) {
  if (r.type == 1) {
    for (int a = 0; a < 3; ++a) flip_new_tet<1>(r, a, nv[a]);
    return 3;
  }
  for (int a = 0; a < 2; ++a) flip_new_tet<2>(r, a, nv[a]);
  return 2;
}

// Face l of new tet a of a complete record of type Type, from the vertex orders of
// FlipRec, flip_outputs and prop_tets. Internal (`inner`): face `face` of new tet `tet`.
// External: the face of old tet in[`tet`] opposite the record's vertex v[`face`]. 2-3:
// out[a] = (c_a, c_a+1, x, v); in[0] holds c0 c1 c2 v, in[1] c0 c1 c2 x. 3-2: out[0] =
// (r0, r1, r2, eA), out[1] = (r1, r0, r2, eB); in[0] lacks r2, in[1] r0, in[2] r1, so
// in[(j + 1) % 3] lacks r_j.
struct FlipFace {
  bool inner;
  int tet, face;
};
template <int Type>
GDEL_HD constexpr FlipFace flip_face(int a, int l) {
  if constexpr (Type == 1) {
    if (l == 0) return {true, (a + 1) % 3, 1};
    if (l == 1) return {true, (a + 2) % 3, 0};
    return {false, l - 2, (a + 2) % 3};  // l = 2: in in[0], opposite x; l = 3: in in[1], opposite v
  } else {
    if (l == 3) return {true, 1 - a, 3};
    const int j = (a == 1 && l < 2) ? 1 - l : l;  // face l is opposite ring vertex r_j
    return {false, (j + 1) % 3, a == 0 ? 4 : 3};  // opposite the edge's other end
  }
}

// A flip's six external faces, for the adjacency pass (GFlip3D::commit_flips): entry e
// of flip f is new tet out[a]'s face l, which replaces a face of old tet in[o], whose
// neighbour there was tet eot (kNoTet: the hull). code packs a << 2 | l (bits 0-3) and
// o (bits 4-5).
struct ExtFaces {
  std::uint16_t* code;
  tid_t* eot;
};
GDEL_HD inline int ext_new_tet(std::uint16_t c) { return (c >> 2) & 3; }
GDEL_HD inline int ext_new_face(std::uint16_t c) { return c & 3; }
GDEL_HD inline int ext_old_tet(std::uint16_t c) { return (c >> 4) & 3; }

// Writes the new tets of flip record r (type Type) into slots out[]: each whole, with one
// vector store each for its vertices and its neighbour entries (the tets with the faces'
// flags). An internal face links two new tets (kInternal); an external one gets the
// neighbour of the old tet there, and an entry for the adjacency pass (ExtFaces, from
// position `at`, in (a, l) order). The old tets are read before any slot is written
// (out[0], out[1] are in[0], in[1]). Each old tet's `mark` is set to `stamp` (the
// adjacency pass finds the flip that took a neighbour by it).
template <int Type>
GDEL_HD inline void write_flip(const MeshView& m, const FlipRec& r, const tid_t out[3], std::uint64_t* mark,
                               std::uint64_t stamp, const ExtFaces& ext, std::int64_t at) {
  constexpr int no = Type == 1 ? 2 : 3, nn = 5 - no;
  Tet ot[no];
  tid_t on[no][4];
#pragma unroll
  for (int o = 0; o < no; ++o) {
    ot[o] = m.tet[r.in[o]];
    m.get_opp_tets(r.in[o], on[o]);
    mark[r.in[o]] = stamp;
  }
  int ne = 0;
#pragma unroll
  for (int a = 0; a < nn; ++a) {
    tid_t nt[4];
#pragma unroll
    for (int l = 0; l < 4; ++l) {
      const FlipFace x = flip_face<Type>(a, l);
      if (x.inner) {
        nt[l] = mesh::nb_entry(out[x.tet], true);
        continue;
      }
      // the old tet's face opposite w: found by compile-time indices (a run-time index
      // into on would put it in the stack)
      const vid_t w = r.v[x.face];
      const vid_t* tv = ot[x.tet].v;
      nt[l] = on[x.tet][3];
#pragma unroll
      for (int c = 2; c >= 0; --c)
        if (tv[c] == w) nt[l] = on[x.tet][c];
      ext.code[at + ne] = static_cast<std::uint16_t>(a << 2 | l | x.tet << 4);
      ext.eot[at + ne] = nt[l];
      ++ne;
    }
    Tet t;
    flip_new_tet<Type>(r, a, t.v);
    m.put_tet(out[a], t, nt);
    // out[0] and out[1] are old tets' slots, alive already (a state byte is a random
    // store of its own: one a new tet, not three)
    if (a == 2) m.state[out[a]] = mesh::kAlive;
  }
}

// Executes accepted flip f (proposer A[flp[f]]): its record, with the new tets' slots
// (in[0], in[1], and for a 2-3 flip the claimed slot src.slot(o23[f])), into rec[f], and
// its new tets (write_flip: old tets stamped with stamp | f, external faces into ext from
// 6 f); false, before anything is written, if undecided. One pass: the record's old tets
// are still in cache when their successors are written (bench/RESULTS.md, session 22).
struct ExecuteFlip {
  MeshView m;
  Geo g;
  const tid_t* A;
  const std::int32_t* flp;
  const std::int32_t* pp;
  FlipRec* rec;
  mesh::SlotSource src;
  const std::int32_t* o23;
  std::uint64_t* mark;
  std::uint64_t stamp;
  ExtFaces ext;
  template <bool Exact, class Work>
  GDEL_HD bool run(std::int64_t f, Work work) const {
    const tid_t b = A[flp[f]];
    const int p = pp[flp[f]];
    FlipRec r;
    flip_outputs(m, b, p, r);
    if (r.type == 2 && order_32<Exact>(g, r, work) == kUndecidedResult) return false;
    tid_t ts[3];
    const int nt = prop_tets(m, b, p, ts);
    const bool t23 = r.type == 1;
    for (int l = 0; l < 3; ++l) r.in[l] = l < nt ? ts[l] : -1;
    r.out[0] = r.in[0];
    r.out[1] = r.in[1];
    r.out[2] = t23 ? src.slot(o23[f]) : tid_t(-1);
    rec[f] = r;
    const std::uint64_t mk = stamp | static_cast<std::uint64_t>(f);
    if (t23) write_flip<1>(m, r, r.out, mark, mk, ext, 6 * f);
    else write_flip<2>(m, r, r.out, mark, mk, ext, 6 * f);
    return true;
  }
};

// The exact forms of propose_flip and ExecuteFlip out of line, for the small flip
// iterations (GFlip3D::commit_flips' teams, GFlip3D::propose_spread), where one thread
// runs the fast form and then, if it could not decide, the exact one: few threads take
// the exact form, and one out-of-line copy keeps it out of each kernel's main path.
// work: the thread's scratch, or nullptr where every evaluation runs in the integer
// stage (Geo::int_all; as std::nullptr_t, an instance without expansions).
template <class Work>
GDEL_NOINLINE GDEL_HD int propose_flip_exact(const Geo& g, const MeshView& m, tid_t b, Work work) {
  return propose_flip<true>(g, m, b, work);
}
template <class Work>
GDEL_NOINLINE GDEL_HD bool execute_flip_exact(const ExecuteFlip& xf, std::int64_t f, Work work) {
  return xf.run<true>(f, work);
}
// Tet b's proposal in one thread: the fast form, then the exact one where the fast one
// could not decide (counted in nex).
template <class Work>
GDEL_HD int propose_flip_in_thread(const Geo& g, const MeshView& m, tid_t b, Work work, std::int64_t& nex) {
  const int p = propose_flip<false>(g, m, b, nullptr);
  if (p != kUndecidedResult) return p;
  ++nex;
  return propose_flip_exact(g, m, b, work);
}

// Which output of flip record r contains q: 0..2, or kUndecidedResult.
template <bool Exact, class Work>
GDEL_HD int dag_child(const Geo& g, const FlipRec& r, vid_t q, Work work) {
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
