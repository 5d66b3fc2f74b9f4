// Stars of lifted points (ALGORITHMS.md §2.5, §4.5, §4.6): the per-star routines of the
// star splaying engine, usable on host and device (one thread owns one star).
//
// A star of vertex s is a triangulated 2-sphere, its link: triangles (a,b,c) oriented so
// that the lifted tet (s,a,b,c) has every other point of the star beneath it, i.e.
// Geo::orient4(s,a,b,c,x) < 0. The link may contain ∞ (s on the hull). A star's
// triangles live in a contiguous slot range [0, count) (no holes between operations);
// adj[k] = (local triangle << 2 | edge) across edge k, edge k being the one opposite v[k],
// i.e. (v[k+1], v[k+2]).
#pragma once

#include <cstdint>

#include "flip/geo.hpp"
#include "mesh/conventions.hpp"

// Out of line in device code only (the host compiler keeps its own choice): the engine's
// large per-star functions, inlined into a kernel capped at 255 registers, make it spill
// (the scratch-free star builds: 9.5 KB of spill stores a thread, 2x the time on the
// sphere; bench/RESULTS.md, session 42). Their scratch instances were out of line anyway.
#if defined(__CUDA_ARCH__)
#define GDEL_STAR_NOINLINE __noinline__
#else
#define GDEL_STAR_NOINLINE
#endif

namespace gdel::splay {

struct Tri {
  vid_t v[3];
  std::int32_t adj[3];
};

enum TriState : std::uint8_t {
  kTriFree = 0,
  kTriChecked = 1,  // consistency already checked (or known from the input triangulation)
  kTriNew = 2,      // created since the last consistency check
  kTriBeyond = 4,       // flag bit, transient: beyond the point being inserted
  kTriNonPositive = 8,  // flag bit: the tet (s, a, b, c) is not positive in the 3-D embedding
  kTriTested = 16,      // flag bit, transient: tested and not beyond (flood fill)
};
inline constexpr std::uint8_t kTriKind = 3;  // Free / Checked / New

GDEL_HD inline bool is_beyond(std::uint8_t s) { return (s & kTriBeyond) != 0; }
GDEL_HD inline std::uint8_t tri_kind(std::uint8_t s) { return s & kTriKind; }
GDEL_HD inline void set_kind(std::uint8_t& s, std::uint8_t kind) { s = std::uint8_t((s & ~kTriKind) | kind); }

// 3-D orientation of (a, b, c, d) with ∞ embedded as in gFlip3D (Geo::orient): never 0.
template <class Work>
GDEL_HD int orient_any(const flip::Geo& g, vid_t a, vid_t b, vid_t c, vid_t d, Work work) {
  const int r = g.orient_fast(a, b, c, d);
  return r != par::kUndecided ? r : g.orient_exact(a, b, c, d, work);
}
template <class Work>
GDEL_STAR_NOINLINE GDEL_HD std::uint8_t positivity_flag(const flip::Geo& g, vid_t s, const Tri& t, Work work) {
  return orient_any(g, s, t.v[0], t.v[1], t.v[2], work) > 0 ? std::uint8_t(0) : std::uint8_t(kTriNonPositive);
}

// Visibility walk on the link of s towards the ray s->q (q finite, not in the link):
// the triangle whose 3-D cone from s contains q's direction, or -1 after `count` steps.
// Meaningful when every tet of the star is positive in the 3-D embedding: the star is
// then the projection of a convex lifted star, a partition of the directions around s.
template <class Work>
GDEL_HD std::int32_t star_locate(const flip::Geo& g, const Tri* T, std::int32_t count, vid_t s, vid_t q,
                                 std::int32_t t, Work work) {
  for (std::int32_t step = 0; step <= count; ++step) {
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k) {
      // q beyond the plane (s, b, c) of edge k, on the other side from v[k]
      if (orient_any(g, s, T[t].v[(k + 1) % 3], T[t].v[(k + 2) % 3], q, work) < 0) {
        t = T[t].adj[k] >> 2;
        moved = true;
      }
    }
    if (!moved) return t;
  }
  return -1;
}

// kStarDead (weighted points only, Geo::w): q is beyond every facet of the star, so s
// lies inside the hull of its star and q: s is redundant (hidden) and its star dies.
// The star is left as it was before q, for the death certificate (star_proof).
enum InsertResult : int { kInserted = 0, kDrowned = 1, kStarDead = 2, kStarBroken = -1, kStarFull = -2 };

GDEL_HD inline int tri_pos(const Tri& t, vid_t x) {
  return t.v[0] == x ? 0 : t.v[1] == x ? 1 : t.v[2] == x ? 2 : -1;
}

GDEL_HD inline bool star_has(const Tri* T, std::int32_t count, vid_t x) {
  for (std::int32_t i = 0; i < count; ++i)
    if (tri_pos(T[i], x) >= 0) return true;
  return false;
}

// Beyond test of q against triangle i of the star of s (filter first, then exact).
template <class Work>
GDEL_STAR_NOINLINE GDEL_HD int star_side(const flip::Geo& g, const Tri& t, vid_t s, vid_t q, Work work) {
  const vid_t v[5] = {s, t.v[0], t.v[1], t.v[2], q};
  return g.orient4_any(v, work);
}

// Links the adjacency of k triangles with distinct directed edges by brute force
// (used for tiny stars only).
GDEL_HD inline void link_by_edges(Tri* T, int k) {
  for (int i = 0; i < k; ++i)
    for (int e = 0; e < 3; ++e) {
      const vid_t a = T[i].v[(e + 1) % 3], b = T[i].v[(e + 2) % 3];
      for (int j = 0; j < k; ++j) {
        if (j == i) continue;
        for (int f = 0; f < 3; ++f)
          if (T[j].v[(f + 1) % 3] == b && T[j].v[(f + 2) % 3] == a) T[i].adj[e] = (j << 2) | f;
      }
    }
}

// The star of s in the 4-simplex (s, a, b, c, d): the 4 facets through s.
template <class Work>
GDEL_HD void star_simplex(const flip::Geo& g, Tri* T, std::uint8_t* S, vid_t s, const vid_t* abcd,
                          std::uint8_t state, Work work) {
  const vid_t v[5] = {s, abcd[0], abcd[1], abcd[2], abcd[3]};
  const bool flip = g.orient4_any(v, work) > 0;  // d beyond (a,b,c): reverse every face
  for (int i = 0; i < 4; ++i) {
    T[i].v[0] = abcd[face_vertex(i, 0)];
    T[i].v[1] = abcd[face_vertex(i, flip ? 2 : 1)];
    T[i].v[2] = abcd[face_vertex(i, flip ? 1 : 2)];
    S[i] = std::uint8_t(state | positivity_flag(g, s, T[i], work));
  }
  // face_vertex(3,·) = (0,1,2): unflipped means (a,b,c) with d beneath. The face table
  // orients all four faces alike, so the others follow.
  link_by_edges(T, 4);
}

GDEL_HD inline void star_move(Tri* T, std::uint8_t* S, std::int32_t from, std::int32_t to) {
  T[to] = T[from];
  S[to] = S[from];
  for (int k = 0; k < 3; ++k) {
    const std::int32_t a = T[to].adj[k];
    T[a >> 2].adj[a & 3] = (to << 2) | k;
  }
  S[from] = kTriFree;
}

// Beneath-beyond insertion of q into the convex star of s (§4.5). Finds one beyond
// triangle (walk, or scan), floods the beyond set (a disk), walks its boundary creating
// the fan (q, u, v) in fresh slots past `count`, reports the link vertices that leave the
// star (submerged) to `gone(x)`, then closes the holes. Needs cap >= 2 * count + 2.
// Returns an InsertResult. Apart from the locating scan, the work is O(beyond set + fan),
// not O(count): one thread may own a star of thousands of triangles (a point on a
// coplanar hull face), and on a GPU every pass over it costs a dependent load per slot.
// `nonpos` (optional, in/out): the number of triangles flagged kTriNonPositive, kept by a
// caller that inserts many points into one star; without it that count is a scan.
template <class Gone, class Work>
GDEL_STAR_NOINLINE GDEL_HD int star_insert(const flip::Geo& g, Tri* T, std::uint8_t* S, std::int32_t& count,
                                           std::int32_t cap, vid_t s, vid_t q, Work work, Gone gone,
                                           std::int32_t hint = 0, std::int32_t* nonpos = nullptr) {
  std::int32_t np = 0;
  if (nonpos) np = *nonpos;
  else
    for (std::int32_t i = 0; i < count; ++i) np += (S[i] & kTriNonPositive) ? 1 : 0;
  // Fast path (every tet of the star positive in 3-D, q finite): locate the triangle
  // whose cone holds q's direction; if q conflicts with any tet of s it conflicts with
  // that one (the segment sq becomes a Delaunay edge, so the old tets it crosses are in
  // conflict), so "not beyond" there means drowned.
  std::int32_t t = -1;
  if (q != g.inf && count > 0 && np == 0) {
    t = star_locate(g, T, count, s, q, hint >= 0 && hint < count ? hint : 0, work);
    if (t >= 0 && star_side(g, T[t], s, q, work) <= 0) return kDrowned;
  }
  if (t < 0) {
    // No walk (a tet of the star is flat or negative in 3-D, or q is ∞): scan for one
    // beyond triangle, newest slots first (in a growing star the newest triangles are the
    // frontier the next point, nearest first, sees). None beyond: drowned.
    for (std::int32_t i = count - 1; i >= 0 && t < 0; --i)
      if (star_side(g, T[i], s, q, work) > 0) t = i;
    if (t < 0) return kDrowned;
  }
  // Flood fill of the beyond set (the facets of a convex cone that q sees: a disk). The
  // beyond triangles are listed (BFS order) at the top of the free slots, growing down
  // from slot `cap`: cap - count >= count + 2 slots of 6 ints hold every triangle.
  std::int32_t* list = reinterpret_cast<std::int32_t*>(T + cap);
  std::int32_t r = 0;
  auto at = [&](std::int32_t i) -> std::int32_t& { return list[-1 - i]; };
  S[t] |= kTriBeyond;
  at(r++) = t;
  for (std::int32_t h = 0; h < r; ++h) {
    const std::int32_t x = at(h);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t y = T[x].adj[k] >> 2;
      if (S[y] & (kTriBeyond | kTriTested)) continue;
      if (star_side(g, T[y], s, q, work) > 0) {
        S[y] |= kTriBeyond;
        at(r++) = y;
      } else {
        S[y] |= kTriTested;
      }
    }
  }
  for (std::int32_t h = 0; h < r; ++h)  // the tested ones are the beyond set's neighbours
    for (int k = 0; k < 3; ++k) S[T[at(h)].adj[k] >> 2] &= std::uint8_t(~kTriTested);
  // the beyond triangles: from the list, or (once the fan needs the list's slots) by a
  // scan, which costs O(count) = O(r) only in that case
  bool listed = true;
  auto each_beyond = [&](auto&& f) {
    if (listed) {
      for (std::int32_t h = 0; h < r; ++h) f(at(h));
    } else {
      for (std::int32_t i = 0; i < count; ++i)
        if (is_beyond(S[i])) f(i);
    }
  };
  auto restore = [&] { each_beyond([&](std::int32_t i) { S[i] &= std::uint8_t(~kTriBeyond); }); };
  if (r == count) {
    restore();
    return g.w ? kStarDead : kStarBroken;
  }
  // a boundary edge (a beyond triangle with a non-beyond neighbour), and their number
  std::int32_t t0 = -1, k0 = -1, edges = 0;
  for (std::int32_t h = 0; h < r; ++h) {
    const std::int32_t i = at(h);
    for (int k = 0; k < 3; ++k)
      if (!is_beyond(S[T[i].adj[k] >> 2])) {
        ++edges;
        if (t0 < 0) {
          t0 = i;
          k0 = k;
        }
      }
  }
  if (t0 < 0) {
    restore();
    return kStarBroken;
  }
  // the fan fills slots [count, count + edges); the list must stay clear of it
  if (count + edges > cap) {
    restore();
    return kStarFull;
  }
  if (count + edges + (r + 5) / 6 > cap) listed = false;
  // walk the hole boundary; boundary edge j = (u_j, v_j) with v_j = u_{j+1}
  std::int32_t nb = 0;
  std::int32_t cur = t0, ck = k0;
  auto drop_fan = [&] {
    for (std::int32_t j = 0; j < nb; ++j) S[count + j] = kTriFree;
    restore();
  };
  do {
    if (nb >= edges) {  // more boundary steps than boundary edges: not a disk
      drop_fan();
      return kStarBroken;
    }
    const std::int32_t slot = count + nb;
    Tri& n = T[slot];
    n.v[0] = q;
    n.v[1] = T[cur].v[(ck + 1) % 3];
    n.v[2] = T[cur].v[(ck + 2) % 3];
    n.adj[0] = T[cur].adj[ck];
    S[slot] = std::uint8_t(kTriNew | positivity_flag(g, s, n, work));
    ++nb;
    // next boundary edge: rotate around v = n.v[2] through beyond triangles
    const vid_t v = n.v[2];
    std::int32_t tt = cur;
    int p = (ck + 2) % 3;
    for (std::int32_t steps = 0;; ++steps) {
      const int e = (p + 2) % 3;  // edge (v, next vertex) of tt
      const std::int32_t a = T[tt].adj[e];
      if (!is_beyond(S[a >> 2])) {
        cur = tt;
        ck = e;
        break;
      }
      tt = a >> 2;
      p = tri_pos(T[tt], v);
      if (p < 0 || steps > r) {
        drop_fan();
        return kStarBroken;
      }
    }
  } while (!(cur == t0 && ck == k0));
  if (nb != edges) {  // the beyond set is not a disk: the star was not convex
    drop_fan();
    return kStarBroken;
  }
  // fan adjacency and outside back-references
  for (std::int32_t j = 0; j < nb; ++j) {
    Tri& n = T[count + j];
    n.adj[1] = ((count + (j + 1) % nb) << 2) | 2;
    n.adj[2] = ((count + (j + nb - 1) % nb) << 2) | 1;
    const std::int32_t a = n.adj[0];
    T[a >> 2].adj[a & 3] = ((count + j) << 2) | 0;
    np += (S[count + j] & kTriNonPositive) ? 1 : 0;
  }
  // submerged link vertices: on a beyond triangle, not on the boundary; each reported
  // once, from the triangle of smallest slot around it (all of them are beyond)
  auto smallest_around = [&](std::int32_t i, vid_t x) {
    std::int32_t m = i, c = i;
    for (std::int32_t steps = 0; steps <= r; ++steps) {
      c = T[c].adj[(tri_pos(T[c], x) + 2) % 3] >> 2;  // across edge (x, next vertex)
      if (c == i) break;
      if (c < m) m = c;
    }
    return m;
  };
  each_beyond([&](std::int32_t i) {
    np -= (S[i] & kTriNonPositive) ? 1 : 0;
    for (int k = 0; k < 3; ++k) {
      const vid_t x = T[i].v[k];
      bool on_boundary = false;
      for (std::int32_t j = 0; j < nb && !on_boundary; ++j) on_boundary = T[count + j].v[1] == x;
      if (!on_boundary && smallest_around(i, x) == i) gone(x);
    }
  });
  // close the holes: live triangles at or past nc move into the beyond slots below nc
  // (as many of each: both are r minus the beyond slots in [nc, count))
  const std::int32_t nc = count - r + nb;
  std::int32_t src = nc;
  each_beyond([&](std::int32_t i) {
    if (i >= nc) return;
    while (is_beyond(S[src])) ++src;
    star_move(T, S, src, i);
    ++src;
  });
  for (std::int32_t i = nc; i < count + nb; ++i) S[i] = kTriFree;
  count = nc;
  if (nonpos) *nonpos = np;
  return kInserted;
}

// Confinement proof (§4.6): v is drowned in the convex star of s (beneath every facet);
// finds link vertices e, t0, t1, t2 with v in the cone from s over them. Returns false
// only if the star is not convex around v.
// Death certificate (§6.4, reflect = true): v is the killer k, beyond every facet of the
// star of s. Then s - k points into the cone of the star, and the link triangle t (not
// holding e = the first link vertex) whose simplicial cone (s; e, t) holds that direction
// gives s inside the 4-simplex (k, e, t0, t1, t2): s is redundant. Testing the virtual
// point 2s - k against the planes (s, e, ti, tj) is testing k with the sign reversed (the
// 5x5 determinant is linear in its last row, and the row of s repeats), under the same
// perturbation.
template <class Work>
GDEL_HD bool star_proof(const flip::Geo& g, const Tri* T, std::int32_t count, vid_t s, vid_t v, vid_t* out,
                        Work work, bool reflect = false) {
  if (count <= 0) return false;
  const vid_t e = T[0].v[0];
  // The cones from s over e and each link triangle without e partition the star's cone (the
  // star pulled to e; one of them holds v under the perturbation). fails(t): the edge k of
  // t (opposite t.v[k]) whose hyperplane (s, e, edge) has v and t.v[k] apart, or -1 if
  // none: t is the answer. The first test that differs stops it.
  auto fails = [&](const Tri& t) -> int {
    for (int k = 0; k < 3; ++k) {
      const vid_t ti = t.v[k], tj = t.v[(k + 1) % 3], tk = t.v[(k + 2) % 3];
      const vid_t a[5] = {s, e, ti, tj, v};
      const vid_t b[5] = {s, e, ti, tj, tk};
      const int sv = g.orient4_any(a, work);
      if ((reflect ? -sv : sv) != g.orient4_any(b, work)) return (k + 2) % 3;
    }
    return -1;
  };
  auto answer = [&](const Tri& t) {
    out[0] = e;
    for (int k = 0; k < 3; ++k) out[1 + k] = t.v[k];
    return true;
  };
  // A visibility walk through that pulled triangulation, across an edge that v lies beyond,
  // from the triangle across from e in T[0]: a few triangles instead of a scan of half the
  // star's (bench/RESULTS.md, session 44). Leaving the disk of triangles without e, or more
  // than `count` steps, falls back to the scan; neither is expected (a pulling triangulation
  // is regular, and a visibility walk in a regular triangulation does not cycle).
  std::int32_t t = T[0].adj[0] >> 2;
  for (std::int32_t step = 0; step < count && tri_pos(T[t], e) < 0; ++step) {
    const int k = fails(T[t]);
    if (k < 0) return answer(T[t]);
    t = T[t].adj[k] >> 2;
  }
  for (std::int32_t i = 0; i < count; ++i)
    if (tri_pos(T[i], e) < 0 && fails(T[i]) < 0) return answer(T[i]);
  return false;
}

}  // namespace gdel::splay
