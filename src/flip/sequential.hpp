// gFlip3D with one point per round: the CPU backend's default insertion (FlipConfig::
// sequential; docs/gflip3d.md "One point per round on the CPU").
//
// The thesis inserts thousands of points per round so that a GPU has work for all its
// threads; every round then re-proposes flips over the whole active set, and the flips
// of different points block each other, which leaves facets stuck for the repair. On a
// few CPU cores those rounds cost several times CGAL's sequential insertion (bench/
// RESULTS.md, session 9). With one point per round the same split and flips become the
// classical flip-based incremental algorithm (Joe 1991; Edelsbrunner-Shah 1996 for the
// lifted form): the point is located by a walk from the last tet made, its tet is split
// 1-4, and the faces opposite it are flipped (2-3 or 3-2, the same face_flip decision as
// gFlip3D's) until every one is locally Delaunay. A face whose flip is blocked is left
// alone: the theorem guarantees that the others' flips remove it. Inserted into a
// Delaunay triangulation this way, every point leaves a Delaunay triangulation, so the
// result is the exact Delaunay triangulation of the (symbolically perturbed) points with
// no facet left for gDel3D's repair. Or (Knobs::cavity = FlipConfig::cavity, gdel3d's
// default on the CPU) the point replaces its conflict cavity at once (Bowyer-Watson,
// insert_cavity): the same triangulation with less work per point. Every decision is an
// exact predicate (filter, then exact arithmetic + SoS) of flip::Geo, the same as
// gFlip3D's and the repair's.
//
// Order: BRIO (Amenta-Choi-Rote): point q belongs to round ctz(hash(q)) (half the points
// in round 0, a quarter in round 1, ...), rounds inserted from the highest down, each in
// the points' Hilbert order (internal ids), so consecutive points are near each other
// and the walks are short, and the randomisation bounds the expected work.
//
// Host threads. A large round is cut into as many contiguous pieces of the curve as there
// are threads (spatially compact regions); each thread inserts its piece's points one at
// a time, as above, while the others do theirs. A point's insertion is a transaction: the
// thread takes every tet it reads or writes (an owner byte per block of 16 tets,
// compare-and-swap), logs each tet before its first write, and releases them a few
// points later (Knobs::hold: its next points mostly touch the same blocks) or at once
// after a conflict. Finding a tet taken by another thread (only near the pieces'
// borders), it restores the logged tets and defers the point; the deferred points go
// again after the round, on all threads in pieces about the borders, and the last of them
// on one thread (parallel_round). A cavity insertion takes every tet it will write (its
// search reads them, its claims take the new slots) before its first write, so it has
// nothing to restore and logs nothing (Worker::log_). Each insertion is thus atomic with
// respect to the others, so the result is the one a sequential insertion in some order
// gives: the unique Delaunay triangulation of the perturbed points, whatever the threads'
// timing (only the tets' slots differ from run to run; Options::canonical_order fixes
// the output order).
//
// Host only: the CPU backend's buffers are host memory (a simplification of the thesis's
// parallel rounds for few cores: the rounds stay available, FlipConfig::sequential =
// false, Options::cpu_rounds). While it runs, the tets live in one 32-byte record each
// (4 vertices, 4 packed neighbour facets t << 2 | face): a tet and its adjacency in one
// cache line instead of the mesh's five arrays (bench/RESULTS.md, session 15). At the end
// either the mesh is written back from them, compacted (write_back), or the output is
// extracted from them directly (extract: gdel::delaunay's exact path, no mesh at all).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include <omp.h>

#include "flip/flip_kernels.hpp"
#include "geometry/filters_simd.hpp"
#include "gdel/errors.hpp"
#include "mesh/open_faces.hpp"
#include "mesh/tet_mesh.hpp"
#include "parallel/host_threads.hpp"

namespace gdel::flip {

struct SequentialCounts {
  std::int64_t inserted = 0, flips23 = 0, flips32 = 0, exact = 0, deferred = 0;
};

template <class B>
class SequentialInsertion {
 public:
  // A link is a non-negative int32 (tet << 2 | face): tet ids below 2^29, about 7·10^7
  // points, more than a run on host cores takes. fits() says whether `slots` (the slots
  // reserved for a run, GFlip3D::initial_slots) stay below that.
  static constexpr std::int64_t kMaxTets = std::int64_t(1) << 29;
  static bool fits(std::int64_t slots) { return slots < kMaxTets; }

  // Study and test knobs (environment, read by GFlip3D::run_sequential): threads
  // (GDEL_CPU_THREADS; 0: OpenMP's count, as the CPU backend's other loops: OMP_NUM_THREADS
  // or the hardware's), the least round run on several threads
  // (GDEL_CPU_PARALLEL_MIN), and a conflict forced at every k-th tet taken in a parallel
  // round (GDEL_CPU_FORCE_CONFLICT; 0: none), which exercises the undo, and the insertions
  // a thread keeps its blocks for (GDEL_CPU_HOLD; bench/RESULTS.md session 16: 4 saves
  // ≈ 2 % of compare-and-swaps over 1, at 1.6x the deferred points; 64 defers 14 %).
  struct Knobs {
    unsigned threads = 0;
    std::int64_t parallel_min = 1 << 12;
    std::int64_t force_conflict = 0;
    std::int64_t hold = 4;
    bool cavity = false;  // FlipConfig::cavity (GDEL_CPU_INSERT=cavity / flip)
  };

  SequentialInsertion(mesh::TetMesh<B>& mesh, const Geo& g, std::int64_t reserve, Knobs k = {})
      : mesh_(mesh), g_(g), cells_(mesh.context()), knobs_(k) {
    static_assert(!B::is_device, "one point per round runs on host memory");
    const std::int64_t n0 = mesh.size();
    grow(std::max(reserve, n0 + 64));
    hwm_ = n0;
    const mesh::MeshView mv = mesh.view();
    threads_ = std::min(64u, k.threads ? k.threads : static_cast<unsigned>(std::max(1, omp_get_max_threads())));
    workers_.reserve(threads_);
    for (unsigned w = 0; w < threads_; ++w) workers_.emplace_back(*this, static_cast<std::uint8_t>(w + 1));
    for (std::int64_t t = 0; t < n0; ++t) {
      Cell& c = cells_.data()[t];
      const bool alive = mv.alive(static_cast<tid_t>(t));
      for (int i = 0; i < 4; ++i) {
        c.v[i] = alive ? mv.tet[t].v[i] : kNoVertex;
        // Cells hold 32-bit packed facets: fits() keeps the mesh below kMaxTets = 2^29 tets.
        c.n[i] = alive ? static_cast<std::int32_t>(mv.opp(4 * t + i)) : -1;
      }
      if (!alive) workers_[0].free_.push_back(static_cast<tid_t>(t));
    }
  }

  // Inserts the points todo[0..n) (internal ids, none a vertex yet) in BRIO order. The
  // tets stay in the records: write_back() or extract() next.
  void run(const vid_t* todo, std::int64_t n) {
    std::vector<std::int64_t> rounds;
    const std::vector<vid_t> order = brio_order(todo, n, rounds);
    Worker& w0 = workers_[0];
    w0.begin(false);
    w0.newest_ = 0;
    while (w0.newest_ < hwm_ && cells_.data()[w0.newest_].v[0] == kNoVertex) ++w0.newest_;
    for (std::size_t r = 0; r + 1 < rounds.size(); ++r) {
      const std::int64_t s = rounds[r], e = rounds[r + 1];
      if (threads_ > 1 && e - s >= std::max<std::int64_t>(knobs_.parallel_min, threads_)) {
        parallel_round(order.data() + s, e - s);
      } else {
        for (std::int64_t k = s; k < e; ++k) w0.insert_point(order[static_cast<std::size_t>(k)]);
      }
    }
    for (Worker& w : workers_) {
      c_.inserted += w.c_.inserted;
      c_.flips23 += w.c_.flips23;
      c_.flips32 += w.c_.flips32;
      c_.exact += w.c_.exact;
      c_.deferred += w.c_.deferred;
    }
    workers_.clear();
    owner_.reset();
    logged_ = {};
    mark_ = {};
  }

  // The records back into the mesh's arrays, compacted: the alive tets in slot order at
  // [0, alive), neighbours renumbered, capacity exactly alive (the output stage then has
  // nothing to compact). Frees the records.
  void write_back() {
    const std::int64_t n = slots();
    par::Context<B>& ctx = mesh_.context();
    par::Buffer<tid_t, B> slot(ctx, static_cast<std::size_t>(n + 1));
    tid_t* sl = slot.data();
    const Cell* cs = cells_.data();
    par::parallel_for(ctx, n, [=](std::int64_t t) { sl[t] = cs[t].v[0] != kNoVertex ? 1 : 0; });
    const std::int64_t alive = par::counts_to_offsets(ctx, sl, static_cast<std::size_t>(n));
    mesh_.set_size(0);
    mesh_.reserve(alive);
    mesh_.set_size(alive);
    const mesh::MeshView mv = mesh_.view();
    par::parallel_for(ctx, n, [=](std::int64_t t) {
      if (sl[t + 1] == sl[t]) return;
      const Cell& c = cs[t];
      const std::int64_t d = sl[t];
      for (int i = 0; i < 4; ++i) {
        mv.tet[d].v[i] = c.v[i];
        mv.set_opp(4 * d + i, c.n[i] >= 0 ? pack_facet(sl[tet_of(c.n[i])], face_of(c.n[i])) : fid_t(-1));
      }
      mv.state[d] = mesh::kAlive;
    });
    cells_.release();
  }

  // Instead of write_back() and the mesh's extraction (splay::GDel3D::extract): the
  // finite tets of the exact Delaunay triangulation straight from the records, vertices
  // as sid[v] (the input ids), neighbours numbered, -1 across the hull. Tets with ∞ are
  // dropped, and exactly flat ones (orient3d = 0: only on coplanar hull faces, docs/
  // gdel3d.md); a face of a flat tet's neighbour is matched by its vertices
  // (mesh::match_open_faces), or is a hull face. room(k) gives the arrays for k tets (4 k
  // vertex ids, 4 k neighbours: host memory, e.g. the caller's own, so that the output is
  // not copied again). Returns the flat tets dropped; adds the exact orientations to
  // `exact`. Frees the records.
  template <class Room>
  std::int64_t extract(Room room, const std::int64_t* sid, std::int64_t& exact) {
    using I64 = std::int64_t;
    constexpr std::int8_t kDead = -1, kInfTet = -100;  // else: the orientation (> 0 kept, 0 flat)
    constexpr I64 kAhead = 16;
    const I64 n = slots();
    par::Context<B>& ctx = mesh_.context();
    const Cell* cs = cells_.data();
    const Geo g = g_;
    par::Buffer<std::int8_t, B> sign(ctx, static_cast<std::size_t>(std::max<I64>(n, 1)));
    std::int8_t* sg = sign.data();
    exact += par::two_stage_signs(
        ctx, n, sg,
        [=](I64 t) -> std::int8_t {
          if (t + kAhead < n)  // the points of a tet a few slots on (their reads wait on the cache)
            for (int i = 0; i < 4; ++i)
              if (cs[t + kAhead].v[i] >= 0) __builtin_prefetch(g.p(cs[t + kAhead].v[i]));
          const vid_t* v = cs[t].v;
          if (v[0] == kNoVertex) return kDead;
          if (Geo::inf_slot(v, g.inf) >= 0) return kInfTet;
          return g.volume_sign_fast(v);
        },
        [=](I64 t, double* work) { return g.volume_sign_exact(cs[t].v, work); },
        geom::kPredicateWork);
    par::Buffer<tid_t, B> num(ctx, static_cast<std::size_t>(n + 1));
    tid_t* nm = num.data();
    par::parallel_for(ctx, n, [=](I64 t) { nm[t] = sg[t] > 0 ? 1 : 0; });
    const I64 nkeep = par::counts_to_offsets(ctx, nm, static_cast<std::size_t>(n));
    const I64 flat = par::count_indices(ctx, static_cast<std::size_t>(n), [=](I64 t) { return sg[t] == 0; });
    const auto [op, np] = room(nkeep);
    par::parallel_for(ctx, n, [=](I64 t) {
      if (t + kAhead < n)  // the neighbours' numbers a few slots on
        for (int i = 0; i < 4; ++i)
          if (cs[t + kAhead].n[i] >= 0) __builtin_prefetch(nm + tet_of(cs[t + kAhead].n[i]));
      if (nm[t + 1] == nm[t]) return;
      const Cell& c = cs[t];
      const I64 d = nm[t];
      for (int i = 0; i < 4; ++i) {
        op[4 * d + i] = static_cast<vid_t>(sid[c.v[i]]);
        const tid_t u = tet_of(c.n[i]);  // a closed mesh: every face has a neighbour
        np[4 * d + i] = sg[u] == kInfTet ? -1 : nm[u + 1] != nm[u] ? static_cast<std::int32_t>(nm[u]) : -2;
      }
    });
    num.release();
    sign.release();
    cells_.release();
    if (flat > 0) mesh::match_open_faces(ctx, op, np, nkeep);
    return flat;
  }

  const SequentialCounts& counts() const { return c_; }

 private:
  static constexpr std::int64_t kChunk = 1024;           // slots a thread takes at once
  static constexpr int kBlockShift = 4;                  // tets per lock: 16
  static constexpr int kDeferredPasses = 4;              // parallel passes of a round, at most

  struct Cell {
    vid_t v[4];         // kNoVertex: a free slot
    std::int32_t n[4];  // neighbour across face i: (tet << 2 | its face), -1 none
  };
  static tid_t tet_of(std::int32_t f) { return f >> 2; }
  static int face_of(std::int32_t f) { return f & 3; }
  struct Conflict {};  // a tet another thread holds, or no room left in a parallel round

  std::int64_t slots() const { return std::min<std::int64_t>(hwm_, static_cast<std::int64_t>(cells_.size())); }

  // BRIO order; rounds gets the start of every round and the end.
  static std::vector<vid_t> brio_order(const vid_t* todo, std::int64_t n, std::vector<std::int64_t>& rounds) {
    constexpr int kLevels = 24;
    auto level = [](vid_t q) {
      std::uint32_t h = static_cast<std::uint32_t>(q) * 0x9E3779B1u;
      h ^= h >> 15;
      h *= 0x85EBCA77u;
      h ^= h >> 13;
      int l = 0;
      while (l < kLevels - 1 && (h & 1u) == 0) {
        h >>= 1;
        ++l;
      }
      return l;
    };
    std::vector<std::uint8_t> round(static_cast<std::size_t>(n));  // kLevels - 1 - level: highest first
    std::vector<std::int64_t> start(kLevels + 1, 0);
    for (std::int64_t k = 0; k < n; ++k) {
      round[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(kLevels - 1 - level(todo[k]));
      ++start[round[static_cast<std::size_t>(k)] + 1];
    }
    for (int l = 0; l < kLevels; ++l) start[l + 1] += start[l];
    rounds.clear();
    for (int l = 0; l <= kLevels; ++l)
      if (rounds.empty() || start[l] != rounds.back()) rounds.push_back(start[l]);
    std::vector<vid_t> out(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) out[static_cast<std::size_t>(start[round[static_cast<std::size_t>(k)]]++)] = todo[k];
    return out;
  }

  // Room for cap slots (one thread only: the records may move); the new ones free.
  void grow(std::int64_t cap) {
    const std::int64_t old = static_cast<std::int64_t>(cells_.size());
    if (cap <= old) return;
    cells_.reserve(static_cast<std::size_t>(cap));  // keeps the contents
    cells_.resize(static_cast<std::size_t>(cap));
    if (knobs_.cavity) mark_.resize(static_cast<std::size_t>(cap), 0);
    Cell* cs = cells_.data();
    par::parallel_for(mesh_.context(), cap - old, [=](std::int64_t k) {
      cs[old + k] = Cell{{kNoVertex, kNoVertex, kNoVertex, kNoVertex}, {-1, -1, -1, -1}};
    });
  }

  // One round on all threads: the points cut into contiguous pieces, one per thread; the
  // deferred ones again in pieces about the borders, then the last of them on this thread.
  void parallel_round(const vid_t* pts, std::int64_t n) {
    Worker& w0 = workers_[0];
    // room for every slot the round can take without growing: ≈ 6.7 tets per point
    // (7.25 reserved) and each thread's unused chunks; a thread that runs out defers its
    // points to the single-threaded pass, which grows the records
    const std::int64_t need = hwm_ + 7 * n + n / 4 + 4 * kChunk * static_cast<std::int64_t>(threads_);
    if (need > static_cast<std::int64_t>(cells_.size())) grow(need + need / 4);
    const std::size_t nb = (cells_.size() >> kBlockShift) + 1;
    owner_.reset(new std::atomic<std::uint8_t>[nb]);
    for (std::size_t b = 0; b < nb; ++b) owner_[b].store(0, std::memory_order_relaxed);
    if (!knobs_.cavity) logged_.assign(cells_.size(), 0);
    std::vector<std::int64_t> cut(threads_ + 1);
    for (unsigned w = 0; w <= threads_; ++w) cut[w] = n * w / threads_;
    std::vector<vid_t> rest = insert_pieces(pts, cut);
    std::vector<vid_t> prev;  // a later pass's points (pts then points here), for the next cut
    // The deferred points lie about the borders of the pieces (where two threads met). They
    // go again on all threads, in pieces centred on those borders: cut at the middles of
    // the pieces before (by id: the curve), while that leaves fewer; the rest on this
    // thread. (With 16 threads 3-4 % of the points are deferred at 10^6, counted
    // oversubscribed on 2 cores: one thread's work after every round, else.)
    for (int pass = 1; pass < kDeferredPasses; ++pass) {
      const std::int64_t nr = static_cast<std::int64_t>(rest.size());
      if (nr < std::max<std::int64_t>(knobs_.parallel_min, threads_)) break;
      std::vector<std::int64_t> mid;
      mid.push_back(0);
      for (std::size_t w = 0; w + 1 < cut.size(); ++w) {
        if (cut[w] == cut[w + 1]) continue;
        const vid_t m = pts[(cut[w] + cut[w + 1]) / 2];
        mid.push_back(std::lower_bound(rest.begin(), rest.end(), m) - rest.begin());
      }
      mid.push_back(nr);
      std::vector<vid_t> more = insert_pieces(rest.data(), mid);
      const bool fewer = more.size() < rest.size();
      prev = std::move(rest);
      pts = prev.data();
      cut = std::move(mid);
      rest = std::move(more);
      if (!fewer) break;
    }
    w0.begin(false);
    for (vid_t q : rest) w0.insert_point(q);
  }

  // The points pts[cut[j] .. cut[j + 1]) as piece j, the pieces on the host threads (each
  // from its first point's tet, found here before the threads run); returns the points
  // deferred, sorted (the curve's order).
  std::vector<vid_t> insert_pieces(const vid_t* pts, const std::vector<std::int64_t>& cut) {
    const std::size_t np = cut.size() - 1;
    Worker& w0 = workers_[0];
    w0.begin(false);  // the records may have moved
    std::vector<tid_t> start(np);
    for (std::size_t j = 0; j < np; ++j) start[j] = cut[j] < cut[j + 1] ? w0.locate(pts[cut[j]], w0.newest_) : w0.newest_;
    par::on_host_threads(
        np,
        [&](std::size_t j) {
          Worker& me = workers_[static_cast<std::size_t>(omp_get_thread_num())];
          me.begin(true);
          me.newest_ = start[j];
          for (std::int64_t k = cut[j]; k < cut[j + 1]; ++k) me.try_insert(pts[k]);
          me.release_all();
        },
        static_cast<int>(threads_));
    std::vector<vid_t> rest;
    for (Worker& w : workers_) {
      rest.insert(rest.end(), w.deferred_.begin(), w.deferred_.end());
      w.deferred_.clear();
    }
    std::sort(rest.begin(), rest.end());
    return rest;
  }

  // One thread's state. Outside a parallel round only workers_[0] runs, without taking
  // tets or logging.
  class Worker {
   public:
    Worker(SequentialInsertion& s, std::uint8_t id) : s_(&s), g_(s.g_), id_(id), work_(geom::kPredicateWork) {}

    // --- predicates: filter first, exact (SoS) when it cannot decide --------------------
    // r: a filter's answer; undecided: exact() instead, counted
    template <class Exact>
    GDEL_FORCEINLINE int settle(int r, Exact&& exact) {
      if (r != par::kUndecided) return r;
      ++c_.exact;
      return exact();
    }
    int orient(vid_t a, vid_t b, vid_t c, vid_t d) {
      return settle(g_.orient_fast(a, b, c, d), [&] { return g_.orient_exact(a, b, c, d, work_.data()); });
    }
    int insphere(const vid_t* t, vid_t e) {
      return settle(g_.template insphere<false>(t, e, nullptr),
                    [&] { return g_.template insphere<true>(t, e, work_.data()); });
    }
    // in[j] = insphere(q[j]->v, p) > 0 for j < n (n <= 4): the finite tets' filters
    // together (geom::insphere_filter4, one per SIMD lane) when there are several, the
    // rest as insphere() does.
    void insphere_batch(const Cell* const* q, int n, vid_t p, bool* in) {
      const double* pts[4][4];
      int lane[4], nf = 0;
      for (int j = 0; j < n; ++j) {
        if (Geo::inf_slot(q[j]->v, g_.inf) >= 0) {
          in[j] = insphere(q[j]->v, p) > 0;
          continue;
        }
        for (int i = 0; i < 4; ++i) pts[nf][i] = g_.p(q[j]->v[i]);
        lane[nf++] = j;
      }
      if (nf == 1) in[lane[0]] = insphere(q[lane[0]]->v, p) > 0;
      if (nf <= 1) return;
      int s[4];
      geom::insphere_filter4(pts, g_.p(p), nf, s);
      for (int f = 0; f < nf; ++f)
        in[lane[f]] = settle(Geo::filter_answer(s[f]),
                             [&] { return g_.template insphere<true>(q[lane[f]]->v, p, work_.data()); }) > 0;
    }
    int face_flip_any(const vid_t* bv, const vid_t* apex, int i) {
      const int f = face_flip<false>(g_, bv, apex, i, nullptr);
      if (f != kUndecidedResult) return f;
      ++c_.exact;
      return face_flip<true>(g_, bv, apex, i, work_.data());
    }

    // --- tets: taken before any access in a parallel round, logged before a write ---------
    // A thread takes the block of 2^kBlockShift slots a tet is in (owner byte = its id,
    // compare-and-swap): one atomic operation for several tets of a point's neighbourhood.
    GDEL_FORCEINLINE void take(tid_t t) {
      if (!par_) return;
      std::atomic<std::uint8_t>& o = own_[static_cast<std::size_t>(t) >> kBlockShift];
      if (o.load(std::memory_order_relaxed) == id_) return;
      acquire(o, t);
    }
    void acquire(std::atomic<std::uint8_t>& o, tid_t t) {
      if (writing_) throw std::logic_error("gflip3d (one point per round): a cavity insertion took a tet after its first write");
      std::uint8_t z = 0;
      if (!o.compare_exchange_strong(z, id_, std::memory_order_acquire)) throw Conflict{};
      held_.push_back(t >> kBlockShift);
      if (force_ > 0 && ++takes_ % force_ == 0) throw Conflict{};
    }
    GDEL_FORCEINLINE const Cell& rd(tid_t t) {
      take(t);
      return cs_[t];
    }
    GDEL_FORCEINLINE Cell& wr(tid_t t) {
      Cell& c = cs_[t];
      if (!par_) return c;
      take(t);
      if (!log_) return c;
      std::uint8_t& lg = logged_[static_cast<std::size_t>(t)];  // the block holder's alone
      if (!lg) log(t, lg);
      return c;
    }
    void log(tid_t t, std::uint8_t& lg) {
      undo_.push_back({t, cs_[t]});
      lg = 1;
    }
    // Starts a round: parallel or not, on the current records.
    void begin(bool parallel) {
      par_ = parallel;
      cs_ = s_->cells_.data();
      own_ = s_->owner_.get();
      logged_ = s_->logged_.data();
      mark_ = s_->mark_.data();
      force_ = parallel ? s_->knobs_.force_conflict : 0;
      hold_ = s_->knobs_.hold;
      cavity_ = s_->knobs_.cavity;
      log_ = parallel && !cavity_;
    }

    // --- slots -------------------------------------------------------------------------
    // A claimed slot is taken and flagged as logged without a copy: it held no tet, so an
    // undo frees it again (try_insert) instead of restoring it, and its first write skips
    // the log's read of the old record.
    tid_t claim() {
      tid_t t;
      if (!free_.empty()) {
        t = free_.back();
        if (par_) take(t);  // before the pop: a conflict leaves the slot on the list
        free_.pop_back();
      } else {
        if (next_ == end_) {
          if (par_) {
            const std::int64_t b = s_->hwm_.fetch_add(kChunk);
            if (b + kChunk > std::min<std::int64_t>(static_cast<std::int64_t>(s_->cells_.size()), kMaxTets))
              throw Conflict{};  // the single-threaded pass grows the records, or reports the limit
            next_ = b;
            end_ = b + kChunk;
          } else {
            const std::int64_t b = s_->hwm_.load();
            if (b + kChunk > kMaxTets)
              throw Error("gflip3d (one point per round): more than 2^29 tets; use Options::cpu_rounds");
            if (b + kChunk > static_cast<std::int64_t>(s_->cells_.size())) {
              s_->grow(b + kChunk + static_cast<std::int64_t>(s_->cells_.size()) / 4);
              cs_ = s_->cells_.data();  // the records moved
              mark_ = s_->mark_.data();
            }
            s_->hwm_.store(b + kChunk);
            next_ = b;
            end_ = b + kChunk;
          }
        }
        if (par_) take(static_cast<tid_t>(next_));
        t = static_cast<tid_t>(next_++);
      }
      if (par_) {
        if (log_) logged_[static_cast<std::size_t>(t)] = 1;
        claimed_.push_back(t);
      }
      return t;
    }
    void kill(tid_t t) {
      Cell& c = wr(t);
      c = Cell{{kNoVertex, kNoVertex, kNoVertex, kNoVertex}, {-1, -1, -1, -1}};
      (par_ ? freed_ : free_).push_back(t);
    }
    vid_t apex(const Cell& c, int i) { return c.n[i] < 0 ? kNoVertex : rd(tet_of(c.n[i])).v[face_of(c.n[i])]; }

    // --- location: remembering stochastic visibility walk (Devillers-Pion-Teillaud) -----
    // Exact orientations with ∞ (Geo: the kernel point's cones outside the hull)
    // subdivide space consistently, so the walk ends in the tet that holds q (SoS: never
    // on a face). A free start (another thread's flips took it) is replaced by a live
    // tet of this thread's recent slots.
    tid_t locate(vid_t q, tid_t t) {
      if (rd(t).v[0] == kNoVertex) t = live_tet();
      int from = -1;
      // a walk longer than that would be a broken mesh: an error, not a hang
      const std::int64_t cap = 16 * s_->hwm_.load(std::memory_order_relaxed) + (1 << 20);
      for (std::int64_t step = 0;; ++step) {
        if (step > cap) throw std::logic_error("gflip3d (one point per round): point location did not end");
        const Cell c = rd(t);
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 17;
        rng_ ^= rng_ << 5;
        const int k0 = static_cast<int>(rng_ & 3u);
        // The faces from k0 on (not the one come through): the first that q is beyond is
        // the exit. Their filters run together (geom::orient3d_filter4, one per SIMD lane);
        // an undecided one goes exact when its turn comes, as orient() does.
        int face[4], nf = 0;
        for (int k = 0; k < 4; ++k)
          if (((k0 + k) & 3) != from) face[nf++] = (k0 + k) & 3;
        const double* pts[4][3];
        for (int j = 0; j < nf; ++j)
          for (int m = 0; m < 3; ++m) pts[j][m] = g_.p(c.v[face_vertex(face[j], m)]);
        int s[4];
        geom::orient3d_filter4(pts, g_.p(q), nf, s);
        int exit = -1;
        for (int j = 0; j < nf && exit < 0; ++j) {
          const vid_t a = c.v[face_vertex(face[j], 0)], b = c.v[face_vertex(face[j], 1)];
          const vid_t d = c.v[face_vertex(face[j], 2)];
          const bool with_inf = g_.has_inf(a, b, d, q);
          int r = Geo::filter_answer(s[j]);
          if (with_inf && g_.k_centroid) r = g_.orient_fast(a, b, d, q);          // (K is not the slot's double)
          else if (r != par::kUndecided && with_inf) r = g_.inf_sign * r;  // as Geo::orient_fast
          if (settle(r, [&] { return g_.orient_exact(a, b, d, q, work_.data()); }) < 0) exit = face[j];
        }
        if (exit < 0) return t;
        from = face_of(c.n[exit]);
        t = tet_of(c.n[exit]);
      }
    }
    tid_t live_tet() {
      for (std::int64_t t = std::max<std::int64_t>(next_ - 1, 0); t >= 0; --t) {
        try {
          if (rd(static_cast<tid_t>(t)).v[0] != kNoVertex) return static_cast<tid_t>(t);
        } catch (const Conflict&) {
        }
      }
      throw Conflict{};
    }

    // --- 1-4 split (children as flip_kernels.hpp's split_child_vertices) ---------------
    void split(tid_t o, vid_t p) {
      const Cell oc = rd(o);
      tid_t c[4] = {o, 0, 0, 0};
      for (int i = 1; i < 4; ++i) c[i] = claim();
      Cell* cc[4];  // taken and logged once (after the claims: a claim may move the records)
      for (int i = 0; i < 4; ++i) cc[i] = &wr(c[i]);
      for (int i = 0; i < 4; ++i) {
        Cell& x = *cc[i];
        split_child_vertices(oc.v, p, i, x.v);
        x.n[3] = oc.n[i];
        back(oc.n[i], c[i], 3);
        for (int k = 0; k < 3; ++k) {
          const int j = face_vertex(i, k);
          x.n[k] = c[j] << 2 | split_shared_face(j, i);
        }
        stack_.push_back(c[i]);
      }
      newest_ = c[3];
    }

    // --- flips (records and new tets as flip_kernels.hpp's FlipRec / flip_new_tets) ----
    // The neighbour across the face of tet c opposite its vertex w, as a packed facet.
    static std::int32_t across(const Cell& c, vid_t w) {
      int l = 0;
      for (int k = 1; k < 4; ++k)
        if (c.v[k] == w) l = k;
      return c.n[l];
    }
    // The back link of the tet across a new tet's face: facet e (-1: none) gets (t, i).
    // A flip's outer neighbours are never among its own tets, so the new tets' records
    // are written through references taken once.
    void back(std::int32_t e, tid_t t, int i) {
      if (e >= 0) wr(tet_of(e)).n[face_of(e)] = t << 2 | i;
    }
    // 2-3: ts = (b, u), b = (face c0 c1 c2, v), u = (face, x); new N_k = (c_k, c_k+1, x,
    // v). N_k's face 0 is N_k+1's face 1; its face 2 (opposite x) was b's face opposite
    // c_k+2, its face 3 (opposite v) u's.
    void flip23(const tid_t* ts, const FlipRec& r) {
      const Cell T = rd(ts[0]), U = rd(ts[1]);
      std::int32_t eb[3], eu[3];
      for (int k = 0; k < 3; ++k) {
        eb[k] = across(T, r.v[(k + 2) % 3]);
        eu[k] = across(U, r.v[(k + 2) % 3]);
      }
      const tid_t s[3] = {ts[0], ts[1], claim()};
      Cell* sc[3] = {&wr(s[0]), &wr(s[1]), &wr(s[2])};
      vid_t nv[3][4];
      flip_new_tets(r, nv);
      for (int k = 0; k < 3; ++k) {
        Cell& x = *sc[k];
        for (int q = 0; q < 4; ++q) x.v[q] = nv[k][q];
        x.n[0] = s[(k + 1) % 3] << 2 | 1;
        x.n[1] = s[(k + 2) % 3] << 2 | 0;
        x.n[2] = eb[k];
        x.n[3] = eu[k];
        back(eb[k], s[k], 2);
        back(eu[k], s[k], 3);
        stack_.push_back(s[k]);
      }
      newest_ = s[2];
    }
    // 3-2 of edge (eA, eB) = (r.v[3], r.v[4]): the old tet without r_j gives A = (r0, r1,
    // r2, eA) its face opposite r_j (its own face opposite eB) and B = (r1, r0, r2, eB)
    // its face opposite r_j (its own opposite eA); A and B share their faces 3.
    void flip32(const tid_t* ts, const FlipRec& r) {
      const vid_t eA = r.v[3], eB = r.v[4];
      std::int32_t ea[3], eb[3];
      for (int a = 0; a < 3; ++a) {
        const Cell T = rd(ts[a]);
        int j = 0;
        for (int q = 0; q < 3; ++q) {
          bool in = false;
          for (int k = 0; k < 4; ++k) in = in || T.v[k] == r.v[q];
          if (!in) j = q;
        }
        ea[j] = across(T, eB);
        eb[j] = across(T, eA);
      }
      const tid_t s[2] = {ts[0], ts[1]};
      kill(ts[2]);
      Cell& na = wr(s[0]);
      Cell& nb = wr(s[1]);
      vid_t nv[3][4];
      flip_new_tets(r, nv);
      for (int q = 0; q < 4; ++q) {
        na.v[q] = nv[0][q];
        nb.v[q] = nv[1][q];
      }
      na.n[3] = s[1] << 2 | 3;
      nb.n[3] = s[0] << 2 | 3;
      constexpr int kInB[3] = {1, 0, 2};  // local index of r_j in B
      for (int j = 0; j < 3; ++j) {
        na.n[j] = ea[j];
        nb.n[kInB[j]] = eb[j];
        back(ea[j], s[0], j);
        back(eb[j], s[1], kInB[j]);
      }
      stack_.push_back(s[0]);
      stack_.push_back(s[1]);
      newest_ = s[1];
    }

    // --- one point ---------------------------------------------------------------------
    void insert(vid_t p) {
      split(locate(p, newest_), p);
      while (!stack_.empty()) {
        const tid_t t = stack_.back();
        stack_.pop_back();
        const Cell c = rd(t);
        int ip = -1;
        for (int k = 0; k < 4; ++k)
          if (c.v[k] == p) ip = k;
        if (ip < 0 || c.n[ip] < 0) continue;  // gone (its slot free or taken by a tet of this point's)
        vid_t ap[4];
        ap[ip] = apex(c, ip);
        if (insphere(c.v, ap[ip]) <= 0) continue;  // locally Delaunay
        for (int i = 0; i < 4; ++i)
          if (i != ip) ap[i] = apex(c, i);
        const int prop = face_flip_any(c.v, ap, ip);
        if (prop < 0) continue;  // blocked: other flips of this point remove the face
        // the record, as flip_outputs makes it
        FlipRec r;
        r.type = prop_type(prop);
        tid_t ts[3] = {t, tet_of(c.n[ip]), -1};
        if (r.type == 1) {
          for (int k = 0; k < 3; ++k) r.v[k] = c.v[face_vertex(ip, k)];
          r.v[3] = p;
          r.v[4] = ap[ip];
          ++c_.flips23;
          flip23(ts, r);
          continue;
        }
        const int k = prop_other(prop);
        ts[2] = tet_of(c.n[k]);
        int ne = 3;
        for (int l = 0; l < 4; ++l)
          if (l != ip && l != k) r.v[ne++] = c.v[l];
        r.v[0] = p;
        r.v[1] = c.v[k];
        r.v[2] = ap[ip];
        if (order_32<false>(g_, r, nullptr) == kUndecidedResult) {
          ++c_.exact;
          order_32<true>(g_, r, work_.data());
        }
        ++c_.flips32;
        flip32(ts, r);
      }
      ++c_.inserted;
    }

    // --- one point by its conflict cavity (Bowyer-Watson; Knobs::cavity) ---------------
    // The tets whose circumsphere holds p (Geo::insphere > 0; with ∞: p beyond the hull
    // face) form a connected region that holds p's tet and is star-shaped from p: in the
    // lifted view they are the facets of the lower hull that lifted p sees, under the one
    // consistent perturbation of Geo (SoS: no ties). It is found by a search over faces
    // from p's tet, each tet tested once (mark_). Every face of the region's boundary gets
    // a new tet, the face's tet with p in place of its vertex inside the region (p lies on
    // that vertex's side of the face, so the orientation stays positive); two new tets
    // meet across the face (p, a, b) of each boundary edge ab, matched through a hash of
    // the edge. The region's slots are used again; the rest are claimed or freed. The
    // result is the Delaunay triangulation of the points so far, as after the flips of
    // insert(); the work per point is less (bench/RESULTS.md, session 26): each tet near p
    // is tested once, no flip is decided (face_flip's orientations) and every new tet is
    // written once instead of being made and flipped away again.
    struct Bnd {
      vid_t v[4];           // the new tet
      std::int32_t outer;   // the tet across the boundary face (t << 2 | face), -1 none
      std::int32_t face;    // the face's index in the new tet (p's slot)
    };
    struct Edge {
      std::uint64_t key;
      std::int32_t link;
      std::uint32_t stamp;  // occupied iff == stamp_
    };
    void insert_cavity(vid_t p) {
      const tid_t t0 = locate(p, newest_);
      unmark();
      rd(t0);
      mark_[static_cast<std::size_t>(t0)] = 1;
      seen_.push_back(t0);
      cav_.push_back(t0);
      // A tet's neighbours' records and marks are fetched when it joins the region, well
      // before its turn in the search (the search waits on them, not on the tests).
      auto fetch_around = [this](const Cell& c) {
        for (int i = 0; i < 4; ++i)
          if (c.n[i] >= 0) {
            __builtin_prefetch(&cs_[tet_of(c.n[i])]);
            __builtin_prefetch(&mark_[static_cast<std::size_t>(tet_of(c.n[i]))]);
          }
      };
      fetch_around(cs_[t0]);
      for (std::size_t k = 0; k < cav_.size(); ++k) {
        const Cell c = rd(cav_[k]);
        // Its neighbours taken in face order, the untested ones' tests made together
        // (insphere_batch), then each face: inside, or a boundary face.
        std::int8_t face[4];  // -1: a neighbour inside (no boundary), -2: boundary, j >= 0: test j
        const Cell* q[4];
        int nq = 0;
        for (int i = 0; i < 4; ++i) {
          face[i] = -2;
          if (c.n[i] < 0) continue;
          const Cell& uc = rd(tet_of(c.n[i]));  // taken before its mark is read: another thread's search marks its own tets
          const std::uint8_t m = mark_[static_cast<std::size_t>(tet_of(c.n[i]))];
          if (m == 1) face[i] = -1;
          if (m == 0) {
            face[i] = static_cast<std::int8_t>(nq);
            q[nq++] = &uc;
          }
        }
        bool in[4];
        if (nq > 0) insphere_batch(q, nq, p, in);
        for (int i = 0; i < 4; ++i) {
          if (face[i] == -1) continue;
          if (face[i] >= 0) {
            const tid_t u = tet_of(c.n[i]);
            const bool inside = in[face[i]];
            mark_[static_cast<std::size_t>(u)] = inside ? 1 : 2;
            seen_.push_back(u);
            if (inside) {
              cav_.push_back(u);
              fetch_around(*q[face[i]]);
              continue;
            }
          }
          Bnd b{{c.v[0], c.v[1], c.v[2], c.v[3]}, c.n[i], i};
          b.v[i] = p;
          bnd_.push_back(b);
        }
      }
      // slots: the region's own, then claimed ones (claims may move the records: no
      // reference is held across them); a region larger than its boundary frees the rest
      const std::size_t nb = bnd_.size(), nc = cav_.size();
      slot_.assign(cav_.begin(), cav_.begin() + static_cast<std::ptrdiff_t>(std::min(nb, nc)));
      for (std::size_t k = nc; k < nb; ++k) slot_.push_back(claim());
      writing_ = par_ && !log_;  // no conflict from here on (nothing logged to undo one)
      for (std::size_t k = nb; k < nc; ++k) kill(cav_[k]);
      for (std::size_t k = 0; k < nb; ++k) wr(slot_[k]);  // taken and logged before the writes
      if (++stamp_ == 0) {  // wrapped: every entry free again
        for (Edge& x : ht_) x.stamp = 0;
        stamp_ = 1;
      }
      std::size_t cap = 64;
      while (cap < 4 * nb) cap <<= 1;
      if (ht_.size() < cap) ht_.assign(cap, Edge{0, -1, 0});
      const std::size_t mask = ht_.size() - 1;
      for (std::size_t k = 0; k < nb; ++k) {
        const Bnd& b = bnd_[k];
        const tid_t t = slot_[k];
        Cell& x = cs_[t];
        for (int q = 0; q < 4; ++q) x.v[q] = b.v[q];
        x.n[b.face] = b.outer;
        back(b.outer, t, b.face);
        for (int j = 0; j < 4; ++j) {
          if (j == b.face) continue;
          vid_t ab[2];
          int na = 0;
          for (int q = 0; q < 4; ++q)
            if (q != j && q != b.face) ab[na++] = b.v[q];
          const std::uint32_t lo = static_cast<std::uint32_t>(std::min(ab[0], ab[1]));
          const std::uint32_t hi = static_cast<std::uint32_t>(std::max(ab[0], ab[1]));
          const std::uint64_t key = std::uint64_t(hi) << 32 | lo;
          for (std::size_t h = (lo * 0x9E3779B1u ^ hi * 0x85EBCA77u) & mask;; h = (h + 1) & mask) {
            Edge& en = ht_[h];
            if (en.stamp != stamp_) {
              en = Edge{key, t << 2 | j, stamp_};
              break;
            }
            if (en.key == key) {
              x.n[j] = en.link;
              cs_[tet_of(en.link)].n[face_of(en.link)] = t << 2 | j;
              break;
            }
          }
        }
      }
      newest_ = slot_[nb - 1];
      writing_ = false;
      unmark();
      ++c_.inserted;
    }
    // The search's marks back to 0 (after the point, or an abort).
    void unmark() {
      for (tid_t t : seen_) mark_[static_cast<std::size_t>(t)] = 0;
      seen_.clear();
      cav_.clear();
      bnd_.clear();
    }
    void insert_point(vid_t p) {
      if (cavity_) insert_cavity(p);
      else insert(p);
    }

    // In a parallel round: insert p as a transaction; on a conflict, undo and defer it.
    void try_insert(vid_t p) {
      bool conflict = false;
      const tid_t newest0 = newest_;
      const SequentialCounts c0 = c_;
      try {
        insert_point(p);
      } catch (const Conflict&) {
        conflict = true;
        unmark();
        for (std::size_t k = undo_.size(); k-- > 0;) cs_[undo_[k].first] = undo_[k].second;
        for (tid_t t : claimed_) {
          cs_[t] = Cell{{kNoVertex, kNoVertex, kNoVertex, kNoVertex}, {-1, -1, -1, -1}};
          free_.push_back(t);
        }
        freed_.clear();
        stack_.clear();
        newest_ = newest0;
        c_ = c0;
        ++c_.deferred;
        deferred_.push_back(p);
      }
      for (tid_t t : freed_) free_.push_back(t);
      freed_.clear();
      if (log_)
        for (tid_t t : claimed_) logged_[static_cast<std::size_t>(t)] = 0;
      claimed_.clear();
      for (const auto& u : undo_) logged_[static_cast<std::size_t>(u.first)] = 0;
      undo_.clear();
      if (conflict || ++since_release_ >= hold_) release_all();
    }
    void release_all() {
      for (tid_t b : held_) own_[static_cast<std::size_t>(b)].store(0, std::memory_order_release);
      held_.clear();
      since_release_ = 0;
    }

    SequentialInsertion* s_;
    Geo g_;
    std::uint8_t id_;
    std::vector<double> work_;
    std::vector<tid_t> stack_;  // tets with the new point whose face opposite it is to check
    std::vector<tid_t> free_;   // this thread's free slots
    std::int64_t next_ = 0, end_ = 0;  // this thread's chunk of fresh slots
    tid_t newest_ = 0;                 // the tet made last
    std::uint32_t rng_ = 2463534242u;
    SequentialCounts c_;
    // the transaction of a parallel round
    std::vector<tid_t> held_, claimed_, freed_;  // held_: blocks
    std::vector<std::pair<tid_t, Cell>> undo_;
    std::vector<vid_t> deferred_;
    std::int64_t takes_ = 0, force_ = 0;  // Knobs::force_conflict
    std::int64_t hold_ = 1, since_release_ = 0;  // Knobs::hold; insertions since the blocks were released
    bool par_ = false;                    // in a parallel round: take, log (if log_)
    // par_ and flips: a flip writes before the next one reads, so a conflict finds tets
    // written; insert_cavity's claims come before its first write, its other writes go to
    // tets its search took: a conflict finds nothing written, and nothing is logged
    bool log_ = false;
    bool writing_ = false;  // insert_cavity without log_ between its first write and its end
    Cell* cs_ = nullptr;                  // the records (s_->cells_; moved only by a grow)
    std::atomic<std::uint8_t>* own_ = nullptr;
    std::uint8_t* logged_ = nullptr;
    // Knobs::cavity: the region's tets, every tet tested (marked), the boundary faces,
    // the new tets' slots, the edge table
    bool cavity_ = false;
    std::uint8_t* mark_ = nullptr;  // s_->mark_: 1 in the region, 2 tested outside
    std::vector<tid_t> cav_, seen_, slot_;
    std::vector<Bnd> bnd_;
    std::vector<Edge> ht_;
    std::uint32_t stamp_ = 0;
  };

  mesh::TetMesh<B>& mesh_;
  Geo g_;
  par::Buffer<Cell, B> cells_;  // the tets (backend memory: counted in Stats::peak_bytes)
  std::atomic<std::int64_t> hwm_{0};  // slots [0, hwm) handed out (some as unused chunks)
  std::unique_ptr<std::atomic<std::uint8_t>[]> owner_;  // parallel rounds: holder of each block of tets
  std::vector<std::uint8_t> logged_;  // parallel rounds: tet logged in its holder's transaction
  std::vector<std::uint8_t> mark_;    // Knobs::cavity: a tet's mark in its holder's search (0 between points)
  Knobs knobs_;
  unsigned threads_ = 1;
  std::vector<Worker> workers_;
  SequentialCounts c_;
};

}  // namespace gdel::flip
