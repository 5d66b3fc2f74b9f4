// Flip-Flop convexification of a star (ALGORITHMS.md §4.3, after Gao et al., I3D 2013):
// the star of s as it is in gFlip3D's triangulation T (a link whose tets all have
// positive 3-D orientation: a partition of the directions around s, star-shaped as seen
// from s, but not convex in the lift where T is not locally Delaunay) is turned into the
// convex star over the same link vertices by 2-2 flips of link edges and 3-1 "flops"
// that remove a degree-3 vertex.
//
// Every test is one of the engine's exact, perturbed predicates (orient4 with s as apex
// for reflexity, 3-D orientation with s for the validity of a flip), so each star lives
// in one consistent perturbed world where the thesis' argument applies. The routine still
// does not trust itself: it returns false (the caller then rebuilds the star by
// beneath-beyond insertion) when a step budget runs out, a scratch area is too small, a
// flip would make a tet non-positive, or when the final star is not locally convex at
// every edge. A locally convex star whose tets are all positive is convex. Vertices the
// flops removed are then inserted into that convex star by beneath-beyond (star_insert):
// each is reported drowned there (the expected case), or comes back if a flop was wrong,
// so the result is the unique convex star over the link vertices either way.
#pragma once

#include <cstdint>

#include "parallel/lockstep.hpp"
#include "splay/star.hpp"

namespace gdel::splay {

// S bits for "edge k of this triangle is on the Flip-Flop stack" (k = 0, 1, 2).
inline constexpr std::uint8_t kTriStacked0 = 32;

// Convexifies the star of s held in T[0, count) (adjacency set). S[i] & (kTriStacked0 << k)
// on input flags the edges to start from: those that may be reflex (the others must be
// known convex, as gDel3D's facets of T that are locally Delaunay under the same orient4).
// `nws` link vertices, through `ws`: ws(x) is x's index in [0, nws) (-1 if none) and
// ws.vertex(i) the vertex of index i (e.g. a sorted list and a binary search).
// `record(x)` receives the vertices that end up outside the star (not extreme); it may
// have been called when false is returned (the caller discards those records). On
// success returns true with the star compact in [0, count), every state kTriNew, every
// slot past count kTriFree; on failure the contents of T and S are unspecified (the
// caller rebuilds; it must clear S).
template <class WorkingSet, class Record, class Work>
GDEL_STAR_NOINLINE GDEL_HD bool star_flipflop(const flip::Geo& g, Tri* T, std::uint8_t* S, std::int32_t& count,
                                              std::int32_t cap, vid_t s, std::int32_t nws, WorkingSet ws,
                                              Record record, Work work, std::int64_t step_cap = -1) {
  const std::int32_t c0 = count;
  if (c0 < 4) return false;
  // scratch past the live triangles: the edge stack (3 * c0 ints: one entry per
  // (triangle, edge) at most, thanks to the stacked bits), one mark byte per link vertex
  // (1: not extreme; removed by a flop: 2 at a reflex edge, which certifies it is not
  // extreme, 4 as a marked vertex), then the edges left reflex (to test again at the
  // end; if they do not fit, every edge is). At the end the top holds the removed ids.
  const std::int64_t bytes = 24 * static_cast<std::int64_t>(cap - c0);
  const std::int64_t need = 12 * static_cast<std::int64_t>(c0) + 5 * static_cast<std::int64_t>(nws) + 32;
  if (bytes < need) return false;
  std::int32_t* stack = reinterpret_cast<std::int32_t*>(T + c0);
  std::uint8_t* mark = reinterpret_cast<std::uint8_t*>(stack + 3 * c0);
  for (std::int32_t i = 0; i < nws; ++i) mark[i] = 0;
  std::int32_t* redo = stack + 3 * c0 + (nws + 3) / 4;
  const std::int64_t redo_cap = (reinterpret_cast<std::int32_t*>(T + cap) - redo);
  std::int64_t nredo = 0;
  bool check_all = false;
  auto left_reflex = [&](std::int32_t t, int k) {
    if (nredo < redo_cap) redo[nredo++] = (t << 2) | k;
    else check_all = true;
  };
  std::int32_t sp = 0;
  std::int32_t live = c0;
  auto push = [&](std::int32_t t, int k) {
    const std::uint8_t bit = std::uint8_t(kTriStacked0 << k);
    if (S[t] & bit) return;
    S[t] |= bit;
    stack[sp++] = (t << 2) | k;
  };
  // The loops below run in lockstep with the warp's other stars (par::Lockstep): where they
  // give up they set `failed` and finish the loop, instead of returning from it.
  const par::Lockstep group;
  bool failed = false;
  for (std::int32_t i = 0; i < c0 && !failed; ++i) {
    if (positivity_flag(g, s, T[i], work) != 0) failed = true;  // not star-shaped: rebuild
    const std::uint8_t given = S[i];
    S[i] = kTriNew;
    for (int k = 0; k < 3; ++k)
      if (given & (kTriStacked0 << k)) push(i, k);
  }
  auto marked = [&](vid_t x) -> bool {
    const std::int32_t i = ws(x);
    return i >= 0 && (mark[i] & 1);
  };
  // degree of x (in triangle t), counted up to 4
  auto degree = [&](std::int32_t t, vid_t x) {
    std::int32_t c = t, d = 0;
    do {
      c = T[c].adj[(tri_pos(T[c], x) + 2) % 3] >> 2;  // across edge (x, next vertex)
      ++d;
    } while (c != t && d < 4);
    return d;
  };
  auto relink = [&](std::int32_t t) {
    for (int e = 0; e < 3; ++e) {
      const std::int32_t a = T[t].adj[e];
      T[a >> 2].adj[a & 3] = (t << 2) | e;
    }
  };
  auto push_around = [&](std::int32_t t, vid_t x) {
    std::int32_t c = t;
    std::int32_t d = 0;
    do {
      const int p = tri_pos(T[c], x);
      push(c, (p + 1) % 3);  // edges (x, ·) of c: opposite the other two vertices
      push(c, (p + 2) % 3);
      c = T[c].adj[(p + 2) % 3] >> 2;
    } while (c != t && ++d <= live);
  };
  // 3-1 flop: removes x = T[t].v[(k+1)%3] (degree 3) keeping slot t as (p, w, y)
  auto flop = [&](std::int32_t t, int k, bool certified) -> bool {
    const vid_t x = T[t].v[(k + 1) % 3], p = T[t].v[(k + 2) % 3], w = T[t].v[k];
    const std::int32_t t2 = T[t].adj[k] >> 2;                // (p, x, y)
    const std::int32_t t3 = T[t].adj[(k + 2) % 3] >> 2;      // (x, w, y), across (w, x)
    const vid_t y = T[t2].v[(tri_pos(T[t2], x) + 1) % 3];
    if (tri_pos(T[t3], y) < 0) return false;
    Tri n;
    n.v[0] = p;
    n.v[1] = w;
    n.v[2] = y;
    n.adj[0] = T[t3].adj[tri_pos(T[t3], x)];  // (w, y)
    n.adj[1] = T[t2].adj[tri_pos(T[t2], x)];  // (y, p)
    n.adj[2] = T[t].adj[(k + 1) % 3];         // (p, w)
    if (positivity_flag(g, s, n, work) != 0) return false;
    T[t] = n;
    relink(t);
    S[t2] = kTriFree;
    S[t3] = kTriFree;
    live -= 2;
    const std::int32_t i = ws(x);
    if (i < 0) return false;
    mark[i] = certified ? 2 : 4;
    for (int e = 0; e < 3; ++e) push(t, e);
    return true;
  };
  // the step budget (step_cap >= 0 lowers it: tests drive the caller's fallback with 0)
  std::int64_t budget = 64 * static_cast<std::int64_t>(c0) + 4096;
  if (step_cap >= 0 && step_cap < budget) budget = step_cap;
  std::int64_t steps = 0;
  while (group.any(!failed && sp > 0)) {
    if (failed || sp <= 0) continue;
    if (++steps > budget) {
      failed = true;
      continue;
    }
    const std::int32_t e = stack[--sp];
    const std::int32_t t = e >> 2;
    const int k = e & 3;
    S[t] &= std::uint8_t(~(kTriStacked0 << k));
    if (tri_kind(S[t]) == kTriFree) continue;
    const vid_t u = T[t].v[(k + 1) % 3], v = T[t].v[(k + 2) % 3], w = T[t].v[k];
    const std::int32_t t2 = T[t].adj[k] >> 2;
    const int k2 = T[t].adj[k] & 3;
    const vid_t y = T[t2].v[k2];
    const bool reflex = star_side(g, T[t], s, y, work) > 0;
    // the smallest marked (not extreme) vertex of the four
    vid_t m = -1;
    const vid_t four[4] = {u, v, w, y};
    for (int q = 0; q < 4; ++q)
      if ((m < 0 || four[q] < m) && marked(four[q])) m = four[q];
    if (m >= 0 && (m == w || m == y)) {  // a flip would raise its degree
      if (reflex) left_reflex(t, k);
      continue;
    }
    if (m < 0 && !reflex) continue;
    if (live > 4) {
      if ((reflex || m == u) && degree(t, u) == 3) {
        failed = !flop(t, k, reflex);
        continue;
      }
      if ((reflex || m == v) && degree(t2, v) == 3) {
        failed = !flop(t2, k2, reflex);
        continue;
      }
    }
    // 2-2: uv -> wy, as (u, y, w) in t and (y, v, w) in t2, if both tets stay positive
    Tri a, b;
    a.v[0] = u;
    a.v[1] = y;
    a.v[2] = w;
    b.v[0] = y;
    b.v[1] = v;
    b.v[2] = w;
    const bool pa = positivity_flag(g, s, a, work) == 0;
    const bool pb = pa && positivity_flag(g, s, b, work) == 0;
    if (pa && pb) {
      a.adj[0] = (t2 << 2) | 1;
      a.adj[1] = T[t].adj[(k + 2) % 3];    // (w, u)
      a.adj[2] = T[t2].adj[(k2 + 1) % 3];  // (u, y)
      b.adj[0] = T[t].adj[(k + 1) % 3];    // (v, w)
      b.adj[1] = (t << 2) | 0;
      b.adj[2] = T[t2].adj[(k2 + 2) % 3];  // (y, v)
      if ((a.adj[1] >> 2) == t2 || (a.adj[2] >> 2) == t || (b.adj[0] >> 2) == t2 || (b.adj[2] >> 2) == t) {
        failed = true;  // a degree-3 vertex (cannot happen with both tets positive)
        continue;
      }
      T[t] = a;
      T[t2] = b;
      relink(t);
      relink(t2);
      if (!reflex) left_reflex(t, 0);  // flipping a convex edge (m's): wy may be reflex
      push(t, 1);
      push(t, 2);
      push(t2, 0);
      push(t2, 2);
      continue;
    }
    if (reflex) {  // blocked: the quadrilateral is not convex at u (or v) seen from s
      left_reflex(t, k);
      const vid_t x = pa ? v : u;
      const std::int32_t i = ws(x);
      if (i < 0) {
        failed = true;
        continue;
      }
      if (!(mark[i] & 1)) {
        mark[i] |= 1;
        push_around(pa ? t2 : t, x);
      }
    }
  }
  if (failed) return false;
  // locally convex at every edge (with every tet positive): convex. Every edge was
  // tested after the triangles on its two sides last changed (a change pushes it; the
  // diagonal of a flip of a reflex edge is convex) and found convex, unless it was left
  // reflex (a marked vertex in the way, a blocked flip) or is the diagonal of a flip of
  // a convex edge: those (listed) are tested again.
  auto reflex_at = [&](std::int32_t i, int k) {
    const std::int32_t o = T[i].adj[k];
    return star_side(g, T[i], s, T[o >> 2].v[o & 3], work) > 0;
  };
  if (check_all) {
    for (std::int32_t i = 0; i < c0; ++i) {
      if (tri_kind(S[i]) == kTriFree) continue;
      for (int k = 0; k < 3; ++k)
        if (T[i].v[(k + 1) % 3] < T[i].v[(k + 2) % 3] && reflex_at(i, k)) return false;
    }
  } else {
    for (std::int64_t j = 0; j < nredo; ++j) {
      const std::int32_t i = redo[j] >> 2;
      if (tri_kind(S[i]) != kTriFree && reflex_at(i, redo[j] & 3)) return false;
    }
  }
  // compact: live triangles past `live` move into the holes below it
  std::int32_t src = live;
  for (std::int32_t i = 0; i < live; ++i) {
    if (tri_kind(S[i]) != kTriFree) continue;
    while (tri_kind(S[src]) == kTriFree) ++src;
    star_move(T, S, src, i);
    ++src;
  }
  for (std::int32_t i = live; i < c0; ++i) S[i] = kTriFree;
  count = live;
  // the vertices removed at a reflex edge are not extreme; the others (removed as marked
  // vertices) go to the top of the scratch, then into the convex star by beneath-beyond
  std::int32_t nr = 0;
  for (std::int32_t i = 0; i < nws; ++i) {
    if (mark[i] & 2) record(ws.vertex(i));
    nr += (mark[i] & 4) ? 1 : 0;
  }
  vid_t* rem = reinterpret_cast<vid_t*>(T + cap) - nr;
  if (reinterpret_cast<std::uint8_t*>(rem) < mark + nws) return false;
  nr = 0;
  for (std::int32_t i = 0; i < nws; ++i)
    if (mark[i] & 4) rem[nr++] = i;
  const std::int32_t cap2 = cap - (4 * nr + 23) / 24 - 1;
  if (cap2 < 2 * count + 2) return false;
  std::int32_t nonpos = 0;
  for (std::int32_t j = 0; j < nr; ++j) {
    const vid_t x = ws.vertex(rem[j]);
    const int r = star_insert(g, T, S, count, cap2, s, x, work, record, 0, &nonpos);
    if (r == kDrowned) record(x);
    else if (r != kInserted) return false;
  }
  return true;
}

}  // namespace gdel::splay
