// Exact verifier, written once over the backend tag (see include/gdel/verify.hpp).
// Every geometric decision is an exact predicate without symbolic perturbation,
// evaluated by the two-stage filter/exact split of the parallel layer.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "gdel/verify.hpp"
#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"
#include "parallel/atomic.hpp"
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

// Bit width of values in [0, v] (v >= 0).
GDEL_HD inline int bit_width_of(std::int64_t v) {
  int b = 1;
  while (b < 63 && (v >> b) != 0) ++b;
  return b;
}

// --- chunking --------------------------------------------------------------------
// The facet, hull-edge and edge steps sort up to 6m keys. They run in chunks: the
// items whose bucket vertex (their smallest vertex id) lies in one vertex-id range.
// Items that must meet (copies of one facet, of one edge) share their smallest
// vertex, so every chunk is self-contained and the counts add up. Ranges are cut
// from a histogram of the buckets so that a chunk holds about `cap` items (more
// only where one vertex alone has more): the sorts' memory is bounded by the cap,
// not by the mesh.
struct Chunk {
  vid_t lo, hi;          // bucket vertices [lo, hi)
  std::int64_t items;    // items in the chunk
  // bits of chunk_pair_key's keys in this chunk
  int key_bits(int vbits) const { return vbits + bit_width_of(hi - lo); }
};
// Sort key of the vertex pair (a, b), a in the chunk starting at vertex lo, b below
// 2^vbits: (a - lo) above b, so that a chunk's sort needs only Chunk::key_bits bits.
GDEL_HD inline std::uint64_t chunk_pair_key(vid_t a, vid_t b, vid_t lo, int vbits) {
  return (std::uint64_t(std::uint32_t(a - lo)) << vbits) | std::uint32_t(b);
}

template <class B, class BucketOf>
std::vector<Chunk> plan_chunks(Context<B>& ctx, std::int64_t n, std::int64_t items, std::int64_t cap,
                               BucketOf bucket_of) {
  using I64 = std::int64_t;
  std::vector<Chunk> out;
  if (items <= 0) return out;
  if (items <= cap) {
    out.push_back({0, static_cast<vid_t>(n), items});
    return out;
  }
  Buffer<I64, B> off(ctx, static_cast<std::size_t>(n + 1));
  I64* o = off.data();
  par::fill(ctx, o, static_cast<std::size_t>(n + 1), I64(0));
  par::parallel_for(ctx, items, [=] GDEL_LAMBDA(I64 i) { par::atomic_add(o + bucket_of(i), I64(1)); });
  par::counts_to_offsets(ctx, o, static_cast<std::size_t>(n));  // o[v] = items with bucket < v
  const I64 k = (items + cap - 1) / cap;
  Buffer<I64, B> cut(ctx, static_cast<std::size_t>(2 * (k + 1)));
  I64* c = cut.data();
  par::parallel_for(ctx, k + 1, [=] GDEL_LAMBDA(I64 j) {
    I64 lo = 0, hi = n;  // smallest v with o[v] >= j * cap (n for the last cut)
    if (j == k) lo = n;
    while (lo < hi) {
      const I64 mid = lo + (hi - lo) / 2;
      if (o[mid] >= j * cap) hi = mid;
      else lo = mid + 1;
    }
    c[j] = lo;
    c[k + 1 + j] = o[lo];
  });
  const std::vector<I64> h = cut.to_host();
  for (I64 j = 0; j < k; ++j) {
    const I64 cnt = h[k + 2 + j] - h[k + 1 + j];
    if (cnt > 0) out.push_back({static_cast<vid_t>(h[j]), static_cast<vid_t>(h[j + 1]), cnt});
  }
  return out;
}

// chunk_items: about the most items one chunked step sorts at a time; 0: no chunks.
template <class B>
VerifyReport run(Context<B>& ctx, const double* host_xyz, std::int64_t n, const vid_t* host_tets, std::int64_t m,
                 const double* host_w, std::int64_t chunk_items = 0) {
  using I64 = std::int64_t;
  using U64 = std::uint64_t;
  VerifyReport r;
  r.points = n;
  r.tets = m;
  const I64 cap = chunk_items > 0 ? chunk_items : I64(1) << 40;

  Buffer<double, B> xyz(ctx);
  xyz.assign(host_xyz, static_cast<std::size_t>(3 * n));
  Buffer<double, B> wts(ctx);
  if (host_w) wts.assign(host_w, static_cast<std::size_t>(n));
  Buffer<vid_t, B> tetb(ctx);
  tetb.assign(host_tets, static_cast<std::size_t>(4 * m));
  const vid_t* tet = tetb.data();
  Geometry g{xyz.data(), host_w ? wts.data() : nullptr};
  const bool regular = host_w != nullptr;
  const int vbits = bit_width_of(n);  // vertex ids < n fit in vbits bits

  // --- 1. vertex ids in range and distinct within each tet -----------------------
  r.bad_index = par::count_indices(ctx, static_cast<std::size_t>(m), [=] GDEL_LAMBDA(I64 t) {
    const vid_t* v = tet + 4 * t;
    bool bad = false;
    for (int i = 0; i < 4; ++i) {
      if (v[i] < 0 || v[i] >= n) bad = true;
      for (int j = 0; j < i; ++j) bad = bad || v[i] == v[j];
    }
    return bad;
  });
  if (r.bad_index) return r;  // geometry on bad ids would read out of bounds

  // --- 2. orientation of every tet -----------------------------------------------
  {
    Buffer<std::int8_t, B> sgn(ctx, static_cast<std::size_t>(std::max<I64>(m, 1)));
    std::int8_t* sg = sgn.data();
    r.exact_evaluations += par::two_stage_signs(
        ctx, m, sg,
        [=] GDEL_LAMBDA(I64 t) -> std::int8_t {
          const vid_t* v = tet + 4 * t;
          return static_cast<std::int8_t>(geom::orient3d_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3])));
        },
        [=] GDEL_LAMBDA(I64 t, double* work) -> std::int8_t {
          const vid_t* v = tet + 4 * t;
          return static_cast<std::int8_t>(geom::orient3d_exact(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), work));
        },
        geom::kPredicateWork);
    r.inverted_tets = par::count_indices(ctx, static_cast<std::size_t>(m), [=] GDEL_LAMBDA(I64 t) { return sg[t] < 0; });
    r.degenerate_tets = par::count_indices(ctx, static_cast<std::size_t>(m), [=] GDEL_LAMBDA(I64 t) { return sg[t] == 0; });
  }

  // --- 3. facets, chunk by chunk: sort the (t,i) of a chunk by sorted vertex triple;
  // each run of equal triples is a hull facet (1), an interior facet (2: the two
  // tets on opposite sides, else "same side") or an overshared one (> 2). Interior
  // pairs get the local Delaunay / regular test (step 7) in the same pass; hull
  // facets are kept for step 4; in regular mode nb[f] (the facet across f, -1 hull,
  // -2 overshared) is kept for the redundancy walk of step 6.
  const I64 nf = 4 * m;
  Buffer<I64, B> nbb(ctx, static_cast<std::size_t>(regular ? std::max<I64>(nf, 1) : 0));
  I64* nb = nbb.data();
  std::vector<Buffer<I64, B>> hull_parts;
  auto local_test = [&](I64 ni, const I64* fp, const I64* pos) {
    // sign of the apex of the second facet of each pair against the first's tet
    Buffer<std::int8_t, B> s(ctx, static_cast<std::size_t>(std::max<I64>(ni, 1)));
    std::int8_t* sp = s.data();
    auto args = [=] GDEL_LAMBDA(I64 j, vid_t* v) {
      const I64 f = fp[pos[j]], o2 = fp[pos[j] + 1];
      const vid_t* t = tet + 4 * (f >> 2);
      for (int k = 0; k < 4; ++k) v[k] = t[k];
      v[4] = tet[4 * (o2 >> 2) + (o2 & 3)];
    };
    r.exact_evaluations += par::two_stage_signs(
        ctx, ni, sp,
        [=] GDEL_LAMBDA(I64 j) -> std::int8_t {
          vid_t v[5];
          args(j, v);
          if (g.w)
            return static_cast<std::int8_t>(geom::power_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4]),
                                                               g.wt(v[0]), g.wt(v[1]), g.wt(v[2]), g.wt(v[3]),
                                                               g.wt(v[4])));
          return static_cast<std::int8_t>(
              geom::insphere_filter(g.p(v[0]), g.p(v[1]), g.p(v[2]), g.p(v[3]), g.p(v[4])));
        },
        [=] GDEL_LAMBDA(I64 j, double* work) -> std::int8_t {
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
    r.non_delaunay_facets += par::count_indices(ctx, static_cast<std::size_t>(ni), [=] GDEL_LAMBDA(I64 j) { return sp[j] > 0; });
    r.cospherical_facets += par::count_indices(ctx, static_cast<std::size_t>(ni), [=] GDEL_LAMBDA(I64 j) { return sp[j] == 0; });
  };
  const std::vector<Chunk> facet_chunks =
      plan_chunks(ctx, n, nf, cap, [=] GDEL_LAMBDA(I64 f) -> I64 { return face_key(tet, f).a; });
  for (const Chunk ch : facet_chunks) {
    const I64 F = ch.items;
    const vid_t lo = ch.lo, hi = ch.hi;
    Buffer<I64, B> fid(ctx, static_cast<std::size_t>(F));
    I64* fp = fid.data();
    par::select_indices(ctx, static_cast<std::size_t>(nf), fp, [=] GDEL_LAMBDA(I64 f) {
      const vid_t a = face_key(tet, f).a;
      return a >= lo && a < hi;
    });
    {
      Buffer<U64, B> key(ctx, static_cast<std::size_t>(F));
      U64* kp = key.data();
      par::parallel_for(ctx, F, [=] GDEL_LAMBDA(I64 k) { kp[k] = static_cast<std::uint32_t>(face_key(tet, fp[k]).c); });
      par::sort_pairs(ctx, kp, fp, static_cast<std::size_t>(F), vbits);
      par::parallel_for(ctx, F, [=] GDEL_LAMBDA(I64 k) {
        const FaceKey q = face_key(tet, fp[k]);
        kp[k] = chunk_pair_key(q.a, q.b, lo, vbits);
      });
      par::sort_pairs(ctx, kp, fp, static_cast<std::size_t>(F), ch.key_bits(vbits));  // stable: ties keep c order
    }
    // per sorted position, at run starts: 1 hull, 2 interior, 3 same side, 4 overshared
    Buffer<std::int8_t, B> kind(ctx, static_cast<std::size_t>(F));
    std::int8_t* kd = kind.data();
    par::parallel_for(ctx, F, [=] GDEL_LAMBDA(I64 k) {
      const FaceKey q = face_key(tet, fp[k]);
      kd[k] = 0;
      if (k > 0 && face_key(tet, fp[k - 1]) == q) return;  // not a run start
      I64 len = 1;
      while (k + len < F && face_key(tet, fp[k + len]) == q) ++len;
      if (len == 1) {
        kd[k] = 1;
        if (nb) nb[fp[k]] = -1;
      } else if (len == 2) {
        const I64 f1 = fp[k], f2 = fp[k + 1];
        kd[k] = (q.parity != face_key(tet, f2).parity) ? 2 : 3;
        if (nb) {
          nb[f1] = f2;
          nb[f2] = f1;
        }
      } else {
        kd[k] = 4;
        if (nb)
          for (I64 j = 0; j < len; ++j) nb[fp[k + j]] = -2;
      }
    });
    auto count_kind = [&](std::int8_t which) {
      return par::count_indices(ctx, static_cast<std::size_t>(F), [=] GDEL_LAMBDA(I64 k) { return kd[k] == which; });
    };
    const I64 h = count_kind(1), interior = count_kind(2), same = count_kind(3), over = count_kind(4);
    r.hull_facets += h;
    r.same_side_facets += same;
    r.overshared_facets += over;
    r.facets += h + interior + same + over;
    if (h) {
      Buffer<I64, B> part(ctx, static_cast<std::size_t>(h));
      I64* pp = part.data();
      Buffer<I64, B> pos(ctx, static_cast<std::size_t>(h));
      I64* ps = pos.data();
      par::select_indices(ctx, static_cast<std::size_t>(F), ps, [=] GDEL_LAMBDA(I64 k) { return kd[k] == 1; });
      par::parallel_for(ctx, h, [=] GDEL_LAMBDA(I64 j) { pp[j] = fp[ps[j]]; });
      hull_parts.push_back(std::move(part));
    }
    // --- 7. local Delaunay / regular property of the chunk's two-tet facets ------
    if (interior + same) {
      Buffer<I64, B> pos(ctx, static_cast<std::size_t>(interior + same));
      I64* ps = pos.data();
      par::select_indices(ctx, static_cast<std::size_t>(F), ps,
                          [=] GDEL_LAMBDA(I64 k) { return kd[k] == 2 || kd[k] == 3; });
      local_test(interior + same, fp, ps);
    }
  }

  // --- 4. hull surface: closed, consistently oriented, locally convex ------------
  // Directed edges (u -> v) of the hull facets, chunked by their smaller vertex.
  {
    I64 h = 0;
    for (const auto& part : hull_parts) h += static_cast<I64>(part.size());
    Buffer<I64, B> hull(ctx, static_cast<std::size_t>(std::max<I64>(h, 1)));
    I64* hp = hull.data();
    {
      I64 at = 0;
      for (auto& part : hull_parts) {
        par::detail::Memory<B>::copy(ctx, hp + at, part.data(), part.size() * sizeof(I64));
        at += static_cast<I64>(part.size());
        part.release();
      }
      hull_parts.clear();
    }
    auto hull_vertex = [=] GDEL_LAMBDA(I64 hidx, int j) -> vid_t {
      const I64 f = hp[hidx];
      return tet[4 * (f >> 2) + face_vertex(static_cast<int>(f & 3), j)];
    };
    auto edge_lo = [=] GDEL_LAMBDA(I64 e) -> vid_t {
      const vid_t u = hull_vertex(e / 3, static_cast<int>(e % 3)), v = hull_vertex(e / 3, static_cast<int>((e + 1) % 3));
      return u < v ? u : v;
    };
    const I64 ne = 3 * h;
    for (const Chunk ch : plan_chunks(ctx, n, ne, cap, [=] GDEL_LAMBDA(I64 e) -> I64 { return edge_lo(e); })) {
      const I64 E = ch.items;
      const vid_t lo = ch.lo, hi = ch.hi;
      Buffer<I64, B> ev(ctx, static_cast<std::size_t>(E));
      I64* evp = ev.data();
      par::select_indices(ctx, static_cast<std::size_t>(ne), evp, [=] GDEL_LAMBDA(I64 e) {
        const vid_t a = edge_lo(e);
        return a >= lo && a < hi;
      });
      Buffer<U64, B> ek(ctx, static_cast<std::size_t>(E));
      U64* ekp = ek.data();
      par::parallel_for(ctx, E, [=] GDEL_LAMBDA(I64 k) {
        const I64 e = evp[k];
        const vid_t u = hull_vertex(e / 3, static_cast<int>(e % 3)), v = hull_vertex(e / 3, static_cast<int>((e + 1) % 3));
        const vid_t a = u < v ? u : v, b = u < v ? v : u;
        ekp[k] = chunk_pair_key(a, b, lo, vbits);
      });
      par::sort_pairs(ctx, ekp, evp, static_cast<std::size_t>(E), ch.key_bits(vbits));
      // Per run start: exactly 2 with opposite directions (2), else open (1).
      Buffer<std::int8_t, B> kind(ctx, static_cast<std::size_t>(E));
      std::int8_t* kd = kind.data();
      par::parallel_for(ctx, E, [=] GDEL_LAMBDA(I64 k) {
        kd[k] = 0;
        if (k > 0 && ekp[k - 1] == ekp[k]) return;
        I64 len = 1;
        while (k + len < E && ekp[k + len] == ekp[k]) ++len;
        if (len != 2) {
          kd[k] = 1;
          return;
        }
        const I64 e1 = evp[k], e2 = evp[k + 1];
        const vid_t u1 = hull_vertex(e1 / 3, static_cast<int>(e1 % 3)), u2 = hull_vertex(e2 / 3, static_cast<int>(e2 % 3));
        kd[k] = u1 == u2 ? 1 : 2;  // same direction: inconsistent orientation
      });
      r.hull_open_edges += par::count_indices(ctx, static_cast<std::size_t>(E), [=] GDEL_LAMBDA(I64 k) { return kd[k] == 1; });
      // convexity: orient3d(facet of e1, apex of facet of e2) must be >= 0
      const I64 np = par::count_indices(ctx, static_cast<std::size_t>(E), [=] GDEL_LAMBDA(I64 k) { return kd[k] == 2; });
      if (!np) continue;
      Buffer<I64, B> plist(ctx, static_cast<std::size_t>(np));
      I64* pl = plist.data();
      par::select_indices(ctx, static_cast<std::size_t>(E), pl, [=] GDEL_LAMBDA(I64 k) { return kd[k] == 2; });
      Buffer<std::int8_t, B> cs(ctx, static_cast<std::size_t>(np));
      std::int8_t* csp = cs.data();
      auto hull_args = [=] GDEL_LAMBDA(I64 j, const double** a) {
        const I64 k = pl[j];
        const I64 e1 = evp[k], e2 = evp[k + 1];
        const I64 h1 = e1 / 3, h2 = e2 / 3;
        const int j2 = static_cast<int>(e2 % 3);
        const vid_t apex = hull_vertex(h2, (j2 + 2) % 3);
        a[0] = g.p(hull_vertex(h1, 0));
        a[1] = g.p(hull_vertex(h1, 1));
        a[2] = g.p(hull_vertex(h1, 2));
        a[3] = g.p(apex);
      };
      r.exact_evaluations += par::two_stage_signs(
          ctx, np, csp,
          [=] GDEL_LAMBDA(I64 j) -> std::int8_t {
            const double* a[4];
            hull_args(j, a);
            return static_cast<std::int8_t>(geom::orient3d_filter(a[0], a[1], a[2], a[3]));
          },
          [=] GDEL_LAMBDA(I64 j, double* work) -> std::int8_t {
            const double* a[4];
            hull_args(j, a);
            return static_cast<std::int8_t>(geom::orient3d_exact(a[0], a[1], a[2], a[3], work));
          },
          geom::kPredicateWork);
      r.hull_reflex_edges += par::count_indices(ctx, static_cast<std::size_t>(np), [=] GDEL_LAMBDA(I64 j) { return csp[j] < 0; });
    }
  }

  // --- 5. Euler characteristic: distinct edges, chunked by their smaller vertex ----
  Buffer<std::int8_t, B> used(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
  std::int8_t* up = used.data();
  used.memset(0);
  par::parallel_for(ctx, 4 * m, [=] GDEL_LAMBDA(I64 k) { up[tet[k]] = 1; });  // benign identical writes
  r.vertices_used = par::count_indices(ctx, static_cast<std::size_t>(n), [=] GDEL_LAMBDA(I64 v) { return up[v] != 0; });
  {
    auto edge_of = [=] GDEL_LAMBDA(I64 k, vid_t& a, vid_t& b) {
      const vid_t* t = tet + 4 * (k / 6);
      const int e = static_cast<int>(k % 6);
      const vid_t u = t[edge_vertex(e, 0)], v = t[edge_vertex(e, 1)];
      a = u < v ? u : v;
      b = u < v ? v : u;
    };
    const I64 ne = 6 * m;
    for (const Chunk ch : plan_chunks(ctx, n, ne, cap, [=] GDEL_LAMBDA(I64 k) -> I64 {
           vid_t a, b;
           edge_of(k, a, b);
           return a;
         })) {
      const I64 E = ch.items;
      const vid_t lo = ch.lo, hi = ch.hi;
      Buffer<U64, B> ek(ctx, static_cast<std::size_t>(E));
      U64* ekp = ek.data();
      {
        Buffer<I64, B> ids(ctx, static_cast<std::size_t>(E));
        I64* ip = ids.data();
        par::select_indices(ctx, static_cast<std::size_t>(ne), ip, [=] GDEL_LAMBDA(I64 k) {
          vid_t a, b;
          edge_of(k, a, b);
          return a >= lo && a < hi;
        });
        par::parallel_for(ctx, E, [=] GDEL_LAMBDA(I64 j) {
          vid_t a, b;
          edge_of(ip[j], a, b);
          ekp[j] = chunk_pair_key(a, b, lo, vbits);
        });
      }
      par::sort_keys(ctx, ekp, static_cast<std::size_t>(E), ch.key_bits(vbits));
      r.edges += par::count_indices(ctx, static_cast<std::size_t>(E),
                                    [=] GDEL_LAMBDA(I64 k) { return k == 0 || ekp[k] != ekp[k - 1]; });
    }
  }
  r.euler = r.vertices_used - r.edges + r.facets - r.tets;
  r.euler_ok = (m == 0) ? false : (r.euler == 1);

  // --- 6. every distinct point used once (duplicates merged) -----------------------
  {
    Buffer<I64, B> ord(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    I64* o = ord.data();
    const double* X = g.xyz;
    sort::lexicographic_order(ctx, X, n, o);
    auto same = [=] GDEL_LAMBDA(I64 a, I64 b) { return sort::same_point(X, a, b); };
    // per sorted position, at group starts: bit 0 start, bit 1 no member used,
    // bit 2 more than one member used
    Buffer<std::int8_t, B> code(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    std::int8_t* cd = code.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 k) {
      cd[k] = 0;
      if (k > 0 && same(o[k - 1], o[k])) return;
      I64 u = 0;
      for (I64 j = k; j < n && same(o[j], o[k]); ++j) u += up[o[j]];
      cd[k] = static_cast<std::int8_t>(1 | (u == 0 ? 2 : 0) | (u > 1 ? 4 : 0));
    });
    auto count_bit = [&](int bit) {
      return par::count_indices(ctx, static_cast<std::size_t>(n), [=] GDEL_LAMBDA(I64 k) { return (cd[k] & bit) != 0; });
    };
    r.distinct_points = count_bit(1);
    const I64 unused = count_bit(2);
    r.duplicate_vertices = count_bit(4);
    if (!regular || unused == 0 || m == 0) {
      r.unused_points = unused;
    } else {
      // Regular mode: an unused point must be redundant: locate it by a visibility
      // walk (exact orient3d; terminates on regular triangulations, capped
      // otherwise) and check it is not in conflict with its tet (power test <= 0).
      Buffer<I64, B> ul(ctx, static_cast<std::size_t>(unused));
      I64* ulp = ul.data();
      Buffer<I64, B> pos(ctx, static_cast<std::size_t>(unused));
      I64* pp = pos.data();
      par::select_indices(ctx, static_cast<std::size_t>(n), pp, [=] GDEL_LAMBDA(I64 k) { return (cd[k] & 2) != 0; });
      par::parallel_for(ctx, unused, [=] GDEL_LAMBDA(I64 j) { ulp[j] = o[pp[j]]; });
      Buffer<std::int8_t, B> res(ctx, static_cast<std::size_t>(unused));
      std::int8_t* rs = res.data();
      const I64 max_steps = 4 * m + 16;
      par::for_each_with_scratch(ctx, unused, geom::kPredicateWork, [=] GDEL_LAMBDA(I64 j, double* work) {
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
      r.unused_points = par::count_indices(ctx, static_cast<std::size_t>(unused), [=] GDEL_LAMBDA(I64 j) { return rs[j] == 1; });
      r.locate_failures = par::count_indices(ctx, static_cast<std::size_t>(unused), [=] GDEL_LAMBDA(I64 j) { return rs[j] == 2; });
      r.redundant_points = unused - r.unused_points - r.locate_failures;
    }
  }

  ctx.synchronize();
  return r;
}

}  // namespace gdel::verify_detail
