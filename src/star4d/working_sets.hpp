// gStar4D stage 2: working sets — for every point, the candidate neighbours its initial
// star is built from, read off the digital Voronoi diagram of stage 1 (pba.hpp).
// Written once over the backend tag B.
//
// ---------------------------------------------------------------------------------
// Interface
//
//   WorkingSets<B> working_sets(ctx, dv, WorkingSetOptions{})
//     dv   the DigitalVoronoi<B> of the n points (stage 1; its site grid and voxels)
//     returns (buffers live in ctx):
//       offsets  n + 1 int64: the candidates of point i are ids[offsets[i] .. offsets[i+1])
//       ids      offsets[n] vid_t (int32) point ids
//       stats    pair counts and seconds per step
//   Guarantees: every list is sorted ascending, holds no i itself and no duplicate; the
//   relation is symmetric (j in list(i) ⇔ i in list(j)); every list has at least
//   min(K, n − 1) entries (K = WorkingSetOptions::min_candidates, default 8); a missing
//   point (one whose voxel another point owns) lists its owner. Deterministic: the same
//   input gives the same arrays on every run and backend.
//
// ---------------------------------------------------------------------------------
// Steps
//   a. missing points: point i with site[voxel(i)] = o ≠ i gives the pair {i, o}.
//   b. grid scan: every cube of 2×2×2 voxels is cut into the 6 tets of the Kuhn
//      (Freudenthal) triangulation around its diagonal (0,0,0)–(1,1,1): tet j =
//      {000, 111, h_j, h_j+1} over the hexagon h = 011, 010, 110, 100, 101, 001 (x,y,z
//      offsets). All cubes use the same diagonal direction, so the tets of neighbouring
//      cubes match across faces and the grid is triangulated. A tet whose 4 voxels carry
//      4 distinct sites gives the pairs of ALL its 6 edges (the diagonal included: it is
//      an edge of the dual site tet like the others). Voxels outside the grid are a
//      marker colour; every tet of a cube that sticks out of the grid holds 000 or 111
//      outside, so only the (W−1)³ interior cubes can yield pairs and only they are
//      scanned. One thread per row of cubes along z; two passes (count, exclusive scan
//      of the row counts, write). A pair repeated inside one cube, or among the last 8
//      pairs its row wrote, is written once (fewer raw pairs to sort).
//   c. sort + unique the undirected pairs (64-bit keys lo<<32 | hi), reciprocate (both
//      directions), sort: CSR.
//   d. pumping: a point i with fewer than k = min(K, n−1) candidates takes the k − deg
//      nearest (squared voxel distance to i's voxel, ties by smaller id; exact integers)
//      of the candidates of its candidates (not i, not already listed); if that is not
//      enough, points i+1, i−1, i+2, i−2, … (ids close to i are spatially close when the
//      points are Hilbert-sorted, as gStar4D's are), skipping itself and points already
//      present, until it has k. Measured (10^4 uniform points, default W): nearest-first
//      holds 72 % of the Delaunay edges, ascending-id order 71 %. Pumped pairs are
//      reciprocated (a pumped x is never in list(i), so by symmetry both directions are
//      new), sorted, made unique and merged list by list into the CSR. (The fallback
//      always ends: it walks all n − 1 others at worst, and k ≤ n − 1.)
//
// Memory peak (besides dv): the raw undirected keys (8 bytes each; ~23 per point for
// uniform points at the default W) and their sort temporaries (CUDA: a second key array
// + CUB scratch), then 16 bytes per undirected pair (directed keys) + the CSR (4 bytes per
// directed pair + 8 (n+1)); row counts 8 (W−1)² bytes.
//
// Synchronisation: the counts (grid pairs, unique pairs, pumped pairs) come back to the
// host, so the call synchronizes several times; the stats timings synchronize per step.
#pragma once

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>

#include "core/bits.hpp"
#include "mesh/conventions.hpp"
#include "parallel/primitives.hpp"
#include "star4d/pba.hpp"

namespace gdel::star4d {

struct WorkingSetOptions {
  int min_candidates = 8;  // K
};

struct WorkingSetStats {
  std::int64_t points = 0;
  std::int64_t missing_points = 0;     // points whose voxel another point owns
  std::int64_t grid_pairs = 0;         // pairs written by the grid scan (each cube's distinct pairs)
  std::int64_t raw_pairs = 0;          // grid_pairs + missing_points (before sort/unique)
  std::int64_t unique_pairs = 0;       // undirected pairs after unique
  std::int64_t pumped_points = 0;      // points that had fewer than min(K, n-1) candidates
  std::int64_t pumped_pairs = 0;       // pairs those points added (one direction)
  std::int64_t directed_pairs = 0;     // final offsets[n]
  double t_missing = 0, t_scan = 0, t_sort = 0, t_csr = 0, t_pump = 0, t_total = 0;
};

template <class B>
struct WorkingSets {
  explicit WorkingSets(par::Context<B>& c) : offsets(c), ids(c) {}
  par::Buffer<std::int64_t, B> offsets;  // n + 1
  par::Buffer<vid_t, B> ids;             // offsets[n]
  WorkingSetStats stats;
};

namespace ws_detail {

using I64 = std::int64_t;
using U64 = std::uint64_t;

GDEL_HD GDEL_FORCEINLINE U64 pack(std::int32_t a, std::int32_t b) {
  return (U64(std::uint32_t(a)) << 32) | U64(std::uint32_t(b));
}
GDEL_HD GDEL_FORCEINLINE std::int32_t key_hi(U64 k) { return static_cast<std::int32_t>(k >> 32); }
GDEL_HD GDEL_FORCEINLINE std::int32_t key_lo(U64 k) { return static_cast<std::int32_t>(k & 0xffffffffu); }

// Distinct undirected site pairs (lo<<32 | hi) of the 4-coloured Kuhn tets of a cube
// whose corner (dx,dy,dz) has colour c[dx + 2dy + 4dz], into local; returns their number.
// Corners are labelled by the first corner of their colour, so a pair of colours is one
// bit of a 64-bit mask (this dedupes the pairs of the cube's tets).
GDEL_HD inline int cube_pairs(const std::int32_t c[8], U64 local[28]) {
  if (c[0] == c[7]) return 0;  // every tet holds both diagonal corners
  constexpr int hex[6] = {6, 2, 3, 1, 5, 4};  // 011, 010, 110, 100, 101, 001
  // tet j = {0, 7, hex[j], hex[j+1]} has 4 colours iff both hexagon corners differ from
  // corners 0 and 7 and from each other
  bool off[6];
  for (int j = 0; j < 6; ++j) off[j] = c[hex[j]] != c[0] && c[hex[j]] != c[7];
  int tets = 0;
  for (int j = 0; j < 6; ++j) {
    const int k = j + 1 == 6 ? 0 : j + 1;
    if (off[j] && off[k] && c[hex[j]] != c[hex[k]]) tets |= 1 << j;
  }
  if (!tets) return 0;
  int lab[8];
  for (int v = 0; v < 8; ++v) {
    lab[v] = v;
    for (int u = 0; u < v; ++u)
      if (c[u] == c[v]) {
        lab[v] = u;
        break;
      }
  }
  std::uint64_t mask = 0;
  for (int j = 0; j < 6; ++j) {
    if (!(tets >> j & 1)) continue;
    const int l[4] = {lab[0], lab[7], lab[hex[j]], lab[hex[(j + 1) % 6]]};
    for (int e = 0; e < 6; ++e) {
      const int a = l[edge_vertex(e, 0)], b = l[edge_vertex(e, 1)];
      mask |= std::uint64_t(1) << (a < b ? 8 * a + b : 8 * b + a);
    }
  }
  int m = 0;  // at most C(8,2) = 28 colour pairs
  while (mask) {
    const int bit = lowest_bit(mask);
    mask &= mask - 1;
    const std::int32_t a = c[bit >> 3], b = c[bit & 7];
    local[m++] = a < b ? pack(a, b) : pack(b, a);
  }
  return m;
}

// Pairs a row remembers (the last kRowMemory it wrote) so that a pair found again in a
// nearby cube of the same row is not written twice: fewer raw pairs to sort (10^6
// uniform points, default W: 30.0 M raw pairs without, 22.9 M with 8, 22.6 M with 32;
// 8 costs little more scan time than none, 32 much more).
inline constexpr int kRowMemory = 8;

// Scan row r of cubes, (x, y, 0..W-2) with x = r mod (W-1), y = r div (W-1); count only
// when out is null. The count and write passes run the same deterministic code, so they
// agree. Neighbouring threads read neighbouring voxels (coalesced on the GPU). (Rows along
// x, contiguous for a CPU thread, measured only ~10 % faster on the CPU backend.)
GDEL_HD inline I64 scan_row(const std::int32_t* g, int W, I64 r, U64* out) {
  const I64 W2 = I64(W) * W;
  const I64 base = (r / (W - 1)) * W + r % (W - 1);  // cube (x, y, 0)
  std::int32_t c[8];
  U64 local[28];
  U64 recent[kRowMemory];
  int nrecent = 0, head = 0;
  I64 cnt = 0;
  for (int q = 0; q < 4; ++q) c[q] = g[base + (q & 1) + (q >> 1) * I64(W)];  // layer z = 0
  for (I64 t = 0; t + 1 < W; ++t) {
    const I64 b = base + (t + 1) * W2;  // layer z = t + 1; layer t is kept from the last step
    for (int q = 0; q < 4; ++q) c[4 + q] = g[b + (q & 1) + (q >> 1) * I64(W)];
    const int m = cube_pairs(c, local);
    for (int q = 0; q < m; ++q) {
      bool seen = false;
      for (int k = 0; k < nrecent && !seen; ++k) seen = recent[k] == local[q];
      if (seen) continue;
      if (out) out[cnt] = local[q];
      ++cnt;
      recent[head] = local[q];
      head = head + 1 == kRowMemory ? 0 : head + 1;
      if (nrecent < kRowMemory) ++nrecent;
    }
    for (int q = 0; q < 4; ++q) c[q] = c[4 + q];
  }
  return cnt;
}

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// CSR from sorted, unique directed keys (src<<32 | dst): offsets (n+1) and ids.
template <class B>
void keys_to_csr(par::Context<B>& ctx, const U64* keys, I64 m, I64 n, par::Buffer<I64, B>& offsets,
                 par::Buffer<vid_t, B>& ids) {
  offsets.resize_discard(static_cast<std::size_t>(n + 1));
  ids.resize_discard(static_cast<std::size_t>(m));
  I64* op = offsets.data();
  vid_t* ip = ids.data();
  par::parallel_for(ctx, m, [=] GDEL_LAMBDA(I64 j) {
    const I64 s = key_hi(keys[j]);
    const I64 sp = j == 0 ? -1 : I64(key_hi(keys[j - 1]));
    for (I64 t = sp + 1; t <= s; ++t) op[t] = j;
    ip[j] = key_lo(keys[j]);
  });
  I64 last = -1;
  if (m > 0) {
    U64 k;
    par::detail::Memory<B>::to_host(ctx, &k, keys + (m - 1), sizeof(U64));
    last = key_hi(k);
  }
  par::parallel_for(ctx, n + 1 - (last + 1), [=] GDEL_LAMBDA(I64 j) { op[last + 1 + j] = m; });
}

inline int key_bits(I64 n) {
  // keys hold ids < n in both halves: 32 + bit_width(n - 1) bits
  const std::uint64_t top = n > 1 ? std::uint64_t(n - 1) : 1;
  return 32 + static_cast<int>(std::bit_width(top));
}

}  // namespace ws_detail

template <class B>
WorkingSets<B> working_sets(par::Context<B>& ctx, const DigitalVoronoi<B>& dv, const WorkingSetOptions& opt = {}) {
  using namespace ws_detail;
  WorkingSets<B> out(ctx);
  WorkingSetStats& st = out.stats;
  const I64 n = static_cast<I64>(dv.voxel.size() / 3);
  const int W = dv.W;
  st.points = n;
  auto t_all = std::chrono::steady_clock::now();
  if (n == 0) {
    out.offsets.resize_discard(1);
    out.offsets.memset(0);
    return out;
  }
  const std::int32_t* g = dv.site.data();
  const std::int32_t* vox = dv.voxel.data();
  const int end_bit = key_bits(n);

  // a. missing points
  auto t0 = std::chrono::steady_clock::now();
  par::Buffer<I64, B> miss(ctx, static_cast<std::size_t>(n));
  I64* mp = miss.data();
  const I64 nmiss = static_cast<I64>(par::select_indices(ctx, static_cast<std::size_t>(n), mp, [=] GDEL_LAMBDA(I64 i) {
    const I64 k = (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i];
    return g[k] != static_cast<std::int32_t>(i);
  }));
  st.missing_points = nmiss;
  st.t_missing = seconds_since(t0);

  // b. grid scan: count, scan, write
  t0 = std::chrono::steady_clock::now();
  const I64 R = W >= 2 ? I64(W - 1) * (W - 1) : 0;
  par::Buffer<I64, B> rows(ctx, static_cast<std::size_t>(R + 1));
  I64* rp = rows.data();
  par::parallel_for(ctx, R, [=] GDEL_LAMBDA(I64 r) {
    rp[r] = scan_row(g, W, r, nullptr);
  });
  const I64 ngrid = par::counts_to_offsets(ctx, rp, static_cast<std::size_t>(R));
  st.grid_pairs = ngrid;
  st.raw_pairs = ngrid + nmiss;
  par::Buffer<U64, B> keys(ctx, static_cast<std::size_t>(ngrid + nmiss));
  U64* kp = keys.data();
  par::parallel_for(ctx, R, [=] GDEL_LAMBDA(I64 r) {
    scan_row(g, W, r, kp + rp[r]);
  });
  par::parallel_for(ctx, nmiss, [=] GDEL_LAMBDA(I64 j) {
    const I64 i = mp[j];
    const I64 k = (I64(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i];
    const std::int32_t o = g[k];
    const std::int32_t a = static_cast<std::int32_t>(i);
    kp[ngrid + j] = a < o ? pack(a, o) : pack(o, a);
  });
  miss.release();
  rows.release();
  ctx.synchronize();
  st.t_scan = seconds_since(t0);

  // c. sort + unique, reciprocate, CSR
  t0 = std::chrono::steady_clock::now();
  const I64 nraw = ngrid + nmiss;
  par::sort_keys(ctx, kp, static_cast<std::size_t>(nraw), end_bit);
  const I64 nu = static_cast<I64>(par::unique(ctx, kp, static_cast<std::size_t>(nraw)));
  st.unique_pairs = nu;
  par::Buffer<U64, B> dir(ctx, static_cast<std::size_t>(2 * nu));
  U64* dp = dir.data();
  par::parallel_for(ctx, nu, [=] GDEL_LAMBDA(I64 j) {
    const U64 k = kp[j];
    dp[2 * j] = k;
    dp[2 * j + 1] = pack(key_lo(k), key_hi(k));
  });
  keys.release();
  par::sort_keys(ctx, dp, static_cast<std::size_t>(2 * nu), end_bit);
  ctx.synchronize();
  st.t_sort = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  keys_to_csr(ctx, dp, 2 * nu, n, out.offsets, out.ids);
  dir.release();
  ctx.synchronize();
  st.t_csr = seconds_since(t0);

  // d. pumping
  t0 = std::chrono::steady_clock::now();
  const I64 K = std::min<I64>(std::max(opt.min_candidates, 0), n - 1);
  par::Buffer<I64, B> need(ctx, static_cast<std::size_t>(n + 1));
  I64* np = need.data();
  {
    const I64* op = out.offsets.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
      const I64 d = op[i + 1] - op[i];
      np[i] = d < K ? K - d : 0;
    });
  }
  {
    par::Buffer<I64, B> flag(ctx, static_cast<std::size_t>(n));
    I64* fp = flag.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) { fp[i] = np[i] > 0 ? 1 : 0; });
    st.pumped_points = par::reduce_sum(ctx, fp, static_cast<std::size_t>(n));
  }
  const I64 npump = par::counts_to_offsets(ctx, np, static_cast<std::size_t>(n));
  st.pumped_pairs = npump;
  if (npump > 0) {
    par::Buffer<vid_t, B> got(ctx, static_cast<std::size_t>(npump));
    vid_t* gp = got.data();
    const I64* op = out.offsets.data();
    const vid_t* ip = out.ids.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
      const I64 want = np[i + 1] - np[i];
      if (want == 0) return;
      vid_t* q = gp + np[i];
      I64 added = 0;
      const I64 b = op[i], e = op[i + 1];
      const vid_t self = static_cast<vid_t>(i);
      auto fresh = [&](vid_t x) {
        if (x == self) return false;
        // already a candidate of i?
        I64 lo = b, hi = e;
        while (lo < hi) {
          const I64 m = lo + (hi - lo) / 2;
          if (ip[m] < x)
            lo = m + 1;
          else
            hi = m;
        }
        if (lo < e && ip[lo] == x) return false;
        for (I64 t = 0; t < added; ++t)
          if (q[t] == x) return false;
        return true;
      };
      // the `want` nearest candidates of candidates: (squared voxel distance, id), q sorted
      const std::int32_t* vi = vox + 3 * i;
      auto d2 = [&](vid_t x) {
        const std::int32_t* v = vox + 3 * I64(x);
        const I64 dx = v[0] - vi[0], dy = v[1] - vi[1], dz = v[2] - vi[2];
        return dx * dx + dy * dy + dz * dz;
      };
      for (I64 j = b; j < e; ++j) {
        const vid_t c = ip[j];
        for (I64 l = op[c]; l < op[c + 1]; ++l) {
          const vid_t x = ip[l];
          if (!fresh(x)) continue;
          const I64 dx = d2(x);
          I64 p = added < want ? added : want - 1;
          if (added == want) {
            const I64 dl = d2(q[p]);
            if (dx > dl || (dx == dl && x > q[p])) continue;  // not nearer than the farthest kept
          } else {
            ++added;
          }
          while (p > 0) {
            const I64 dp = d2(q[p - 1]);
            if (dp < dx || (dp == dx && q[p - 1] < x)) break;
            q[p] = q[p - 1];
            --p;
          }
          q[p] = x;
        }
      }
      for (I64 d = 1; added < want && d < n; ++d) {
        if (i + d < n && fresh(static_cast<vid_t>(i + d))) q[added++] = static_cast<vid_t>(i + d);
        if (added < want && i - d >= 0 && fresh(static_cast<vid_t>(i - d))) q[added++] = static_cast<vid_t>(i - d);
      }
    });
    // pumped pairs, both directions; a pumped x is not in list(i), so (by symmetry) both
    // directions are new: sort + unique them alone and merge them into the lists.
    par::Buffer<U64, B> add(ctx, static_cast<std::size_t>(2 * npump));
    U64* ap = add.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {
      for (I64 t = np[i]; t < np[i + 1]; ++t) {
        const std::int32_t a = static_cast<std::int32_t>(i), x = gp[t];
        ap[2 * t] = pack(a, x);
        ap[2 * t + 1] = pack(x, a);
      }
    });
    got.release();
    par::sort_keys(ctx, ap, static_cast<std::size_t>(2 * npump), end_bit);
    const I64 ma = static_cast<I64>(par::unique(ctx, ap, static_cast<std::size_t>(2 * npump)));
    par::Buffer<I64, B> aoff(ctx);
    par::Buffer<vid_t, B> aids(ctx);
    keys_to_csr(ctx, ap, ma, n, aoff, aids);
    add.release();
    const I64 m0 = static_cast<I64>(out.ids.size());
    par::Buffer<I64, B> noff(ctx, static_cast<std::size_t>(n + 1));
    par::Buffer<vid_t, B> nids(ctx, static_cast<std::size_t>(m0 + ma));
    I64* nop = noff.data();
    vid_t* nip = nids.data();
    const I64* aop = aoff.data();
    const vid_t* aip = aids.data();
    par::parallel_for(ctx, n + 1, [=] GDEL_LAMBDA(I64 i) { nop[i] = op[i] + aop[i]; });
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) {  // merge two sorted disjoint lists
      I64 u = op[i], ue = op[i + 1], v = aop[i], ve = aop[i + 1], w = op[i] + aop[i];
      while (u < ue && v < ve) nip[w++] = ip[u] < aip[v] ? ip[u++] : aip[v++];
      while (u < ue) nip[w++] = ip[u++];
      while (v < ve) nip[w++] = aip[v++];
    });
    out.offsets = std::move(noff);
    out.ids = std::move(nids);
  }
  ctx.synchronize();
  st.t_pump = seconds_since(t0);
  st.directed_pairs = static_cast<I64>(out.ids.size());
  st.t_total = seconds_since(t_all);
  return out;
}

}  // namespace gdel::star4d
