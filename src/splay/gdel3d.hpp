// gDel3D phase 2 (ALGORITHMS.md §4): repairs gFlip3D's near-Delaunay triangulation T
// into the exact Delaunay triangulation by adaptive star splaying, in parallel bulk
// rounds on either backend (§4.8), then extracts the final tets.
//
//  1. failed vertices: the vertices of facets of T (∞ included) that are not locally
//     Delaunay under Geo::orient4;
//  2. their stars are made convex: taken from T as they are and convexified by
//     Flip-Flop (splay/flipflop.hpp, §4.3), or, where Flip-Flop gives up, rebuilt by
//     beneath-beyond insertion of their T-neighbours (the same convex star over the same
//     points); neighbours left outside start proofs; a triangle of the convex star that
//     is a tet of T is known consistent and not checked;
//  3. splaying rounds (splay/splayer.hpp); a star a request targets is pulled from T;
//  4. output: tets of T none of whose vertices has a star, plus each tet of the stars
//     once (from its smallest vertex that has a star); tets with ∞ and flat tets
//     (exact orient3d = 0, only on coplanar hull faces) are dropped; neighbours from
//     T's adjacency where both sides are kept, else by matching face keys.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "flip/flip_kernels.hpp"
#include "flip/local_delaunay.hpp"
#include "mesh/open_faces.hpp"
#include "mesh/tet_mesh.hpp"
#include "splay/splayer.hpp"

namespace gdel::splay {

// The list of tets with a pulled vertex (GDel3D::incidence) is first sized for this many
// a vertex: an interior vertex of a uniform sample has ≈ 27 tets.
inline constexpr I64 kListedTetsPerVertex = 48;

struct RepairResult {
  I64 failed = 0, stars_built = 0, flat_removed = 0;
  SplayStats splay;
  I64 exact_evaluations = 0;
};

template <class B>
class GDel3D {
 public:
  GDel3D(Context<B>& ctx, mesh::TetMesh<B>& mesh, flip::Geo g, I64 m)
      : ctx_(ctx), mesh_(mesh), g_(g), m_(m), sp_(ctx, g, static_cast<vid_t>(m + 1)) {}

  RepairResult& result() { return res_; }
  Splayer<B>& splayer() { return sp_; }

  // Marks fv[v] = 1 for the vertices of facets that are not locally Delaunay.
  // Returns the number of items the exact pass decided. `keep` (optional) receives the
  // facet signs (flip::facet_signs: > 0 not locally Delaunay, on one side of each facet).
  static I64 failed_flags(Context<B>& ctx, mesh::MeshView mv, I64 nt, flip::Geo g, I64 m, std::int8_t* fvp,
                          Buffer<std::int8_t, B>* keep = nullptr) {
    Buffer<std::int8_t, B> sgn(ctx, static_cast<std::size_t>(4 * std::max<I64>(nt, 1)));
    std::int8_t* sg = sgn.data();
    const vid_t inf = g.inf;
    const I64 ex = flip::facet_signs(ctx, mv, nt, g, sg);
    par::fill(ctx, fvp, static_cast<std::size_t>(m), std::int8_t(0));
    par::parallel_for(ctx, 4 * nt, [=] GDEL_LAMBDA(I64 f) {
      if (sg[f] <= 0) return;
      const vid_t* v = mv.tet[f >> 2].v;
      const int i = static_cast<int>(f & 3);
      for (int k = 0; k < 3; ++k) {
        const vid_t x = v[face_vertex(i, k)];
        if (x != inf) fvp[x] = 1;
      }
    });
    if (keep) *keep = std::move(sgn);
    return ex;
  }

  // Sorted keys (v << 32 | t) of the tets t of T incident to the vertices in `verts`.
  Buffer<U64, B> incidence(const Buffer<vid_t, B>& verts) {
    Buffer<std::int32_t, B> wanted(ctx_, static_cast<std::size_t>(m_ + 1));
    std::int32_t* want = wanted.data();
    par::fill(ctx_, want, wanted.size(), std::int32_t(-1));
    const vid_t* vp = verts.data();
    par::parallel_for(ctx_, static_cast<I64>(verts.size()),
                      [=] GDEL_LAMBDA(I64 i) { want[vp[i]] = static_cast<std::int32_t>(i); });
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    const vid_t inf = g_.inf;
    auto hits = [=] GDEL_LAMBDA(I64 t) -> int {
      int c = 0;
      for (int i = 0; i < 4; ++i) {
        const vid_t v = mv.tet[t].v[i];
        c += (v != inf && want[v] >= 0) ? 1 : 0;
      }
      return c;
    };
    // The tets with a wanted vertex first (few: memory by them, not by the mesh), listed
    // by one pass over T into a list of a bound's size (an atomic counter: their order
    // does not matter, the keys are sorted below); a second pass, into a list of the
    // count, only where a wanted vertex's star was larger than the bound allows for (a
    // point on a flat hull has thousands of tets).
    Buffer<I64, B> found(ctx_, 1);
    I64* fp = found.data();
    I64 cap = std::min<I64>(nt, kListedTetsPerVertex * static_cast<I64>(verts.size()) + 4096);
    Buffer<tid_t, B> list(ctx_, static_cast<std::size_t>(std::max<I64>(cap, 1)));
    I64 nl = 0;
    for (;;) {
      par::fill(ctx_, fp, 1, I64(0));
      tid_t* lp = list.data();
      const I64 c = cap;
      par::parallel_for(ctx_, nt, [=] GDEL_LAMBDA(I64 t) {
        if (hits(t) == 0) return;
        const I64 k = par::atomic_add(fp, I64(1));
        if (k < c) lp[k] = static_cast<tid_t>(t);
      });
      nl = found.get(0);
      if (nl <= cap) break;
      cap = nl;
      list = Buffer<tid_t, B>(ctx_, static_cast<std::size_t>(cap));
    }
    const tid_t* lp = list.data();
    Buffer<I64, B> cnt(ctx_, static_cast<std::size_t>(nl + 1));
    I64* cp = cnt.data();
    par::parallel_for(ctx_, nl, [=] GDEL_LAMBDA(I64 j) { cp[j] = hits(lp[j]); });
    const I64 total = par::counts_to_offsets(ctx_, cp, static_cast<std::size_t>(nl));
    Buffer<U64, B> keys(ctx_, static_cast<std::size_t>(total));
    U64* kp = keys.data();
    par::parallel_for(ctx_, nl, [=] GDEL_LAMBDA(I64 j) {
      I64 k = cp[j];
      const tid_t t = lp[j];
      for (int i = 0; i < 4; ++i) {
        const vid_t v = mv.tet[t].v[i];
        if (v != inf && want[v] >= 0) kp[k++] = pair_key(v, t);
      }
    });
    if (total > 0) par::sort_keys(ctx_, kp, static_cast<std::size_t>(total));
    return keys;
  }

  // Creates the stars of `verts` as they are in T (convex there).
  void pull(const Buffer<vid_t, B>& verts) {
    const I64 nv = static_cast<I64>(verts.size());
    Buffer<U64, B> keys = incidence(verts);
    I64 k = 0;
    Buffer<I64, B> heads = sp_.group_heads(keys, k);
    if (k != nv) throw std::runtime_error("gdel internal error: a vertex to pull has no tet in T");
    // stars in the order of the groups (ascending vertex)
    Buffer<vid_t, B> gv(ctx_, static_cast<std::size_t>(k));
    Buffer<std::int32_t, B> caps(ctx_, static_cast<std::size_t>(k));
    vid_t* gvp = gv.data();
    std::int32_t* cp = caps.data();
    const U64* kp = keys.data();
    const I64* hp = heads.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) {
      gvp[j] = key_target(kp[hp[j]]);
      cp[j] = static_cast<std::int32_t>(2 * (hp[j + 1] - hp[j]) + 4);
    });
    const I64 s0 = sp_.add_stars(gv, caps);
    const StarView sv = sp_.view();
    const mesh::MeshView mv = mesh_.view();
    std::int32_t* ep = sp_.error_ptr();
    // one thread per tet of a star (a pulled star of a point on a coplanar hull face has
    // thousands: one thread per star would walk them all alone)
    par::parallel_for(ctx_, static_cast<I64>(keys.size()), [=] GDEL_LAMBDA(I64 i) {
      const I64 j = group_of(hp, k, i);
      const I64 s = s0 + j;
      const I64 a = hp[j], q = i - a;
      if (!star_tri_from_T(mv, kp + a, hp[j + 1] - a, gvp[j], q, sv.tri[sv.begin[s] + q])) ep[0] = 5;
      sv.state[sv.begin[s] + q] = kTriChecked;
      if (q == 0) sv.count[s] = static_cast<std::int32_t>(hp[j + 1] - a);
    });
    sp_.throw_if_error("pulling a star from T");
  }

  // Triangle q of the star of `me` as it is in T: the link triangle of the q-th of its m
  // tets (inc: their sorted keys (me << 32 | t)), with the link adjacency (neighbour
  // triangles by the same local index). False if T's adjacency around `me` is not a
  // closed link (an internal error).
  GDEL_HD static bool star_tri_from_T(const mesh::MeshView& mv, const U64* inc, I64 m, vid_t me, I64 q, Tri& tr) {
    bool ok = true;
    const tid_t t = key_vertex(inc[q]);
    link_triangle(mv, t, me, tr);
    for (int e = 0; e < 3; ++e) {
      // edge e of the link triangle is opposite tr.v[e]: the tet face opposite it
      const int lf = tet_slot(mv, t, tr.v[e]);
      const tid_t u = mv.opp_tet(4 * I64(t) + lf);
      const I64 lo = sorted_find(inc, m, pair_key(me, u));  // local index of u
      if (lo < 0) {
        ok = false;
        continue;
      }
      // the edge of u's triangle with the same two vertices, reversed
      Tri tu;
      link_triangle(mv, u, me, tu);
      const vid_t x = tr.v[(e + 1) % 3], y = tr.v[(e + 2) % 3];
      int f = -1;
      for (int r = 0; r < 3; ++r)
        if (tu.v[(r + 1) % 3] == y && tu.v[(r + 2) % 3] == x) f = r;
      if (f < 0) ok = false;
      tr.adj[e] = static_cast<std::int32_t>((lo << 2) | (f < 0 ? 0 : f));
    }
    return ok;
  }

  // build_stars' seed: a failed vertex's star as it is in T, for Flip-Flop, with the
  // link edges whose facet is not locally Delaunay in T (facet signs sg) flagged in S:
  // the others are convex (the same orient4), so Flip-Flop starts from the flagged ones.
  // One thread per tet of a star (the star of a point on a coplanar hull face has
  // thousands of them), in two passes: the triangles, then, for the stars whose link
  // closed, their flags and the seed's size.
  struct TSeed {
    static constexpr bool enabled = true;
    mesh::MeshView mv;
    const U64* inc;    // the failed vertices' tets, sorted keys (v << 32 | t)
    const I64* heads;  // their groups, one per star
    I64 ni;            // the keys' count
    const std::int8_t* sg;
    void operator()(Context<B>& ctx, I64 s0, I64 k, const StarView& sv, std::int32_t* seeded) const {
      Buffer<std::int32_t, B> bad(ctx, static_cast<std::size_t>(std::max<I64>(k, 1)));
      std::int32_t* bp = bad.data();
      par::fill(ctx, bp, bad.size(), std::int32_t(0));
      const mesh::MeshView m = mv;
      const U64* ip = inc;
      const I64* hp = heads;
      const std::int8_t* sgp = sg;
      par::parallel_for(ctx, ni, [=] GDEL_LAMBDA(I64 i) {
        const I64 j = group_of(hp, k, i);
        const I64 s = s0 + j, a = hp[j], n = hp[j + 1] - a;
        if (n > sv.cap[s]) return;
        if (!star_tri_from_T(m, ip + a, n, key_target(ip[i]), i - a, sv.tri[sv.begin[s] + (i - a)]))
          par::atomic_or(bp + j, std::int32_t(1));
      });
      par::parallel_for(ctx, ni, [=] GDEL_LAMBDA(I64 i) {
        const I64 j = group_of(hp, k, i);
        const I64 s = s0 + j, a = hp[j], n = hp[j + 1] - a;
        const bool ok = n <= sv.cap[s] && bp[j] == 0;
        if (i == a) seeded[j] = ok ? static_cast<std::int32_t>(n) : -1;
        if (!ok) return;
        const Tri& tr = sv.tri[sv.begin[s] + (i - a)];
        const tid_t t = key_vertex(ip[i]);
        std::uint8_t mask = 0;
        for (int e = 0; e < 3; ++e) {
          if (!(tr.v[(e + 1) % 3] < tr.v[(e + 2) % 3])) continue;  // each edge from one side
          const I64 f = 4 * I64(t) + tet_slot(m, t, tr.v[e]);
          const fid_t o = m.opp(f);
          const std::int8_t sign = (o >= 0 && facet_tet(o) < t) ? sgp[o] : sgp[f];
          if (sign > 0) mask |= std::uint8_t(kTriStacked0 << e);
        }
        sv.state[sv.begin[s] + (i - a)] = mask;
      });
    }
  };

  GDEL_HD static int tet_slot(const mesh::MeshView& mv, tid_t t, vid_t v) {
    for (int i = 0; i < 4; ++i)
      if (mv.tet[t].v[i] == v) return i;
    return -1;
  }
  // The link triangle of tet t in the star of its vertex `me`, oriented so that
  // (me, a, b, c) is a positive tet: the face opposite `me`, reversed.
  GDEL_HD static void link_triangle(const mesh::MeshView& mv, tid_t t, vid_t me, Tri& out) {
    const int j = tet_slot(mv, t, me);
    out.v[0] = mv.tet[t].v[face_vertex(j, 0)];
    out.v[1] = mv.tet[t].v[face_vertex(j, 2)];
    out.v[2] = mv.tet[t].v[face_vertex(j, 1)];
  }

  // Rebuilds the stars of the failed vertices from their T-neighbours; returns the gone
  // pairs (drowned and submerged) through `gone`.
  void build_failed(const Buffer<vid_t, B>& failed, Buffer<U64, B>& gone) {
    Buffer<U64, B> inc = incidence(failed);
    I64 k = 0;
    Buffer<I64, B> ih = sp_.group_heads(inc, k);
    const U64* ip = inc.data();
    const I64* ihp = ih.data();
    const mesh::MeshView mv = mesh_.view();
    // link vertex sets: (v << 32 | x), sorted, unique
    const I64 ni = static_cast<I64>(inc.size());
    Buffer<U64, B> lk(ctx_, static_cast<std::size_t>(3 * ni));
    U64* lp = lk.data();
    par::parallel_for(ctx_, ni, [=] GDEL_LAMBDA(I64 i) {
      const vid_t v = key_target(ip[i]);
      const tid_t t = key_vertex(ip[i]);
      int q = 0;
      for (int a = 0; a < 4; ++a) {
        const vid_t x = mv.tet[t].v[a];
        if (x != v) lp[3 * i + q++] = pair_key(v, x);
      }
    });
    par::sort_keys(ctx_, lp, static_cast<std::size_t>(3 * ni));
    lk.resize(par::unique(ctx_, lp, static_cast<std::size_t>(3 * ni)));
    if (std::getenv("GDEL_SPLAY_DEBUG"))
      std::fprintf(stderr, "gdel3d: %lld failed stars, %lld tets around them\n", (long long)k, (long long)ni);
    par::mark(ctx_, "repair: failed stars' tets, link sets");
    // stars s0 + j, j in [0, k): group j of lk and of inc are the same vertex (both sorted);
    // convexified from their form in T by Flip-Flop, rebuilt where that gives up
    // (GDEL_STAR_BUILD=rebuild: all rebuilt, for comparison)
    const char* how = std::getenv("GDEL_STAR_BUILD");
    const bool rebuild = how && std::strcmp(how, "rebuild") == 0;
    const I64 s0 = rebuild ? sp_.build_stars(lk, gone) : sp_.build_stars(lk, gone, TSeed{mv, ip, ihp, ni, facet_sign_.data()});
    res_.stars_built = k;
    if (rebuild) sp_.stats().rebuilt += k;
    // triangles that are tets of T need no check (Flip-Flop keeps most of them; a rebuilt
    // star has them anew): T's link triangles of every star in canonical form (smallest
    // vertex first), sorted by (star, triangle), then a binary search per star triangle
    // in its star's range: O((m + k) log m) in all, one thread per item, not per star (a
    // star of a point on a coplanar hull face has thousands of both: bench/RESULTS.md
    // 2026-11-25 and session 45). The keys: (me << 32 | v0) and (v1 << 32 | v2), sorted
    // by the second, then stably by the first.
    const StarView sv = sp_.view();
    Buffer<U64, B> khi(ctx_, static_cast<std::size_t>(std::max<I64>(ni, 1)));
    Buffer<U64, B> klo(ctx_, static_cast<std::size_t>(std::max<I64>(ni, 1)));
    U64* hip = khi.data();
    U64* lop = klo.data();
    par::parallel_for(ctx_, ni, [=] GDEL_LAMBDA(I64 i) {
      const vid_t me = key_target(ip[i]);
      Tri lt;
      link_triangle(mv, key_vertex(ip[i]), me, lt);
      const LinkKey x = LinkKey::of(lt.v);
      hip[i] = pair_key(me, x.v[0]);
      lop[i] = pair_key(x.v[1], x.v[2]);
    });
    par::sort_pairs(ctx_, lop, hip, static_cast<std::size_t>(ni));
    par::sort_pairs(ctx_, hip, lop, static_cast<std::size_t>(ni));
    Buffer<I64, B> toff(ctx_, static_cast<std::size_t>(k + 1));
    I64* top = toff.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(I64 j) { top[j] = sv.count[s0 + j]; });
    const I64 ntri = par::counts_to_offsets(ctx_, top, static_cast<std::size_t>(k));
    par::parallel_for(ctx_, ntri, [=] GDEL_LAMBDA(I64 x) {
      const I64 j = group_of(top, k, x);
      const I64 s = s0 + j, i = x - top[j];
      const vid_t me = sv.vert[s];
      const LinkKey y = LinkKey::of(sv.tri[sv.begin[s] + i].v);
      const U64 h = pair_key(me, y.v[0]), l = pair_key(y.v[1], y.v[2]);
      I64 lo = ihp[j], hi = ihp[j + 1];
      while (lo < hi) {
        const I64 mid = (lo + hi) / 2;
        if (hip[mid] < h || (hip[mid] == h && lop[mid] < l)) lo = mid + 1;
        else hi = mid;
      }
      const bool in_t = lo < ihp[j + 1] && hip[lo] == h && lop[lo] == l;
      set_kind(sv.state[sv.begin[s] + i], in_t ? kTriChecked : kTriNew);
    });
    par::mark(ctx_, "repair: failed stars' T check");
  }

  // An oriented link triangle rotated so that its smallest vertex comes first: equal
  // keys, same oriented triangle.
  struct LinkKey {
    vid_t v[3];
    GDEL_HD static LinkKey of(const vid_t* t) {
      const int r = (t[0] < t[1]) ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
      return LinkKey{{t[r], t[(r + 1) % 3], t[(r + 2) % 3]}};
    }
  };
  // Steps 1-3.
  void repair() {
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    Buffer<std::int8_t, B> fv(ctx_, static_cast<std::size_t>(m_));
    const bool dbg = std::getenv("GDEL_SPLAY_DEBUG") != nullptr;
    auto t0 = std::chrono::steady_clock::now();
    auto lap = [&](const char* what) {
      par::mark(ctx_, what);  // (GDEL_PROFILE; the splaying rounds mark their own steps)
      if (!dbg) return;
      ctx_.synchronize();
      std::fprintf(stderr, "gdel3d %s: %.3f s\n", what,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    };
    res_.exact_evaluations += failed_flags(ctx_, mv, nt, g_, m_, fv.data(), &facet_sign_);
    lap("repair: failed vertices");
    const std::int8_t* fvp = fv.data();
    Buffer<vid_t, B> failed(ctx_, static_cast<std::size_t>(m_));
    const std::size_t nf = par::select_indices(ctx_, static_cast<std::size_t>(m_), failed.data(),
                                               [=] GDEL_LAMBDA(I64 v) { return fvp[v] != 0; });
    failed.resize(nf);
    res_.failed = static_cast<I64>(nf);
    if (nf == 0) return;
    Buffer<U64, B> gone(ctx_);
    build_failed(failed, gone);
    lap("repair: stars of failed vertices");
    facet_sign_ = Buffer<std::int8_t, B>(ctx_);
    Buffer<U64, B> req(ctx_);
    sp_.set_source([this](const Buffer<vid_t, B>& verts) { pull(verts); });
    sp_.proofs(gone, req);
    sp_.checks(req);
    par::mark(ctx_, "repair: first proofs and checks");
    sp_.run(req);
    lap("repair: splaying rounds");
    res_.splay = sp_.stats();
  }

  // Step 4: final tets (internal ids) and neighbours (-1 on the hull). Consumes the
  // mesh: its arrays are released as the output is written.
  void extract(Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr) {
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    const std::int32_t* so = sp_.star_of();
    const vid_t inf = g_.inf;
    const flip::Geo g = g_;
    // T tets kept: finite, no vertex with a star, not flat. flp[t] > 0: kept; 0: flat;
    // kInfTet: a tet with the vertex at infinity (read by the neighbours' pass below);
    // kStarTet: finite with a vertex that has a star (the star tets come from the stars,
    // each once). One pass over the records.
    Buffer<std::int8_t, B> flat(ctx_, static_cast<std::size_t>(std::max<I64>(nt, 1)));
    std::int8_t* flp = flat.data();
    constexpr std::int8_t kInfTet = -100, kStarTet = -101;
    res_.exact_evaluations += par::two_stage_signs(
        ctx_, nt, flp,
        [=] GDEL_LAMBDA(I64 t) -> std::int8_t {
          const mesh::Tet x = mv.tet[t];
          bool star = false;
          for (int i = 0; i < 4; ++i) {
            if (x.v[i] == inf) return kInfTet;
            star = star || so[x.v[i]] >= 0;
          }
          return star ? kStarTet : g.volume_sign_fast(x.v);
        },
        [=] GDEL_LAMBDA(I64 t, double* work) { return g.volume_sign_exact(mv.tet[t].v, work); },
        geom::kPredicateWork);
    Buffer<I64, B> snum(ctx_);
    I64 flat_stars = 0;
    const I64 nstar = sp_.plan_star_tets(snum, flat_stars, res_.exact_evaluations);
    // numbering: T tets first, then star tets
    Buffer<I64, B> tnum(ctx_, static_cast<std::size_t>(nt + 1));
    I64* tnp = tnum.data();
    par::parallel_for(ctx_, nt, [=] GDEL_LAMBDA(I64 t) { tnp[t] = flp[t] > 0 ? 1 : 0; });
    const I64 nkeep = par::counts_to_offsets(ctx_, tnp, static_cast<std::size_t>(nt));
    const I64 nout = nkeep + nstar;
    // flat tets dropped (T tets without star vertices, and star tets)
    res_.flat_removed =
        par::count_indices(ctx_, static_cast<std::size_t>(nt), [=] GDEL_LAMBDA(I64 t) { return flp[t] == 0; }) +
        flat_stars;
    // The mesh is consumed from here on, one array at a time, so that the output is
    // never beside the whole mesh: the states first, then the neighbours read out of the
    // records, which then become the output's tets in place
    // (TetMesh::take_tets).
    mesh_.state().release();
    nbr.resize(static_cast<std::size_t>(4 * nout));
    std::int32_t* np = nbr.data();
    par::parallel_for(ctx_, nt, [=] GDEL_LAMBDA(I64 t) {
      if (tnp[t + 1] == tnp[t]) return;
      const I64 d = tnp[t];
      for (int i = 0; i < 4; ++i) {
        const tid_t u = mv.opp_tet(4 * t + i);
        // -2: to be matched by face key; -1: hull (∞ on the other side)
        const bool u_inf = u < 0 || flp[u] == kInfTet;
        np[4 * d + i] = u_inf ? -1 : (tnp[u + 1] != tnp[u] ? static_cast<std::int32_t>(tnp[u]) : -2);
      }
    });
    // the tets written over the records (the mesh is gone after this)
    tets = mesh_.take_tets(tnp, 4 * nout, [] GDEL_LAMBDA(vid_t v) { return v; });
    vid_t* op = tets.data();
    tnum.release();
    flat.release();
    sp_.write_star_tets(snum, op, np, nkeep);
    mesh::match_open_faces(ctx_, tets.data(), nbr.data(), nout);
  }

 private:
  Context<B>& ctx_;
  mesh::TetMesh<B>& mesh_;
  flip::Geo g_;
  I64 m_;
  Splayer<B> sp_;
  RepairResult res_;
  Buffer<std::int8_t, B> facet_sign_{ctx_};  // failed_flags' facet signs, until the stars are built
};

}  // namespace gdel::splay
