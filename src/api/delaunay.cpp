// gdel::delaunay: argument checks, backend dispatch, canonical order, verification.
// The CPU backend is instantiated here, the CUDA one in delaunay_cuda.cu.
#include <atomic>
#include <cmath>
#include <numeric>
#include <sstream>

#include "api/delaunay_impl.hpp"
#include "api/validate.hpp"
#include "core/backend_select.hpp"
#include "gdel/device_memory.hpp"
#include "gdel/verify.hpp"
#include "mesh/canonical.hpp"

namespace gdel {

const char* to_string(Algorithm a) {
  switch (a) {
    case Algorithm::Auto: return "auto";
    case Algorithm::gflip3d: return "gflip3d";
    case Algorithm::gdel3d: return "gdel3d";
    case Algorithm::gstar4d: return "gstar4d";
  }
  return "?";
}

std::string Stats::to_string() const {
  std::ostringstream s;
  s << "algorithm " << algorithm << " on " << backend << ": " << seconds << " s, " << points << " points ("
    << distinct_points << " distinct)\n";
  for (auto& [name, t] : stages) s << "  " << name << ": " << t << " s\n";
  s << "  rounds " << rounds << ", flip iterations " << flip_iterations << ", flips 2-3 " << flips23 << ", 3-2 "
    << flips32 << ", exact evaluations " << exact_evaluations << ", failed vertices " << failed_vertices
    << ", peak memory " << peak_bytes / (1024.0 * 1024.0) << " MiB";
  if (kernel_point_centroid) s << "\n  kernel point: the exact centroid of the first tetrahedron (no double inside it)";
  if (sos_order_round > 0) s << "\n  insertion in SoS order after round " << sos_order_round << " (exact ties)";
  if (nonoptimal_rounds > 0)
    s << "\n  non-optimal flipping: rounds " << nonoptimal_rounds << " (" << nonoptimal_between_rounds
      << " between insertion rounds), non-improving flips " << nonoptimal_flips
      << ", non-LD facets " << nonld_facets_stuck << " when stuck -> " << nonld_facets_kept << " kept";
  if (algorithm == "gstar4d" || algorithm == "greg3d")
    s << "\n  " << algorithm << ": grid " << grid << "^3, working-set pairs " << working_set_pairs << ", stars "
      << stars_built << ", splay rounds " << splay_rounds << ", insertions " << splay_insertions
      << ", certificate fallbacks " << certificate_fallbacks;
  if (algorithm == "greg3d") s << ", dead stars " << dead_stars << ", redundant points " << redundant_points;
  if (algorithm == "gdel3d")
    s << "\n  repair: failed vertices " << repair_failed_vertices << ", stars built " << stars_built << " ("
      << stars_flipflop << " by Flip-Flop, " << stars_rebuilt << " rebuilt), stars pulled " << stars_pulled
      << ", splay rounds " << splay_rounds << ", insertions " << splay_insertions << ", flat tets removed "
      << flat_tets_removed;
  if (algorithm == "gdel3d" && (stars_built_on_host > 0 || host_star_insertions > 0))
    s << "\n  repair on the host (huge stars): stars built " << stars_built_on_host << ", insertions "
      << host_star_insertions;
  if (points_deferred > 0) s << "\n  one point per round: insertions deferred between threads " << points_deferred;
  if (!verify_summary.empty()) s << "\n  verify: " << verify_summary;
  return s.str();
}

namespace {

// Each tet rotated to its canonical even permutation (neighbours permuted alike),
// tets sorted, neighbour ids remapped.
void canonicalize(Triangulation& t) {
  const std::size_t m = t.tets.size() / 4;
  std::vector<std::array<std::int64_t, 4>> key(m);
  for (std::size_t i = 0; i < m; ++i) {
    std::array<std::int64_t, 4> enc;
    for (int k = 0; k < 4; ++k) enc[k] = std::int64_t(t.tets[4 * i + k]) * 4 + k;  // value, then position
    key[i] = canonical_tet(enc);
  }
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  // by vertex ids only: the position bits (low 2) say where a vertex came from, which
  // differs between algorithms and must not order the list
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    for (int k = 0; k < 4; ++k)
      if ((key[a][k] >> 2) != (key[b][k] >> 2)) return (key[a][k] >> 2) < (key[b][k] >> 2);
    return false;
  });
  std::vector<std::int32_t> newid(m);
  for (std::size_t r = 0; r < m; ++r) newid[order[r]] = static_cast<std::int32_t>(r);
  std::vector<std::int32_t> tets(4 * m), nb(4 * m);
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = order[r];
    for (int k = 0; k < 4; ++k) {
      const int from = static_cast<int>(key[i][k] & 3);
      tets[4 * r + k] = t.tets[4 * i + from];
      const std::int32_t o = t.neighbors[4 * i + from];
      nb[4 * r + k] = o < 0 ? -1 : newid[o];
    }
  }
  t.tets.swap(tets);
  t.neighbors.swap(nb);
}

}  // namespace

Triangulation delaunay(std::span<const double> points, const Options& options) {
  const int k = api::validate_points(points);
  std::vector<double> scaled_copy;
  std::span<const double> work = points;
  if (k != 0) {
    scaled_copy = api::scaled(points, k);
    work = scaled_copy;
  }
  Triangulation t;
  if (resolve_backend(options.backend) == Backend::Cuda) {
#if defined(GDEL_HAVE_CUDA)
    try {
      t = cuda_backend::delaunay(work, options);
    } catch (const OutOfDeviceMemory& e) {
      if (!options.fallback_to_cpu) throw;
      par::Context<par::Cpu> ctx;
      t = api::delaunay_on(ctx, work, options);
      t.stats.backend = std::string("cpu (fallback: ") + e.what() + ")";
    }
#endif
  } else {
    par::Context<par::Cpu> ctx;
    t = api::delaunay_on(ctx, work, options);
  }
  if (options.algorithm == Algorithm::gstar4d) {
    // Certificate: valid triangulation of the hull, every facet locally Delaunay, no flat
    // tet (exact). On failure the answer comes from gdel3d (star4d/star_stage.hpp says why).
    auto r = verify(work, t.tets, {}, options.backend);
    if (!r.delaunay() || r.degenerate_tets != 0) {
      Options o = options;
      o.algorithm = Algorithm::gdel3d;
      o.canonical_order = false;
      o.verify = false;
      Stats first = t.stats;
      t = delaunay(work, o);
      first.certificate_fallbacks = 1;
      first.stages.push_back({"gstar4d certificate failed: gdel3d", t.stats.seconds});
      first.seconds += t.stats.seconds;
      first.verify_summary.clear();
      t.stats = first;
    } else {
      t.stats.stages.push_back({"gstar4d certificate (exact verifier)", r.seconds});
      t.stats.seconds += r.seconds;
    }
  }
  if (options.canonical_order) canonicalize(t);
  if (options.verify) {
    auto r = verify(work, t.tets, {}, options.backend);
    t.stats.verify_summary = r.summary();
  }
  return t;
}

DeviceTriangulation delaunay_device(const DevicePoints& points, const Options& options) {
  if (points.n < 0 || (points.n > 0 && points.data == nullptr))
    throw InvalidInput("delaunay_device: no device pointer for " + std::to_string(points.n) + " points");
  if (points.n >= (std::int64_t(1) << 31) - 1)
    throw InvalidInput("delaunay_device: " + std::to_string(points.n) + " points; vertex ids are int32 (at most 2^31 - 2 points)");
  if (options.backend == Backend::Cpu)
    throw InvalidInput("delaunay_device: points in device memory need the CUDA backend (Backend::Cpu asked for); "
                       "copy them to the host and call gdel::delaunay");
  if (options.algorithm == Algorithm::gstar4d || options.verify || options.canonical_order)
    throw InvalidInput("delaunay_device: gstar4d (its exact certificate), Options::verify and Options::canonical_order "
                       "run on host arrays; use gdel::delaunay for them");
  if (points.n == 0) throw DegenerateInput("need at least 4 distinct points, got 0");
#if defined(GDEL_HAVE_CUDA)
  resolve_backend(Backend::Cuda);  // BackendUnavailable without a visible device
  return cuda_backend::delaunay_device(points, options);
#else
  throw BackendUnavailable("delaunay_device: this build of gdel has no CUDA support (rebuild with the cuda preset)");
#endif
}

#if !defined(GDEL_HAVE_CUDA)
void device_free(void*, int) noexcept {}  // nothing is ever allocated without CUDA
// gdel/device_memory.hpp without CUDA: the setting is recorded, nothing is kept
namespace {
std::atomic<std::size_t> kept_setting{0};
}
void keep_device_memory(std::size_t bytes) noexcept { kept_setting.store(bytes); }
void release_device_memory() noexcept {}
std::size_t kept_device_memory_bound() noexcept { return kept_setting.load(); }
DeviceArray<double> copy_to_device(std::span<const double>, int) {
  throw BackendUnavailable("copy_to_device: this build of gdel has no CUDA support (rebuild with the cuda preset)");
}
std::vector<std::int32_t> copy_to_host(const DeviceArray<std::int32_t>& a) {
  if (a.size() == 0) return {};
  throw BackendUnavailable("copy_to_host: this build of gdel has no CUDA support (rebuild with the cuda preset)");
}
#endif

}  // namespace gdel
