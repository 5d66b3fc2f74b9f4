// gStar4D (ALGORITHMS.md §5), all five stages, written once over the backend tag B:
//
//   1. digital Voronoi diagram of the points on a W³ grid (pba.hpp, Parallel Banding);
//   2. working sets: candidate neighbours from the grid (working_sets.hpp);
//   3-5. stars, splaying, lower-hull tets with adjacency (star_stage.hpp).
//
// Input: the m distinct points in internal (Hilbert) order with their SoS indices, slot
// m reserved for ∞'s kernel point (set here: the same seed as gFlip3D, which also
// raises DegenerateInput for coplanar input). Output: tets in internal ids, positive,
// neighbours (-1 on the hull). The API certifies the result with the exact verifier
// (api/delaunay_impl.hpp): star splaying's local rules cannot see a globally wrong but
// locally consistent set of stars (star_stage.hpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "flip/gflip3d.hpp"
#include "gdel/delaunay.hpp"
#include "star4d/pba.hpp"
#include "star4d/star_stage.hpp"
#include "star4d/working_sets.hpp"

namespace gdel::star4d {

// Weighted points (gReg3D, ALGORITHMS.md §6): `weights` holds m + 1 weights in internal
// order (nullptr: Delaunay). The digital Voronoi diagram and the working sets ignore the
// weights (they only propose candidates); the stars use the power lifting, and a star
// whose point turns out redundant dies (splay/star.hpp). `deaths` (if given) receives a
// death certificate per dead star: (star vertex, killer, e, t0, t1, t2), internal ids.
template <class B>
void gstar4d(Context<B>& ctx, Buffer<double, B>& P, Buffer<std::int64_t, B>& sid, I64 m, const double* lo,
             const double* hi, const Options& opt, Stats& st, Buffer<vid_t, B>& tets, Buffer<std::int32_t, B>& nbr,
             const double* weights = nullptr, std::vector<vid_t>* deaths = nullptr) {
  const char* name = weights ? "greg3d" : "gstar4d";
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  auto t0 = std::chrono::steady_clock::now();
  vid_t first[4];
  flip::Geo kg{};  // the seed's ∞: K in slot m, or the exact centroid of kg.kq (Geo::k_centroid)
  {
    flip::GFlip3D<B> seed(ctx, P, sid, m, flip::FlipConfig{}, st);
    seed.first_tetrahedron(first);  // degeneracy check + kernel point (slot m)
    kg = seed.geo();
  }
  if (m == 4) {
    // Four affinely independent points: their (regular) triangulation is that one
    // tetrahedron, and no point is redundant (none lies in the hull of the others). A 4-D
    // star needs five points, so the stages below cannot run.
    const std::int32_t none[4] = {-1, -1, -1, -1};
    tets.assign(first, 4);
    nbr.assign(none, 4);
    st.stages.push_back({std::string(name) + " single tetrahedron", since(t0)});
    return;
  }
  WorkingSets<B> ws = [&] {
    PbaOptions po;
    po.grid = opt.grid;
    DigitalVoronoi<B> dv = digital_voronoi(ctx, P.data(), m, lo, hi, po);  // freed on return
    st.grid = dv.W;
    ctx.synchronize();
    st.stages.push_back({std::string(name) + " digital Voronoi (PBA)", since(t0)});
    t0 = std::chrono::steady_clock::now();
    WorkingSetOptions wo;
    wo.min_candidates = opt.min_candidates;
    WorkingSets<B> w = working_sets(ctx, dv, wo);
    ctx.synchronize();
    st.stages.push_back({std::string(name) + " working sets", since(t0)});
    return w;
  }();
  st.working_set_pairs = static_cast<I64>(ws.ids.size());
  t0 = std::chrono::steady_clock::now();
  // integer input: exact evaluations without a scratch (flip::Geo::int_points / int_all;
  // slot m holds the kernel point, weights[m] its weight)
  const bool int_points = flip::all_integer_points(ctx, P.data(), weights, m);
  const bool int_all =
      !kg.k_centroid && flip::all_integer_points(ctx, P.data(), weights, m + 1, geom::kQuarterScale);
  flip::Geo g{P.data(), sid.data(), static_cast<vid_t>(m), weights, int_points, int_all};
  g.take_kernel_point(kg);
  StarStage<B> stage(ctx, g, m);
  stage.splay(ws.offsets.data(), ws.ids.data());
  ctx.synchronize();
  st.stages.push_back({std::string(name) + " stars + splaying", since(t0)});
  t0 = std::chrono::steady_clock::now();
  stage.extract(tets, nbr);
  ctx.synchronize();
  st.stages.push_back({std::string(name) + " tets", since(t0)});
  const auto& r = stage.result();
  st.stars_built = r.stars;
  st.splay_rounds = r.splay.rounds;
  st.splay_insertions = r.splay.insertions;
  st.flat_tets_removed = r.flat_removed;
  st.dead_stars = r.splay.dead;
  if (deaths) *deaths = stage.splayer().death_certificates();
  st.exact_evaluations += r.exact_evaluations;
}

}  // namespace gdel::star4d
