// Delaunay triangulation of 3-D points: the public C++ API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gdel/options.hpp"

namespace gdel {

enum class Algorithm {
  Auto,     // the best available exact algorithm: today gdel3d, on the CUDA backend with
            // non-optimal flipping when it is stuck on fewer facets than 1 % of the points
            // (bench/RESULTS.md, 2026-11-24: much faster repair on the grid, no loss
            // elsewhere; on the CPU backend it only costs time, session 9)
  gflip3d,  // parallel insertion + flipping: a near-Delaunay triangulation (failed vertices reported)
  gdel3d,   // gflip3d + parallel star-splaying repair: the exact Delaunay triangulation
  gstar4d,  // digital Voronoi diagram -> working sets -> 4-D stars -> parallel star splaying:
            // the exact Delaunay triangulation, certified by the exact verifier (on a
            // failed certificate the result is recomputed by gdel3d; Stats says so)
};
const char* to_string(Algorithm a);

// Which uninserted point a tet inserts in a round of gFlip3D.
enum class InsertionRule {
  // nearest to the circumcentre (largest insphere determinant), default; switches to
  // SosOrder once exact insphere ties dominate the flipping (cospherical input: docs/
  // gflip3d.md, "Insertion in SoS order"; Stats::sos_order_round says when)
  Circumcenter,
  Centroid,  // nearest to the centroid
  Random,    // a hash of the point index
  SosOrder,  // the smallest SoS index, i.e. input index (for study; see Circumcenter)
};

// What gFlip3D (and so gDel3D) starts inserting from (docs/grid.md).
enum class Initial {
  Default,  // one tetrahedron of extreme points (+ its cones to infinity)
  grid,     // the Delaunay triangulation of a coarse grid's sample (one site per occupied
            // voxel), obtained from the dual of the sample's digital Voronoi diagram by star
            // splaying and certified exactly; falls back to Default on degenerate samples
            // (Stats::grid_fallbacks says so). gstar4d: its grid already is its start (no change)
};
const char* to_string(Initial i);

struct Options {
  Algorithm algorithm = Algorithm::Auto;
  Backend backend = Backend::Auto;
  int device = 0;  // CUDA device ordinal
  InsertionRule insertion = InsertionRule::Circumcenter;
  // gFlip3D's terminal variant ("InsAll"): insert every point by splitting, flip once
  // at the end. For comparison only: it leaves many more non-Delaunay facets.
  bool terminal_flipping = false;
  // gFlip3D (and so gDel3D): non-optimal flipping (docs/gflip3d.md). Once flipping is
  // stuck at the end, a facet that is not locally Delaunay but cannot be flipped gets
  // one of its edges removed: valid, non-improving 2-3 flips around that edge (following
  // a valid triangulation of the edge's ring, found exactly) until the edge has degree 3
  // and its 3-2 flip removes the edge and the facet; normal flipping then resumes.
  // Capped rounds; the triangulation with the fewest non-locally-Delaunay facets seen is
  // kept. With independent_splits, also one such round after every insertion round's
  // flipping, from the tets it left stuck (when they are fewer than 1 % of the points).
  // true: always (any algorithm built on gFlip3D). false: only under Algorithm::Auto,
  // and only when the stuck facets are fewer than 1 % of the points (on cospherical
  // input, where most facets are ties, it costs more than the repair it saves; measured
  // in bench/RESULTS.md and docs/gflip3d.md).
  bool nonoptimal_flips = false;
  // gFlip3D (and so gDel3D): independent splits, a quality option. In an insertion
  // round that is followed by flipping, a tet holding points splits only if none of its
  // neighbours that also hold points comes before it in a fixed pseudo-random order of
  // tets, so no two splits of a round share a face (the others insert in later rounds);
  // and a tet left stuck (a face not locally Delaunay, none flippable) stays in the
  // active set, this round and the next. gflip3d leaves 3-5x fewer facets not locally
  // Delaunay, for 2-4x the rounds and 1.7-3x the time on an H100 (10^6-10^7 uniform
  // points; far more on cospherical input, whose stuck ties are re-proposed exactly).
  // false (default): every tet holding points splits in every round (the original rule).
  bool independent_splits = false;
  // gFlip3D's parallel rounds (GPU, or CPU with cpu_rounds): sort tets by smallest
  // vertex id after every insertion round and before the output, for memory locality;
  // each sort only when its temporaries fit under the run's memory peak so far, so the
  // peak does not grow. On an H200: uniform 10^7 -7.5 %, 10^8 -8.7 %, every generator
  // at 10^6 faster (bench/RESULTS.md, session 23; a sort every second round then, every
  // round since session 25: 10^7 a further -5 %). The result is the same set of tets;
  // gflip3d's flips (hence its output) can differ, as the slots' order decides the votes.
  // The environment variable GDEL_TET_REORDER=0/1 overrides this field.
  bool reorder_tets = true;
  // CPU backend: run gFlip3D in the thesis's parallel rounds, as on the GPU. Default
  // (false): one point per round (docs/gflip3d.md): each point located by a walk and
  // inserted before the next (gdel3d/Auto: its conflict cavity replaced, Bowyer-Watson;
  // gflip3d: split in and flipped to Delaunay), which leaves the exact Delaunay
  // triangulation, so gdel3d has nothing to repair. That is several times faster on a few
  // cores; the rounds remain for study and comparison with the GPU. The rounds are used
  // anyway when an option above asks for them (terminal, non-optimal flips, independent
  // splits, an insertion rule other than circumcenter, initial = grid).
  bool cpu_rounds = false;
  // Sort output tets (each rotated to start at its smallest vertex, list sorted) so
  // that the arrays are bitwise identical across runs and backends. Without it the tets
  // are the same set on every run, but on the CPU backend's threads (one point per round,
  // cpu_rounds = false) their order may differ from run to run.
  bool canonical_order = false;
  // Run the exact verifier on the result and store its report summary in stats.
  bool verify = false;
  // gstar4d: side W of the W^3 digital Voronoi grid (0 = automatic: about 8 voxels per
  // point within a quarter of the free memory; docs/gstar4d.md), and the least number
  // of candidates in a working set (pumping, default 8).
  // With initial = grid: the coarse grid's side (0 = automatic: about 16 points per voxel).
  int grid = 0;
  int min_candidates = 8;
  Initial initial = Initial::Default;
  // gdel::regular: fill RegularTriangulation::certificates (a proof per redundant point).
  bool certificates = false;
  // On the CUDA backend: when the device runs out of memory (OutOfDeviceMemory), run the
  // same algorithm on the CPU backend instead of throwing (Stats::backend then reads
  // "cpu (fallback: ...)"). The device memory is released before the CPU run.
  bool fallback_to_cpu = false;
  // CUDA backend: the most device memory (bytes) one call may hold; 0 = no limit but the
  // device's. Exceeding it raises OutOfDeviceMemory as a full device would (for tests and
  // for sharing a GPU).
  std::size_t device_memory_limit = 0;
};

struct Stats {
  std::string algorithm;
  std::string backend;
  double seconds = 0;                                 // total wall time
  std::vector<std::pair<std::string, double>> stages;  // seconds per stage, in order
  std::int64_t points = 0;          // input points
  std::int64_t distinct_points = 0; // after removing exact duplicates
  std::int64_t rounds = 0;          // insertion rounds (one point per round: the points inserted)
  std::int64_t flip_iterations = 0; // parallel flipping iterations
  std::int64_t flips23 = 0, flips32 = 0;  // (0 for gdel3d's cavity insertion on the CPU)
  std::int64_t exact_evaluations = 0;  // items decided by the exact (non-filter) pass
  std::int64_t failed_vertices = 0;    // vertices of facets left not locally Delaunay (in the output)
  // InsertionRule::Circumcenter: the round after which the rounds inserted in SoS order
  // (exact insphere ties dominated the flipping so far); 0: never
  std::int64_t sos_order_round = 0;
  // 1 when no double lies strictly inside the first tetrahedron (e.g. four points one ulp
  // apart), so that the kernel point standing for ∞ is its vertices' exact centroid
  // (docs/gflip3d.md, first tetrahedron); else 0
  std::int64_t kernel_point_centroid = 0;
  // Options::nonoptimal_flips: rounds run (those after insertion rounds included), of
  // them the rounds run after an insertion round (independent splits only),
  // non-improving flips made (all rounds, kept or not), and the facets (∞'s included)
  // not locally Delaunay when the last flip loop got stuck and in the triangulation kept
  // (fewest seen); all 0 without the option
  std::int64_t nonoptimal_rounds = 0, nonoptimal_between_rounds = 0, nonoptimal_flips = 0, nonld_facets_stuck = 0,
               nonld_facets_kept = 0;
  // gdel3d repair: vertices gFlip3D left failing (their stars are made convex), of those
  // stars the ones Flip-Flop convexified and the ones rebuilt by beneath-beyond insertion
  // (where Flip-Flop gave up, or all with GDEL_STAR_BUILD=rebuild), stars pulled from the
  // triangulation on demand, splaying rounds, star insertions attempted, flat tets (exact
  // zero volume, on coplanar hull faces) dropped from the output
  std::int64_t repair_failed_vertices = 0, stars_built = 0, stars_flipflop = 0, stars_rebuilt = 0,
               stars_pulled = 0, splay_rounds = 0, splay_insertions = 0, flat_tets_removed = 0;
  // gdel3d repair on the CUDA backend: stars with large working sets (over 48 points, at
  // most 4 per host thread per build, and only where one exceeds 128: points on a
  // coplanar hull face) built on the host's cores, and the insertions made into such
  // stars (over 96 triangles, the same cap, where one exceeds 256) on the host in the
  // splaying rounds (docs/gdel3d.md)
  std::int64_t stars_built_on_host = 0, host_star_insertions = 0;
  // CPU backend, one point per round (Options::cpu_rounds = false): insertions undone
  // after meeting another thread's tets, then redone by one thread after their round
  std::int64_t points_deferred = 0;
  // gstar4d (or Options::initial = grid: its coarse grid): grid side; gstar4d: candidate
  // pairs in the working sets, and whether the exact
  // certificate of its result failed so that gdel3d recomputed it (0 or 1)
  std::int64_t grid = 0, working_set_pairs = 0, certificate_fallbacks = 0;
  // greg3d (gdel::regular): stars that died (their points proved redundant by a death
  // certificate), and all redundant points (dead, hidden duplicates, upper hull only)
  std::int64_t dead_stars = 0, redundant_points = 0;
  // Options::initial = grid (docs/grid.md): sites of the coarse grid (the sample), whether
  // the grid start was abandoned for the default one (0 or 1; Stats::stages says why), and
  // the raw dual of the sites' digital Voronoi diagram under the grid perturbation: its
  // distinct site tets, how many are flat / inverted / folded, its facets in more than two
  // tets or in two on the same side, its cospherical and non-Delaunay facet pairs, and how
  // many of the sites' Delaunay tets it holds or misses (exact predicates, no perturbation)
  std::int64_t grid_sites = 0, grid_fallbacks = 0, dual_tets = 0, dual_flat = 0, dual_inverted = 0,
               dual_folded = 0, dual_overshared_facets = 0, dual_overlapping_facets = 0,
               dual_cospherical_pairs = 0, dual_non_delaunay_pairs = 0, dual_delaunay_tets = 0,
               dual_missed_delaunay_tets = 0;
  std::int64_t peak_bytes = 0;         // peak backend memory (device memory for CUDA)
  std::string verify_summary;          // with Options::verify
  std::string to_string() const;
};

struct Triangulation {
  // 4 input point ids per tet, positively oriented (orient3d > 0, see docs). gdel3d:
  // every tet has non-zero volume (exact), and ties between cospherical points are
  // broken by a symbolic perturbation of the lifting (docs/gdel3d.md).
  std::vector<std::int32_t> tets;
  // 4 per tet: neighbours[4t+i] is the tet across the face opposite vertex i, -1 on the hull.
  std::vector<std::int32_t> neighbors;
  // Input ids of vertices incident to facets that are not locally Delaunay
  // (gflip3d only; empty for exact algorithms), ascending.
  std::vector<std::int32_t> failed_vertices;
  // For each input point, the id of the point that represents it: itself, or the
  // smallest index of an exactly equal point (duplicates appear once in tets).
  std::vector<std::int32_t> representative;
  Stats stats;
  std::int64_t num_tets() const { return static_cast<std::int64_t>(tets.size() / 4); }
};

// points: 3n doubles (x0,y0,z0,x1,...). Throws InvalidInput (NaN/Inf, bad size,
// coordinates outside the exact range), DegenerateInput (fewer than 4 distinct points,
// all points coplanar), OutOfDeviceMemory, BackendUnavailable.
Triangulation delaunay(std::span<const double> points, const Options& options = {});

// The device memory a CUDA run is expected to need for n points (bytes): a fixed 64 MiB
// plus what uniform input was measured to need (bench/RESULTS.md): for gflip3d / gdel3d
// (Auto) 450 bytes per point plus 160 bytes for each flip of the largest flip iteration
// (1.2n, at most 2^24: FlipConfig::max_flips_per_iteration), i.e. 642 bytes per point
// up to 1.4*10^7 points (709 at 10^6 with the fixed part) and 478 at 10^8 (measured at
// 10^6, 10^7 and 10^8: 601, 520 and 454); 5 400 per point for
// gstar4d, and the same for gdel::regular (gReg3D, `weighted`). Input whose repair splays
// many or large stars needs more (gdel3d at 10^6: 1.9x on the grid and 1.8x on the
// exactly cospherical sphere (1 389 and 1 319 bytes per point); gstar4d 1.8x on the thin
// shell). The CUDA backend compares this with the free device
// memory (and Options::device_memory_limit) before it starts: when it does not fit, the
// call fails at once with OutOfDeviceMemory (needed = the estimate, free = what is free),
// or runs on the CPU with Options::fallback_to_cpu, instead of failing later at an
// allocation. A run that passes the check can still run out (then the same clean error).
std::size_t estimated_device_bytes(std::int64_t n, Algorithm algorithm = Algorithm::Auto, bool weighted = false);

}  // namespace gdel

// ---------------------------------------------------------------------------------------
// Points already in CUDA device memory, results left there (CUDA builds).
// ---------------------------------------------------------------------------------------
namespace gdel {

// Frees memory that a DeviceArray handed over with release(): cudaFree on `device`.
// No-op for nullptr; never throws (an error is swallowed, as in a destructor).
void device_free(void* p, int device) noexcept;

// n elements of T in CUDA device memory on `device`, allocated with cudaMalloc by gdel
// and owned by this object (freed by its destructor) until release() hands the pointer
// over; whoever takes it frees it with device_free(p, device()). Move-only.
template <class T>
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(T* p, std::int64_t n, int device) : p_(p), n_(n), device_(device) {}
  ~DeviceArray() { reset(); }
  DeviceArray(DeviceArray&& o) noexcept : p_(o.p_), n_(o.n_), device_(o.device_) { o.p_ = nullptr, o.n_ = 0; }
  DeviceArray& operator=(DeviceArray&& o) noexcept {
    if (this != &o) {
      reset();
      p_ = o.p_, n_ = o.n_, device_ = o.device_;
      o.p_ = nullptr, o.n_ = 0;
    }
    return *this;
  }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  T* data() const { return p_; }
  std::int64_t size() const { return n_; }
  int device() const { return device_; }
  // The caller now owns the memory (free it with device_free(p, device())).
  T* release() {
    T* p = p_;
    p_ = nullptr, n_ = 0;
    return p;
  }
  void reset() {
    device_free(p_, device_);
    p_ = nullptr, n_ = 0;
  }

 private:
  T* p_ = nullptr;
  std::int64_t n_ = 0;
  int device_ = 0;
};

// Input of delaunay_device(): n points as 3n coordinates (x0,y0,z0,x1,...), C-contiguous,
// in device memory of CUDA device `device` (or managed memory).
struct DevicePoints {
  const void* data = nullptr;
  std::int64_t n = 0;
  bool float32 = false;      // float (converted to double on the device) instead of double
  int device = 0;            // CUDA ordinal the memory belongs to; the work runs there
  // cudaStream_t on which the producer wrote the points (nullptr: the legacy default
  // stream). gdel's own stream waits for the work queued on it so far; the call returns
  // only after gdel's work is complete, so the results are ready for any stream.
  void* stream = nullptr;
};

// The result of delaunay_device(): the arrays of Triangulation, in device memory of the
// input's device (int32, same layout and contract as Triangulation's vectors).
struct DeviceTriangulation {
  DeviceArray<std::int32_t> tets;             // 4m
  DeviceArray<std::int32_t> neighbors;        // 4m
  DeviceArray<std::int32_t> failed_vertices;  // gflip3d (ascending), else empty
  DeviceArray<std::int32_t> representative;   // n
  Stats stats;
  // The device pointer whose coordinates the algorithm read: DevicePoints::data itself
  // (no copy of the points at all), unless converted_input says that a device-side
  // float64 copy was made (float32 input, or coordinates scaled by a power of two into
  // the predicates' exact range).
  const void* points_read = nullptr;
  bool converted_input = false;
  std::int64_t num_tets() const { return tets.size() / 4; }
};

// Copies between host memory and CUDA device memory, for callers that have no CUDA
// toolchain of their own (the benchmark, tests, C++ programs built with a host compiler).
// CUDA builds only (BackendUnavailable otherwise); OutOfDeviceMemory when cudaMalloc fails.
DeviceArray<double> copy_to_device(std::span<const double> host, int device = 0);
std::vector<std::int32_t> copy_to_host(const DeviceArray<std::int32_t>& a);

// gdel::delaunay for points in device memory: the same validation (NaN/Inf, exact
// range, run on the device by reductions; only a few scalars reach the host),
// duplicate removal, Hilbert sort and algorithm on the CUDA backend, without copying
// the points or the results through the host. Options: algorithm gdel3d, gflip3d or
// Auto (gstar4d's exact certificate and Options::verify / canonical_order run on host
// arrays: use gdel::delaunay for those); backend Auto or Cuda; Options::device is
// ignored (DevicePoints::device decides). Throws as gdel::delaunay does, plus
// BackendUnavailable in a build without CUDA and InvalidInput for the options above.
DeviceTriangulation delaunay_device(const DevicePoints& points, const Options& options = {});

}  // namespace gdel
