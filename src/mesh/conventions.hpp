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

// kFaceVertex[i][k]: k-th vertex (local index) of the face opposite vertex i.
GDEL_HD constexpr int face_vertex(int i, int k) {
  constexpr int t[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  return t[i][k];
}

// The 6 edges of a tet as (local a, local b); edge e and edge 5-e are opposite.
GDEL_HD constexpr int edge_vertex(int e, int k) {
  constexpr int t[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  return t[e][k];
}

GDEL_HD constexpr fid_t pack_facet(tid_t t, int face) { return (static_cast<fid_t>(t) << 2) | face; }
GDEL_HD constexpr tid_t facet_tet(fid_t f) { return static_cast<tid_t>(f >> 2); }
GDEL_HD constexpr int facet_face(fid_t f) { return static_cast<int>(f & 3); }

}  // namespace gdel
