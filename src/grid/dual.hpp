// The dual of a digital Voronoi colouring under the grid perturbation (kuhn.hpp), and the
// measurable form of the thesis' negative results (ALGORITHMS.md §7, docs/grid.md).
// Written once over the backend tag B.
//
// ---------------------------------------------------------------------------------
// Interface
//
//   Dual<B> d = dual_of_colouring(ctx, site, W, X)
//     site  W³ int32 on the backend: the colouring (site id per voxel, x fastest:
//           index (z·W + y)·W + x), e.g. DigitalVoronoi::site (star4d/pba.hpp)
//     X     the sites' coordinates on the backend (3 doubles per id used in `site`)
//   d.stats   the counts below;  d.hi, d.lo   the distinct site tets, each as its 4 ids
//             sorted ascending (a<<32|b, c<<32|d), in lexicographic order
//   d.flags   per distinct site tet (same order), the DualTetFlag bits of its
//             classification: the counts below, tet by tet (facet kinds on each tet
//             holding the facet)
//   d.compare(ref, m)  how many of the m tets `ref` (4 ids each, backend memory, any
//             vertex order) are dual tets, and how many no grid tet dualizes
//
// Every 2×2×2 cube of voxels (all inside the grid) contributes its 4-coloured Kuhn tets.
// The counts (every decision an exact predicate without symbolic perturbation: a tie
// is reported as a tie, since the question is what the raw dual is):
//   grid_tets      4-coloured grid tets (occurrences; a site tet may have several)
//   tets           distinct site tets
//   flat           site tets whose 4 sites are exactly coplanar
//   inverted       non-flat site tets with an occurrence whose grid tet has the opposite
//                  orientation (the map from grid to space folds there)
//   folded         site tets dualized by grid tets of both orientations
//   open_facets, overshared_facets, overlapping_facets
//                  facets of the non-flat site tets that lie in exactly one of them (the
//                  dual's boundary: convex hull or a hole), in three or more, or in two
//                  lying on the same side of it (the two tets overlap)
//   cospherical_pairs, non_delaunay_pairs
//                  facets in exactly two tets on opposite sides whose 5 sites are exactly
//                  cospherical, or whose apex lies strictly inside the other tet's sphere
// A valid triangulation has flat = inverted = folded = overshared = overlapping = 0, and
// then is Delaunay iff non_delaunay_pairs = 0 and its boundary is the convex hull.
//
// Memory: 8 bytes per cube (counts), 17 bytes per grid tet (keys + expected sign) plus the
// sort's index and key copies (16 bytes per grid tet), 41 bytes per facet for the facet
// pass, 1 byte per site tet (flags). Synchronizes (counts come back to the host).
#pragma once

#include <chrono>
#include <cstdint>

#include "geometry/predicates.hpp"
#include "grid/kuhn.hpp"
#include "mesh/conventions.hpp"
#include "parallel/exact_batch.hpp"
#include "parallel/primitives.hpp"

namespace gdel::grid {

using I64 = std::int64_t;
using U64 = std::uint64_t;

struct DualStats {
  I64 grid_tets = 0, tets = 0, flat = 0, inverted = 0, folded = 0;
  I64 open_facets = 0, overshared_facets = 0, overlapping_facets = 0;
  I64 cospherical_pairs = 0, non_delaunay_pairs = 0;
  double seconds = 0;
};

// Bits of Dual::flags: a site tet that is flat / inverted / folded, or that holds a
// facet counted as open / overshared / overlapping, or a facet of a cospherical /
// non-Delaunay pair (see the counts above).
enum DualTetFlag : std::uint8_t {
  kDualFlat = 1,
  kDualInverted = 2,
  kDualFolded = 4,
  kDualOpenFacet = 8,
  kDualOversharedFacet = 16,
  kDualOverlappingFacet = 32,
  kDualCosphericalPair = 64,
  kDualNonDelaunayPair = 128,
};

namespace dual_detail {

GDEL_HD GDEL_FORCEINLINE U64 pack2(std::int32_t a, std::int32_t b) {
  return (U64(std::uint32_t(a)) << 32) | U64(std::uint32_t(b));
}

// Sorts 4 ids ascending; returns the parity of the permutation (0 even, 1 odd).
GDEL_HD inline int sort4(std::int32_t v[4]) {
  int par = 0;
  for (int i = 1; i < 4; ++i)
    for (int j = i; j > 0 && v[j - 1] > v[j]; --j) {
      const std::int32_t t = v[j];
      v[j] = v[j - 1];
      v[j - 1] = t;
      par ^= 1;
    }
  return par;
}

// Corner colours of cube c among the (W−1)³ cubes.
GDEL_HD inline void cube_colours(const std::int32_t* site, int W, I64 c, std::int32_t col[8]) {
  const I64 w1 = W - 1;
  const I64 x = c % w1, y = (c / w1) % w1, z = c / (w1 * w1);
  for (int k = 0; k < 8; ++k)
    col[k] = site[((z + (k >> 2)) * W + (y + ((k >> 1) & 1))) * W + (x + (k & 1))];
}

GDEL_HD GDEL_FORCEINLINE int popcount6(int m) {
  int n = 0;
  for (int j = 0; j < 6; ++j) n += (m >> j) & 1;
  return n;
}

}  // namespace dual_detail

// Lexicographic order of n 128-bit keys (hi, lo) on the backend: two stable radix passes.
template <class B>
par::Buffer<I64, B> lex_order(par::Context<B>& ctx, const U64* hi, const U64* lo, I64 n) {
  par::Buffer<I64, B> idx(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
  par::Buffer<U64, B> k(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
  par::sequence(ctx, idx.data(), static_cast<std::size_t>(n), I64(0));
  par::detail::Memory<B>::copy(ctx, k.data(), lo, static_cast<std::size_t>(n) * sizeof(U64));
  par::sort_pairs(ctx, k.data(), idx.data(), static_cast<std::size_t>(n));
  par::gather(ctx, idx.data(), hi, k.data(), static_cast<std::size_t>(n));
  par::sort_pairs(ctx, k.data(), idx.data(), static_cast<std::size_t>(n));
  idx.resize(static_cast<std::size_t>(n));
  return idx;
}

template <class B>
struct Dual {
  explicit Dual(par::Context<B>& c) : ctx(&c), hi(c), lo(c), flags(c) {}
  par::Context<B>* ctx;
  par::Buffer<U64, B> hi, lo;  // distinct site tets, sorted ids packed, lexicographic order
  par::Buffer<std::uint8_t, B> flags;  // DualTetFlag bits per distinct site tet
  DualStats stats;

  // Of the m tets `ref` (4 ids each, backend memory): how many are dual tets (returned),
  // the others are tets that no grid tet dualizes (m − returned). Synchronizes.
  I64 compare(const vid_t* ref, I64 m) {
    using namespace dual_detail;
    const I64 u = static_cast<I64>(hi.size());
    const I64 tot = u + m;
    par::Buffer<U64, B> h(*ctx, static_cast<std::size_t>(std::max<I64>(tot, 1)));
    par::Buffer<U64, B> l(*ctx, static_cast<std::size_t>(std::max<I64>(tot, 1)));
    U64* hp = h.data();
    U64* lp = l.data();
    par::detail::Memory<B>::copy(*ctx, hp, hi.data(), static_cast<std::size_t>(u) * sizeof(U64));
    par::detail::Memory<B>::copy(*ctx, lp, lo.data(), static_cast<std::size_t>(u) * sizeof(U64));
    par::parallel_for(*ctx, m, [=] GDEL_LAMBDA(I64 t) {
      std::int32_t v[4] = {ref[4 * t], ref[4 * t + 1], ref[4 * t + 2], ref[4 * t + 3]};
      sort4(v);
      hp[u + t] = pack2(v[0], v[1]);
      lp[u + t] = pack2(v[2], v[3]);
    });
    par::Buffer<I64, B> ord = lex_order(*ctx, hp, lp, tot);
    const I64* o = ord.data();
    // the dual's tets are distinct, so are ref's: a key present in both forms a run of
    // exactly two, one from each side
    par::Buffer<I64, B> hit(*ctx, static_cast<std::size_t>(std::max<I64>(tot, 1)));
    I64* hq = hit.data();
    par::parallel_for(*ctx, tot, [=] GDEL_LAMBDA(I64 r) {
      hq[r] = 0;
      if (r == 0) return;
      const I64 a = o[r - 1], b = o[r];
      if (hp[a] == hp[b] && lp[a] == lp[b] && ((a < u) != (b < u))) hq[r] = 1;
    });
    return par::reduce_sum(*ctx, hq, static_cast<std::size_t>(tot));
  }
};

template <class B>
Dual<B> dual_of_colouring(par::Context<B>& ctx, const std::int32_t* site, int W, const double* X) {
  using namespace dual_detail;
  auto t0 = std::chrono::steady_clock::now();
  Dual<B> out(ctx);
  DualStats& st = out.stats;
  const I64 C = W >= 2 ? I64(W - 1) * (W - 1) * (W - 1) : 0;
  // 1. 4-coloured grid tets: count per cube, offsets, write (sorted ids + expected sign)
  par::Buffer<I64, B> cnt(ctx, static_cast<std::size_t>(C + 1));
  I64* cp = cnt.data();
  par::parallel_for(ctx, C, [=] GDEL_LAMBDA(I64 c) {
    std::int32_t col[8];
    cube_colours(site, W, c, col);
    cp[c] = popcount6(coloured_kuhn_tets(col, -1));
  });
  const I64 G = par::counts_to_offsets(ctx, cp, static_cast<std::size_t>(C));
  st.grid_tets = G;
  if (G == 0) {
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  par::Buffer<U64, B> gh(ctx, static_cast<std::size_t>(G)), gl(ctx, static_cast<std::size_t>(G));
  par::Buffer<std::int8_t, B> ge(ctx, static_cast<std::size_t>(G));
  U64* ghp = gh.data();
  U64* glp = gl.data();
  std::int8_t* gep = ge.data();
  par::parallel_for(ctx, C, [=] GDEL_LAMBDA(I64 c) {
    std::int32_t col[8];
    cube_colours(site, W, c, col);
    const int mask = coloured_kuhn_tets(col, -1);
    I64 w = cp[c];
    for (int j = 0; j < 6; ++j) {
      if (!((mask >> j) & 1)) continue;
      std::int32_t v[4];
      for (int k = 0; k < 4; ++k) v[k] = col[kuhn_corner(j, k)];
      const int par = sort4(v);
      ghp[w] = pack2(v[0], v[1]);
      glp[w] = pack2(v[2], v[3]);
      // the grid tet is kKuhnSign-oriented in corner order; a consistent site tet has
      // that orientation in grid order, i.e. kKuhnSign · (−1)^parity in sorted order
      gep[w] = static_cast<std::int8_t>(par ? -kKuhnSign : kKuhnSign);
      ++w;
    }
  });
  cnt.release();

  // 2. distinct site tets (runs of equal keys), with the expected signs of each run
  par::Buffer<I64, B> ord = lex_order(ctx, ghp, glp, G);
  const I64* o = ord.data();
  par::Buffer<I64, B> heads(ctx, static_cast<std::size_t>(G + 1));
  I64* hd = heads.data();
  I64 U = static_cast<I64>(par::select_indices(ctx, static_cast<std::size_t>(G), hd, [=] GDEL_LAMBDA(I64 r) {
    return r == 0 || ghp[o[r]] != ghp[o[r - 1]] || glp[o[r]] != glp[o[r - 1]];
  }));
  par::fill(ctx, hd + U, 1, G);
  st.tets = U;
  out.hi.resize(static_cast<std::size_t>(U));
  out.lo.resize(static_cast<std::size_t>(U));
  out.flags.resize(static_cast<std::size_t>(U));
  U64* uh = out.hi.data();
  U64* ul = out.lo.data();
  std::uint8_t* tf = out.flags.data();
  par::Buffer<std::int8_t, B> expect(ctx, static_cast<std::size_t>(U));  // bit 0: +1 seen, bit 1: −1 seen
  std::int8_t* ex = expect.data();
  par::parallel_for(ctx, U, [=] GDEL_LAMBDA(I64 u) {
    uh[u] = ghp[o[hd[u]]];
    ul[u] = glp[o[hd[u]]];
    std::int8_t e = 0;
    for (I64 r = hd[u]; r < hd[u + 1]; ++r) e |= gep[o[r]] > 0 ? 1 : 2;
    ex[u] = e;
  });
  ord.release();
  heads.release();
  gh.release();
  gl.release();
  ge.release();

  // 3. exact orientation of every site tet (sorted order)
  par::Buffer<std::int8_t, B> sg(ctx, static_cast<std::size_t>(U));
  std::int8_t* sp = sg.data();
  auto pt = [=] GDEL_LAMBDA(U64 key, int half) { return X + 3 * I64(half ? std::int32_t(key & 0xffffffffu) : std::int32_t(key >> 32)); };
  par::two_stage_signs(
      ctx, U, sp,
      [=] GDEL_LAMBDA(I64 u) -> std::int8_t {
        return static_cast<std::int8_t>(geom::orient3d_filter(pt(uh[u], 0), pt(uh[u], 1), pt(ul[u], 0), pt(ul[u], 1)));
      },
      [=] GDEL_LAMBDA(I64 u, double* work) -> std::int8_t {
        return static_cast<std::int8_t>(
            geom::orient3d_exact(pt(uh[u], 0), pt(uh[u], 1), pt(ul[u], 0), pt(ul[u], 1), work));
      },
      geom::kPredicateWork);
  {
    par::Buffer<I64, B> f(ctx, static_cast<std::size_t>(3 * U));
    I64* fp = f.data();
    par::parallel_for(ctx, U, [=] GDEL_LAMBDA(I64 u) {
      const int s = sp[u];
      fp[u] = s == 0;
      fp[U + u] = (s > 0 && (ex[u] & 2)) || (s < 0 && (ex[u] & 1));
      fp[2 * U + u] = ex[u] == 3;
      tf[u] = static_cast<std::uint8_t>((fp[u] ? kDualFlat : 0) | (fp[U + u] ? kDualInverted : 0) |
                                        (fp[2 * U + u] ? kDualFolded : 0));
    });
    st.flat = par::reduce_sum(ctx, fp, static_cast<std::size_t>(U));
    st.inverted = par::reduce_sum(ctx, fp + U, static_cast<std::size_t>(U));
    st.folded = par::reduce_sum(ctx, fp + 2 * U, static_cast<std::size_t>(U));
  }

  // 4. facets of the non-flat site tets: key = sorted triple, side of the tet's apex
  const I64 F = 4 * U;
  par::Buffer<U64, B> fh(ctx, static_cast<std::size_t>(F)), fl(ctx, static_cast<std::size_t>(F));
  U64* fhp = fh.data();
  U64* flp = fl.data();
  par::parallel_for(ctx, U, [=] GDEL_LAMBDA(I64 u) {
    const std::int32_t v[4] = {std::int32_t(uh[u] >> 32), std::int32_t(uh[u] & 0xffffffffu),
                               std::int32_t(ul[u] >> 32), std::int32_t(ul[u] & 0xffffffffu)};
    for (int i = 0; i < 4; ++i) {
      std::int32_t f[3];
      int c = 0;
      for (int k = 0; k < 4; ++k)
        if (k != i) f[c++] = v[k];
      if (sp[u] == 0) {  // flat tets take no part: a key no facet has
        fhp[4 * u + i] = ~U64(0);
        flp[4 * u + i] = ~U64(0);
        continue;
      }
      fhp[4 * u + i] = pack2(f[0], f[1]);
      flp[4 * u + i] = U64(std::uint32_t(f[2]));
    }
  });
  par::Buffer<I64, B> ford = lex_order(ctx, fhp, flp, F);
  const I64* fo = ford.data();
  par::Buffer<I64, B> fheads(ctx, static_cast<std::size_t>(F + 1));
  I64* fhd = fheads.data();
  I64 NF = static_cast<I64>(par::select_indices(ctx, static_cast<std::size_t>(F), fhd, [=] GDEL_LAMBDA(I64 r) {
    const I64 a = fo[r];
    if (fhp[a] == ~U64(0)) return false;
    return r == 0 || fhp[a] != fhp[fo[r - 1]] || flp[a] != flp[fo[r - 1]];
  }));
  // runs end at the next head, or where the flat tets' sentinel keys begin
  par::Buffer<I64, B> fend(ctx, static_cast<std::size_t>(std::max<I64>(NF, 1)));
  I64* fe = fend.data();
  par::parallel_for(ctx, NF, [=] GDEL_LAMBDA(I64 j) {
    I64 r = fhd[j] + 1;
    while (r < F && fhp[fo[r]] == fhp[fo[fhd[j]]] && flp[fo[r]] == flp[fo[fhd[j]]]) ++r;
    fe[j] = r;
  });
  // side of the apex of facet i of tet u (sorted order, orientation s): moving vertex i
  // to the end is a cycle of length 4 − i, so orient(facet, apex) = s · (−1)^(3−i)
  auto side = [=] GDEL_LAMBDA(I64 f) -> int {
    const int i = static_cast<int>(f & 3);
    const int s = sp[f >> 2];
    return ((3 - i) & 1) ? -s : s;
  };
  par::Buffer<std::int8_t, B> kind(ctx, static_cast<std::size_t>(std::max<I64>(NF, 1)));  // 0 open 1 pair 2 over 3 same
  std::int8_t* kp = kind.data();
  par::parallel_for(ctx, NF, [=] GDEL_LAMBDA(I64 j) {
    const I64 len = fe[j] - fhd[j];
    if (len == 1) kp[j] = 0;
    else if (len > 2) kp[j] = 2;
    else kp[j] = side(fo[fhd[j]]) == side(fo[fhd[j] + 1]) ? 3 : 1;
  });
  // pairs: insphere of the first tet (made positive) with the other tet's apex
  par::Buffer<std::int8_t, B> ins(ctx, static_cast<std::size_t>(std::max<I64>(NF, 1)));
  std::int8_t* ip = ins.data();
  auto tet_pts = [=] GDEL_LAMBDA(I64 u, const double* p[4]) {
    p[0] = pt(uh[u], 0);
    p[1] = pt(uh[u], 1);
    p[2] = pt(ul[u], 0);
    p[3] = pt(ul[u], 1);
    if (sp[u] < 0) {  // swap two vertices: positive orientation
      const double* t = p[0];
      p[0] = p[1];
      p[1] = t;
    }
  };
  auto apex = [=] GDEL_LAMBDA(I64 f) {
    const int i = static_cast<int>(f & 3);
    const I64 u = f >> 2;
    const U64 k = i < 2 ? uh[u] : ul[u];
    return pt(k, i & 1);
  };
  par::two_stage_signs(
      ctx, NF, ip,
      [=] GDEL_LAMBDA(I64 j) -> std::int8_t {
        if (kp[j] != 1) return 0;
        const double* p[4];
        tet_pts(fo[fhd[j]] >> 2, p);
        return static_cast<std::int8_t>(geom::insphere_filter(p[0], p[1], p[2], p[3], apex(fo[fhd[j] + 1])));
      },
      [=] GDEL_LAMBDA(I64 j, double* work) -> std::int8_t {
        const double* p[4];
        tet_pts(fo[fhd[j]] >> 2, p);
        return static_cast<std::int8_t>(geom::insphere_exact(p[0], p[1], p[2], p[3], apex(fo[fhd[j] + 1]), work));
      },
      geom::kPredicateWork);
  {
    par::Buffer<I64, B> f(ctx, static_cast<std::size_t>(5 * std::max<I64>(NF, 1)));
    I64* fp = f.data();
    par::parallel_for(ctx, NF, [=] GDEL_LAMBDA(I64 j) {
      fp[j] = kp[j] == 0;
      fp[NF + j] = kp[j] == 2;
      fp[2 * NF + j] = kp[j] == 3;
      fp[3 * NF + j] = kp[j] == 1 && ip[j] == 0;
      fp[4 * NF + j] = kp[j] == 1 && ip[j] > 0;
    });
    const std::size_t nf = static_cast<std::size_t>(NF);
    st.open_facets = par::reduce_sum(ctx, fp, nf);
    st.overshared_facets = par::reduce_sum(ctx, fp + NF, nf);
    st.overlapping_facets = par::reduce_sum(ctx, fp + 2 * NF, nf);
    st.cospherical_pairs = par::reduce_sum(ctx, fp + 3 * NF, nf);
    st.non_delaunay_pairs = par::reduce_sum(ctx, fp + 4 * NF, nf);
  }
  // 5. the facet kinds tet by tet: each facet slot of a non-flat tet lies in one run
  {
    par::Buffer<std::uint8_t, B> fb(ctx, static_cast<std::size_t>(F));
    std::uint8_t* fbp = fb.data();
    par::fill(ctx, fbp, static_cast<std::size_t>(F), std::uint8_t(0));
    par::parallel_for(ctx, NF, [=] GDEL_LAMBDA(I64 j) {
      const std::uint8_t bit = kp[j] == 0   ? kDualOpenFacet
                               : kp[j] == 2 ? kDualOversharedFacet
                               : kp[j] == 3 ? kDualOverlappingFacet
                               : ip[j] == 0 ? kDualCosphericalPair
                               : ip[j] > 0  ? kDualNonDelaunayPair
                                            : 0;
      for (I64 r = fhd[j]; r < fe[j]; ++r) fbp[fo[r]] = bit;
    });
    par::parallel_for(ctx, U, [=] GDEL_LAMBDA(I64 u) {
      tf[u] = static_cast<std::uint8_t>(tf[u] | fbp[4 * u] | fbp[4 * u + 1] | fbp[4 * u + 2] | fbp[4 * u + 3]);
    });
  }
  ctx.synchronize();
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace gdel::grid
