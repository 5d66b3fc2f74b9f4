// Exact verifier, written once over the backend tag (see include/gdel/verify.hpp).
// Every geometric decision is an exact predicate without symbolic perturbation,
// evaluated by the two-stage filter/exact split of the parallel layer.
#pragma once

#include <cstdint>
#include <cstring>

#include "gdel/verify.hpp"
#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"
#include "parallel/exact_batch.hpp"
#include "parallel/primitives.hpp"
#include "sort/point_sort.hpp"

namespace gdel::verify_detail {

using par::Buffer;
using par::Context;

struct Geometry {
  const double* xyz;
  const double* w;  // nullptr: Delaunay mode
  GDEL_HD const double* p(vid_t v) const { return xyz + 3 * static_cast<std::int64_t>(v); }
  GDEL_HD double wt(vid_t v) const { return w[v]; }
};

// Sorted vertex triple of facet (t, i) and the parity of that sort relative to the
// facet's stored orientation (face_vertex order).
struct FaceKey {
  vid_t a, b, c;
  int parity;
  GDEL_HD bool operator==(const FaceKey& o) const { return a == o.a && b == o.b && c == o.c; }
};
GDEL_HD inline FaceKey face_key(const vid_t* tet, std::int64_t f) {
  const vid_t* t = tet + 4 * (f >> 2);
  int i = static_cast<int>(f & 3);
  vid_t x = t[face_vertex(i, 0)], y = t[face_vertex(i, 1)], z = t[face_vertex(i, 2)];
  int par = 0;
  if (x > y) { vid_t s = x; x = y; y = s; par ^= 1; }
  if (y > z) { vid_t s = y; y = z; z = s; par ^= 1; }
  if (x > y) { vid_t s = x; x = y; y = s; par ^= 1; }
  return {x, y, z, par};
}

template <class B>
VerifyReport run(Context<B>& ctx, const double* host_xyz, std::int64_t n, const vid_t* host_tets, std::int64_t m,
                 const double* host_w) {
  using I64 = std::int64_t;
  VerifyReport r;
  r.points = n;
  r.tets = m;

  Buffer<double, B> xyz(ctx);
  xyz.assign(host_xyz, static_cast<std::size_t>(3 * n));
  Buffer<double, B> wts(ctx);
  if (host_w) wts.assign(host_w, static_cast<std::size_t>(n));
  Buffer<vid_t, B> tetb(ctx);
  tetb.assign(host_tets, static_cast<std::size_t>(4 * m));
  const vid_t* tet = tetb.data();
  Geometry g{xyz.data(), host_w ? wts.data() : nullptr};
  const bool regular = host_w != nullptr;

  Buffer<I64, B> flag(ctx, static_cast<std::size_t>(std::max<I64>(m, 1)));
  I64* fl = flag.data();

  // --- 1. vertex ids in range and distinct within each tet -----------------------
  par::parallel_for(ctx, m, [=] GDEL_HD(I64 t) {
    const vid_t* v = tet + 4 * t;
    bool bad = false;
    for (int i = 0; i < 4; ++i) {
      if (v[i] < 0 || v[i] >= n) bad = true;
      for (int j = 0; j < i; ++j) bad = bad || v[i] == v[j];
    }
    fl[t] = bad ? 1 : 0;
  });
  r.bad_index = par::reduce_sum(ctx, fl, static_cast<std::size_t>(m));
  if (r.bad_index) return r;  // geometry on bad ids would read out of bounds

  // --- 2. orientation of every tet -----------------------------------------------
  Buffer<std::int8_t, B> sgn(ctx, static_cast<std::size_t>(std::max<I64>(m, 1)));
  std::int8_t* sg = sgn.data();
  r.exact_evaluations += par::two_stage_signs(
      ctx, m, sg,
      [=] GDEL_HD(I64 t) -> std::int8_t {
        const vid_t* v = tet + 4 * t;
        return static_cast<std::int8_t>(geom::orient3d_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3])));
      },
      [=] GDEL_HD(I64 t, double* work) -> std::int8_t {
        const vid_t* v = tet + 4 * t;
        return static_cast<std::int8_t>(geom::orient3d_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), work));
      },
      geom::kPredicateWork);
  par::parallel_for(ctx, m, [=] GDEL_HD(I64 t) { fl[t] = sg[t] < 0 ? 1 : 0; });
  r.inverted_tets = par::reduce_sum(ctx, fl, static_cast<std::size_t>(m));
  par::parallel_for(ctx, m, [=] GDEL_HD(I64 t) { fl[t] = sg[t] == 0 ? 1 : 0; });
  r.degenerate_tets = par::reduce_sum(ctx, fl, static_cast<std::size_t>(m));

  // --- 3. facets: sort the 4m (t,i) by sorted vertex triple ----------------------
  const I64 nf = 4 * m;
  Buffer<I64, B> fid(ctx, static_cast<std::size_t>(nf));
  I64* fp = fid.data();
  {
    Buffer<std::uint64_t, B> key(ctx, static_cast<std::size_t>(nf));
    std::uint64_t* kp = key.data();
    par::sequence(ctx, fp, static_cast<std::size_t>(nf), I64(0));
    par::parallel_for(ctx, nf, [=] GDEL_HD(I64 f) { kp[f] = static_cast<std::uint32_t>(face_key(tet, f).c); });
    par::sort_pairs(ctx, kp, fp, static_cast<std::size_t>(nf), 32);
    par::parallel_for(ctx, nf, [=] GDEL_HD(I64 k) {
      FaceKey q = face_key(tet, fp[k]);
      kp[k] = (std::uint64_t(std::uint32_t(q.a)) << 32) | std::uint32_t(q.b);
    });
    par::sort_pairs(ctx, kp, fp, static_cast<std::size_t>(nf), 64);  // stable: ties keep c order
  }
  // Per sorted position: run starts classify the facet.
  // nb[f] = facet across f, -1 for hull, -2 for facets in an overshared run.
  Buffer<I64, B> nbb(ctx, static_cast<std::size_t>(nf));
  I64* nb = nbb.data();
  Buffer<std::int8_t, B> kind(ctx, static_cast<std::size_t>(nf));  // per sorted position
  std::int8_t* kd = kind.data();
  par::parallel_for(ctx, nf, [=] GDEL_HD(I64 k) {
    FaceKey q = face_key(tet, fp[k]);
    kd[k] = 0;
    if (k > 0 && face_key(tet, fp[k - 1]) == q) return;  // not a run start
    I64 len = 1;
    while (k + len < nf && face_key(tet, fp[k + len]) == q) ++len;
    if (len == 1) {
      nb[fp[k]] = -1;
      kd[k] = 1;  // hull
    } else if (len == 2) {
      I64 f1 = fp[k], f2 = fp[k + 1];
      nb[f1] = f2;
      nb[f2] = f1;
      kd[k] = (q.parity != face_key(tet, f2).parity) ? 2 : 3;  // 3: same side
    } else {
      for (I64 j = 0; j < len; ++j) nb[fp[k + j]] = -2;
      kd[k] = 4;  // overshared
    }
  });
  auto count_kind = [&](std::int8_t which) {
    Buffer<I64, B> c(ctx, static_cast<std::size_t>(nf));
    I64* cp = c.data();
    par::parallel_for(ctx, nf, [=] GDEL_HD(I64 k) { cp[k] = kd[k] == which ? 1 : 0; });
    return par::reduce_sum(ctx, cp, static_cast<std::size_t>(nf));
  };
  r.hull_facets = count_kind(1);
  I64 interior = count_kind(2);
  r.same_side_facets = count_kind(3);
  r.overshared_facets = count_kind(4);
  r.facets = r.hull_facets + interior + r.same_side_facets + r.overshared_facets;

  // --- 4. hull surface: closed, consistently oriented, locally convex ------------
  {
    Buffer<I64, B> hull(ctx, static_cast<std::size_t>(std::max<I64>(nf, 1)));
    I64* hp = hull.data();
    I64 h = static_cast<I64>(par::select_indices(ctx, static_cast<std::size_t>(nf), hp,
                                                 [=] GDEL_HD(I64 f) { return nb[f] == -1; }));
    // directed edges (u -> v) of hull facets; key = (min, max), value = 3*hullIdx + j
    const I64 ne = 3 * h;
    Buffer<std::uint64_t, B> ek(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));
    Buffer<I64, B> ev(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));
    std::uint64_t* ekp = ek.data();
    I64* evp = ev.data();
    auto hull_vertex = [=] GDEL_HD(I64 hidx, int j) -> vid_t {
      I64 f = hp[hidx];
      return tet[4 * (f >> 2) + face_vertex(static_cast<int>(f & 3), j)];
    };
    par::parallel_for(ctx, ne, [=] GDEL_HD(I64 e) {
      vid_t u = hull_vertex(e / 3, static_cast<int>(e % 3)), v = hull_vertex(e / 3, static_cast<int>((e + 1) % 3));
      vid_t lo = u < v ? u : v, hi = u < v ? v : u;
      ekp[e] = (std::uint64_t(std::uint32_t(lo)) << 32) | std::uint32_t(hi);
      evp[e] = e;
    });
    par::sort_pairs(ctx, ekp, evp, static_cast<std::size_t>(ne), 64);
    // Per run start: exactly 2 with opposite directions, else open; for good pairs
    // the apex of the second facet must not be beyond the first facet's plane.
    Buffer<I64, B> open(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));
    I64* op = open.data();
    Buffer<I64, B> pairs(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));  // e1 index or -1
    I64* pp = pairs.data();
    par::parallel_for(ctx, ne, [=] GDEL_HD(I64 k) {
      op[k] = 0;
      pp[k] = -1;
      if (k > 0 && ekp[k - 1] == ekp[k]) return;
      I64 len = 1;
      while (k + len < ne && ekp[k + len] == ekp[k]) ++len;
      if (len != 2) {
        op[k] = 1;
        return;
      }
      I64 e1 = evp[k], e2 = evp[k + 1];
      vid_t u1 = hull_vertex(e1 / 3, static_cast<int>(e1 % 3)), u2 = hull_vertex(e2 / 3, static_cast<int>(e2 % 3));
      if (u1 == u2) {
        op[k] = 1;  // same direction: inconsistent orientation
        return;
      }
      pp[k] = k;
    });
    r.hull_open_edges = par::reduce_sum(ctx, op, static_cast<std::size_t>(ne));
    // convexity: sign of orient3d(facet of e1, apex of facet of e2) must be >= 0
    Buffer<I64, B> plist(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));
    I64* pl = plist.data();
    I64 np = static_cast<I64>(
        par::copy_if(ctx, pp, pl, static_cast<std::size_t>(ne), [=] GDEL_HD(I64 x) { return x >= 0; }));
    Buffer<std::int8_t, B> cs(ctx, static_cast<std::size_t>(std::max<I64>(np, 1)));
    std::int8_t* csp = cs.data();
    auto hull_args = [=] GDEL_HD(I64 j, const double** a) {
      I64 k = pl[j];
      I64 e1 = evp[k], e2 = evp[k + 1];
      I64 h1 = e1 / 3, h2 = e2 / 3;
      int j2 = static_cast<int>(e2 % 3);
      vid_t apex = hull_vertex(h2, (j2 + 2) % 3);
      a[0] = g.p(hull_vertex(h1, 0));
      a[1] = g.p(hull_vertex(h1, 1));
      a[2] = g.p(hull_vertex(h1, 2));
      a[3] = g.p(apex);
    };
    r.exact_evaluations += par::two_stage_signs(
        ctx, np, csp,
        [=] GDEL_HD(I64 j) -> std::int8_t {
          const double* a[4];
          hull_args(j, a);
          return static_cast<std::int8_t>(geom::orient3d_filter(a[0], a[1], a[2], a[3]));
        },
        [=] GDEL_HD(I64 j, double* work) -> std::int8_t {
          const double* a[4];
          hull_args(j, a);
          return static_cast<std::int8_t>(geom::orient3d_exact(a[0], a[1], a[2], a[3], work));
        },
        geom::kPredicateWork);
    Buffer<I64, B> rf(ctx, static_cast<std::size_t>(std::max<I64>(np, 1)));
    I64* rfp = rf.data();
    par::parallel_for(ctx, np, [=] GDEL_HD(I64 j) { rfp[j] = csp[j] < 0 ? 1 : 0; });
    r.hull_reflex_edges = par::reduce_sum(ctx, rfp, static_cast<std::size_t>(np));
  }

  // --- 5. Euler characteristic -----------------------------------------------------
  Buffer<I64, B> used(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
  I64* up = used.data();
  par::fill(ctx, up, static_cast<std::size_t>(n), I64(0));
  par::parallel_for(ctx, 4 * m, [=] GDEL_HD(I64 k) { up[tet[k]] = 1; });  // benign identical writes
  r.vertices_used = par::reduce_sum(ctx, up, static_cast<std::size_t>(n));
  {
    const I64 ne = 6 * m;
    Buffer<std::uint64_t, B> ek(ctx, static_cast<std::size_t>(std::max<I64>(ne, 1)));
    std::uint64_t* ekp = ek.data();
    par::parallel_for(ctx, ne, [=] GDEL_HD(I64 k) {
      const vid_t* t = tet + 4 * (k / 6);
      int e = static_cast<int>(k % 6);
      vid_t u = t[edge_vertex(e, 0)], v = t[edge_vertex(e, 1)];
      vid_t lo = u < v ? u : v, hi = u < v ? v : u;
      ekp[k] = (std::uint64_t(std::uint32_t(lo)) << 32) | std::uint32_t(hi);
    });
    par::sort_keys(ctx, ekp, static_cast<std::size_t>(ne), 64);
    r.edges = static_cast<I64>(par::unique(ctx, ekp, static_cast<std::size_t>(ne)));
  }
  r.euler = r.vertices_used - r.edges + r.facets - r.tets;
  r.euler_ok = (m == 0) ? false : (r.euler == 1);

  // --- 6. every distinct point used once (duplicates merged) -----------------------
  {
    Buffer<I64, B> ord(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    I64* o = ord.data();
    const double* X = g.xyz;
    sort::lexicographic_order(ctx, X, n, o);
    auto same = [=] GDEL_HD(I64 a, I64 b) { return sort::same_point(X, a, b); };
    // per group start: number of used members; unused groups go to a list
    Buffer<I64, B> cnt(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    I64* cp = cnt.data();
    Buffer<I64, B> dup(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    I64* dp = dup.data();
    Buffer<I64, B> starts(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    I64* sp = starts.data();
    par::parallel_for(ctx, n, [=] GDEL_HD(I64 k) {
      cp[k] = 0;
      dp[k] = 0;
      sp[k] = 0;
      if (k > 0 && same(o[k - 1], o[k])) return;
      sp[k] = 1;
      I64 u = 0;
      for (I64 j = k; j < n && same(o[j], o[k]); ++j) u += up[o[j]];
      cp[k] = (u == 0) ? 1 : 0;
      dp[k] = (u > 1) ? 1 : 0;
    });
    r.distinct_points = par::reduce_sum(ctx, sp, static_cast<std::size_t>(n));
    I64 unused = par::reduce_sum(ctx, cp, static_cast<std::size_t>(n));
    r.duplicate_vertices = par::reduce_sum(ctx, dp, static_cast<std::size_t>(n));
    if (!regular || unused == 0) {
      r.unused_points = unused;
    } else {
      // Regular mode: an unused point must be redundant: locate it by a visibility
      // walk (exact orient3d; terminates on regular triangulations, capped
      // otherwise) and check it is not in conflict with its tet (power test <= 0).
      Buffer<I64, B> ul(ctx, static_cast<std::size_t>(unused));
      I64* ulp = ul.data();
      Buffer<I64, B> pos(ctx, static_cast<std::size_t>(unused));
      I64* pp = pos.data();
      par::select_indices(ctx, static_cast<std::size_t>(n), pp, [=] GDEL_HD(I64 k) { return cp[k] == 1; });
      par::parallel_for(ctx, unused, [=] GDEL_HD(I64 j) { ulp[j] = o[pp[j]]; });
      Buffer<std::int8_t, B> res(ctx, static_cast<std::size_t>(unused));
      std::int8_t* rs = res.data();
      const I64 max_steps = 4 * m + 16;
      par::for_each_with_scratch(ctx, unused, geom::kPredicateWork, [=] GDEL_HD(I64 j, double* work) {
        const vid_t q = static_cast<vid_t>(ulp[j]);
        const double* pq = g.p(q);
        I64 t = (static_cast<I64>(q) * 2654435761LL) % m;  // arbitrary start
        for (I64 step = 0; step < max_steps; ++step) {
          const vid_t* v = tet + 4 * t;
          int exit_face = -1;
          for (int i = 0; i < 4 && exit_face < 0; ++i) {
            const double* a = g.p(v[face_vertex(i, 0)]);
            const double* b = g.p(v[face_vertex(i, 1)]);
            const double* c = g.p(v[face_vertex(i, 2)]);
            int s = geom::orient3d_filter(a, b, c, pq);
            if (s == geom::kUncertain) s = geom::orient3d_exact(a, b, c, pq, work);
            if (s < 0) exit_face = i;
          }
          if (exit_face < 0) {  // q in tet t (closed)
            int s = geom::power_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), pq, g.wt(v[0]), g.wt(v[1]),
                                       g.wt(v[2]), g.wt(v[3]), g.wt(q));
            if (s == geom::kUncertain)
              s = geom::power_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), pq, g.wt(v[0]), g.wt(v[1]),
                                    g.wt(v[2]), g.wt(v[3]), g.wt(q), work);
            rs[j] = s > 0 ? 1 : 0;  // 1: in conflict, so not redundant
            return;
          }
          I64 next = nb[4 * t + exit_face];
          if (next < 0) {
            rs[j] = 1;  // outside the hull: cannot be redundant
            return;
          }
          t = next >> 2;
        }
        rs[j] = 2;  // walk did not terminate
      });
      Buffer<I64, B> c1(ctx, static_cast<std::size_t>(unused));
      I64* c1p = c1.data();
      par::parallel_for(ctx, unused, [=] GDEL_HD(I64 j) { c1p[j] = rs[j] == 1 ? 1 : 0; });
      r.unused_points = par::reduce_sum(ctx, c1p, static_cast<std::size_t>(unused));
      par::parallel_for(ctx, unused, [=] GDEL_HD(I64 j) { c1p[j] = rs[j] == 2 ? 1 : 0; });
      r.locate_failures = par::reduce_sum(ctx, c1p, static_cast<std::size_t>(unused));
      r.redundant_points = unused - r.unused_points - r.locate_failures;
    }
  }

  // --- 7. local Delaunay / regular property of interior facets --------------------
  {
    Buffer<I64, B> il(ctx, static_cast<std::size_t>(std::max<I64>(nf, 1)));
    I64* ilp = il.data();
    I64 ni = static_cast<I64>(par::select_indices(ctx, static_cast<std::size_t>(nf), ilp,
                                                  [=] GDEL_HD(I64 f) { return nb[f] >= 0 && f < nb[f]; }));
    Buffer<std::int8_t, B> s(ctx, static_cast<std::size_t>(std::max<I64>(ni, 1)));
    std::int8_t* sp = s.data();
    auto args = [=] GDEL_HD(I64 j, vid_t* v) {
      I64 f = ilp[j], o2 = nb[f];
      const vid_t* t = tet + 4 * (f >> 2);
      for (int k = 0; k < 4; ++k) v[k] = t[k];
      v[4] = tet[4 * (o2 >> 2) + (o2 & 3)];
    };
    r.exact_evaluations += par::two_stage_signs(
        ctx, ni, sp,
        [=] GDEL_HD(I64 j) -> std::int8_t {
          vid_t v[5];
          args(j, v);
          if (g.w)
            return static_cast<std::int8_t>(geom::power_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4]),
                                                               g.wt(v[0]), g.wt(v[1]), g.wt(v[2]), g.wt(v[3]),
                                                               g.wt(v[4])));
          return static_cast<std::int8_t>(
              geom::insphere_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4])));
        },
        [=] GDEL_HD(I64 j, double* work) -> std::int8_t {
          vid_t v[5];
          args(j, v);
          if (g.w)
            return static_cast<std::int8_t>(geom::power_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4]),
                                                              g.wt(v[0]), g.wt(v[1]), g.wt(v[2]), g.wt(v[3]),
                                                              g.wt(v[4]), work));
          return static_cast<std::int8_t>(
              geom::insphere_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4]), work));
        },
        geom::kPredicateWork);
    Buffer<I64, B> c(ctx, static_cast<std::size_t>(std::max<I64>(ni, 1)));
    I64* cp = c.data();
    par::parallel_for(ctx, ni, [=] GDEL_HD(I64 j) { cp[j] = sp[j] > 0 ? 1 : 0; });
    r.non_delaunay_facets = par::reduce_sum(ctx, cp, static_cast<std::size_t>(ni));
    par::parallel_for(ctx, ni, [=] GDEL_HD(I64 j) { cp[j] = sp[j] == 0 ? 1 : 0; });
    r.cospherical_facets = par::reduce_sum(ctx, cp, static_cast<std::size_t>(ni));
  }
  ctx.synchronize();
  return r;
}

}  // namespace gdel::verify_detail
