// gDel3D phase 2 (ALGORITHMS.md §4): repairs gFlip3D's near-Delaunay triangulation T
// into the exact Delaunay triangulation by adaptive star splaying, in parallel bulk
// rounds on either backend (§4.8), then extracts the final tets.
//
//  1. failed vertices: the vertices of facets of T (∞ included) that are not locally
//     Delaunay under Geo::orient4;
//  2. their stars are rebuilt convex by beneath-beyond insertion of their T-neighbours
//     (this replaces the original's Flip-Flop convexification of the T-star: same
//     result, a convex star over the same points; drowned neighbours start proofs);
//     a rebuilt triangle that is a tet of T is known consistent and not checked;
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
#include "mesh/tet_mesh.hpp"
#include "splay/splayer.hpp"

namespace gdel::splay {

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
  // Returns the number of items the exact pass decided.
  static I64 failed_flags(Context<B>& ctx, mesh::MeshView mv, I64 nt, flip::Geo g, I64 m, std::int8_t* fvp) {
    Buffer<std::int8_t, B> sgn(ctx, static_cast<std::size_t>(4 * std::max<I64>(nt, 1)));
    std::int8_t* sg = sgn.data();
    const vid_t inf = g.inf;
    auto tuple = [=] GDEL_HD(I64 f, vid_t* v) -> bool {
      const fid_t o = mv.opp[f];
      const tid_t t = static_cast<tid_t>(f >> 2);
      if (o < 0 || facet_tet(o) < t) return false;
      for (int i = 0; i < 4; ++i) v[i] = mv.tet[t].v[i];
      v[4] = flip::apex_of(mv, o);
      // facet test: both tets may hold ∞, but the 5-tuple must be 5 distinct vertices
      return true;
    };
    const I64 ex = par::two_stage_signs(
        ctx, 4 * nt, sg,
        [=] GDEL_HD(I64 f) -> std::int8_t {
          vid_t v[5] = {0, 0, 0, 0, 0};
          if (!tuple(f, v)) return 0;
          return static_cast<std::int8_t>(g.orient4<false>(v, nullptr));
        },
        [=] GDEL_HD(I64 f, double* work) -> std::int8_t {
          vid_t v[5] = {0, 0, 0, 0, 0};
          if (!tuple(f, v)) return 0;
          return static_cast<std::int8_t>(g.orient4<true>(v, work));
        },
        geom::kPredicateWork);
    par::fill(ctx, fvp, static_cast<std::size_t>(m), std::int8_t(0));
    par::parallel_for(ctx, 4 * nt, [=] GDEL_HD(I64 f) {
      if (sg[f] <= 0) return;
      const vid_t* v = mv.tet[f >> 2].v;
      const int i = static_cast<int>(f & 3);
      for (int k = 0; k < 3; ++k) {
        const vid_t x = v[face_vertex(i, k)];
        if (x != inf) fvp[x] = 1;
      }
    });
    return ex;
  }

  // Sorted keys (v << 32 | t) of the tets t of T incident to the vertices in `verts`.
  Buffer<U64, B> incidence(const Buffer<vid_t, B>& verts) {
    Buffer<std::int32_t, B> wanted(ctx_, static_cast<std::size_t>(m_ + 1));
    std::int32_t* want = wanted.data();
    par::fill(ctx_, want, wanted.size(), std::int32_t(-1));
    const vid_t* vp = verts.data();
    par::parallel_for(ctx_, static_cast<I64>(verts.size()),
                      [=] GDEL_HD(I64 i) { want[vp[i]] = static_cast<std::int32_t>(i); });
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    Buffer<I64, B> cnt(ctx_, static_cast<std::size_t>(nt + 1));
    I64* cp = cnt.data();
    const vid_t inf = g_.inf;
    par::parallel_for(ctx_, nt, [=] GDEL_HD(I64 t) {
      I64 c = 0;
      for (int i = 0; i < 4; ++i) {
        const vid_t v = mv.tet[t].v[i];
        c += (v != inf && want[v] >= 0) ? 1 : 0;
      }
      cp[t] = c;
    });
    const I64 total = par::counts_to_offsets(ctx_, cp, static_cast<std::size_t>(nt));
    Buffer<U64, B> keys(ctx_, static_cast<std::size_t>(total));
    U64* kp = keys.data();
    par::parallel_for(ctx_, nt, [=] GDEL_HD(I64 t) {
      I64 k = cp[t];
      for (int i = 0; i < 4; ++i) {
        const vid_t v = mv.tet[t].v[i];
        if (v != inf && want[v] >= 0) kp[k++] = pair_key(v, static_cast<vid_t>(t));
      }
    });
    if (total > 0) par::sort_keys(ctx_, kp, static_cast<std::size_t>(total));
    return keys;
  }

  // Per-vertex group starts in sorted incidence keys; heads[j] for j in [0, k], k groups.
  Buffer<I64, B> group_heads(const Buffer<U64, B>& keys, I64& k) {
    const I64 n = static_cast<I64>(keys.size());
    const U64* kp = keys.data();
    Buffer<I64, B> heads(ctx_, static_cast<std::size_t>(n + 1));
    k = static_cast<I64>(par::select_indices(ctx_, static_cast<std::size_t>(n), heads.data(), [=] GDEL_HD(I64 i) {
      return i == 0 || key_target(kp[i - 1]) != key_target(kp[i]);
    }));
    I64* hp = heads.data();
    const I64 kk = k;
    par::parallel_for(ctx_, 1, [=] GDEL_HD(I64) { hp[kk] = n; });
    return heads;
  }

  // Creates the stars of `verts` as they are in T (convex there).
  void pull(const Buffer<vid_t, B>& verts) {
    const I64 nv = static_cast<I64>(verts.size());
    Buffer<U64, B> keys = incidence(verts);
    I64 k = 0;
    Buffer<I64, B> heads = group_heads(keys, k);
    if (k != nv) throw std::runtime_error("gdel internal error: a vertex to pull has no tet in T");
    // stars in the order of the groups (ascending vertex)
    Buffer<vid_t, B> gv(ctx_, static_cast<std::size_t>(k));
    Buffer<std::int32_t, B> caps(ctx_, static_cast<std::size_t>(k));
    vid_t* gvp = gv.data();
    std::int32_t* cp = caps.data();
    const U64* kp = keys.data();
    const I64* hp = heads.data();
    par::parallel_for(ctx_, k, [=] GDEL_HD(I64 j) {
      gvp[j] = key_target(kp[hp[j]]);
      cp[j] = static_cast<std::int32_t>(2 * (hp[j + 1] - hp[j]) + 4);
    });
    const I64 s0 = sp_.add_stars(gv, caps);
    const StarView sv = sp_.view();
    const mesh::MeshView mv = mesh_.view();
    std::int32_t* ep = sp_.error_ptr();
    par::parallel_for(ctx_, k, [=] GDEL_HD(I64 j) {
      const I64 s = s0 + j;
      const I64 a = hp[j], b = hp[j + 1];
      const vid_t me = gvp[j];
      Tri* T = sv.tri + sv.begin[s];
      std::uint8_t* S = sv.state + sv.begin[s];
      for (I64 i = a; i < b; ++i) link_triangle(mv, key_vertex(kp[i]), me, T[i - a]);
      for (I64 i = a; i < b; ++i) {
        const tid_t t = key_vertex(kp[i]);
        Tri& tr = T[i - a];
        for (int e = 0; e < 3; ++e) {
          // edge e of the link triangle is opposite tr.v[e]: the tet face opposite it
          const int lf = tet_slot(mv, t, tr.v[e]);
          const tid_t u = facet_tet(mv.opp[4 * I64(t) + lf]);
          // local index of u: binary search in [a, b)
          I64 lo = a, hi = b;
          const U64 key = pair_key(me, u);
          while (lo < hi) {
            const I64 mid = (lo + hi) / 2;
            if (kp[mid] < key) lo = mid + 1;
            else hi = mid;
          }
          if (lo >= b || kp[lo] != key) {
            ep[0] = 5;
            continue;
          }
          // the edge of u's triangle with the same two vertices, reversed
          Tri tu;
          link_triangle(mv, u, me, tu);
          const vid_t x = tr.v[(e + 1) % 3], y = tr.v[(e + 2) % 3];
          int f = -1;
          for (int q = 0; q < 3; ++q)
            if (tu.v[(q + 1) % 3] == y && tu.v[(q + 2) % 3] == x) f = q;
          if (f < 0) ep[0] = 6;
          tr.adj[e] = static_cast<std::int32_t>(((lo - a) << 2) | (f < 0 ? 0 : f));
        }
        S[i - a] = kTriChecked;
      }
      sv.count[s] = static_cast<std::int32_t>(b - a);
    });
    sp_.throw_if_error("pulling a star from T");
  }

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

  // Rebuilds the stars of the failed vertices; returns the gone pairs (drowned and
  // submerged) through `gone`.
  void build_failed(const Buffer<vid_t, B>& failed, Buffer<U64, B>& gone) {
    Buffer<U64, B> inc = incidence(failed);
    I64 k = 0;
    Buffer<I64, B> ih = group_heads(inc, k);
    const U64* ip = inc.data();
    const I64* ihp = ih.data();
    const mesh::MeshView mv = mesh_.view();
    // link vertex sets: (v << 32 | x), sorted, unique
    const I64 ni = static_cast<I64>(inc.size());
    Buffer<U64, B> lk(ctx_, static_cast<std::size_t>(3 * ni));
    U64* lp = lk.data();
    par::parallel_for(ctx_, ni, [=] GDEL_HD(I64 i) {
      const vid_t v = key_target(ip[i]);
      const tid_t t = key_vertex(ip[i]);
      int q = 0;
      for (int a = 0; a < 4; ++a) {
        const vid_t x = mv.tet[t].v[a];
        if (x != v) lp[3 * i + q++] = pair_key(v, x);
      }
    });
    par::sort_keys(ctx_, lp, static_cast<std::size_t>(3 * ni));
    const I64 nl = static_cast<I64>(par::unique(ctx_, lp, static_cast<std::size_t>(3 * ni)));
    lk.resize(static_cast<std::size_t>(nl));
    I64 k2 = 0;
    Buffer<I64, B> lh = group_heads(lk, k2);
    const I64* lhp = lh.data();
    // stars: group j of lk and of inc are the same vertex (both sorted by vertex)
    Buffer<vid_t, B> gv(ctx_, static_cast<std::size_t>(k));
    Buffer<std::int32_t, B> caps(ctx_, static_cast<std::size_t>(k));
    vid_t* gvp = gv.data();
    std::int32_t* cp = caps.data();
    par::parallel_for(ctx_, k, [=] GDEL_HD(I64 j) {
      gvp[j] = key_target(lp[lhp[j]]);
      cp[j] = static_cast<std::int32_t>(4 * (lhp[j + 1] - lhp[j]) + 8);
    });
    if (std::getenv("GDEL_SPLAY_DEBUG"))
      std::fprintf(stderr, "gdel3d: %lld failed stars, largest link %d vertices, %lld tets around them\n",
                   (long long)k, par::reduce_max(ctx_, cp, static_cast<std::size_t>(k), std::int32_t(0)) / 4 - 2,
                   (long long)ni);
    const I64 s0 = sp_.add_stars(gv, caps);
    res_.stars_built = k;
    // the neighbour sets are tried pairs
    sp_.add_history(lk);
    // insertion order: ∞, then nearest first (the order changes only the work, never
    // the result: the convex star over a point set is unique). T's star of a failed vertex
    // can be huge on degenerate input (a fan of flat tets on a coplanar hull face);
    // inserting the near neighbours first makes the far ones drown against a small star
    // instead of growing it: O(k * true degree) instead of O(k^2).
    Buffer<U64, B> okey(ctx_, static_cast<std::size_t>(nl));
    Buffer<vid_t, B> ordv(ctx_, static_cast<std::size_t>(nl));
    {
      U64* okp = okey.data();
      vid_t* ovp = ordv.data();
      const flip::Geo gg = g_;
      const vid_t inf = g_.inf;
      par::parallel_for(ctx_, nl, [=] GDEL_HD(I64 i) {
        const vid_t v = key_target(lp[i]), x = key_vertex(lp[i]);
        std::uint32_t bits = 0;  // ∞ first: then no star holds upper facets (∞ is beyond
                                 // them), every tet is positive in 3-D, and insertion can
                                 // walk instead of scanning (star_insert)
        if (x != inf) {
          double d2 = 0;
          for (int c = 0; c < 3; ++c) {
            const double t = gg.p(x)[c] - gg.p(v)[c];
            d2 += t * t;
          }
          const float f = static_cast<float>(d2);
          std::memcpy(&bits, &f, sizeof bits);
        }
        okp[i] = (U64(static_cast<std::uint32_t>(v)) << 32) | bits;
        ovp[i] = x;
      });
      par::sort_pairs(ctx_, okp, ovp, static_cast<std::size_t>(nl));  // stable: ties by id
    }
    const vid_t* ov = ordv.data();
    // room for gone pairs
    Buffer<I64, B> room(ctx_, static_cast<std::size_t>(k + 1));
    I64* rmp = room.data();
    par::parallel_for(ctx_, k, [=] GDEL_HD(I64 j) { rmp[j] = 2 * (lhp[j + 1] - lhp[j]) + 4; });
    const I64 total = par::counts_to_offsets(ctx_, rmp, static_cast<std::size_t>(k));
    Buffer<U64, B> g1(ctx_, static_cast<std::size_t>(std::max<I64>(total, 1)));
    U64* gp = g1.data();
    Buffer<I64, B> used(ctx_, static_cast<std::size_t>(k));
    I64* up = used.data();
    const StarView sv = sp_.view();
    const flip::Geo g = g_;
    std::int32_t* ep = sp_.error_ptr();
    par::for_each_with_scratch(ctx_, k, geom::kPredicateWork, [=] GDEL_HD(I64 j, double* work) {
      const I64 s = s0 + j;
      const vid_t me = gvp[j];
      const I64 a = lhp[j], b = lhp[j + 1];
      Tri* T = sv.tri + sv.begin[s];
      std::uint8_t* S = sv.state + sv.begin[s];
      I64 gk = rmp[j];
      const I64 gend = rmp[j + 1];
      if (b - a < 4) {
        ep[0] = 7;
        up[j] = 0;
        return;
      }
      vid_t first[4];
      for (int q = 0; q < 4; ++q) first[q] = ov[a + q];
      star_simplex(g, T, S, me, first, kTriNew, work);
      std::int32_t count = 4;
      for (I64 i = a + 4; i < b; ++i)
        insert_recording(g, T, S, count, sv.cap[s], me, ov[i], work, gp, gk, gend, ep);
      sv.count[s] = count;
      up[j] = gk - rmp[j];
      // triangles that are tets of T need no check
      const I64 ta = ihp[j], tb = ihp[j + 1];
      for (std::int32_t i = 0; i < count; ++i) {
        bool in_t = false;
        for (I64 q = ta; q < tb && !in_t; ++q) {
          Tri lt;
          link_triangle(mv, key_vertex(ip[q]), me, lt);
          const int p = tri_pos(lt, T[i].v[0]);
          in_t = p >= 0 && lt.v[(p + 1) % 3] == T[i].v[1] && lt.v[(p + 2) % 3] == T[i].v[2];
        }
        set_kind(S[i], in_t ? kTriChecked : kTriNew);
      }
    });
    sp_.throw_if_error("building a failed vertex's star");
    gone = sp_.pack_pairs(gp, rmp, up, k);
  }

  // Steps 1-3.
  void repair() {
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    Buffer<std::int8_t, B> fv(ctx_, static_cast<std::size_t>(m_));
    const bool dbg = std::getenv("GDEL_SPLAY_DEBUG") != nullptr;
    auto t0 = std::chrono::steady_clock::now();
    auto lap = [&](const char* what) {
      if (!dbg) return;
      ctx_.synchronize();
      std::fprintf(stderr, "gdel3d %s: %.3f s\n", what,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    };
    res_.exact_evaluations += failed_flags(ctx_, mv, nt, g_, m_, fv.data());
    lap("failed vertices");
    const std::int8_t* fvp = fv.data();
    Buffer<vid_t, B> failed(ctx_, static_cast<std::size_t>(m_));
    const std::size_t nf = par::select_indices(ctx_, static_cast<std::size_t>(m_), failed.data(),
                                               [=] GDEL_HD(I64 v) { return fvp[v] != 0; });
    failed.resize(nf);
    res_.failed = static_cast<I64>(nf);
    if (nf == 0) return;
    Buffer<U64, B> gone(ctx_);
    build_failed(failed, gone);
    lap("stars of failed vertices");
    Buffer<U64, B> req(ctx_);
    sp_.set_source([this](const Buffer<vid_t, B>& verts) { pull(verts); });
    sp_.proofs(gone, req);
    sp_.checks(req);
    sp_.run(req);
    lap("splaying rounds");
    res_.splay = sp_.stats();
  }

  // Step 4: final tets (internal ids) and neighbours (-1 on the hull).
  void extract(Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr) {
    const mesh::MeshView mv = mesh_.view();
    const I64 nt = mesh_.size();
    const std::int32_t* so = sp_.star_of();
    const vid_t inf = g_.inf;
    const flip::Geo g = g_;
    // T tets kept: finite, no vertex with a star, not flat
    Buffer<std::int8_t, B> flat(ctx_, static_cast<std::size_t>(std::max<I64>(nt, 1)));
    std::int8_t* flp = flat.data();
    auto t_candidate = [=] GDEL_HD(I64 t) -> bool {
      for (int i = 0; i < 4; ++i) {
        const vid_t v = mv.tet[t].v[i];
        if (v == inf || so[v] >= 0) return false;
      }
      return true;
    };
    res_.exact_evaluations += par::two_stage_signs(
        ctx_, nt, flp,
        [=] GDEL_HD(I64 t) -> std::int8_t {
          if (!t_candidate(t)) return 0;
          const vid_t* v = mv.tet[t].v;
          const int s = geom::orient3d_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]));
          return s == geom::kUncertain ? par::kUndecided : static_cast<std::int8_t>(s);
        },
        [=] GDEL_HD(I64 t, double* work) -> std::int8_t {
          const vid_t* v = mv.tet[t].v;
          return static_cast<std::int8_t>(geom::orient3d_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), work));
        },
        geom::kPredicateWork);
    // flp[t] > 0: kept. Star tets: per star, per triangle.
    const I64 nst = sp_.num_stars();
    const StarView sv = sp_.view();
    const I64 slots = sp_.slot_count();
    Buffer<std::int8_t, B> sflat(ctx_, static_cast<std::size_t>(std::max<I64>(slots, 1)));
    std::int8_t* sfp = sflat.data();
    Buffer<I64, B> slot_star(ctx_, static_cast<std::size_t>(std::max<I64>(slots, 1)));
    I64* ssp = slot_star.data();
    par::fill(ctx_, ssp, slot_star.size(), I64(-1));
    par::parallel_for(ctx_, nst, [=] GDEL_HD(I64 s) {
      for (std::int32_t i = 0; i < sv.count[s]; ++i) ssp[sv.begin[s] + i] = s;
    });
    auto s_candidate = [=] GDEL_HD(I64 q, vid_t* tet) -> bool {
      const I64 s = ssp[q];
      if (s < 0) return false;
      const Tri& tr = sv.tri[q];
      tet[0] = sv.vert[s];
      tet[1] = tr.v[0];
      tet[2] = tr.v[1];
      tet[3] = tr.v[2];
      for (int i = 1; i < 4; ++i) {
        if (tet[i] == inf) return false;
        if (so[tet[i]] >= 0 && tet[i] < tet[0]) return false;  // owned by a smaller star
      }
      return true;
    };
    res_.exact_evaluations += par::two_stage_signs(
        ctx_, slots, sfp,
        [=] GDEL_HD(I64 q) -> std::int8_t {
          vid_t v[4] = {0, 0, 0, 0};
          if (!s_candidate(q, v)) return 0;
          const int s = geom::orient3d_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]));
          return s == geom::kUncertain ? par::kUndecided : static_cast<std::int8_t>(s);
        },
        [=] GDEL_HD(I64 q, double* work) -> std::int8_t {
          vid_t v[4] = {0, 0, 0, 0};
          if (!s_candidate(q, v)) return 0;
          return static_cast<std::int8_t>(geom::orient3d_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), work));
        },
        geom::kPredicateWork);
    // negative star tets would mean an upper facet survived: inconsistent
    std::int32_t* ep = sp_.error_ptr();
    par::parallel_for(ctx_, slots, [=] GDEL_HD(I64 q) {
      if (sfp[q] < 0) ep[0] = 8;
    });
    sp_.throw_if_error("extracting tets");
    // numbering: T tets first, then star tets
    Buffer<I64, B> tnum(ctx_, static_cast<std::size_t>(nt + 1));
    I64* tnp = tnum.data();
    par::parallel_for(ctx_, nt, [=] GDEL_HD(I64 t) { tnp[t] = flp[t] > 0 ? 1 : 0; });
    const I64 nkeep = par::counts_to_offsets(ctx_, tnp, static_cast<std::size_t>(nt));
    Buffer<I64, B> snum(ctx_, static_cast<std::size_t>(slots + 1));
    I64* snp = snum.data();
    par::parallel_for(ctx_, slots, [=] GDEL_HD(I64 q) { snp[q] = sfp[q] > 0 ? 1 : 0; });
    const I64 nstar = par::counts_to_offsets(ctx_, snp, static_cast<std::size_t>(slots));
    const I64 nout = nkeep + nstar;
    // flat tets dropped (T tets without star vertices, and star tets)
    {
      Buffer<I64, B> z(ctx_, static_cast<std::size_t>(std::max<I64>(nt, slots) + 1));
      I64* zp = z.data();
      par::parallel_for(ctx_, nt, [=] GDEL_HD(I64 t) { zp[t] = (t_candidate(t) && flp[t] == 0) ? 1 : 0; });
      res_.flat_removed = par::reduce_sum(ctx_, zp, static_cast<std::size_t>(nt));
      par::parallel_for(ctx_, slots, [=] GDEL_HD(I64 q) {
        vid_t v[4];
        zp[q] = (s_candidate(q, v) && sfp[q] == 0) ? 1 : 0;
      });
      res_.flat_removed += par::reduce_sum(ctx_, zp, static_cast<std::size_t>(slots));
    }
    tets.resize(static_cast<std::size_t>(4 * nout));
    nbr.resize(static_cast<std::size_t>(4 * nout));
    vid_t* op = tets.data();
    std::int32_t* np = nbr.data();
    par::parallel_for(ctx_, nt, [=] GDEL_HD(I64 t) {
      if (tnp[t + 1] == tnp[t]) return;
      const I64 d = tnp[t];
      for (int i = 0; i < 4; ++i) {
        op[4 * d + i] = mv.tet[t].v[i];
        const fid_t o = mv.opp[4 * t + i];
        const tid_t u = facet_tet(o);
        // -2: to be matched by face key; -1: hull (∞ on the other side)
        const bool u_inf = o < 0 || tet_slot(mv, u, inf) >= 0;
        np[4 * d + i] = u_inf ? -1 : (tnp[u + 1] != tnp[u] ? static_cast<std::int32_t>(tnp[u]) : -2);
      }
    });
    par::parallel_for(ctx_, slots, [=] GDEL_HD(I64 q) {
      if (snp[q + 1] == snp[q]) return;
      const I64 d = nkeep + snp[q];
      const I64 s = ssp[q];
      op[4 * d + 0] = sv.vert[s];
      for (int i = 0; i < 3; ++i) op[4 * d + 1 + i] = sv.tri[q].v[i];
      for (int i = 0; i < 4; ++i) np[4 * d + i] = -2;
    });
    match_faces(tets, nbr, nout);
  }

  // Resolves neighbours marked -2 by sorting their faces' vertex keys; a face without
  // a partner is a hull face (-1).
  void match_faces(Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr, I64 nout) {
    std::int32_t* np = nbr.data();
    const vid_t* tp = tets.data();
    Buffer<I64, B> open(ctx_, static_cast<std::size_t>(std::max<I64>(4 * nout, 1)));
    const std::size_t k = par::select_indices(ctx_, static_cast<std::size_t>(4 * nout), open.data(),
                                              [=] GDEL_HD(I64 f) { return np[f] == -2; });
    if (k == 0) return;
    const I64* fp = open.data();
    auto face = [=] GDEL_HD(I64 f, vid_t* w) {
      const I64 t = f >> 2;
      const int i = static_cast<int>(f & 3);
      vid_t a = tp[4 * t + face_vertex(i, 0)], b = tp[4 * t + face_vertex(i, 1)], c = tp[4 * t + face_vertex(i, 2)];
      if (a > b) { vid_t x = a; a = b; b = x; }
      if (b > c) { vid_t x = b; b = c; c = x; }
      if (a > b) { vid_t x = a; a = b; b = x; }
      w[0] = a; w[1] = b; w[2] = c;
    };
    // two stable passes: by c, then by (a, b)
    Buffer<U64, B> key(ctx_, k);
    Buffer<I64, B> val(ctx_, k);
    U64* kp = key.data();
    I64* vp = val.data();
    par::parallel_for(ctx_, static_cast<I64>(k), [=] GDEL_HD(I64 j) {
      vid_t w[3];
      face(fp[j], w);
      kp[j] = static_cast<std::uint32_t>(w[2]);
      vp[j] = fp[j];
    });
    par::sort_pairs(ctx_, kp, vp, k);
    par::parallel_for(ctx_, static_cast<I64>(k), [=] GDEL_HD(I64 j) {
      vid_t w[3];
      face(vp[j], w);
      kp[j] = pair_key(w[0], w[1]);
    });
    par::sort_pairs(ctx_, kp, vp, k);
    const I64 kk = static_cast<I64>(k);
    par::parallel_for(ctx_, kk, [=] GDEL_HD(I64 j) {
      vid_t w[3], x[3];
      face(vp[j], w);
      bool paired = false;
      if (j + 1 < kk) {
        face(vp[j + 1], x);
        if (x[0] == w[0] && x[1] == w[1] && x[2] == w[2]) {
          np[vp[j]] = static_cast<std::int32_t>(vp[j + 1] >> 2);
          paired = true;
        }
      }
      if (j > 0) {
        face(vp[j - 1], x);
        if (x[0] == w[0] && x[1] == w[1] && x[2] == w[2]) {
          np[vp[j]] = static_cast<std::int32_t>(vp[j - 1] >> 2);
          paired = true;
        }
      }
      if (!paired) np[vp[j]] = -1;
    });
  }

 private:
  Context<B>& ctx_;
  mesh::TetMesh<B>& mesh_;
  flip::Geo g_;
  I64 m_;
  Splayer<B> sp_;
  RepairResult res_;
};

}  // namespace gdel::splay
