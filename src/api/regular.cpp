// gdel::regular: validation, backend dispatch, the exact certificate of the result, and
// the redundancy certificates on request.
#include "gdel/regular.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/regular_impl.hpp"
#include "api/validate.hpp"
#include "gdel/errors.hpp"
#include "gdel/verify.hpp"
#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"

namespace gdel {

#if defined(GDEL_HAVE_CUDA)
namespace cuda_backend {
api::RegularRun regular(std::span<const double> points, std::span<const double> weights, const Options& options);
}
#endif

namespace {

api::RegularRun run_once(std::span<const double> points, std::span<const double> weights, const Options& options) {
  if (resolve_backend(options.backend) == Backend::Cuda) {
#if defined(GDEL_HAVE_CUDA)
    try {
      return cuda_backend::regular(points, weights, options);
    } catch (const OutOfDeviceMemory& e) {
      if (!options.fallback_to_cpu) throw;
      par::Context<par::Cpu> ctx;
      api::RegularRun r = api::regular_on(ctx, points, weights, options);
      r.out.stats.backend = std::string("cpu (fallback: ") + e.what() + ")";
      return r;
    }
#endif
  }
  par::Context<par::Cpu> ctx;
  return api::regular_on(ctx, points, weights, options);
}

// Power test of q against the tet (a, b, c, d): > 0 iff q's lifted point is strictly
// below the tet's lifted hyperplane (a, b, c, d positive).
int power_of(const double* P, const double* W, const std::int32_t* t, std::int32_t q, double* work) {
  auto p = [&](std::int32_t i) { return P + 3 * static_cast<std::int64_t>(i); };
  return geom::power(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(q), W[t[0]], W[t[1]], W[t[2]], W[t[3]], W[q], work);
}

// The output tet that holds q (visibility walk with exact orient3d), or -1.
std::int64_t locate(const double* P, const RegularTriangulation& r, std::int32_t q, double* work) {
  const std::int64_t m = r.num_tets();
  if (m == 0) return -1;
  auto p = [&](std::int32_t i) { return P + 3 * static_cast<std::int64_t>(i); };
  std::int64_t t = 0;
  for (std::int64_t step = 0; step < 4 * m + 16; ++step) {
    const std::int32_t* v = r.tets.data() + 4 * t;
    int exit_face = -1;
    for (int i = 0; i < 4 && exit_face < 0; ++i)
      if (geom::orient3d(p(v[face_vertex(i, 0)]), p(v[face_vertex(i, 1)]), p(v[face_vertex(i, 2)]), p(q), work) < 0)
        exit_face = i;
    if (exit_face < 0) return t;
    t = r.neighbors[4 * t + exit_face];
    if (t < 0) return -1;
  }
  return -1;
}

void fill_certificates(std::span<const double> points, std::span<const double> weights, RegularTriangulation& r,
                       const std::vector<std::int32_t>& deaths) {
  const std::size_t n = weights.size();
  std::vector<std::int64_t> death_of(n, -1);
  for (std::size_t i = 0; i + 6 <= deaths.size(); i += 6) death_of[static_cast<std::size_t>(deaths[i])] = i;
  std::vector<double> work(geom::kPredicateWork);
  r.certificates.assign(5 * r.redundant.size(), -1);
  for (std::size_t j = 0; j < r.redundant.size(); ++j) {
    const std::int32_t q = r.redundant[j];
    std::int32_t* c = r.certificates.data() + 5 * j;
    if (r.representative[q] != q) {
      c[0] = r.representative[q];
    } else if (death_of[q] >= 0) {
      for (int k = 0; k < 5; ++k) c[k] = deaths[death_of[q] + 1 + k];
    } else {
      const std::int64_t t = locate(points.data(), r, q, work.data());
      if (t < 0 || power_of(points.data(), weights.data(), r.tets.data() + 4 * t, q, work.data()) > 0)
        throw std::runtime_error("gdel internal error: redundant point " + std::to_string(q) +
                                 " has no certificate (not located, or in conflict with its tet)");
      for (int k = 0; k < 4; ++k) c[k] = r.tets[4 * t + k];
    }
  }
}

}  // namespace

RegularTriangulation regular(std::span<const double> points, std::span<const double> weights,
                             const Options& options) {
  if (options.algorithm != Algorithm::Auto && options.algorithm != Algorithm::gstar4d)
    throw InvalidInput(std::string("regular: algorithm '") + to_string(options.algorithm) +
                       "' does not take weights (use auto or gstar4d: both run gReg3D)");
  const int k = api::validate_points(points);
  if (weights.size() != points.size() / 3)
    throw InvalidInput("weights: expected one weight per point (" + std::to_string(points.size() / 3) + "), got " +
                       std::to_string(weights.size()));
  std::vector<double> sp;
  std::span<const double> P = points;
  if (k != 0) {
    sp = api::scaled(points, k);
    P = sp;
  }
  const std::vector<double> sw = api::scaled_weights(weights, k, "weights");  // squared lengths: 2^(2k)
  std::span<const double> W = sw;
  api::RegularRun run = run_once(P, W, options);
  // Certificate: a valid triangulation of the hull, every facet locally regular, every
  // unused point redundant, no flat tet (exact). Star splaying's local rules cannot see
  // a globally wrong but locally consistent set of stars (star4d/star_stage.hpp); if the
  // check ever fails, run again with four times the working sets, then give up loudly.
  auto certify = [&](api::RegularRun& r) {
    auto rep = verify(P, r.out.tets, W, options.backend);
    r.out.stats.stages.push_back({"greg3d certificate (exact verifier)", rep.seconds});
    r.out.stats.seconds += rep.seconds;
    if (options.verify) r.out.stats.verify_summary = rep.summary();
    return rep.delaunay() && rep.degenerate_tets == 0 && rep.locate_failures == 0 && rep.unused_points == 0;
  };
  if (!certify(run)) {
    Options o = options;
    o.min_candidates = 4 * std::max(options.min_candidates, 8);
    const Stats first = run.out.stats;
    run = run_once(P, W, o);
    run.out.stats.certificate_fallbacks = 1;
    run.out.stats.seconds += first.seconds;
    if (!certify(run))
      throw std::runtime_error("gdel internal error: the regular triangulation failed its exact certificate twice: " +
                               verify(P, run.out.tets, W, options.backend).summary());
  }
  if (options.certificates) {
    auto t0 = std::chrono::steady_clock::now();
    fill_certificates(P, W, run.out, run.deaths);
    run.out.stats.stages.push_back(
        {"certificates", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
  }
  return std::move(run.out);
}

}  // namespace gdel
