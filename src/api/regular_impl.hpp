// gdel::regular on one backend: upload → duplicates (the heaviest copy kept) → Hilbert
// sort → gReg3D (gStar4D's stages with the power lifting and star death) → output in
// input ids. Written once over the backend tag.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

#include "api/prepare.hpp"
#include "gdel/regular.hpp"
#include "star4d/gstar4d.hpp"

namespace gdel::api {

// Internal results of one run, before the host-side certificate (regular.cpp).
struct RegularRun {
  RegularTriangulation out;
  std::vector<std::int32_t> deaths;  // per dead star: (point, killer, e, t0, t1, t2), input ids
};

template <class B>
RegularRun regular_on(par::Context<B>& ctx, std::span<const double> points, std::span<const double> weights,
                      const Options& opt) {
  using I64 = std::int64_t;
  auto t_start = std::chrono::steady_clock::now();
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  RegularRun run;
  RegularTriangulation& out = run.out;
  Stats& st = out.stats;
  st.backend = B::name;
  st.algorithm = "greg3d";
  const I64 n = static_cast<I64>(points.size() / 3);
  st.points = n;

  auto t0 = std::chrono::steady_clock::now();
  par::Buffer<double, B> X(ctx), Wt(ctx);
  X.assign(points.data(), points.size());
  Wt.assign(weights.data(), weights.size());
  Prepared<B> pr(ctx);
  prepare_points(ctx, X.data(), n, Wt.data(), pr);
  const I64 m = pr.m;
  st.distinct_points = m;
  {
    auto r = pr.rep.to_host();
    out.representative.resize(static_cast<std::size_t>(n));
    for (I64 i = 0; i < n; ++i) out.representative[i] = static_cast<std::int32_t>(r[i]);
  }
  st.stages.push_back({"prepare (duplicates, Hilbert sort)", since(t0)});

  par::Buffer<vid_t, B> tv(ctx);
  par::Buffer<std::int32_t, B> tn(ctx);
  std::vector<vid_t> deaths;
  star4d::gstar4d(ctx, pr.P, pr.sid, m, pr.lo, pr.hi, opt, st, tv, tn, pr.W.data(), &deaths);

  t0 = std::chrono::steady_clock::now();
  to_input_ids(ctx, tv, pr.sid);
  out.tets = tv.to_host();
  out.neighbors = tn.to_host();
  {
    auto sid = pr.sid.to_host();
    run.deaths.resize(deaths.size());
    for (std::size_t i = 0; i < deaths.size(); ++i)
      run.deaths[i] = deaths[i] < 0 ? -1 : static_cast<std::int32_t>(sid[static_cast<std::size_t>(deaths[i])]);
  }
  // redundant: every input point that is not a vertex
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  for (std::int32_t v : out.tets) used[static_cast<std::size_t>(v)] = 1;
  for (I64 i = 0; i < n; ++i)
    if (!used[static_cast<std::size_t>(i)]) out.redundant.push_back(static_cast<std::int32_t>(i));
  st.redundant_points = static_cast<I64>(out.redundant.size());
  st.stages.push_back({"output", since(t0)});
  st.peak_bytes = static_cast<I64>(ctx.memory().peak());
  st.seconds = since(t_start);
  return run;
}

}  // namespace gdel::api
