// The combinatorial conventions of gdel, fixed in one place. Every table elsewhere
// (split children, flip outputs, star links, verifier) derives from these.
//
//  * Orientation. orient3d(a,b,c,d) is the sign of det[b-a, c-a, d-a] (CGAL's
//    convention): positive iff d lies on the side of plane abc from which a,b,c turn
//    counter-clockwise. A tetrahedron (v0,v1,v2,v3) is positively oriented iff
//    orient3d(v0,v1,v2,v3) > 0. All stored tets are positively oriented.
//  * insphere(a,b,c,d,e) > 0 iff e lies strictly inside the circumsphere of the
//    positively oriented tet abcd. The power test (weighted) has the same sign rule.
//  * Facet = (tet, i): the face opposite local vertex i. kFaceVertex[i] lists its
//    vertices so that (face..., v_i) is positively oriented, i.e. the face turns
//    counter-clockwise as seen from v_i (its inner side).
//  * Neighbour i of a tet is the tet across facet i (-1 on the hull in public output).
//  * The point at infinity: index kInfinite in internal meshes (never in output).
#pragma once

#include <cstdint>

#include "core/macros.hpp"

namespace gdel {

using vid_t = std::int32_t;    // vertex (point) index: < 2^31 points
using tid_t = std::int32_t;    // tet index: < 2^31 tets (about 3·10^8 points)
using fid_t = std::int64_t;    // packed facet (tet << 2 | face): 64-bit, passes 2^31

inline constexpr vid_t kInfinite = -2;  // the virtual vertex at infinity
inline constexpr vid_t kNoVertex = -1;
inline constexpr tid_t kNoTet = -1;

// The small tables below are kept as 2-bit fields of one integer constant: indexed at
// run time, a local array would live in the kernel's stack (local memory, measured:
// bench/RESULTS.md, session 22); a shift and a mask stay in registers.
namespace detail {
template <int R, int C>
constexpr std::uint32_t pack2(const int (&t)[R][C]) {
  std::uint32_t bits = 0;
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) bits |= static_cast<std::uint32_t>(t[r][c]) << (2 * (C * r + c));
  return bits;
}
constexpr int kFaceVertexTable[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
constexpr int kEdgeVertexTable[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
}  // namespace detail

// kFaceVertex[i][k]: k-th vertex (local index) of the face opposite vertex i.
GDEL_HD constexpr int face_vertex(int i, int k) {
  constexpr std::uint32_t bits = detail::pack2(detail::kFaceVertexTable);
  return static_cast<int>((bits >> (2 * (3 * i + k))) & 3u);
}

// The 6 edges of a tet as (local a, local b); edge e and edge 5-e are opposite.
GDEL_HD constexpr int edge_vertex(int e, int k) {
  constexpr std::uint32_t bits = detail::pack2(detail::kEdgeVertexTable);
  return static_cast<int>((bits >> (2 * (2 * e + k))) & 3u);
}
// a[i] of a 4-array held in registers, by selects: a run-time index into a local array
// would put the array in the kernel's stack (local memory).
template <class T>
GDEL_HD constexpr T pick4(const T* a, int i) {
  return i == 0 ? a[0] : i == 1 ? a[1] : i == 2 ? a[2] : a[3];
}
// The two corners of a tet other than i and k (i != k), smaller first.
GDEL_HD constexpr int other_corner(int i, int k, int which) {
  const int rest = 0xf & ~(1 << i) & ~(1 << k);
  return which == 0 ? ((rest & 1) ? 0 : (rest & 2) ? 1 : 2) : ((rest & 8) ? 3 : (rest & 4) ? 2 : 1);
}

static_assert(face_vertex(0, 1) == 3 && face_vertex(2, 2) == 1 && face_vertex(3, 0) == 0);
static_assert(edge_vertex(2, 1) == 3 && edge_vertex(3, 0) == 1 && edge_vertex(5, 1) == 3);
static_assert(other_corner(0, 3, 0) == 1 && other_corner(0, 3, 1) == 2 && other_corner(2, 1, 0) == 0 &&
              other_corner(2, 1, 1) == 3 && other_corner(3, 2, 1) == 1);

GDEL_HD constexpr fid_t pack_facet(tid_t t, int face) { return (static_cast<fid_t>(t) << 2) | face; }
GDEL_HD constexpr tid_t facet_tet(fid_t f) { return static_cast<tid_t>(f >> 2); }
GDEL_HD constexpr int facet_face(fid_t f) { return static_cast<int>(f & 3); }

}  // namespace gdel
