// gdel::delaunay on one backend: validation → duplicate removal → Hilbert sort →
// algorithm → output in input ids. Written once over the backend tag.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include "api/prepare.hpp"
#include "flip/gflip3d.hpp"
#include "grid/initial.hpp"
#include "parallel/host_threads.hpp"
#include "splay/gdel3d.hpp"
#include "star4d/gstar4d.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "sort/point_sort.hpp"

namespace gdel::api {

using par::Buffer;
using par::Context;

// Where delaunay_into() reads the points and leaves the results. HostOutput (what
// gdel::delaunay uses): the points are host memory, uploaded once; results are copied to
// the Triangulation's vectors. The device entry point (delaunay_cuda.cu) passes one that
// reads device memory in place and keeps the results on the device.
struct HostOutput {
  template <class B>
  const double* input(Buffer<double, B>& X, std::span<const double> points) {
    X.assign(points.data(), points.size());
    return X.data();
  }
  template <class B>
  void representative(Context<B>&, const Buffer<std::int64_t, B>& rep, std::int64_t n, Triangulation& out) {
    auto r = rep.to_host();
    out.representative.resize(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) out.representative[i] = static_cast<std::int32_t>(r[i]);
  }
  template <class B>
  void failed_vertices(Context<B>&, const Buffer<std::int64_t, B>& fl, std::size_t nfv,
                       const Buffer<std::int64_t, B>& sid, Triangulation& out) {
    auto flh = fl.to_host();
    auto sidh = sid.to_host();
    out.failed_vertices.reserve(nfv);
    for (std::size_t k = 0; k < nfv; ++k) out.failed_vertices.push_back(static_cast<std::int32_t>(sidh[flh[k]]));
    std::sort(out.failed_vertices.begin(), out.failed_vertices.end());
  }
  template <class B>
  void tets(Buffer<std::int32_t, B>& tv, Buffer<std::int32_t, B>& tn, Triangulation& out) {
    out.tets = tv.to_host();
    out.neighbors = tn.to_host();
  }
  // Host backends: an extraction that writes the results into the Triangulation's arrays
  // itself (SequentialInsertion::extract's room), with nothing to copy after. The two
  // arrays are made on two threads: most of their time is their pages' first touch.
  auto room(Triangulation& out) {
    return [&out](std::int64_t k) {
      par::on_host_threads(2, [&](std::size_t j) { (j == 0 ? out.tets : out.neighbors).resize(static_cast<std::size_t>(4 * k)); });
      return std::pair<vid_t*, std::int32_t*>{out.tets.data(), out.neighbors.data()};
    };
  }
};

// GDEL_PROFILE: the step profile of this call to stderr (parallel/profile.hpp).
template <class B>
void report_profile(Context<B>& ctx, const Stats& st) {
  if (!ctx.profiling()) return;
  std::fprintf(stderr, "gdel profile (%s on %s, %lld points):\n%s", st.algorithm.c_str(), st.backend.c_str(),
               static_cast<long long>(st.points), par::format_profile(ctx.profile_report()).c_str());
}

// FlipConfig::sequential: on host backends, unless Options ask for the parallel rounds.
template <class B>
bool one_point_per_round(const Options& opt) {
  return !B::is_device && !opt.cpu_rounds && !opt.terminal_flipping && !opt.nonoptimal_flips &&
         !opt.independent_splits && opt.insertion == InsertionRule::Circumcenter &&
         opt.initial == Initial::Default;
}

template <class B, class Out>
Triangulation delaunay_into(Context<B>& ctx, std::span<const double> points, const Options& opt, Out& sink) {
  using I64 = std::int64_t;
  auto t_start = std::chrono::steady_clock::now();
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  Triangulation out;
  Stats& st = out.stats;
  st.backend = B::name;
  const bool exact = opt.algorithm != Algorithm::gflip3d;
  st.algorithm = opt.algorithm == Algorithm::gstar4d ? "gstar4d" : exact ? "gdel3d" : "gflip3d";
  const I64 n = static_cast<I64>(points.size() / 3);
  st.points = n;
  // finished: the output stage's time (from t_out), the run's totals; finish: the results
  // to the caller first
  auto finished = [&](auto t_out) {
    st.stages.push_back({"output", since(t_out)});
    st.peak_bytes = static_cast<I64>(ctx.memory().peak());
    st.seconds = since(t_start);
    report_profile(ctx, st);
  };
  auto finish = [&](Buffer<vid_t, B>& tv, Buffer<std::int32_t, B>& tn, auto t_out) {
    sink.tets(tv, tn, out);
    par::mark(ctx, "output: results to caller");
    finished(t_out);
  };

  // --- prepare: upload, duplicates, spatial order ------------------------------------
  auto t0 = std::chrono::steady_clock::now();
  Buffer<double, B> X(ctx);
  const double* xp = sink.input(X, points);
  // duplicates, bounding box, internal (Hilbert) order; slot m = ∞ / kernel point
  Prepared<B> pr(ctx);
  ctx.profile_start();
  prepare_points(ctx, xp, n, nullptr, pr);  // DegenerateInput with fewer than 4 distinct points
  X.release();                              // the upload (HostOutput): prepare made its sorted copy
  const I64 m = pr.m;
  st.distinct_points = m;
  sink.representative(ctx, pr.rep, n, out);
  Buffer<double, B>& P = pr.P;
  Buffer<I64, B>& sid = pr.sid;
  const double* lo = pr.lo;
  const double* hi = pr.hi;
  st.stages.push_back({"prepare (duplicates, Hilbert sort)", since(t0)});
  par::mark(ctx, "prepare (duplicates, Hilbert sort)");

  // --- gStar4D ----------------------------------------------------------------------------
  if (opt.algorithm == Algorithm::gstar4d) {
    Buffer<vid_t, B> tv(ctx);
    Buffer<std::int32_t, B> tn(ctx);
    star4d::gstar4d(ctx, P, sid, m, lo, hi, opt, st, tv, tn);
    t0 = std::chrono::steady_clock::now();
    to_input_ids(ctx, tv, sid);
    finish(tv, tn, t0);
    return out;
  }

  // --- algorithm -------------------------------------------------------------------------
  flip::FlipConfig cfg;
  cfg.rule = opt.insertion;
  cfg.terminal = opt.terminal_flipping;
  // non-optimal flipping: on request, or under Auto on the GPU when stuck on < 1 % of the
  // points. Not under Auto on the CPU backend: there its exact facet counts cost 5-40 % of
  // the run and the repair gains nothing (bench/RESULTS.md, session 9); the exact result is
  // the same triangulation either way.
  cfg.nonoptimal = opt.nonoptimal_flips || (opt.algorithm == Algorithm::Auto && !std::is_same_v<B, par::Cpu>);
  if (!opt.nonoptimal_flips) {
    cfg.nonoptimal_max_share = 0.01;
    cfg.nonoptimal_keep_best = false;  // memory: no copy of the mesh (the repair is exact anyway)
  }
  cfg.reorder_tets = opt.reorder_tets;
  cfg.independent_splits = opt.independent_splits;
  cfg.sequential = one_point_per_round<B>(opt);
  cfg.cavity = exact;  // the exact path inserts by cavities; gflip3d by flips (FlipConfig::cavity)
  flip::GFlip3D<B> alg(ctx, P, sid, m, cfg, st);
  if (opt.initial == Initial::grid) grid::grid_initial(ctx, alg, P, sid, m, lo, hi, opt, st);  // else: first tet
  alg.run();
  alg.release_work();
  const bool sequential = alg.ran_one_point_per_round();

  // --- output ----------------------------------------------------------------------------
  t0 = std::chrono::steady_clock::now();
  // One point per round leaves the exact Delaunay triangulation (flip/sequential.hpp) in
  // its records: the exact output comes straight from them (no repair, no mesh).
  if constexpr (!B::is_device) {
    if (exact && sequential && alg.extract_one_point_per_round(sink.room(out), sid.data(), st.flat_tets_removed)) {
      par::mark(ctx, "one point per round: extract into the results");
      finished(t0);
      return out;
    }
  }
  auto& mesh = alg.mesh();
  if (!sequential) {  // one point per round wrote the mesh back compacted
    alg.finish_mesh();  // compacted, or sorted by vertex (Options::reorder_tets)
    par::mark(ctx, "output: compact mesh");
  }
  const I64 nt = mesh.size();
  mesh::MeshView mv = mesh.view();
  const vid_t inf = alg.infinite();
  const flip::Geo g = alg.geo();
  if (exact) {
    auto t1 = std::chrono::steady_clock::now();
    splay::GDel3D<B> rep(ctx, mesh, g, m);
    if (!sequential) {  // (one point per round with its mesh written back: nothing to repair)
      rep.repair();
      par::mark(ctx, "gdel3d repair");
      st.stages.push_back({"gdel3d repair (star splaying)", since(t1)});
    }
    t1 = std::chrono::steady_clock::now();
    Buffer<vid_t, B> tv(ctx);
    Buffer<std::int32_t, B> tn(ctx);
    rep.extract(tv, tn);
    par::mark(ctx, "gdel3d extract");
    const auto& r = rep.result();
    st.exact_evaluations += r.exact_evaluations;
    st.repair_failed_vertices = r.failed;
    st.stars_built = r.stars_built;
    st.stars_flipflop = r.splay.flipflop;
    st.stars_rebuilt = r.splay.rebuilt;
    st.stars_built_on_host = r.splay.host_built;
    st.host_star_insertions = r.splay.host_insertions;
    st.stars_pulled = r.splay.stars_pulled;
    st.splay_rounds = r.splay.rounds;
    st.splay_insertions = r.splay.insertions;
    st.flat_tets_removed = r.flat_removed;
    to_input_ids(ctx, tv, sid);
    par::mark(ctx, "output: input ids");
    finish(tv, tn, t1);
    return out;
  }
  // failed vertices: vertices of facets that are not locally Delaunay (the repair's test)
  {
    Buffer<std::int8_t, B> fv(ctx, static_cast<std::size_t>(m));
    std::int8_t* fvp = fv.data();
    st.exact_evaluations += splay::GDel3D<B>::failed_flags(ctx, mv, nt, g, m, fvp);
    Buffer<I64, B> fl(ctx, static_cast<std::size_t>(m));
    std::size_t nfv = par::select_indices(ctx, static_cast<std::size_t>(m), fl.data(),
                                          [=] GDEL_LAMBDA(I64 v) { return fvp[v] != 0; });
    st.failed_vertices = static_cast<I64>(nfv);
    sink.failed_vertices(ctx, fl, nfv, sid, out);
    par::mark(ctx, "output: failed vertices");
  }
  // finite tets, input ids, neighbours (-1 across the hull)
  Buffer<tid_t, B> fin(ctx, static_cast<std::size_t>(nt + 1));
  tid_t* fp = fin.data();
  par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(I64 t) { fp[t] = flip::Geo::inf_slot(mv.tet[t].v, inf) < 0 ? 1 : 0; });
  const tid_t nfin = par::counts_to_offsets(ctx, fp, static_cast<std::size_t>(nt));
  // The mesh is consumed one array at a time, so that the output never sits beside
  // the whole mesh: the neighbours first, then the tets written over the records.
  mesh.state().release();
  Buffer<std::int32_t, B> tn(ctx, static_cast<std::size_t>(4 * std::max<tid_t>(nfin, 1)));
  std::int32_t* tnp = tn.data();
  par::parallel_for(ctx, nt, [=] GDEL_LAMBDA(I64 t) {
    if (fp[t + 1] == fp[t]) return;
    const I64 d = fp[t];
    for (int i = 0; i < 4; ++i) {
      const tid_t u = mv.opp_tet(4 * t + i);
      tnp[4 * d + i] = (u < 0 || fp[u + 1] == fp[u]) ? -1 : fp[u];
    }
  });
  const I64* sp = sid.data();
  Buffer<std::int32_t, B> tv = mesh.take_tets(fp, 4 * std::max<I64>(nfin, 1),
                                              [=] GDEL_LAMBDA(vid_t v) { return static_cast<std::int32_t>(sp[v]); });
  tv.resize(static_cast<std::size_t>(4 * nfin));
  tn.resize(static_cast<std::size_t>(4 * nfin));
  par::mark(ctx, "output: finite tets, input ids");
  finish(tv, tn, t0);
  return out;
}

template <class B>
Triangulation delaunay_on(Context<B>& ctx, std::span<const double> points, const Options& opt) {
  HostOutput sink;
  return delaunay_into(ctx, points, opt, sink);
}

}  // namespace gdel::api

namespace gdel::cuda_backend {
// gdel::delaunay_device's CUDA part (delaunay_cuda.cu); the checks of the options are in
// delaunay.cpp.
DeviceTriangulation delaunay_device(const DevicePoints& points, const Options& options);
}  // namespace gdel::cuda_backend
