// gStar4D stage 1: the digital Voronoi diagram of the points on a W³ voxel grid,
// computed by the Parallel Banding Algorithm (PBA; Cao, Tang, Mohamed, Tan, I3D 2010).
// Written once over the backend tag B (par::Cpu, par::Cuda); every decision is exact
// integer arithmetic on voxel coordinates.
//
// ---------------------------------------------------------------------------------
// Interface
//
//   DigitalVoronoi<B> digital_voronoi(ctx, X, n, lo, hi, PbaOptions{})
//     X      backend pointer, 3n doubles (x0,y0,z0,x1,...), the internal points
//     lo, hi host arrays, the points' bounding box (every point inside it)
//     returns (buffers live in ctx):
//       W        grid side (automatic rule below, or PbaOptions::grid)
//       voxel    3n int32: voxel coordinates (vx,vy,vz) of point i, each in [0, W)
//       site     W³ int32: site[(z*W + y)*W + x] = id of the point whose voxel is
//                nearest (squared Euclidean distance in voxel units, ties: any of the
//                nearest) to voxel (x,y,z). -1 only when n == 0.
//       origin, scale: voxel of p = clamp(floor((p - origin) * scale), 0, W-1) per axis
//       stats    W, bytes, time per phase
//   A voxel holding several points is the site of the smallest of their ids; the other
//   points of that voxel are "missing" (stage 2 pairs them with the owner).
//
//   Buffer<int32,B> pba_colour(ctx, W, voxel, n, bands, stats*)
//     the same colouring for given voxel coordinates (3n int32 in [0,W), backend
//     pointer); used by digital_voronoi and by the tests.
//
//   int choose_grid_size(n, budget_bytes, voxels_per_point)      (host)
//   std::size_t grid_memory_budget(ctx)                          (host; queries memory)
//
// ---------------------------------------------------------------------------------
// Grid size rule (choose_grid_size)
//   W = the smallest integer with W³ > voxels_per_point · n (default 8 voxels per
//   point, measured in docs/gstar4d.md), at least kMinGrid, and at most kMaxGrid and the
//   largest W (≥ 1) whose PBA peak (8·W³ bytes: two W³ int32 grids) fits the memory
//   budget (the memory cap wins over kMinGrid). The budget defaults to a quarter of the
//   free memory of the backend (free host memory for Cpu, free device memory for Cuda):
//   the later stages need the rest.
//   PbaOptions::grid overrides the rule (any W ≥ 1; memory errors then surface as
//   OutOfDeviceMemory). The grid is a cube over the longest side of the bounding box, so
//   voxels are cubes and voxel distances are proportional to Euclidean ones.
//
// Arithmetic: voxel coordinates are < W ≤ kMaxGrid = 2^14 (any W < 2^16 would be safe);
// squared distances (< 3·2^32) and the bisector products of the dominance test
// (< 3·2^32 · 2^16) are int64, far from overflow. Voxel indices are int64.
//
// ---------------------------------------------------------------------------------
// Phases (grid layout: x fastest, index (z*W + y)*W + x; "line" = W voxels along one axis)
//   0. seed   : site[voxel(i)] = min id over the points in that voxel (atomic min).
//   1. along z: each column is cut into m1 bands; per band one forward and one backward
//               sweep give every voxel its nearest site in the band; then every band
//               takes the nearest site of the bands below (top voxel of the nearest
//               non-empty band) and above (bottom voxel), and every voxel keeps the
//               nearest of the three. Result: the nearest site of the column.
//   2. along y: per line (fixed x, z) the proximate sites (those whose Voronoi region
//               can meet the line) are kept: each of m2 bands runs Maurer's stack
//               (a site b between a and c is dropped when the bisector of a,b meets the
//               line at or after the bisector of b,c — exact int64 cross-multiplied
//               test), storing its stack compactly at the start of the band, in place;
//               then bands are merged pairwise (log2 m2 rounds): the left list's top is
//               popped, and the right list's first site dropped, while dominated across
//               the junction. Each band keeps a [lo, hi) range of its compact stack.
//   3. colour : each of m3 bands of a line finds the proximate site nearest to its first
//               voxel (binary search: along the list the distance to a fixed voxel first
//               decreases strictly, then never decreases) and walks forward, writing the
//               nearest site of the plane into a second grid.
//   T. transpose x <-> y, run 2 and 3 again (now along x, the site's x is the line
//      coordinate), transpose back. The result is the exact nearest site (standard
//      separable argument: the nearest site along z, then of the plane, then of space).
//
// Memory peak of pba_colour: 2 grids (8·W³ bytes) + band arrays 8·W²·m2 bytes (phase 1's
// 8·W²·m1, only when m1 > 1, are freed before); seeding holds one grid + 8 n bytes for a
// moment. digital_voronoi adds the voxel coordinates (12 n bytes). W = 201 (10^6 points
// by default): 65 MB; W = 512: 1.07 GB; W = 1024: 8.6 GB.
//
// Synchronisation: each phase is enqueued on ctx's stream; the stats timings
// synchronize between phases (they are measured with ctx.synchronize()).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include <unistd.h>

#include "gdel/errors.hpp"
#include "parallel/atomic.hpp"
#include "parallel/primitives.hpp"

namespace gdel::star4d {

inline constexpr int kMinGrid = 16;
inline constexpr int kMaxGrid = 1 << 14;
inline constexpr double kDefaultVoxelsPerPoint = 8.0;

// Band counts of the three PBA phases (the thesis uses 1, 1, 2). Any value ≥ 1; values
// above W act as W (bands of one voxel).
struct PbaBands {
  int m1 = 1;  // phase 1 (z sweeps)
  int m2 = 1;  // phase 2 (proximate sites)
  int m3 = 2;  // phase 3 (colouring)
};

struct PbaOptions {
  int grid = 0;                                     // W; 0 = automatic (choose_grid_size)
  double voxels_per_point = kDefaultVoxelsPerPoint;  // automatic rule's target density
  std::size_t memory_budget = 0;                    // bytes for the PBA grids; 0 = grid_memory_budget(ctx)
  PbaBands bands;
};

struct PbaStats {
  int W = 0;
  std::int64_t points = 0;
  std::int64_t sites = 0;            // voxels holding at least one point
  std::size_t grid_bytes = 0;        // one W³ int32 grid
  std::size_t peak_bytes = 0;        // peak of PBA's own buffers (see header comment)
  double t_quantize = 0, t_seed = 0, t_phase1 = 0, t_phase2 = 0, t_phase3 = 0, t_transpose = 0, t_total = 0;
};

template <class B>
struct DigitalVoronoi {
  explicit DigitalVoronoi(par::Context<B>& c) : site(c), voxel(c) {}
  int W = 0;
  par::Buffer<std::int32_t, B> site;   // W³
  par::Buffer<std::int32_t, B> voxel;  // 3n
  double origin[3] = {0, 0, 0};
  double scale = 0;
  PbaStats stats;
  std::int64_t voxel_index(int x, int y, int z) const { return (std::int64_t(z) * W + y) * W + x; }
};

// ---------------------------------------------------------------------------------
// Grid size and memory
// ---------------------------------------------------------------------------------

inline std::size_t free_memory(par::Context<par::Cpu>&) {
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::size_t(1) << 32;  // unknown: assume 4 GiB
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page);
}
#if defined(__CUDACC__)
inline std::size_t free_memory(par::Context<par::Cuda>& ctx) { return ctx.free_bytes(); }
#endif

// A quarter of the backend's free memory.
template <class B>
std::size_t grid_memory_budget(par::Context<B>& ctx) {
  return free_memory(ctx) / 4;
}

// The documented rule (see header comment). Host only, exact integer arithmetic.
inline int choose_grid_size(std::int64_t n, std::size_t budget_bytes, double voxels_per_point = kDefaultVoxelsPerPoint) {
  if (!(voxels_per_point > 0)) voxels_per_point = kDefaultVoxelsPerPoint;
  const double want_d = voxels_per_point * static_cast<double>(n < 0 ? 0 : n);
  const std::int64_t want = want_d >= 9.0e18 ? std::int64_t(9.0e18) : static_cast<std::int64_t>(want_d) + 1;
  std::int64_t W = kMinGrid;
  while (W < kMaxGrid && W * W * W < want) ++W;
  // memory cap: 8 W³ ≤ budget
  std::int64_t cap = 1;
  while (cap < kMaxGrid && static_cast<std::size_t>(8) * (cap + 1) * (cap + 1) * (cap + 1) <= budget_bytes) ++cap;
  if (W > cap) W = cap;
  return static_cast<int>(W);
}

// ---------------------------------------------------------------------------------
// Per-element helpers (host and device)
// ---------------------------------------------------------------------------------
namespace pba_detail {

using I64 = std::int64_t;
inline constexpr std::int32_t kNoSeed = 0x7fffffff;  // empty voxel during seeding

// Line coordinate t and squared off-line distance h2 of site s for the line (a, z) of
// pass `pass`: pass 0 runs along y in the normal layout (line fixed x = a, z); pass 1
// runs along the transposed layout's y, i.e. along x, with the line's fixed y = a.
GDEL_HD GDEL_FORCEINLINE void site_geom(const std::int32_t* vox, std::int32_t s, int pass, int a, int z, I64& t,
                                        I64& h2) {
  const std::int32_t* v = vox + 3 * I64(s);
  const I64 dz = I64(v[2]) - z;
  const I64 da = I64(pass == 0 ? v[0] : v[1]) - a;
  t = pass == 0 ? v[1] : v[0];
  h2 = da * da + dz * dz;
}

// Site v (between u and w on the line, t_u < t_v < t_w) has no voxel of the line where
// it is strictly nearest: the bisector of (u,v) meets the line at or after that of (v,w).
GDEL_HD GDEL_FORCEINLINE bool dominated(I64 tu, I64 hu, I64 tv, I64 hv, I64 tw, I64 hw) {
  const I64 l = (tv * tv - tu * tu + hv - hu) * (tw - tv);
  const I64 r = (tw * tw - tv * tv + hw - hv) * (tv - tu);
  return l >= r;
}

// One line of phase 2/3: element i of band k sits at g[base + (k*bs + i)*W]; band k's
// surviving range is [lo[k*W2 + line], hi[k*W2 + line]).
struct LineLists {
  std::int32_t* g;
  std::int32_t* lo;
  std::int32_t* hi;
  I64 base, W, W2, line;
  int bs, nb;
  GDEL_HD std::int32_t at(int k, int i) const { return g[base + (I64(k) * bs + i) * W]; }
  GDEL_HD int lo_of(int k) const { return lo[I64(k) * W2 + line]; }
  GDEL_HD int hi_of(int k) const { return hi[I64(k) * W2 + line]; }
  // last element of bands [k0, k1) before (k, i) exclusive; false if none
  GDEL_HD bool prev(int k0, int& k, int& i) const {
    if (i - 1 >= lo_of(k)) {
      --i;
      return true;
    }
    for (int j = k - 1; j >= k0; --j)
      if (hi_of(j) > lo_of(j)) {
        k = j;
        i = hi_of(j) - 1;
        return true;
      }
    return false;
  }
  GDEL_HD bool next(int k1, int& k, int& i) const {
    if (i + 1 < hi_of(k)) {
      ++i;
      return true;
    }
    for (int j = k + 1; j < k1; ++j)
      if (hi_of(j) > lo_of(j)) {
        k = j;
        i = lo_of(j);
        return true;
      }
    return false;
  }
  GDEL_HD bool first(int k0, int k1, int& k, int& i) const {
    for (int j = k0; j < k1; ++j)
      if (hi_of(j) > lo_of(j)) {
        k = j;
        i = lo_of(j);
        return true;
      }
    return false;
  }
  GDEL_HD bool last(int k0, int k1, int& k, int& i) const {
    for (int j = k1 - 1; j >= k0; --j)
      if (hi_of(j) > lo_of(j)) {
        k = j;
        i = hi_of(j) - 1;
        return true;
      }
    return false;
  }
  // element number idx of the whole list (bands [0, nb)); idx < total
  GDEL_HD void locate(int idx, int& k, int& i) const {
    for (int j = 0; j < nb; ++j) {
      const int c = hi_of(j) - lo_of(j);
      if (idx < c) {
        k = j;
        i = lo_of(j) + idx;
        return;
      }
      idx -= c;
    }
    k = nb - 1;
    i = hi_of(nb - 1) - 1;
  }
};

inline int band_size(int W, int m) {
  if (m < 1) m = 1;
  if (m > W) m = W;
  return (W + m - 1) / m;
}

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Phase 1: nearest site along z for every voxel, in place in g (seeded grid in, with
// kNoSeed for empty voxels; out: site id or -1).
template <class B>
void phase1(par::Context<B>& ctx, int W, int m1, std::int32_t* g, const std::int32_t* vox, std::size_t& peak) {
  const I64 W2 = I64(W) * W;
  const int bs = band_size(W, m1);
  const int nb = (W + bs - 1) / bs;
  par::parallel_for(ctx, W2 * nb, [=] GDEL_LAMBDA(I64 id) {
    const I64 col = id % W2;
    const int band = static_cast<int>(id / W2);
    const int a = band * bs;
    const int b = a + bs < W ? a + bs : W;
    std::int32_t last = -1;
    for (int z = a; z < b; ++z) {
      const I64 k = z * W2 + col;
      const std::int32_t v = g[k];
      if (v != kNoSeed) last = v;
      g[k] = last;
    }
    std::int32_t next = -1;
    int nz = 0;
    for (int z = b - 1; z >= a; --z) {
      const I64 k = z * W2 + col;
      const std::int32_t cur = g[k];
      const int cz = cur >= 0 ? vox[3 * I64(cur) + 2] : 0;
      if (cur >= 0 && cz == z) {
        next = cur;
        nz = z;
      }
      std::int32_t best;
      if (cur < 0)
        best = next;
      else if (next < 0)
        best = cur;
      else
        best = (nz - z) < (z - cz) ? next : cur;
      g[k] = best;
    }
  });
  if (nb == 1) return;
  // inter-band propagation
  par::Buffer<std::int32_t, B> below(ctx, static_cast<std::size_t>(W2 * nb));
  par::Buffer<std::int32_t, B> above(ctx, static_cast<std::size_t>(W2 * nb));
  peak = std::max(peak, below.bytes() + above.bytes());
  std::int32_t* bp = below.data();
  std::int32_t* ap = above.data();
  par::parallel_for(ctx, W2 * nb, [=] GDEL_LAMBDA(I64 id) {
    const I64 col = id % W2;
    const int band = static_cast<int>(id / W2);
    std::int32_t lo_site = -1, hi_site = -1;
    for (int j = band - 1; j >= 0; --j) {  // top voxel of band j holds band j's highest site
      const int top = (j + 1) * bs - 1;
      const std::int32_t v = g[top * W2 + col];
      if (v >= 0) {
        lo_site = v;
        break;
      }
    }
    for (int j = band + 1; j < nb; ++j) {  // bottom voxel of band j holds its lowest site
      const std::int32_t v = g[I64(j) * bs * W2 + col];
      if (v >= 0) {
        hi_site = v;
        break;
      }
    }
    bp[id] = lo_site;
    ap[id] = hi_site;
  });
  par::parallel_for(ctx, W2 * W, [=] GDEL_LAMBDA(I64 k) {
    const int z = static_cast<int>(k / W2);
    const I64 col = k % W2;
    const I64 bid = I64(z / bs) * W2 + col;
    std::int32_t best = g[k];
    I64 bd = best >= 0 ? I64(vox[3 * I64(best) + 2]) - z : 0;
    bd = bd < 0 ? -bd : bd;
    const std::int32_t cand[2] = {bp[bid], ap[bid]};
    for (int c = 0; c < 2; ++c) {
      const std::int32_t s = cand[c];
      if (s < 0) continue;
      I64 d = I64(vox[3 * I64(s) + 2]) - z;
      d = d < 0 ? -d : d;
      if (best < 0 || d < bd) {
        best = s;
        bd = d;
      }
    }
    g[k] = best;
  });
}

// Phases 2 and 3 along the layout's y for pass `pass` (0: y, 1: x in the transposed
// layout). In: g with one candidate per voxel (nearest site of the column / plane, or
// -1); g is overwritten by the band stacks. Out: out = nearest site of the plane / space.
template <class B>
void phase23(par::Context<B>& ctx, int W, const PbaBands& bands, int pass, std::int32_t* g, std::int32_t* out,
             const std::int32_t* vox, std::size_t& peak, double& t2, double& t3) {
  const I64 W2 = I64(W) * W;
  const int bs = band_size(W, bands.m2);
  const int nb = (W + bs - 1) / bs;
  const int bs3 = band_size(W, bands.m3);
  const int nb3 = (W + bs3 - 1) / bs3;
  par::Buffer<std::int32_t, B> lob(ctx, static_cast<std::size_t>(W2 * nb));
  par::Buffer<std::int32_t, B> hib(ctx, static_cast<std::size_t>(W2 * nb));
  peak = std::max(peak, lob.bytes() + hib.bytes());
  std::int32_t* lo = lob.data();
  std::int32_t* hi = hib.data();
  auto t0 = std::chrono::steady_clock::now();

  // 2a: Maurer's stack per band, stored compactly at the band's start.
  par::parallel_for(ctx, W2 * nb, [=] GDEL_LAMBDA(I64 id) {
    const I64 line = id % W2;
    const int band = static_cast<int>(id / W2);
    const int a = static_cast<int>(line % W);
    const int z = static_cast<int>(line / W);
    const I64 base = I64(z) * W2 + a;
    const int y0 = band * bs;
    const int y1 = y0 + bs < W ? y0 + bs : W;
    int cnt = 0;
    I64 t1 = 0, h1 = 0, t0s = 0, h0s = 0;  // top (1) and second (0) of the stack
    for (int y = y0; y < y1; ++y) {
      const std::int32_t s = g[base + I64(y) * W];
      if (s < 0) continue;
      I64 ts, hs;
      site_geom(vox, s, pass, a, z, ts, hs);
      while (cnt >= 2 && dominated(t0s, h0s, t1, h1, ts, hs)) {
        --cnt;
        t1 = t0s;
        h1 = h0s;
        if (cnt >= 2) site_geom(vox, g[base + I64(y0 + cnt - 2) * W], pass, a, z, t0s, h0s);
      }
      g[base + I64(y0 + cnt) * W] = s;
      ++cnt;
      t0s = t1;
      h0s = h1;
      t1 = ts;
      h1 = hs;
    }
    lo[id] = 0;
    hi[id] = cnt;
  });

  // 2b: pairwise merges of adjacent band groups.
  for (int gsz = 1; gsz < nb; gsz *= 2) {
    const int npairs = (nb + 2 * gsz - 1) / (2 * gsz);
    par::parallel_for(ctx, W2 * npairs, [=] GDEL_LAMBDA(I64 id) {
      const I64 line = id % W2;
      const int pair = static_cast<int>(id / W2);
      const int l0 = pair * 2 * gsz;
      const int r0 = l0 + gsz;
      if (r0 >= nb) return;
      const int r1 = r0 + gsz < nb ? r0 + gsz : nb;
      const int a = static_cast<int>(line % W);
      const int z = static_cast<int>(line / W);
      LineLists L{g, lo, hi, I64(z) * W2 + a, I64(W), W2, line, bs, nb};
      int rk, ri, lk, li;
      if (!L.first(r0, r1, rk, ri)) return;  // right side empty
      if (!L.last(l0, r0, lk, li)) return;   // left side empty
      for (;;) {
        I64 tw, hw;
        site_geom(vox, L.at(rk, ri), pass, a, z, tw, hw);
        // pop the left top while the site below it and w dominate it
        for (;;) {
          int pk = lk, pi = li;
          if (!L.prev(l0, pk, pi)) break;
          I64 tu, hu, tv, hv;
          site_geom(vox, L.at(pk, pi), pass, a, z, tu, hu);
          site_geom(vox, L.at(lk, li), pass, a, z, tv, hv);
          if (!dominated(tu, hu, tv, hv, tw, hw)) break;
          hi[I64(lk) * W2 + line] = li;  // li == hi - 1: pop
          lk = pk;
          li = pi;
        }
        // drop w (the right list's first) if the left top and the next right site dominate it
        int nk = rk, ni = ri;
        if (!L.next(r1, nk, ni)) break;
        I64 tu, hu, tx, hx;
        site_geom(vox, L.at(lk, li), pass, a, z, tu, hu);
        site_geom(vox, L.at(nk, ni), pass, a, z, tx, hx);
        if (!dominated(tu, hu, tw, hw, tx, hx)) break;
        lo[I64(rk) * W2 + line] = ri + 1;  // ri == lo: drop the first
        rk = nk;
        ri = ni;
      }
    });
  }
  ctx.synchronize();
  t2 += seconds_since(t0);
  t0 = std::chrono::steady_clock::now();

  // 3: colour each band of m3 from the proximate list.
  par::parallel_for(ctx, W2 * nb3, [=] GDEL_LAMBDA(I64 id) {
    const I64 line = id % W2;
    const int band = static_cast<int>(id / W2);
    const int a = static_cast<int>(line % W);
    const int z = static_cast<int>(line / W);
    const I64 base = I64(z) * W2 + a;
    const int c0 = band * bs3;
    const int c1 = c0 + bs3 < W ? c0 + bs3 : W;
    LineLists L{g, lo, hi, base, I64(W), W2, line, bs, nb};
    int total = 0;
    for (int j = 0; j < nb; ++j) total += L.hi_of(j) - L.lo_of(j);
    if (total == 0) {
      for (int y = c0; y < c1; ++y) out[base + I64(y) * W] = -1;
      return;
    }
    // first list index whose successor is not strictly nearer to voxel c0
    int lo_i = 0, hi_i = total - 1;
    while (lo_i < hi_i) {
      const int mid = (lo_i + hi_i) / 2;
      int k, i;
      L.locate(mid, k, i);
      I64 tm, hm, tn, hn;
      site_geom(vox, L.at(k, i), pass, a, z, tm, hm);
      L.next(nb, k, i);
      site_geom(vox, L.at(k, i), pass, a, z, tn, hn);
      const I64 dm = (c0 - tm) * (c0 - tm) + hm;
      const I64 dn = (c0 - tn) * (c0 - tn) + hn;
      if (dn < dm)
        lo_i = mid + 1;
      else
        hi_i = mid;
    }
    int k, i;
    L.locate(lo_i, k, i);
    std::int32_t cur = L.at(k, i);
    I64 tc, hc;
    site_geom(vox, cur, pass, a, z, tc, hc);
    int nk = k, ni = i;
    bool has_next = L.next(nb, nk, ni);
    I64 tn = 0, hn = 0;
    if (has_next) site_geom(vox, L.at(nk, ni), pass, a, z, tn, hn);
    for (int y = c0; y < c1; ++y) {
      while (has_next && (y - tn) * (y - tn) + hn < (y - tc) * (y - tc) + hc) {
        cur = L.at(nk, ni);
        tc = tn;
        hc = hn;
        k = nk;
        i = ni;
        has_next = L.next(nb, nk, ni);
        if (has_next) site_geom(vox, L.at(nk, ni), pass, a, z, tn, hn);
      }
      out[base + I64(y) * W] = cur;
    }
  });
  ctx.synchronize();
  t3 += seconds_since(t0);
}

// out[(z*W + x)*W + y] = in[(z*W + y)*W + x]
template <class B>
void transpose_xy(par::Context<B>& ctx, int W, const std::int32_t* in, std::int32_t* out) {
  const I64 W2 = I64(W) * W;
  par::parallel_for(ctx, W2 * W, [=] GDEL_LAMBDA(I64 k) {
    const I64 y = k % W;
    const I64 x = (k / W) % W;
    const I64 z = k / W2;
    out[k] = in[z * W2 + y * W + x];
  });
}

}  // namespace pba_detail

// ---------------------------------------------------------------------------------
// Entry points
// ---------------------------------------------------------------------------------

// Exact digital Voronoi colouring of W³ for sites at voxel coordinates vox (3n int32,
// backend memory, each in [0, W)). Returns the W³ grid of site ids (see header).
template <class B>
par::Buffer<std::int32_t, B> pba_colour(par::Context<B>& ctx, int W, const std::int32_t* vox, std::int64_t n,
                                        const PbaBands& bands = {}, PbaStats* stats = nullptr) {
  using namespace pba_detail;
  if (W < 1) throw InvalidInput("pba: grid size must be at least 1, got " + std::to_string(W));
  if (n > std::int64_t(0x7fffffff)) throw InvalidInput("pba: at most 2^31 - 1 sites");
  PbaStats local;
  PbaStats& st = stats ? *stats : local;
  st.W = W;
  const I64 W2 = I64(W) * W;
  const I64 W3 = W2 * W;
  auto t_all = std::chrono::steady_clock::now();
  auto t0 = t_all;

  par::Buffer<std::int32_t, B> g0(ctx, static_cast<std::size_t>(W3));
  std::int32_t* g = g0.data();
  st.grid_bytes = g0.bytes();
  par::fill(ctx, g, static_cast<std::size_t>(W3), kNoSeed);
  par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
    const I64 k = (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i];
    par::atomic_min(g + k, static_cast<std::int32_t>(i));
  });
  st.sites = 0;
  {
    par::Buffer<std::int64_t, B> one(ctx, static_cast<std::size_t>(n > 0 ? n : 1));
    std::int64_t* op = one.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
      const I64 k = (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i];
      op[i] = g[k] == static_cast<std::int32_t>(i) ? 1 : 0;
    });
    st.sites = par::reduce_sum(ctx, op, static_cast<std::size_t>(n));
  }
  ctx.synchronize();
  st.t_seed = seconds_since(t0);

  std::size_t band_peak = 0;
  t0 = std::chrono::steady_clock::now();
  phase1(ctx, W, bands.m1, g, vox, band_peak);
  ctx.synchronize();
  st.t_phase1 = seconds_since(t0);

  par::Buffer<std::int32_t, B> g1(ctx, static_cast<std::size_t>(W3));
  std::int32_t* h = g1.data();
  st.t_phase2 = st.t_phase3 = 0;
  phase23(ctx, W, bands, 0, g, h, vox, band_peak, st.t_phase2, st.t_phase3);
  t0 = std::chrono::steady_clock::now();
  transpose_xy(ctx, W, h, g);
  ctx.synchronize();
  st.t_transpose = seconds_since(t0);
  phase23(ctx, W, bands, 1, g, h, vox, band_peak, st.t_phase2, st.t_phase3);
  t0 = std::chrono::steady_clock::now();
  transpose_xy(ctx, W, h, g);
  ctx.synchronize();
  st.t_transpose += seconds_since(t0);
  st.peak_bytes = g0.bytes() + g1.bytes() + band_peak;
  st.t_total = seconds_since(t_all);
  return g0;
}

// Quantize the points into W³ and colour the grid (see header).
template <class B>
DigitalVoronoi<B> digital_voronoi(par::Context<B>& ctx, const double* X, std::int64_t n, const double lo[3],
                                  const double hi[3], const PbaOptions& opt = {}) {
  using namespace pba_detail;
  DigitalVoronoi<B> dv(ctx);
  auto t0 = std::chrono::steady_clock::now();
  const std::size_t budget = opt.memory_budget ? opt.memory_budget : grid_memory_budget(ctx);
  const int W = opt.grid > 0 ? opt.grid : choose_grid_size(n, budget, opt.voxels_per_point);
  dv.W = W;
  double extent = 0;
  for (int a = 0; a < 3; ++a) {
    dv.origin[a] = lo[a];
    extent = std::max(extent, hi[a] - lo[a]);
  }
  dv.scale = extent > 0 ? static_cast<double>(W) / extent : 0.0;
  const double ox = lo[0], oy = lo[1], oz = lo[2], sc = dv.scale;
  dv.voxel.resize_discard(static_cast<std::size_t>(3 * n));
  std::int32_t* vp = dv.voxel.data();
  par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
    const double o[3] = {ox, oy, oz};
    for (int a = 0; a < 3; ++a) {
      const double f = (X[3 * i + a] - o[a]) * sc;
      int v = 0;
      if (f >= static_cast<double>(W))
        v = W - 1;
      else if (f > 0)
        v = static_cast<int>(f);  // truncation = floor for f > 0
      vp[3 * i + a] = v;
    }
  });
  ctx.synchronize();
  const double tq = seconds_since(t0);
  dv.site = pba_colour(ctx, W, vp, n, opt.bands, &dv.stats);
  dv.stats.points = n;
  dv.stats.t_quantize = tq;
  dv.stats.t_total += tq;
  dv.stats.peak_bytes += dv.voxel.bytes();
  return dv;
}

}  // namespace gdel::star4d
