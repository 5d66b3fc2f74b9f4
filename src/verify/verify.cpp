// Verifier front: argument checks, backend dispatch, report formatting. The CPU
// backend is instantiated here; the CUDA one in verify_cuda.cu.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <sstream>

#include "core/backend_select.hpp"
#include "gdel/errors.hpp"
#include "api/validate.hpp"
#include "verify/verify_impl.hpp"

namespace gdel {

bool VerifyReport::valid() const {
  return bad_index == 0 && degenerate_tets == 0 && inverted_tets == 0 && overshared_facets == 0 &&
         same_side_facets == 0 && hull_open_edges == 0 && hull_reflex_edges == 0 && unused_points == 0 &&
         duplicate_vertices == 0 && locate_failures == 0 && euler_ok;
}

bool VerifyReport::delaunay() const { return valid() && non_delaunay_facets == 0; }

std::string VerifyReport::summary() const {
  std::ostringstream s;
  s << (delaunay() ? "OK: valid and locally Delaunay/regular" : valid() ? "VALID but not Delaunay/regular" : "INVALID")
    << "\n  points " << points << " (distinct " << distinct_points << "), tets " << tets << ", vertices used "
    << vertices_used << ", edges " << edges << ", facets " << facets << " (hull " << hull_facets << ")"
    << "\n  Euler V-E+F-T = " << euler << (euler_ok ? " (3-ball)" : " (NOT a 3-ball)");
  auto item = [&](const char* name, std::int64_t v) {
    if (v) s << "\n  " << name << ": " << v;
  };
  item("tets with bad vertex ids", bad_index);
  item("degenerate (flat) tets", degenerate_tets);
  item("inverted tets", inverted_tets);
  item("facets in more than two tets", overshared_facets);
  item("facets with both tets on one side", same_side_facets);
  item("open or misoriented hull edges", hull_open_edges);
  item("reflex hull edges", hull_reflex_edges);
  item("distinct points not used", unused_points);
  item("duplicate points used more than once", duplicate_vertices);
  item("unused points that could not be located", locate_failures);
  item("facets not locally Delaunay/regular", non_delaunay_facets);
  s << "\n  cospherical ties " << cospherical_facets << ", redundant points " << redundant_points
    << ", exact evaluations " << exact_evaluations << ", " << seconds << " s";
  return s.str();
}

VerifyReport verify(std::span<const double> points, std::span<const std::int32_t> tets,
                    std::span<const double> weights, Backend backend) {
  if (points.size() % 3 != 0) throw InvalidInput("verify: points must hold 3 coordinates per point");
  if (tets.size() % 4 != 0) throw InvalidInput("verify: tets must hold 4 vertex ids per tet");
  const std::int64_t n = static_cast<std::int64_t>(points.size() / 3);
  const std::int64_t m = static_cast<std::int64_t>(tets.size() / 4);
  if (!weights.empty() && static_cast<std::int64_t>(weights.size()) != n)
    throw InvalidInput("verify: " + std::to_string(weights.size()) + " weights for " + std::to_string(n) + " points");
  // Exact scaling by a power of two into the predicates' range (weights scale by its square).
  const int k = api::validate_points(points);
  std::vector<double> sp;
  if (k != 0) {
    sp = api::scaled(points, k);
    points = sp;
  }
  const std::vector<double> sw = api::scaled_weights(weights, k, "verify: weights");
  weights = sw;
  const double* w = weights.empty() ? nullptr : weights.data();
  // The facet and edge sorts run in chunks of about this many items (memory
  // bound); GDEL_VERIFY_CHUNK sets it (tests use tiny chunks to cover the path).
  std::int64_t chunk = 0;
  if (const char* e = std::getenv("GDEL_VERIFY_CHUNK")) chunk = std::max<long long>(1, std::atoll(e));
  auto t0 = std::chrono::steady_clock::now();
  VerifyReport r;
  if (resolve_backend(backend) == Backend::Cuda) {
#if defined(GDEL_HAVE_CUDA)
    r = cuda_backend::verify(points.data(), n, tets.data(), m, w, chunk);
#endif
  } else {
    par::Context<par::Cpu> ctx;
    r = verify_detail::run(ctx, points.data(), n, tets.data(), m, w, chunk ? chunk : std::int64_t(1) << 26);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace gdel
