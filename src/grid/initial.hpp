// Options::initial = grid for gFlip3D / gDel3D: start the insertion and flipping rounds
// from the Delaunay triangulation of a grid sample instead of from one tetrahedron
// (ALGORITHMS.md §7, thesis ch. 5: "a better quality triangulation as input to massively
// parallel flipping"). Written once over the backend tag B. docs/grid.md has the measured
// figures and the reasons.
//
// ---------------------------------------------------------------------------------
// Steps (all on the backend; every combinatorial decision an exact predicate)
//   1. sample: on a coarse grid (side W = the smallest with W³ ≥ m / kPointsPerSite;
//      Options::grid overrides it) the owner of each occupied voxel (its smallest internal
//      id, as PBA seeds) is a *site*. (At this density nearly every voxel holds a site, so
//      the coarse colouring itself carries no more than the grid: the sites get a finer
//      one below.)
//   2. the sites' digital Voronoi diagram on gStar4D's grid (about 8 voxels per site,
//      star4d PBA) and its raw dual (dual.hpp): Kuhn tets → site tets, classified
//      exactly; the counts go to Stats (the measured negative results). A sample with
//      many exact ties (flat dual tets or cospherical dual pairs ≥ kDegenerateShare of
//      the dual tets: lattice-like or cospherical input) is not used — gStar4D's star
//      splaying is slow on such input (exact ties in every test) (docs/gstar4d.md) —
//      and the default start is taken instead.
//   3. the sites' exact Delaunay triangulation from the dual by star splaying: gStar4D
//      (star4d::gstar4d) on the sites with that same grid, so its working sets are the
//      dual's edges (+ pumping); certified by the exact verifier (valid, locally
//      Delaunay, no flat tet), else the default start is taken.
//   4. gFlip3D's mesh: the finite tets in internal ids, one cone (face, ∞) per hull
//      facet, adjacency (finite faces from gStar4D; cone sides by sorting hull edges);
//      the kernel point K of the sites (strictly inside their first tetrahedron, hence
//      inside their hull) becomes the full problem's K.
//   5. every other point is located by a walk from a tet of its voxel's site: in the
//      current tet, the first face (from a start that depends on the point and the step)
//      whose plane separates the point from the tet is crossed; fast filter first,
//      exact + SoS for the undecided points. Visibility walks terminate in a Delaunay
//      triangulation; the cones to ∞ are not Delaunay, so a walk is capped
//      (kMaxWalkSteps) and a capped walk makes the whole start fall back to the default
//      one (never observed).
//   6. GFlip3D::init_from hands the mesh and the located points to gFlip3D, which inserts
//      and flips from there. gDel3D's repair runs unchanged afterwards.
// A fallback leaves the GFlip3D object untouched (its own init() runs), records
// Stats::grid_fallbacks = 1 and names the reason in Stats::stages.
//
// Simplifications against the thesis (whose ch. 5 bodies we do not have): the dual is
// not turned into a triangulation by itself (the negative results say it is not one);
// star splaying repairs it, as gStar4D does from the same grid. The sample rule
// (voxel owners of a grid at kPointsPerSite points per voxel) is ours.
#pragma once

#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "flip/gflip3d.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "grid/dual.hpp"
#include "star4d/gstar4d.hpp"
#include "star4d/pba.hpp"
#include "verify/verify_impl.hpp"

namespace gdel::grid {

// Points per coarse voxel (the sample is about one site per kPointsPerSite points on
// uniform input). Our choice; docs/grid.md has the measured outcome.
inline constexpr double kPointsPerSite = 16.0;
// A sample whose dual has at least this share of exact ties is not used (step 2).
inline constexpr double kDegenerateShare = 0.01;
// Cap of one location walk (step 5).
inline constexpr int kMaxWalkSteps = 1 << 16;

// The coarse grid side for m points (at least 2: a grid of one voxel has no cube).
inline int coarse_grid_size(std::int64_t m, double points_per_site = kPointsPerSite) {
  const double target = static_cast<double>(m) / points_per_site;
  int W = std::max(2, static_cast<int>(std::cbrt(target)));
  while (static_cast<double>(W) * W * W < target) ++W;
  while (W > 2 && static_cast<double>(W - 1) * (W - 1) * (W - 1) >= target) --W;
  return W;
}

// The tet holding q, walking from tet t (see step 5): the tet, kUndecidedResult when a
// fast test could not decide, or -3 when the walk reached kMaxWalkSteps.
template <bool Exact>
GDEL_HD tid_t locate_walk(const flip::Geo& g, const mesh::MeshView& m, tid_t t, vid_t q, double* work) {
  int entry = -1;  // face of t we came through (q is known to be beyond the others' side of it)
  for (int step = 0; step < kMaxWalkSteps; ++step) {
    const vid_t* v = m.tet[t].v;
    std::uint32_t h = static_cast<std::uint32_t>(q) * 0x9E3779B1u + static_cast<std::uint32_t>(step) * 0x85EBCA77u;
    h ^= h >> 15;
    const int start = static_cast<int>(h & 3);
    int exit = -1;
    for (int r = 0; r < 4 && exit < 0; ++r) {
      const int i = (start + r) & 3;
      if (i == entry) continue;
      const int s = g.orient<Exact>(v[face_vertex(i, 0)], v[face_vertex(i, 1)], v[face_vertex(i, 2)], q, work);
      if (s == par::kUndecided) return flip::kUndecidedResult;
      if (s < 0) exit = i;
    }
    if (exit < 0) return t;
    const fid_t o = m.opp(4 * std::int64_t(t) + exit);
    t = facet_tet(o);
    entry = facet_face(o);
  }
  return -3;
}

namespace initial_detail {

inline double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace initial_detail

// Tries the grid start (steps 1–6). True when gFlip3D was initialised from it; false after
// a fallback (alg untouched; its run() starts from the first tetrahedron).
template <class B>
bool grid_initial(par::Context<B>& ctx, flip::GFlip3D<B>& alg, par::Buffer<double, B>& P,
                  par::Buffer<std::int64_t, B>& sid, std::int64_t m, const double* lo, const double* hi,
                  const Options& opt, Stats& st) {
  using initial_detail::since;
  using par::Buffer;
  auto t0 = std::chrono::steady_clock::now();
  auto fallback = [&](const std::string& why) {
    st.grid_fallbacks = 1;
    st.stages.push_back({"grid initial not used (" + why + "): first tetrahedron", 0.0});
    return false;
  };

  // 1. coarse grid, digital Voronoi diagram, sites
  const int W = opt.grid > 0 ? opt.grid : coarse_grid_size(m);
  star4d::PbaOptions po;
  po.grid = W;
  star4d::DigitalVoronoi<B> dv = star4d::digital_voronoi(ctx, P.data(), m, lo, hi, po);
  st.grid = W;
  const std::int32_t* site = dv.site.data();
  const std::int32_t* vox = dv.voxel.data();
  auto voxel_of = [=] GDEL_LAMBDA(std::int64_t i) {
    return (std::int64_t(vox[3 * i + 2]) * W + vox[3 * i + 1]) * W + vox[3 * i];
  };
  Buffer<vid_t, B> S(ctx, static_cast<std::size_t>(m));  // the sites, ascending internal ids
  std::int64_t k = static_cast<std::int64_t>(par::select_indices(
      ctx, static_cast<std::size_t>(m), S.data(), [=] GDEL_LAMBDA(vid_t i) { return site[voxel_of(i)] == i; }));
  S.resize(static_cast<std::size_t>(k));
  st.grid_sites = k;
  st.stages.push_back({"grid initial: sample (coarse grid " + std::to_string(W) + "^3)", since(t0)});

  if (k < 5) return fallback("fewer than 5 sites");

  // 2. the sites' digital Voronoi diagram (gStar4D's grid rule: about 8 voxels per site)
  //    and its raw dual, classified exactly
  t0 = std::chrono::steady_clock::now();
  Buffer<double, B> Ps(ctx, static_cast<std::size_t>(3 * (k + 1)));
  Buffer<std::int64_t, B> sids(ctx, static_cast<std::size_t>(k + 1));
  {
    double* pp = Ps.data();
    std::int64_t* sp = sids.data();
    const double* X = P.data();
    const std::int64_t* sd = sid.data();
    const vid_t* Sp = S.data();
    par::parallel_for(ctx, k, [=] GDEL_LAMBDA(std::int64_t j) {
      for (int a = 0; a < 3; ++a) pp[3 * j + a] = X[3 * std::int64_t(Sp[j]) + a];
      sp[j] = sd[Sp[j]];
    });
    par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { sp[k] = sd[m]; });
  }
  int Wf = 0;
  Dual<B> dual = [&] {
    star4d::DigitalVoronoi<B> fine = star4d::digital_voronoi(ctx, Ps.data(), k, lo, hi, star4d::PbaOptions{});
    Wf = fine.W;
    return dual_of_colouring(ctx, fine.site.data(), Wf, Ps.data());
  }();
  const DualStats& ds = dual.stats;
  st.dual_tets = ds.tets;
  st.dual_flat = ds.flat;
  st.dual_inverted = ds.inverted;
  st.dual_folded = ds.folded;
  st.dual_overshared_facets = ds.overshared_facets;
  st.dual_overlapping_facets = ds.overlapping_facets;
  st.dual_cospherical_pairs = ds.cospherical_pairs;
  st.dual_non_delaunay_pairs = ds.non_delaunay_pairs;
  st.stages.push_back({"grid initial: sites' digital Voronoi diagram (" + std::to_string(Wf) +
                           "^3) and its dual (exact classification)",
                       since(t0)});
  if (static_cast<double>(ds.flat + ds.cospherical_pairs) >= kDegenerateShare * static_cast<double>(ds.tets))
    return fallback("degenerate sample: " + std::to_string(ds.flat) + " flat dual tets, " +
                    std::to_string(ds.cospherical_pairs) + " cospherical dual pairs of " + std::to_string(ds.tets));

  // 3. the sites' Delaunay triangulation by star splaying from the same grid
  t0 = std::chrono::steady_clock::now();
  Buffer<vid_t, B> tv(ctx);
  Buffer<std::int32_t, B> tn(ctx);
  Stats sub;
  Options so = opt;
  so.grid = Wf;
  try {
    star4d::gstar4d(ctx, Ps, sids, k, lo, hi, so, sub, tv, tn);
  } catch (const DegenerateInput&) {
    return fallback("the sites are coplanar");
  }
  if (sub.kernel_point_centroid)  // (K would be copied below as a double: none is inside)
    return fallback("no double lies inside the sites' first tetrahedron");
  st.stages.push_back({"grid initial: sites' triangulation (gStar4D from the grid)", since(t0)});
  const std::int64_t nt = static_cast<std::int64_t>(tv.size() / 4);
  t0 = std::chrono::steady_clock::now();
  {
    std::vector<double> hx(static_cast<std::size_t>(3 * k));
    Ps.copy_to_host(hx.data(), hx.size());
    const std::vector<vid_t> ht = tv.to_host();
    const VerifyReport r = verify_detail::run(ctx, hx.data(), k, ht.data(), nt, nullptr);
    if (!r.delaunay() || r.degenerate_tets != 0) return fallback("the sites' triangulation failed its certificate");
  }
  st.stages.push_back({"grid initial: certificate (exact verifier)", since(t0)});

  st.dual_delaunay_tets = dual.compare(tv.data(), nt);
  st.dual_missed_delaunay_tets = nt - st.dual_delaunay_tets;

  // 4. gFlip3D's mesh: finite tets (internal ids), cones to ∞, adjacency
  t0 = std::chrono::steady_clock::now();
  const vid_t inf = static_cast<vid_t>(m);
  {
    vid_t* tp = tv.data();
    const vid_t* Sp = S.data();
    par::parallel_for(ctx, 4 * nt, [=] GDEL_LAMBDA(std::int64_t i) { tp[i] = Sp[tp[i]]; });
  }
  Buffer<std::int64_t, B> hull(ctx, static_cast<std::size_t>(4 * nt + 1));
  std::int64_t* hp = hull.data();
  const std::int32_t* np = tn.data();
  par::parallel_for(ctx, 4 * nt, [=] GDEL_LAMBDA(std::int64_t f) { hp[f] = np[f] < 0 ? 1 : 0; });
  const std::int64_t nh = par::counts_to_offsets(ctx, hp, static_cast<std::size_t>(4 * nt));
  const std::int64_t ntot = nt + nh;
  Buffer<mesh::Tet, B> tets(ctx, static_cast<std::size_t>(ntot));
  Buffer<fid_t, B> opp(ctx, static_cast<std::size_t>(4 * ntot));
  mesh::Tet* T = tets.data();
  fid_t* O = opp.data();
  const vid_t* tp = tv.data();
  par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(std::int64_t t) {
    for (int i = 0; i < 4; ++i) T[t].v[i] = tp[4 * t + i];
    for (int i = 0; i < 4; ++i) {
      const std::int64_t f = 4 * t + i;
      const std::int32_t u = np[f];
      if (u < 0) {
        // the cone over hull facet i: (facet reversed, ∞); its face 3 faces back here
        const std::int64_t c = nt + hp[f];
        T[c].v[0] = tp[4 * t + face_vertex(i, 0)];
        T[c].v[1] = tp[4 * t + face_vertex(i, 2)];
        T[c].v[2] = tp[4 * t + face_vertex(i, 1)];
        T[c].v[3] = inf;
        O[4 * t + i] = pack_facet(static_cast<tid_t>(c), 3);
        O[4 * c + 3] = pack_facet(static_cast<tid_t>(t), i);
        continue;
      }
      // the neighbour's face opposite its vertex that is not in this tet
      int j = 0;
      for (int l = 0; l < 4; ++l) {
        const vid_t x = tp[4 * std::int64_t(u) + l];
        if (x != tp[4 * t] && x != tp[4 * t + 1] && x != tp[4 * t + 2] && x != tp[4 * t + 3]) j = l;
      }
      O[4 * t + i] = pack_facet(u, j);
    }
  });
  if (nh > 0) {
    // cone sides: face l < 3 of a cone holds ∞ and the hull edge without corner l; the two
    // cones over the hull facets sharing that edge are neighbours there
    Buffer<std::uint64_t, B> ek(ctx, static_cast<std::size_t>(3 * nh));
    Buffer<fid_t, B> ev(ctx, static_cast<std::size_t>(3 * nh));
    std::uint64_t* ekp = ek.data();
    fid_t* evp = ev.data();
    par::parallel_for(ctx, nh, [=] GDEL_LAMBDA(std::int64_t h) {
      const std::int64_t c = nt + h;
      for (int l = 0; l < 3; ++l) {
        const vid_t a = T[c].v[(l + 1) % 3], b = T[c].v[(l + 2) % 3];
        const vid_t x = a < b ? a : b, y = a < b ? b : a;
        ekp[3 * h + l] = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
        evp[3 * h + l] = pack_facet(static_cast<tid_t>(c), l);
      }
    });
    par::sort_pairs(ctx, ekp, evp, static_cast<std::size_t>(3 * nh));
    Buffer<std::int64_t, B> bad(ctx, static_cast<std::size_t>(3 * nh / 2 + 1));
    std::int64_t* bp = bad.data();
    const std::int64_t ne = 3 * nh / 2;
    par::parallel_for(ctx, ne, [=] GDEL_LAMBDA(std::int64_t e) {
      // a closed hull has every edge in exactly two hull facets (the certificate checked it)
      const bool ok = ekp[2 * e] == ekp[2 * e + 1] && (e == 0 || ekp[2 * e - 1] != ekp[2 * e]);
      bp[e] = ok ? 0 : 1;
      O[4 * std::int64_t(facet_tet(evp[2 * e])) + facet_face(evp[2 * e])] = evp[2 * e + 1];
      O[4 * std::int64_t(facet_tet(evp[2 * e + 1])) + facet_face(evp[2 * e + 1])] = evp[2 * e];
    });
    if ((3 * nh) % 2 != 0 || par::reduce_sum(ctx, bp, static_cast<std::size_t>(ne)) != 0)
      return fallback("the sites' hull is not a closed surface");
  }
  // K: the sites' kernel point (inside their first tetrahedron, so inside their hull)
  for (int a = 0; a < 3; ++a) P.set(static_cast<std::size_t>(3 * m + a), Ps.get(static_cast<std::size_t>(3 * k + a)));
  st.stages.push_back({"grid initial: gFlip3D mesh (cones to infinity, adjacency)", since(t0)});

  // 5. locate the other points by walks from their voxel's site
  t0 = std::chrono::steady_clock::now();
  Buffer<tid_t, B> vstart(ctx, static_cast<std::size_t>(m));
  tid_t* vs = vstart.data();
  par::fill(ctx, vs, static_cast<std::size_t>(m), tid_t(INT_MAX));
  par::parallel_for(ctx, ntot, [=] GDEL_LAMBDA(std::int64_t t) {
    for (int i = 0; i < 4; ++i)
      if (T[t].v[i] != inf) par::atomic_min(vs + T[t].v[i], static_cast<tid_t>(t));
  });
  Buffer<tid_t, B> vert_tet(ctx, static_cast<std::size_t>(m));
  tid_t* vt = vert_tet.data();
  Buffer<std::uint8_t, B> state(ctx, static_cast<std::size_t>(ntot));
  par::fill(ctx, state.data(), static_cast<std::size_t>(ntot), std::uint8_t(mesh::kAlive));
  // the mesh in gFlip3D's layout (records of vertices and neighbour tets; flags clear)
  // for the walks
  Buffer<mesh::TetRec, B> rec(ctx, static_cast<std::size_t>(ntot));
  const mesh::MeshView mv(rec.data(), state.data());
  par::parallel_for(ctx, ntot, [=] GDEL_LAMBDA(std::int64_t t) {
    mv.tet[t] = T[t];
    for (int i = 0; i < 4; ++i) mv.set_opp(4 * t + i, O[4 * t + i]);
  });
  const flip::Geo g = alg.geo();
  auto locate = [=] GDEL_LAMBDA(std::int64_t q, double* work, bool exact) -> bool {
    const vid_t s = site[voxel_of(q)];
    if (s == static_cast<vid_t>(q)) {
      vt[q] = -1;  // a vertex of the mesh
      return true;
    }
    const tid_t t = exact ? locate_walk<true>(g, mv, vs[s], vid_t(q), work)
                          : locate_walk<false>(g, mv, vs[s], vid_t(q), work);
    if (t == flip::kUndecidedResult) return false;
    vt[q] = t;  // -3: the walk was capped
    return true;
  };
  Buffer<std::int8_t, B> und(ctx, static_cast<std::size_t>(m));
  st.exact_evaluations += flip::fast_then_exact(
      ctx, g, m, und.data(), [=] GDEL_LAMBDA(std::int64_t q) { return locate(q, nullptr, false); },
      [=] GDEL_LAMBDA(std::int64_t q, double* work) { return locate(q, work, true); });
  Buffer<vid_t, B> todo(ctx, static_cast<std::size_t>(m));
  std::int64_t nu = static_cast<std::int64_t>(
      par::select_indices(ctx, static_cast<std::size_t>(m), todo.data(), [=] GDEL_LAMBDA(vid_t q) { return vt[q] != -1; }));
  todo.resize(static_cast<std::size_t>(nu));
  {
    const vid_t* up = todo.data();
    Buffer<std::int64_t, B> capped(ctx, static_cast<std::size_t>(std::max<std::int64_t>(nu, 1)));
    std::int64_t* cp = capped.data();
    par::parallel_for(ctx, nu, [=] GDEL_LAMBDA(std::int64_t i) { cp[i] = vt[up[i]] < 0 ? 1 : 0; });
    if (par::reduce_sum(ctx, cp, static_cast<std::size_t>(nu)) != 0) return fallback("a location walk was capped");
  }
  st.stages.push_back({"grid initial: point location (walks)", since(t0)});

  // 6. hand over
  alg.init_from(tets, opp, ntot, std::move(vert_tet), std::move(todo));
  return true;
}

}  // namespace gdel::grid
