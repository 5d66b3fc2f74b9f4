// gFlip3D: massively parallel point insertion and flipping (ALGORITHMS.md §3),
// written once over the backend tag B.
//
// Input: n distinct points in internal order (Hilbert-sorted) plus the SoS index of
// each (its original input index). Output: the mesh (internal ids, ∞ = n), the
// failed vertices and statistics. Host orchestration only; all per-element work is
// in flip_kernels.hpp and runs through the parallel layer.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "flip/flip_kernels.hpp"
#include "flip/local_delaunay.hpp"
#include "flip/sequential.hpp"
#include "geometry/interior_point.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "parallel/exact_batch.hpp"
#include "parallel/primitives.hpp"
#include "parallel/team.hpp"

namespace gdel::flip {

using par::Buffer;
using par::Context;

struct FlipConfig {
  InsertionRule rule = InsertionRule::Circumcenter;
  bool terminal = false;
  // One point per round (flip/sequential.hpp), host backends only: the default on the
  // CPU backend (Options::cpu_rounds = false), where the thesis's parallel rounds cost
  // several times CGAL's sequential insertion; leaves the exact Delaunay triangulation.
  // Needs the default start (not Options::initial = grid); the other round options
  // (terminal, independent splits, non-optimal flips, tet reordering) do not apply.
  bool sequential = false;
  // How one point per round inserts a point: true, by its conflict cavity (Bowyer-Watson:
  // the tets whose circumsphere holds it replaced by the new tets of the cavity's
  // boundary, bench/RESULTS.md session 26: ≈ 20 % less time than the flips); false, by a
  // 1-4 split and flips (the classical flip-based algorithm). The same triangulation
  // either way; gdel::delaunay takes the cavity for its exact algorithms and the flips for
  // Algorithm::gflip3d (a flip algorithm, whose stats count flips). GDEL_CPU_INSERT=flip
  // or =cavity overrides it (study).
  bool cavity = false;
  std::int64_t max_flip_iterations = 1 << 20;  // per flip loop; a safety net, never reached in practice
  bool tail_rule = std::getenv("GDEL_FLIP_EVERY_ROUND") == nullptr;  // study knob (ALGORITHMS.md §3.1)
  // The flip loop after the tail's split-only rounds starts from the tets those rounds
  // made (with any stuck tets carried): the rest were left by flip loops with nothing to
  // flip. true: from every tet, as before session 53, which also retries the facets
  // flip loops left stuck - for about nothing (10^6 sphere: 4 152 failed vertices
  // against 4 176; uniform: the same 1 086) at a pass of exact tests over every tet on
  // cospherical input (3.4 s of 20 on the CPU backend; bench/RESULTS.md session 53).
  // The terminal variant (no flipping before the end) always flips from every tet.
  // GDEL_FINAL_ALL_TETS=1 sets it (study).
  bool final_all_tets = par::knob_on("GDEL_FINAL_ALL_TETS");
  // Independent splits (Options::independent_splits): in a round that flips, a tet that
  // holds points splits only when no neighbour that also holds points comes first in a
  // fixed random order of tets (split_defers), so the round's splits share no face; and
  // stuck tets stay active (commit_flips, carry_). 3-5x fewer facets left stuck for 2-4x
  // the rounds (bench/RESULTS.md, session 11). Off: every tet that holds points splits
  // (the original rule) and a stuck tet leaves the active set. Rounds that only split
  // (terminal variant, tail rule) never defer.
  bool independent_splits = false;
  // rule = Circumcenter: the rounds insert in SoS order (InsertionRule::SosOrder) once
  // the flipping's exact insphere ties are at least 1/kTieShare of its proposals, decided
  // once at the first round that brings the proposals to kSosSample
  // (GFlip3D::decide_sos_order). GDEL_SOS_ORDER_SWITCH=0: never (study).
  bool sos_order_switch = !par::knob_off("GDEL_SOS_ORDER_SWITCH");
  // Re-order tets by smallest vertex id every reorder_every-th round and once for the
  // output (ALGORITHMS.md §2.2): with curve-sorted points this restores spatial locality
  // in memory (Options::reorder_tets). Each sort only when its temporaries fit under the
  // memory peak so far (GFlip3D::reorder_tets). reorder_every = 0: the output's sort
  // only. Every round since session 25 (every second before: uniform 10^7 on an H200
  // 0.717 -> 0.681 s at the same peak, bench/RESULTS.md session 24; below 5*10^6 points
  // the interval makes no resolved difference, session 27). Test and study knobs
  // GDEL_TET_REORDER=0/1 and GDEL_REORDER_EVERY (read by run()).
  bool reorder_tets = false;
  int reorder_every = 1;
  // ... and then only when the points inserted since the last sort are at least
  // 1/reorder_share of those inserted so far (0: every reorder_every-th round): the last
  // rounds insert a few per cent of the points, which moves few tets out of order, while
  // each sort moves the whole mesh. 4 by default since session 67 (H100, same calls: uniform 10^7
  // 0.475-0.478 s against 0.499-0.500 with every round's sort, 8 gave 0.489; 2 and 3 the
  // same sorts as 4 there; 10^6 uniform, grid, sphere and 10^8 unchanged; bench/RESULTS.md).
  // Under independent splits -1 means 0 (every round's sort): their quality tests'
  // stuck facets were measured with it and depend on the slot order (with 4, two of them
  // on the CPU's rounds: 1 182 stuck against 1 145 without non-optimal flips, 310 where
  // 129 is the bound). Study knob GDEL_REORDER_SHARE (0: every round's sort).
  int reorder_share = -1;  // -1: 4, or 0 under independent splits
  // Non-optimal flipping once flipping is stuck at the end (Options::nonoptimal_flips):
  // at most nonoptimal_rounds rounds, each of at most nonoptimal_steps parallel steps of
  // non-improving flips followed by a normal flip loop. With independent_splits also one
  // such round after every InsFlip round's flip loop, from the tets it left stuck.
  bool nonoptimal = false;
  // ... skipped when the stuck facets exceed this share of the points (1: never skipped)
  double nonoptimal_max_share = 1.0;
  // ... and the state with the fewest non-locally-Delaunay facets is kept (a copy of the
  // mesh, 37 bytes per tet slot, beside the work arrays); without it (Auto, whose repair
  // makes any state exact) the last state is the result
  bool nonoptimal_keep_best = true;
  int nonoptimal_rounds = 16;
  int nonoptimal_steps = 8;
  // The flip log of a round (the flip DAG that relocates the uninserted points) holds at
  // most this many records per point (48 bytes each): past it, the points are relocated
  // through the flips so far and the log starts again (same result; an extra walk) ...
  double log_records_per_point = 0.5;
  // ... and at least this many from log_floor_min_points points up (two records a point
  // at 10^7, where 5 million took 9-10 ms more in walks: bench/RESULTS.md, session 71;
  // half a record a point is more from 4 * 10^7 up, so 10^8's peak is unchanged)
  std::int64_t log_records_floor = 20000000;
  std::int64_t log_floor_min_points = 10000000;
  // ... or exactly this many records when > 0 (test knob GDEL_FLIP_LOG_RECORDS, read by
  // run(): a few records exercise the flushes).
  std::int64_t log_records = 0;
  // At most this many flips are executed per flip iteration: the accepted flips past it
  // (in proposer order) stand down as if outvoted and propose again in the next
  // iteration. Bounds an iteration's temporaries (≈ 130 bytes per flip: external-face
  // entries, records, next active set), which at 10^8 points would otherwise reach
  // 17 GB in the largest iterations. GDEL_FLIPS_PER_ITERATION sets it (read by run()).
  std::int64_t max_flips_per_iteration = std::int64_t(1) << 24;
};

// The fast/exact split of the parallel layer with the predicates' scratch size. exact
// returns whether it decided; a generic exact(i, auto work) gets its own instance without
// a scratch (work of type std::nullptr_t: no expansions in it, geom's predicates.hpp); on
// integer input (Geo::int_points / int_all) the undecided items are first tried without a
// scratch (par::fast_then_exact_tiered, Geo::int_points).
// With `tally` (a counter in backend memory) the count of exact items goes there and the
// host is not waited for; max_threads > 0 then caps the scratch threads (par::fast_then_exact).
template <class B, class Fast, class Exact>
std::int64_t fast_then_exact(Context<B>& ctx, const Geo& g, std::int64_t n, std::int8_t* undecided, Fast fast,
                             Exact exact, std::int64_t* tally = nullptr, std::int64_t max_threads = -1) {
  return par::fast_then_exact_tiered(ctx, n, undecided, fast, exact, geom::kPredicateWork, g.finite_scratch_free(),
                                     tally, max_threads);
}

// The steps of one flip iteration, each written once for the three ways they run: as
// device-wide passes (GFlip3D::commit_flips on a large active set), in one team (a small
// one), and in the team flip loop (GFlip3D::team_flip_loop: many small iterations in one
// launch).
//
// The decision: A (the active set) proposed pp[k] (propose_flip's codes, < 0: none);
// the proposers are listed in pl (positions in A); each casts its vote (the smallest
// proposer wins each tet: cast_vote with the iteration's vote stamp), and a proposer is
// accepted when it won every tet of its flip, so the accepted flips are disjoint. With
// keep_stuck a stuck tet (kStuckResult) is a proposer that never votes and is never
// accepted: it stays active (GFlip3D::commit_flips).
struct FlipVote {
  MeshView m;
  const tid_t* A;
  const std::int32_t* pp;
  std::int32_t* pl;
  std::uint64_t* vote;
  std::uint64_t vstamp;
  bool keep_stuck;
  GDEL_HD bool is_proposer(std::int64_t k) const { return pp[k] >= 0 || (keep_stuck && pp[k] == kStuckResult); }
  GDEL_HD void vote_of(std::int64_t j) const {  // j: a position in the proposer list
    const std::int64_t k = pl[j];
    if (pp[k] >= 0) cast_vote(m, A[k], pp[k], vote, vstamp);  // (a stuck tet does not vote)
  }
  GDEL_HD bool accepted(std::int64_t j) const {  // after the votes (a stuck tet: never)
    const std::int64_t k = pl[j];
    tid_t ts[3];
    const int nt = pp[k] < 0 ? 0 : prop_tets(m, A[k], pp[k], ts);
    bool ok = nt > 0;
    for (int l = 0; l < nt; ++l) ok = ok && vote[ts[l]] == vote_value(vstamp, A[k]);
    return ok;
  }
  // In a team, over A[0, na): the proposers to pl, the votes, the accepted flips to fl
  // (positions in pl) with their 2-3 offsets to o23 (o23[nf]: the 2-3 count), in index
  // order. Returns the proposers, the accepted flips and the 2-3 flips among them (to
  // every thread), all written and visible on return. Collective.
  struct Counts {
    std::int64_t np, nf, n23;
  };
  GDEL_HD Counts team(const par::Team& tm, std::int64_t na, std::int32_t* fl, std::int32_t* o23) const {
    const std::int64_t np = par::team_select(tm, na, pl, [this](std::int64_t k) { return is_proposer(k); });
    for (std::int64_t j = tm.rank(); j < np; j += tm.size()) vote_of(j);
    tm.sync();
    // accepted flips and the 2-3 flips among them, counted by one sum (high and low
    // words: both below 2^31)
    std::int64_t nf = 0, n2 = 0;
    for (std::int64_t j0 = 0; j0 < np; j0 += tm.size()) {
      const std::int64_t j = j0 + tm.rank();
      bool ok = false;
      bool is23 = false;
      if (j < np) {
        ok = accepted(j);
        is23 = ok && prop_type(pp[pl[j]]) == 1;
      }
      std::int64_t total = 0;
      const std::int64_t at = tm.exclusive_sum((ok ? std::int64_t(1) << 32 : std::int64_t(0)) | (is23 ? 1 : 0), &total);
      if (ok) {
        fl[nf + (at >> 32)] = static_cast<std::int32_t>(j);
        o23[nf + (at >> 32)] = static_cast<std::int32_t>(n2 + (at & 0xffffffff));
      }
      nf += total >> 32;
      n2 += total & 0xffffffff;
    }
    if (tm.rank() == 0) o23[nf] = static_cast<std::int32_t>(n2);
    tm.sync();
    return {np, nf, n2};
  }
};

// A team thread's slice of the team's exact scratch (nullptr: none).
GDEL_HD inline double* team_slice(const par::Team& tm, double* work) {
  return work ? work + std::int64_t(tm.rank()) * std::int64_t(geom::kPredicateWork) : nullptr;
}

// Small active sets' proposals in a team: A[k] for k < live, one thread per tet (fast,
// then exact: propose_flip_in_thread, the exact ones counted into *tally), -1 for
// live <= k < na. work: the team's scratch (a slice per rank), or nullptr where every
// evaluation runs in the integer stage. Collective.
GDEL_HD inline void team_propose(const par::Team& tm, const Geo& g, const MeshView& m, const tid_t* A,
                                 std::int64_t na, std::int64_t live, std::int32_t* pp, double* work,
                                 std::int64_t* tally) {
  double* w = team_slice(tm, work);
  std::int64_t nex = 0;
  for (std::int64_t k = tm.rank(); k < na; k += tm.size()) pp[k] = k < live ? propose_flip_in_thread(g, m, A[k], w, nex) : -1;
  if (nex) par::atomic_add(tally, nex);
  tm.sync();
}

// The commit of the accepted flips (ExecuteFlip xf: their records, slots and new tets)
// that follows: the adjacency across their external faces (link), the 3-2 flips' third
// slots freed (free_third, onto the stack at ftop), and the next active set's
// candidates (candidate: the rejected proposers that no flip took, the flips' new tets).
struct FlipCommit {
  ExecuteFlip xf;
  const std::int32_t* pl;  // the proposer list (positions in xf.A)
  std::int64_t np;
  tid_t* ftop;
  vid_t inf;
  int vshift;
  // adjacency across external face e (6 a flip): a neighbour that no flip took links
  // back to the new tet, across its face that named the old tet (the entry rewritten,
  // that face's flag is cleared with it: left set, it made the neighbour skip the face
  // where it proposes, and the grid's 10^6 points took 566 flip iterations instead of
  // 405, bench/RESULTS.md, session 61); one that flip h took is replaced by h's new tet
  // there.
  GDEL_HD void link(std::int64_t e) const {
    const tid_t* et = xf.ext.eot;
    const std::uint16_t* ec = xf.ext.code;
    const FlipRec* rec = xf.rec;
    const tid_t u = et[e];
    if (u < 0) return;  // the hull: the new tet already says so
    const std::uint16_t c = ec[e];
    const tid_t old = rec[e / 6].in[ext_old_tet(c)];
    const tid_t mine = rec[e / 6].out[ext_new_tet(c)];
    const std::uint64_t mk = xf.mark[u];
    if ((mk & ~std::uint64_t(0xffffffff)) == xf.stamp) {  // u was taken by flip h of this iteration
      const std::int64_t h = static_cast<std::int64_t>(mk & 0xffffffff);
      // h's entry for u's face towards the old tet (the one face u and it share)
      int k = 0;
      while (k < 5 && !(et[6 * h + k] == old && rec[h].in[ext_old_tet(ec[6 * h + k])] == u)) ++k;
      xf.m.nraw[4 * std::int64_t(mine) + ext_new_face(c)] = rec[h].out[ext_new_tet(ec[6 * h + k])];
    } else {
      // (other entries may rewrite u's other entries meanwhile: MeshView::nb_face)
      par::atomic_store(&xf.m.nraw[4 * std::int64_t(u) + xf.m.nb_face<true>(u, old)], mine);
    }
  }
  // a 3-2 flip's third slot: dead, and on the free stack (TetMesh::reserve_free)
  GDEL_HD void free_third(std::int64_t f) const {
    if (xf.rec[f].type != 2) return;
    const tid_t t = xf.rec[f].in[2];
    xf.m.state[t] = 0;
    ftop[f - xf.o23[f]] = t;
  }
  // Candidate c < np is proposer c, kept unless a flip took its tet (stamped by
  // ExecuteFlip: left to that flip, or freed; an accepted proposer's own flip took it);
  // c >= np is new tet (c - np) % 3 of flip (c - np) / 3 (-1: none). Each tet is the
  // candidate of exactly one c.
  GDEL_HD tid_t candidate(std::int64_t c) const {
    if (c < np) {
      const tid_t t = xf.A[pl[c]];
      return (xf.mark[t] & ~std::uint64_t(0xffffffff)) != xf.stamp ? t : tid_t(-1);
    }
    return xf.rec[(c - np) / 3].out[(c - np) % 3];
  }
  GDEL_HD void queue(std::int64_t c) const {
    const tid_t t = candidate(c);
    if (t >= 0) xf.m.state[t] |= mesh::kQueued;
  }
  // the space order's key: the smallest finite vertex (the points are in curve order),
  // coarsened by vshift, then (space_key) the tet id
  GDEL_HD std::uint32_t space_vertex(tid_t t) const {
    return static_cast<std::uint32_t>(smallest_finite_vertex(xf.m.tet[t], inf)) >> vshift;
  }
  GDEL_HD std::uint64_t space_key(tid_t t) const {
    return (static_cast<std::uint64_t>(space_vertex(t)) << 32) | static_cast<std::uint32_t>(t);
  }
  // In a team: the nfl flips executed (fast, then exact in the thread: counted into
  // *tally), linked, their third slots freed; then the next active set. list: its tets
  // to act (returned: their count), in stream order (the candidates' order; lp is act),
  // by space_key or by slot (lp: abound of scratch; skp: 2 abound keys in space order);
  // !list: each marked kQueued (returns 0). Collective; act is visible on return.
  enum class Order { kStream, kSpace, kSlot };
  GDEL_HD std::int64_t team(const par::Team& tm, std::int64_t nfl, double* work, std::int64_t* tally, bool list,
                            Order order, tid_t* lp, tid_t* act, std::uint64_t* skp) const {
    double* w = team_slice(tm, work);
    std::int64_t nex = 0;
    for (std::int64_t f = tm.rank(); f < nfl; f += tm.size()) {
      if (xf.run<false>(f, nullptr)) continue;
      ++nex;
      execute_flip_exact(xf, f, w);
    }
    if (nex) par::atomic_add(tally, nex);
    tm.sync();
    const std::int64_t abound = np + 3 * nfl;
    for (std::int64_t e = tm.rank(); e < 6 * nfl; e += tm.size()) link(e);
    for (std::int64_t f = tm.rank(); f < nfl; f += tm.size()) free_third(f);
    if (!list) {
      for (std::int64_t c = tm.rank(); c < abound; c += tm.size()) queue(c);
      tm.sync();
      return 0;
    }
    // (the candidates read the flips' stamps and records, written before the sync above)
    if (order == Order::kStream) lp = act;
    const std::int64_t k = par::team_select(tm, abound, lp, [this](std::int64_t c) { return candidate(c) >= 0; });
    for (std::int64_t j = tm.rank(); j < k; j += tm.size()) {
      lp[j] = candidate(lp[j]);
      if (order == Order::kSpace) skp[j] = space_key(lp[j]);
    }
    tm.sync();
    if (order == Order::kSpace) {
      par::team_sort_distinct(tm, skp, k, skp + abound);
      for (std::int64_t j = tm.rank(); j < k; j += tm.size()) act[j] = static_cast<tid_t>(skp[abound + j] & 0xffffffffu);
      tm.sync();
    } else if (order == Order::kSlot) {
      par::team_sort_distinct(tm, lp, k, act);
    }  // (in stream order lp is act)
    return k;
  }
};

template <class B>
class GFlip3D {
 public:
  // xyz: 3(n+1) doubles on the backend (slot n is overwritten with the kernel point);
  // sid: n+1 SoS indices (slot n = SoS index of the kernel point).
  GFlip3D(Context<B>& ctx, Buffer<double, B>& xyz, Buffer<std::int64_t, B>& sid, std::int64_t n, FlipConfig cfg,
          Stats& stats)
      : ctx_(ctx), xyz_(xyz), sid_(sid), n_(n), cfg_(cfg), st_(stats), mesh_(ctx), vert_tet_(ctx), todo_(ctx),
        active_(ctx), carry_(ctx), team_work_(ctx), aux_key_(ctx), aux_pick_(ctx), log_(ctx), counts_(ctx, 6) {
    counts_.memset(0);
    int_points_ = all_integer_points(ctx_, xyz_.data(), nullptr, n_);
    quarter_points_ = all_integer_points(ctx_, xyz_.data(), nullptr, n_, geom::kQuarterScale);
  }

  // Debug aid: GDEL_CHECK_MESH=1 runs the structural invariant checker after every
  // step and throws at the first violation (validate level 1; slow).
  void check_mesh(const char* where) {
    if (!debug_) return;
    auto p = mesh::check_invariants(mesh_, n_ + 1);
    if (!p.ok()) throw Error(std::string("gflip3d mesh invariant broken ") + where + ": " + p.items[0]);
  }

  void run() {
    debug_ = std::getenv("GDEL_CHECK_MESH") != nullptr;
    if (const char* e = std::getenv("GDEL_FLIP_LOG_RECORDS")) cfg_.log_records = std::max<long long>(1, std::atoll(e));
    if (const char* e = std::getenv("GDEL_TET_REORDER")) cfg_.reorder_tets = std::atoi(e) != 0;
    if (const char* e = std::getenv("GDEL_REORDER_EVERY")) cfg_.reorder_every = std::max(0, std::atoi(e));
    if (const char* e = std::getenv("GDEL_REORDER_SHARE")) cfg_.reorder_share = std::max(0, std::atoi(e));
    if (cfg_.reorder_share < 0) cfg_.reorder_share = cfg_.independent_splits ? 0 : 4;
    if (const char* e = std::getenv("GDEL_FLIPS_PER_ITERATION"))
      cfg_.max_flips_per_iteration = std::max<long long>(1, std::atoll(e));
    if (const char* tr = std::getenv("GDEL_FLIP_TRACE")) trace_ = std::atoi(tr) > 1 ? 2 : 1;
    tie_mode_ = tie_mode_from_env();
    auto t0 = std::chrono::steady_clock::now();
    const bool preset = mesh_.size() > 0;  // init_from() gave the start (Options::initial = grid)
    const bool sequential = cfg_.sequential && !preset && sequential_fits();
    if (!preset) init(/*locate=*/!sequential);
    par::mark(ctx_, "first tetrahedron + location");
    check_mesh("after init");
    if (!preset) stage(sequential ? "initial tetrahedron" : "initial tetrahedron + location", t0);
    if (sequential) {
      run_sequential();
      sequential_ran_ = true;
      return;
    }
    bool flipping = !cfg_.terminal;
    bool flipped_all_along = flipping;
    bool tail = false;  // flipping turned off by the tail rule
    counting_ties_ = flipping && cfg_.rule == InsertionRule::Circumcenter && cfg_.sos_order_switch;
    std::int64_t remaining = static_cast<std::int64_t>(todo_.size());
    std::int64_t unsorted = 0;  // points inserted since the last tet sort
    while (remaining > 0) {
      auto tr = std::chrono::steady_clock::now();
      std::int64_t inserted = insert_round(flipping && cfg_.independent_splits);
      check_mesh("after split");
      st_.rounds++;
      t_insert_ += since(tr);
      remaining = static_cast<std::int64_t>(todo_.size());
      if (flipping) {
        auto tf = std::chrono::steady_clock::now();
        const std::int64_t it0 = st_.flip_iterations, f0 = st_.flips23 + st_.flips32;
        flip_loop(/*all_tets=*/false, /*with_log=*/remaining > 0);
        decide_sos_order();
        if (cfg_.independent_splits) carry_ = std::move(active_);  // what is still active: the stuck tets
        if (cfg_.independent_splits && cfg_.nonoptimal) nonoptimal_midrun(remaining > 0);
        t_flip_ += since(tf);
        if (trace_)
          std::fprintf(stderr,
                       "gflip3d round %lld: inserted %lld, remaining %lld, tets %lld (slots %lld), flip iterations "
                       "%lld, flips %lld, logged %lld, stuck tets %lld, memory %.1f MiB, %.4f s\n",
                       static_cast<long long>(st_.rounds), static_cast<long long>(inserted),
                       static_cast<long long>(remaining), static_cast<long long>(mesh_.size()),
                       static_cast<long long>(mesh_.capacity()), static_cast<long long>(st_.flip_iterations - it0),
                       static_cast<long long>(st_.flips23 + st_.flips32 - f0), static_cast<long long>(log_.size()),
                       static_cast<long long>(carry_.size()),
                       ctx_.memory().current() / 1048576.0, since(tf));
        if (remaining > 0) {
          auto tl = std::chrono::steady_clock::now();
          relocate_through_dag();
          log_.release();  // the insertion round does not need its storage
          t_relocate_ += since(tl);
        }
        unsorted += inserted;
        if (remaining > 0 && cfg_.reorder_tets && cfg_.reorder_every > 0 && st_.rounds % cfg_.reorder_every == 0 &&
            (cfg_.reorder_share == 0 || unsorted * cfg_.reorder_share >= n_ - remaining)) {
          auto to = std::chrono::steady_clock::now();
          if (reorder_tets(/*shrink=*/false)) {
            t_reorder_ += since(to);  // (a stage only when one ran)
            unsorted = 0;
          }
        }
        // Tail rule (ALGORITHMS.md §3.1): the last tiny rounds are not worth a flip
        // loop each; insert them by splitting and flip once at the end.
        if (cfg_.tail_rule && remaining < inserted && inserted < n_ / 10) {
          if (cfg_.final_all_tets) carry_.release();  // the final flip loop looks at every tet
          flipping = false;
          flipped_all_along = false;
          tail = true;
        }
      } else if (tail && !cfg_.final_all_tets) {
        carry_ = std::move(active_);  // the tail's new tets: the next round's set adds them (insert_round)
      }
    }
    counting_ties_ = false;  // (undecided on small input: nothing counts past the rounds)
    st_.stages.push_back({"insertion (split + relocate)", t_insert_});
    if (t_reorder_ > 0) st_.stages.push_back({"tet reordering", t_reorder_});
    if (flipped_all_along) {
      st_.stages.push_back({"flipping", t_flip_});
      st_.stages.push_back({"relocation through flip DAG", t_relocate_});
    } else {
      st_.stages.push_back({"flipping (InsFlip rounds)", t_flip_});
      st_.stages.push_back({"relocation through flip DAG", t_relocate_});
      auto tf = std::chrono::steady_clock::now();
      const bool all = !tail || cfg_.final_all_tets;
      if (!all) active_ = std::move(carry_);  // the tail's tets (and stuck ones), alive (insert_round)
      flip_loop(/*all_tets=*/all, /*with_log=*/false);
      st_.stages.push_back({all ? "final flipping of all tets" : "final flipping of the tail's tets", since(tf)});
    }
    if (cfg_.nonoptimal) {
      auto tn = std::chrono::steady_clock::now();
      nonoptimal_flipping();
      check_mesh("after non-optimal flipping");
      st_.stages.push_back({"non-optimal flipping", since(tn)});
    }
  }

  // FlipConfig::sequential applies: a host backend and the slots a run reserves below 2^29
  // (SequentialInsertion::fits); otherwise the rounds run.
  bool sequential_fits() const {
    if constexpr (B::is_device) return false;
    else return SequentialInsertion<B>::fits(initial_slots());
  }
  // FlipConfig::sequential: the points todo_ inserted one per round.
  void run_sequential() {
    if constexpr (!B::is_device) {
      auto t0 = std::chrono::steady_clock::now();
      typename SequentialInsertion<B>::Knobs k;
      if (const char* e = std::getenv("GDEL_CPU_THREADS")) k.threads = static_cast<unsigned>(std::max(0, std::atoi(e)));
      if (const char* e = std::getenv("GDEL_CPU_PARALLEL_MIN")) k.parallel_min = std::max(1LL, std::atoll(e));
      if (const char* e = std::getenv("GDEL_CPU_FORCE_CONFLICT")) k.force_conflict = std::max(0LL, std::atoll(e));
      if (const char* e = std::getenv("GDEL_CPU_HOLD")) k.hold = std::max(1LL, std::atoll(e));
      k.cavity = cfg_.cavity;
      if (const char* e = std::getenv("GDEL_CPU_INSERT")) k.cavity = std::string(e) == "cavity";
      seq_ = std::make_unique<SequentialInsertion<B>>(mesh_, geo(), initial_slots(), k);
      seq_->run(todo_.data(), static_cast<std::int64_t>(todo_.size()));
      const SequentialCounts& c = seq_->counts();
      st_.rounds += c.inserted;
      st_.flips23 += c.flips23;
      st_.flips32 += c.flips32;
      st_.exact_evaluations += c.exact;
      st_.points_deferred += c.deferred;
      todo_.release();
      par::mark(ctx_, k.cavity ? "insert by cavities, one point per round" : "insert + flip, one point per round");
      if (debug_) {
        mesh();  // written back
        check_mesh("after one-point-per-round insertion");
      }
      stage(k.cavity ? "insertion by cavities, one point per round (CPU)" : "insertion + flipping, one point per round (CPU)", t0);
    }
  }

  // run() inserted one point per round (FlipConfig::sequential, when it applies): the
  // mesh is the exact Delaunay triangulation, compacted.
  bool ran_one_point_per_round() const { return sequential_ran_; }
  // The mesh. After one point per round the tets are still in its records: the first
  // call writes them back (SequentialInsertion::write_back).
  mesh::TetMesh<B>& mesh() {
    if constexpr (!B::is_device) {
      if (seq_) {
        seq_->write_back();
        seq_.reset();
        par::mark(ctx_, "one point per round: mesh written back");
      }
    }
    return mesh_;
  }
  // After one point per round, before mesh() is called: the finite tets of the exact
  // Delaunay triangulation straight from the records (SequentialInsertion::extract:
  // vertices as sid[v], neighbours -1 across the hull, flat tets dropped and counted in
  // flat; room(k): the arrays for k tets, see there). False, with nothing written, when
  // the mesh holds the result instead.
  template <class Room>
  bool extract_one_point_per_round(Room room, const std::int64_t* sid, std::int64_t& flat) {
    if constexpr (B::is_device) {
      return false;
    } else {
      if (!seq_) return false;
      flat = seq_->extract(room, sid, st_.exact_evaluations);
      seq_.reset();
      return true;
    }
  }
  // Frees everything but the mesh (per-point and per-tet work arrays, flip log): for
  // after run(), so that the repair and the output do not sit beside them.
  void release_work() {
    vert_tet_.release();
    todo_.release();
    active_.release();
    carry_.release();
    aux_key_.release();
    aux_pick_.release();
    log_.release();
  }
  vid_t infinite() const { return static_cast<vid_t>(n_); }
  Geo geo() {
    return Geo{xyz_.data(), sid_.data(), static_cast<vid_t>(n_), nullptr, int_points_, int_all_,
               counting_ties_ ? counts_.data() + 5 : nullptr, k_centroid_, {kq_[0], kq_[1], kq_[2], kq_[3]}};
  }

  // --- a given initial structure (src/grid/initial.hpp, Options::initial = grid) ---------
  // Instead of init()'s first tetrahedron: a valid triangulation of some of the points
  // with a cone (facet, ∞) over every hull facet — nt tets, positively oriented, with
  // their adjacency (4 packed facets per tet, none -1), backend memory — the kernel point
  // already stored as point n (strictly inside the hull of those tets), vert_tet (n: the
  // tet holding each uninserted point, -1 for the mesh's vertices) and the uninserted
  // points todo. Call before run(), which then inserts and flips from there.
  void init_from(const Buffer<mesh::Tet, B>& tets, const Buffer<fid_t, B>& opp, std::int64_t nt,
                 Buffer<tid_t, B>&& vert_tet, Buffer<vid_t, B>&& todo) {
    inv_scale_ = inverse_scale();
    mesh_.reserve(std::max<std::int64_t>(initial_slots(), 2 * nt + 64));  // fresh slots are dead
    mesh_.set_tets_from(tets.data(), nt);
    mesh_.set_opp_from(opp.data(), 4 * nt);  // (face flags cleared)
    par::fill(ctx_, mesh_.state().data(), static_cast<std::size_t>(nt), std::uint8_t(mesh::kAlive));
    mesh_.set_size(nt);
    grow_aux();
    vert_tet_ = std::move(vert_tet);
    todo_ = std::move(todo);
    update_int_all();  // (the caller stored K)
  }

 // (The steps below are public only because nvcc's extended __host__ __device__ lambdas
 // may not live in private member functions; they are not an interface.)
  static double since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  void stage(const char* name, std::chrono::steady_clock::time_point t) { st_.stages.push_back({name, since(t)}); }

  // Tet slots reserved at the start: the Delaunay triangulation of n random points has
  // about 6.8 n tets (ALGORITHMS.md §1.1), gFlip3D's intermediate states a few % more;
  // when a run needs more, TetMesh grows (mesh/tet_mesh.hpp). Not 8 n: at 10^8 points
  // each slot of the mesh and its work arrays costs ≈ 70 bytes (bench/RESULTS.md).
  std::int64_t initial_slots() const { return 7 * n_ + n_ / 4 + 64; }

  // Per-tet auxiliary arrays follow the mesh capacity (exactly: no growth slack of
  // their own). Each is at its reset value between steps:
  //   aux_key_  0 — insertion: a tet's best point key; relocation: 1 + the first logged
  //             flip that consumed the slot (flip DAG; by default dag_stamp() | that,
  //             left in place as stale values; GDEL_DAG_RESET=zero|sparse|dense: no
  //             stamp, zeroed after the walk); flipping: the vote,
  //             vote_stamp() | INT_MAX - smallest proposer (atomic max), then
  //             flip_stamp() | index of the flip that took the tet (stale stamps never
  //             match a later iteration; clear_marks() zeroes them before the other uses)
  //   aux_pick_ -1 — insertion: the split index of a split tet; non-optimal flips: the
  //             vote of the proposals (INT_MAX - smallest position, atomic max)
  void grow_aux() {
    const std::size_t cap = static_cast<std::size_t>(mesh_.capacity());
    auto grow = [&](auto& buf, auto init) {
      std::size_t old = buf.size();
      if (old >= cap) return;
      buf.reserve(cap);
      buf.resize(cap);
      par::fill(ctx_, buf.data() + old, cap - old, init);
    };
    grow(aux_key_, std::uint64_t(0));
    grow(aux_pick_, std::int32_t(-1));
  }
  // aux_key_'s high word in flip iteration i (st_.flip_iterations): the flip DAG's links
  // of a relocation made while i is the iteration count 4 i + 1 (the default:
  // relocate_through_dag), its votes 4 i + 2, its flips' stamps 4 i + 3; each vote stamp
  // above every earlier value and all of them above 0 (clear_marks).
  GDEL_HD static std::uint64_t high_word(std::int64_t i, int use) {
    return (4 * static_cast<std::uint64_t>(i & 0x3fffffff) + static_cast<std::uint64_t>(use)) << 32;
  }
  std::uint64_t dag_stamp() const { return high_word(st_.flip_iterations, 1); }
  std::uint64_t vote_stamp() const { return high_word(st_.flip_iterations, 2); }
  std::uint64_t flip_stamp() const { return high_word(st_.flip_iterations, 3); }
  // Zeroes aux_key_ after votes or flips stamped it (before insertion or relocation reads it).
  void clear_marks() {
    if (!marks_dirty_) return;
    aux_key_.memset(0);
    marks_dirty_ = false;
    dag_stamp_used_ = 0;
  }
  mesh::SlotSource claim(std::int64_t k) {
    mesh::SlotSource src = mesh_.claim(k);
    grow_aux();
    return src;
  }

  // --- initial tetrahedron -------------------------------------------------------
  // Index of the point maximising f (ties: smallest index). Synchronizes.
  template <class F>
  std::int64_t argmax(F f) {
    Buffer<double, B> v(ctx_, static_cast<std::size_t>(n_));
    double* vp = v.data();
    par::parallel_for(ctx_, n_, [=] GDEL_LAMBDA(std::int64_t i) {
      const double x = f(i);
      vp[i] = (x == x) ? x : -1.0;  // NaN never wins
    });
    double best = par::reduce_max(ctx_, vp, static_cast<std::size_t>(n_), -1.0);
    Buffer<std::int64_t, B> idx(ctx_, static_cast<std::size_t>(n_));
    std::int64_t* ip = idx.data();
    par::parallel_for(ctx_, n_, [=] GDEL_LAMBDA(std::int64_t i) { ip[i] = vp[i] == best ? i : INT64_MAX; });
    const std::int64_t r = par::reduce_min(ctx_, ip, static_cast<std::size_t>(n_), INT64_MAX);
    return r == INT64_MAX ? 0 : r;
  }

  // 1 / (largest |coordinate|): choices (not decisions) are computed on normalised
  // coordinates so that they neither overflow nor underflow.
  double inverse_scale() {
    const double* X = xyz_.data();
    Buffer<double, B> a(ctx_, static_cast<std::size_t>(3 * n_));
    double* ap = a.data();
    par::parallel_for(ctx_, 3 * n_, [=] GDEL_LAMBDA(std::int64_t i) { ap[i] = X[i] < 0 ? -X[i] : X[i]; });
    const double m = par::reduce_max(ctx_, ap, static_cast<std::size_t>(3 * n_), 0.0);
    return m > 0 ? 1.0 / m : 1.0;
  }

  // locate = false: the 5 first tets only, todo_ = every other point, no vert_tet_ (for
  // one point per round, whose walks locate each point when it comes).
  void init(bool locate = true) {
    vid_t t0[4];
    first_tetrahedron(t0);
    build_initial(t0, locate);
  }

  // The first tetrahedron t0 (positive; DegenerateInput when every point is coplanar)
  // and the kernel point K strictly inside it, stored as point n. Also the seed of
  // gStar4D, which needs the same degeneracy check and a K.
  void first_tetrahedron(vid_t* t0) {
    if (n_ < 4) throw DegenerateInput("need at least 4 distinct points, got " + std::to_string(n_));
    const double* X = xyz_.data();
    inv_scale_ = inverse_scale();
    const double sc = inv_scale_;
    // extreme points in x (as coordinates; only a choice)
    std::int64_t a = argmax([=] GDEL_LAMBDA(std::int64_t i) { return -X[3 * i]; });
    std::int64_t b = argmax([=] GDEL_LAMBDA(std::int64_t i) { return X[3 * i]; });
    if (a == b) b = (a == 0) ? 1 : 0;
    const auto pa = host_point(a), pb = host_point(b);
    const double ax = pa[0] * sc, ay = pa[1] * sc, az = pa[2] * sc;
    const double ux = pb[0] * sc - ax, uy = pb[1] * sc - ay, uz = pb[2] * sc - az;
    std::int64_t c = argmax([=] GDEL_LAMBDA(std::int64_t i) {
      double wx = X[3 * i] * sc - ax, wy = X[3 * i + 1] * sc - ay, wz = X[3 * i + 2] * sc - az;
      double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
      return cx * cx + cy * cy + cz * cz;
    });
    const auto pc = host_point(c);
    const double bx = pb[0] * sc, by = pb[1] * sc, bz = pb[2] * sc, cx = pc[0] * sc, cy = pc[1] * sc,
                 cz = pc[2] * sc;
    std::int64_t d = argmax([=] GDEL_LAMBDA(std::int64_t i) {
      const double A[3] = {ax, ay, az}, Bp[3] = {bx, by, bz}, C[3] = {cx, cy, cz};
      const double D[3] = {X[3 * i] * sc, X[3 * i + 1] * sc, X[3 * i + 2] * sc};
      double o = orient_value(A, Bp, C, D);
      return o < 0 ? -o : o;
    });
    // Exact check; when the float choice failed, search exactly.
    int s = exact_orient_host(a, b, c, d);
    if (s == 0) {
      bool found = false;
      // The triangle a,b,c may be exactly collinear: try every c, then every d.
      for (int pass = 0; pass < 2 && !found; ++pass) {
        std::int64_t cand = first_noncoplanar(a, b, c);
        if (cand >= 0) {
          d = cand;
          found = true;
        } else {
          std::int64_t c2 = first_noncollinear(a, b);
          if (c2 < 0 || c2 == c) break;
          c = c2;
        }
      }
      if (!found)
        throw DegenerateInput("all " + std::to_string(n_) +
                              " distinct points are coplanar (or collinear): no 3-D triangulation exists");
      s = exact_orient_host(a, b, c, d);
    }
    if (s < 0) std::swap(c, d);
    t0[0] = vid_t(a);
    t0[1] = vid_t(b);
    t0[2] = vid_t(c);
    t0[3] = vid_t(d);
    set_kernel_point(t0);
  }

  void build_initial(const vid_t* t0, bool locate_points = true) {
    // 5 tets: t0 and, for each face i of t0, (face reversed, ∞).
    const vid_t inf = static_cast<vid_t>(n_);
    std::vector<mesh::Tet> tets(5);
    for (int k = 0; k < 4; ++k) tets[0].v[k] = t0[k];
    for (int i = 0; i < 4; ++i) {
      tets[1 + i].v[0] = t0[face_vertex(i, 0)];
      tets[1 + i].v[1] = t0[face_vertex(i, 2)];
      tets[1 + i].v[2] = t0[face_vertex(i, 1)];
      tets[1 + i].v[3] = inf;
    }
    std::vector<fid_t> opp(20, -1);
    for (int t = 0; t < 5; ++t)
      for (int i = 0; i < 4; ++i)
        for (int u = 0; u < 5; ++u)
          for (int j = 0; j < 4; ++j) {
            if (u == t) continue;
            int shared = 0;
            for (int k = 0; k < 3; ++k)
              for (int l = 0; l < 3; ++l)
                shared += tets[t].v[face_vertex(i, k)] == tets[u].v[face_vertex(j, l)];
            if (shared == 3) opp[4 * t + i] = pack_facet(u, j);
          }
    mesh_.reserve(locate_points ? initial_slots() : 5);  // fresh slots are dead
    {
      Buffer<mesh::Tet, B> tb(ctx_);
      tb.assign(tets.data(), 5);
      mesh_.set_tets_from(tb.data(), 5);
      Buffer<fid_t, B> ob(ctx_);
      ob.assign(opp);
      mesh_.set_opp_from(ob.data(), 20);  // (face flags cleared)
    }
    par::fill(ctx_, mesh_.state().data(), 5, std::uint8_t(mesh::kAlive));
    mesh_.set_size(5);
    grow_aux();

    if (!locate_points) {
      const vid_t o0 = t0[0], o1 = t0[1], o2 = t0[2], o3 = t0[3];
      Buffer<vid_t, B> rest(ctx_, static_cast<std::size_t>(n_));
      const std::size_t m = par::select_indices(ctx_, static_cast<std::size_t>(n_), rest.data(), [=] GDEL_LAMBDA(vid_t q) {
        return q != o0 && q != o1 && q != o2 && q != o3;
      });
      rest.resize(m);
      todo_ = std::move(rest);
      return;
    }
    // Locate every other point: the cones from K over t0's faces partition space;
    // in cone i a point lies in t0 or in infinite tet 1+i.
    vert_tet_.resize(static_cast<std::size_t>(n_));
    tid_t* vt = vert_tet_.data();
    Geo gk = geo();
    gk.inf_sign = 1;  // K as a genuine point for the cone test
    gk.int_points = false;  // (K as a point: only int_all says whether K is of the stage)
    const vid_t K = inf;
    const vid_t o0 = t0[0], o1 = t0[1], o2 = t0[2], o3 = t0[3];
    auto locate = [=] GDEL_LAMBDA(std::int64_t q, double* work, bool exact) -> bool {
      if (q == o0 || q == o1 || q == o2 || q == o3) {
        vt[q] = -1;
        return true;
      }
      const vid_t o[4] = {o0, o1, o2, o3};
      int c = exact ? split_locate<true>(gk, o, K, vid_t(q), work) : split_locate<false>(gk, o, K, vid_t(q), work);
      if (c < 0) return false;
      int s = exact ? gk.orient_exact(o[face_vertex(c, 0)], o[face_vertex(c, 1)], o[face_vertex(c, 2)], vid_t(q), work)
                    : gk.orient_fast(o[face_vertex(c, 0)], o[face_vertex(c, 1)], o[face_vertex(c, 2)], vid_t(q));
      if (s == par::kUndecided) return false;
      vt[q] = s > 0 ? 0 : 1 + c;
      return true;
    };
    Buffer<std::int8_t, B> und(ctx_, static_cast<std::size_t>(n_));
    st_.exact_evaluations += fast_then_exact(
        ctx_, gk, n_, und.data(), [=] GDEL_LAMBDA(std::int64_t q) { return locate(q, nullptr, false); },
        [=] GDEL_LAMBDA(std::int64_t q, double* work) { return locate(q, work, true); });
    todo_.resize(static_cast<std::size_t>(n_));
    std::size_t m = par::select_indices(ctx_, static_cast<std::size_t>(n_), todo_.data(),
                                        [=] GDEL_LAMBDA(vid_t q) { return vt[q] >= 0; });
    todo_.resize(m);
  }

  std::vector<double> host_point(std::int64_t i) {
    std::vector<double> p(3);
    xyz_.copy_to_host(p.data(), 3, static_cast<std::size_t>(3 * i));
    return p;
  }
  int exact_orient_host(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
    auto pa = host_point(a), pb = host_point(b), pc = host_point(c), pd = host_point(d);
    std::vector<double> work(geom::kPredicateWork);
    return geom::orient3d_exact(pa.data(), pb.data(), pc.data(), pd.data(), work.data());
  }
  // First point q with orient3d(a,b,c,q) != 0 (exact), or -1.
  std::int64_t first_noncoplanar(std::int64_t a, std::int64_t b, std::int64_t c) {
    const double* X = xyz_.data();
    Buffer<std::int8_t, B> sg(ctx_, static_cast<std::size_t>(n_));
    std::int8_t* sp = sg.data();
    st_.exact_evaluations += par::two_stage_signs(
        ctx_, n_, sp,
        [=] GDEL_LAMBDA(std::int64_t q) -> std::int8_t {
          return static_cast<std::int8_t>(geom::orient3d_filter(X + 3 * a, X + 3 * b, X + 3 * c, X + 3 * q));
        },
        [=] GDEL_LAMBDA(std::int64_t q, double* work) -> std::int8_t {
          return static_cast<std::int8_t>(geom::orient3d_exact(X + 3 * a, X + 3 * b, X + 3 * c, X + 3 * q, work));
        },
        geom::kPredicateWork);
    Buffer<std::int64_t, B> idx(ctx_, static_cast<std::size_t>(n_));
    std::int64_t* ip = idx.data();
    par::parallel_for(ctx_, n_, [=] GDEL_LAMBDA(std::int64_t q) { ip[q] = sp[q] != 0 ? q : INT64_MAX; });
    std::int64_t r = par::reduce_min(ctx_, ip, static_cast<std::size_t>(n_), INT64_MAX);
    return r == INT64_MAX ? -1 : r;
  }
  // First point c such that a, b, c are not collinear (exact), or -1.
  std::int64_t first_noncollinear(std::int64_t a, std::int64_t b) {
    const double* X = xyz_.data();
    Buffer<std::int64_t, B> idx(ctx_, static_cast<std::size_t>(n_));
    std::int64_t* ip = idx.data();
    par::for_each_with_scratch(ctx_, n_, geom::kPredicateWork, [=] GDEL_LAMBDA(std::int64_t q, double* work) {
      const double *pa = X + 3 * a, *pb = X + 3 * b, *pq = X + 3 * q;
      const bool collinear = geom::orient2d_proj(pa, pb, pq, 0, 1, work) == 0 &&
                             geom::orient2d_proj(pa, pb, pq, 1, 2, work) == 0 &&
                             geom::orient2d_proj(pa, pb, pq, 0, 2, work) == 0;
      ip[q] = collinear ? INT64_MAX : q;
    });
    std::int64_t r = par::reduce_min(ctx_, ip, static_cast<std::size_t>(n_), INT64_MAX);
    return r == INT64_MAX ? -1 : r;
  }

  // Geo::int_all: every point and the kernel point K (slot n) at the quarter scale. K, the
  // centroid of four integer points, is a multiple of 1/4 (the sums are exact).
  void update_int_all() {
    const std::vector<double> k = host_point(n_);
    int_all_ = quarter_points_ && !k_centroid_ && geom::integer_point(k.data(), 0.0, geom::kQuarterScale);
  }

  // K = a point strictly inside t0 (checked exactly), every coordinate in the predicates'
  // exact range; stored as point n: geom::interior_point, the rounded centroid first (on
  // integer input a multiple of 1/4, which keeps Geo::int_all), then on a sliver a search
  // of the doubles coordinate by coordinate with exact predicates (property tests found
  // (0,0,0), (0,0,2^-126), (0,1,0), (1,0,1), whose interior points need x and z below
  // ~2^-70, and (0,0,1), (0,1,0), (0,1,-2^-126), (1,0,0)). A tet whose interior holds no
  // double at all (four points one ulp apart around (1,1,1); a wedge 2^-149 thick) gets
  // the exact centroid of its vertices instead (Geo::k_centroid: orientations with ∞ by
  // geom::orient3d_centroid_sos); the slot then holds the rounded centroid, which no
  // predicate reads.
  void set_kernel_point(const vid_t t[4]) {
    std::vector<std::vector<double>> p;
    for (int k = 0; k < 4; ++k) p.push_back(host_point(t[k]));
    const double* pp[4] = {p[0].data(), p[1].data(), p[2].data(), p[3].data()};
    double k[3];
    k_centroid_ = !geom::interior_point(pp, k);
    for (int i = 0; i < 4; ++i) kq_[i] = t[i];
    if (k_centroid_) geom::rounded_centroid(pp, k);
    st_.kernel_point_centroid = k_centroid_ ? 1 : 0;
    xyz_.set(static_cast<std::size_t>(3 * n_), k[0]);
    xyz_.set(static_cast<std::size_t>(3 * n_ + 1), k[1]);
    xyz_.set(static_cast<std::size_t>(3 * n_ + 2), k[2]);
    update_int_all();
  }

  // --- insertion in SoS order ---------------------------------------------------------
  // On cospherical input every insphere test among the sphere's points is an exact tie,
  // and the lifting perturbation (Geo::insphere) decides it by SoS index: a point with a
  // larger index is outside. The Delaunay triangulation of the perturbed points is then
  // the one that inserting in index order builds without a flip among the sphere's
  // existing tets; inserted in another order (the circumcentre rule's), a point with a
  // smaller index than its neighbours conflicts with their tets, and the flips that fix
  // that get stuck far more often (10^5 points on a sphere: 17 859 failed vertices, 577
  // with the switch; bench/RESULTS.md, session 53). So the default rule counts the exact
  // ties of the flipping's insphere tests (Geo::ties) until its proposals reach
  // kSosSample, and switches when ties are at least 1/kTieShare of them (sphere ≈ 2/3,
  // grid and uniform 0). Ties of flat tets are not counted: four collinear points among
  // the five tie with no cosphericity (two skew lines: index order along the lines split
  // unevenly, 15 -> 386 rounds; session 54). A choice of order, never a decision: the
  // output is the same.
  // Near-cospherical input whose tests only miss the filter (no exact tie) is not
  // switched: there index order is one random order among others, and measured no better.
  static constexpr std::int64_t kSosSample = 256;
  static constexpr std::int64_t kTieShare = 8;
  void decide_sos_order() {
    if (!counting_ties_ || proposed_ < kSosSample) return;
    counting_ties_ = false;
    const std::int64_t ties = counts_.get(5);
    if (trace_)
      std::fprintf(stderr, "gflip3d: %lld exact insphere ties in %lld proposals\n", static_cast<long long>(ties),
                   static_cast<long long>(proposed_));
    if (ties * kTieShare >= proposed_) {
      sos_order_ = true;
      st_.sos_order_round = st_.rounds;
    }
  }

  // --- one insertion round: choose, split, relocate ---------------------------------
  // The low half of a tet's best-point key: it decides between equal scores. Equal
  // scores are the rule on degenerate input, and the choice matters (H100, 10^6 grid and
  // 2 000 skew-line points, bench/RESULTS.md 2026-11-24 session 6):
  //  - on two skew lines every candidate in a flat tet scores 0, and the smallest id
  //    (Hilbert order) inserted the points of a segment one per round, in order (400
  //    points: 170 rounds, against 12 with a hash; 2 000 points > 30 s against 7.3 s);
  //  - on the grid (equal nonzero scores) the smallest id left a triangulation the
  //    repair fixed in 0.16 s under Auto, a hash one it needed 8.8 s for; a hybrid (smallest
  //    id among nonzero scores, hash among zeros) was measured no better on the grid and
  //    worse on the skew lines, and was dropped.
  // Default mode 0 "hash". Study knob GDEL_TIE_BREAK: "hash", "dyadic" (mode 1: the id
  // with the most trailing zero bits wins, binary-search order along a run of ids),
  // "first" (mode 2: smallest id). Every mode is a bijection of the id independent of the
  // score, so the low half alone identifies the winning point (the winner check).
  static GDEL_HD std::uint32_t tie_break(std::uint32_t x, int mode) {
    if (mode == 2) return 0xffffffffu - x;
    if (mode == 1) {  // ~bit-reverse(x): more trailing zeros, larger key
      x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
      x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
      x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
      x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
      x = (x >> 16) | (x << 16);
      return ~x;
    }
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
  }
  static int tie_mode_from_env() {
    const char* e = std::getenv("GDEL_TIE_BREAK");
    if (!e) return kDefaultTieMode;
    const std::string v(e);
    return v == "hash" ? 0 : v == "dyadic" ? 1 : v == "first" ? 2 : kDefaultTieMode;
  }
  static constexpr int kDefaultTieMode = 0;
  std::int64_t insert_round(bool independent) {
    clear_marks();
    MeshView m = mesh_.view();
    const Geo g = geo();
    const vid_t* U = todo_.data();
    const std::int64_t u = static_cast<std::int64_t>(todo_.size());
    tid_t* vt = vert_tet_.data();
    std::uint64_t* best = aux_key_.data();
    const InsertionRule rule = cfg_.rule;
    const double is = inv_scale_;
    const int tie = tie_mode_;
    const bool by_sid = rule == InsertionRule::SosOrder || sos_order_;
    // 1. each tet keeps its best point: key = score bits << 32 | tie_break(point); in SoS
    // order the score is ~sid (the smallest index first; indices past 2^32 - 2 tie). In
    // the first rounds 10^7 points share a few hundred tets: a key goes through the atomic
    // only where the tet's key it reads is below it (par::atomic_raise), not every key
    // through an atomic max (GDEL_SCORE_RAISE=0, for measurements); the same keys either
    // way. On the H100 at 10^7 the scores' step fell from 22.9 to 4.7 ms (bench/RESULTS.md,
    // session 69).
    const bool raise_only = score_raise_;
    auto offer_key = [=] GDEL_LAMBDA(std::uint64_t* p, std::uint64_t key) {
      if (raise_only) {
        par::atomic_raise(p, key);
      } else {
        par::atomic_max(p, key);
      }
    };
    par::parallel_for(ctx_, u, [=] GDEL_LAMBDA(std::int64_t k) {
      const vid_t q = U[k];
      const tid_t t = vt[q];
      if (by_sid) {
        const std::uint64_t s = 0xffffffffu - std::min<std::uint64_t>(g.sid[q], 0xfffffffeu);
        offer_key(best + t, (s << 32) | tie_break(std::uint32_t(q), tie));
        return;
      }
      const vid_t* v = m.tet[t].v;
      // normalised copies of the 4 vertices and q (a choice, not a decision)
      double P[5][3];
      for (int a = 0; a < 3; ++a) {
        for (int l = 0; l < 4; ++l) P[l][a] = g.p(v[l])[a] * is;
        P[4][a] = g.p(q)[a] * is;
      }
      double sc;
      int j = Geo::inf_slot(v, g.inf);
      if (rule == InsertionRule::Random) {
        std::uint64_t h = static_cast<std::uint64_t>(q) * 0x9E3779B97F4A7C15ull;
        sc = double((h >> 40) + 1);
      } else if (j >= 0) {
        sc = orient_value(P[face_vertex(j, 0)], P[face_vertex(j, 1)], P[face_vertex(j, 2)], P[4]);
      } else if (rule == InsertionRule::Circumcenter) {
        sc = insphere_value(P[0], P[1], P[2], P[3], P[4]);
      } else {
        double c[3];
        for (int a = 0; a < 3; ++a) c[a] = 0.25 * (P[0][a] + P[1][a] + P[2][a] + P[3][a]);
        double dx = P[4][0] - c[0], dy = P[4][1] - c[1], dz = P[4][2] - c[2];
        sc = 1.0 / (1.0 + dx * dx + dy * dy + dz * dz);
      }
      float f = (sc > 0 && sc < 3.0e38) ? static_cast<float>(sc) : (sc >= 3.0e38 ? 3.0e38f : 0.0f);
      std::uint32_t bits;
      std::memcpy(&bits, &f, sizeof bits);
      offer_key(best + t, (std::uint64_t(bits) << 32) | tie_break(std::uint32_t(q), tie));
    });
    par::mark(ctx_, "insert: scores");
    // 2. winners
    Buffer<std::int64_t, B> win(ctx_, static_cast<std::size_t>(u));
    std::int64_t* wp = win.data();
    std::int64_t k = static_cast<std::int64_t>(par::select_indices(ctx_, static_cast<std::size_t>(u), wp, [=] GDEL_LAMBDA(std::int64_t i) {
      const vid_t q = U[i];
      const tid_t t = vt[q];
      return std::uint32_t(best[t]) == tie_break(std::uint32_t(q), tie) && !(independent && split_defers(m, best, t));
    }));
    // the tets that defer keep their points: their keys too go back to 0
    if (independent) par::parallel_for(ctx_, u, [=] GDEL_LAMBDA(std::int64_t i) { best[vt[U[i]]] = 0; });
    par::mark(ctx_, "insert: select winners");
    // 3. slots: 3 new per split (child 0 reuses the split tet's slot)
    const mesh::SlotSource src = claim(3 * k);
    m = mesh_.view();
    best = aux_key_.data();
    std::int32_t* split_of = aux_pick_.data();
    Buffer<tid_t, B> child(ctx_, static_cast<std::size_t>(4 * k));
    Buffer<mesh::Tet, B> old(ctx_, static_cast<std::size_t>(k));
    Buffer<vid_t, B> newp(ctx_, static_cast<std::size_t>(k));
    tid_t* ch = child.data();
    mesh::Tet* op = old.data();
    vid_t* np = newp.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(std::int64_t s) {
      const vid_t q = U[wp[s]];
      const tid_t t = vt[q];
      ch[4 * s] = t;
      for (int c = 1; c < 4; ++c) ch[4 * s + c] = src.slot(3 * s + c - 1);
      op[s] = m.tet[t];
      np[s] = q;
      split_of[t] = static_cast<std::int32_t>(s);
      best[t] = 0;
      vt[q] = -1;  // inserted
    });
    // 4. split: write children, external links (unsplit neighbours written back here)
    Buffer<fid_t, B> oldopp(ctx_, static_cast<std::size_t>(4 * k));
    fid_t* oo = oldopp.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(std::int64_t s) {
      for (int i = 0; i < 4; ++i) oo[4 * s + i] = m.opp(4 * std::int64_t(ch[4 * s]) + i);
    });
    // each child written whole (its record in one sector, MeshView::put_tet): faces 0-2
    // internal, face 3 the split tet's face i, across to the neighbour's child when that
    // split too, else to the neighbour, which links back
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(std::int64_t s) {
      const vid_t* o = op[s].v;
      for (int i = 0; i < 4; ++i) {
        const tid_t c = ch[4 * s + i];
        mesh::Tet x;
        split_child_vertices(o, np[s], i, x.v);
        tid_t nb[4];  // (faces 0-2 internal: nb_entry)
        for (int kk = 0; kk < 3; ++kk) nb[kk] = mesh::nb_entry(ch[4 * s + face_vertex(i, kk)], true);
        const fid_t ext = oo[4 * s + i];
        const tid_t nt = facet_tet(ext);
        const int nf = facet_face(ext);
        const std::int32_t ns = split_of[nt];
        nb[3] = ns >= 0 ? ch[4 * std::int64_t(ns) + nf] : nt;
        m.put_tet(c, x, nb);
        if (i > 0) m.state[c] = mesh::kAlive;  // (child 0 is the split tet's slot: alive already)
        if (ns < 0) m.nraw[4 * std::int64_t(nt) + nf] = c;  // the neighbour links back (its flag there cleared)
      }
    });
    par::mark(ctx_, "insert: split");
    // 5. relocate the remaining points of split tets among the children
    Buffer<std::int8_t, B> und(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(u, 1)));
    const Geo gg = g;
    auto reloc = [=] GDEL_LAMBDA(std::int64_t i, double* work, bool exact) -> bool {
      const vid_t q = U[i];
      const tid_t t = vt[q];
      if (t < 0) return true;  // inserted this round
      const std::int32_t s = split_of[t];
      if (s < 0) return true;
      int c = exact ? split_locate<true>(gg, op[s].v, np[s], q, work) : split_locate<false>(gg, op[s].v, np[s], q, work);
      if (c < 0) return false;
      vt[q] = ch[4 * std::int64_t(s) + c];
      return true;
    };
    // vt[q] is rewritten by the pass that decides it; undecided items keep the old tet.
    st_.exact_evaluations += fast_then_exact(
        ctx_, gg, u, und.data(), [=] GDEL_LAMBDA(std::int64_t i) { return reloc(i, nullptr, false); },
        [=] GDEL_LAMBDA(std::int64_t i, double* work) { return reloc(i, work, true); });
    par::mark(ctx_, "insert: relocate in split");
    // 6. reset split marks, drop inserted points from the work list
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(std::int64_t s) { split_of[ch[4 * s]] = -1; });
    Buffer<vid_t, B> rest(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(u, 1)));
    std::size_t r = par::copy_if(ctx_, U, rest.data(), static_cast<std::size_t>(u),
                                 [=] GDEL_LAMBDA(vid_t q) { return vt[q] >= 0; });
    rest.resize(r);
    todo_ = std::move(rest);
    par::mark(ctx_, "insert: compact points");
    // the new children are the active set of the next flip loop, with the tets the last
    // flip loop left stuck (carry_, alive ones)
    active_ = std::move(child);
    if (carry_.size() > 0) {
      append(active_, carry_);
      carry_.release();
      set_of(active_);
    }
    return k;
  }

  // --- flipping ----------------------------------------------------------------------
  void flip_loop(bool all_tets, bool with_log) {
    if (all_tets) {
      std::int64_t sz = mesh_.size();
      Buffer<tid_t, B> a(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(sz, 1)));
      const std::uint8_t* stp = mesh_.state().data();
      std::size_t na = par::select_indices(ctx_, static_cast<std::size_t>(sz), a.data(),
                                           [=] GDEL_LAMBDA(tid_t t) { return (stp[t] & mesh::kAlive) != 0; });
      a.resize(na);
      active_ = std::move(a);
    }
    // The log's storage: with a log, its capacity at once (commit_flips flushes before
    // it would outgrow it, so it never grows by a copy: at 10^8 points the copy was the
    // run's peak); without one (the last loop, after the tail), given back.
    const std::int64_t log_cap = log_capacity();
    relocate_through_dag();  // a log left by the caller's flips (non-optimal steps) first
    log_.release();
    if (with_log) log_.reserve(static_cast<std::size_t>(log_cap));
    log_iters_.assign(1, 0);
    active_deferred_ = false;
    for (std::int64_t it = 0; it < cfg_.max_flip_iterations; ++it) {
      const std::int64_t na = static_cast<std::int64_t>(active_.size());
      if (na == 0) break;
      // a run of small iterations in one team (not where the log's cap is below four
      // teams' flips: it would end most runs; the log is consumed first where a run could
      // not add a team's flips to it)
      if (na <= team_max_ && team_loop_on(geo()) && (!with_log || log_cap >= 4 * team_max_)) {
        if (with_log && !log_.empty() && static_cast<std::int64_t>(log_.size()) + team_max_ > log_cap) relocate_through_dag();
        const TeamLoopResult r = team_flip_loop(na, with_log, cfg_.max_flip_iterations - it);
        check_mesh("after a team flip loop");
        if (r.finished) break;
        if (r.iterations > 0) {
          it += r.iterations - 1;
          continue;
        }
      }
      if (!flip_iteration(na, with_log)) break;
      check_mesh("after flip iteration");
      if (with_log && static_cast<std::int64_t>(log_.size()) > log_cap) relocate_through_dag();
    }
    if (active_deferred_) {  // the loop's callers read the active set: its length now
      active_.resize(static_cast<std::size_t>(counts_.get(4)));
      active_deferred_ = false;
    }
    st_.exact_evaluations += counts_.get(3);
    counts_.set(3, 0);
    tally_seen_ = 0;
    team_work_.release();
  }

  // The flip iterations' exact passes count their items on the backend (no wait for the
  // host) below this many points. Above it they wait: a pass's scratch is then sized by
  // its count, not by the bound the host knows, which keeps the peak of the runs that
  // count memory (10^8 points: 491 bytes per point) - and there a wait is little
  // against an iteration's work.
  static constexpr std::int64_t kDeferredExactMax = std::int64_t(1) << 24;
  std::int64_t* exact_tally() { return n_ <= kDeferredExactMax ? counts_.data() + 3 : nullptr; }
  // The same bound for the next active set's length: below it a flip iteration leaves
  // that length on the backend (counts_[4]) and the next one runs over the set's bound,
  // the items past the length doing nothing (active_deferred_); above it the host waits
  // for the length, so that the next iteration's lists are sized by it (the 10^8 peak).
  bool defer_active() const { return n_ <= kDeferredExactMax; }
  // The scratch threads of those passes: twice the exact items of the iteration before
  // (read with the counts), at least kMinScratchThreads; one block where no test needs
  // the scratch (Geo::int_all: the scratch pass gets no items). Without the cap the
  // scratch was sized by the active set: up to 132 x 128 threads (0.95 GB) where
  // uniform input has a few hundred exact items an iteration.
  static constexpr std::int64_t kMinScratchThreads = 1024;
  std::int64_t scratch_threads() {
    if (!exact_tally()) return -1;
    return int_all_ ? 64 : std::max(kMinScratchThreads, 2 * exact_seen_);
  }

  // One parallel flipping iteration over the active set; false when nothing flipped.
  // With active_deferred_, na is the active set's bound and counts_[4] its length: the
  // positions past it propose nothing.
  bool flip_iteration(std::int64_t na, bool with_log) {
    proposed_ += na;  // (a bound where the active set is deferred)
    MeshView m = mesh_.view();
    const Geo g = geo();
    const tid_t* A = active_.data();
    const std::int64_t* alen = active_deferred_ ? counts_.data() + 4 : nullptr;
    Buffer<std::int32_t, B> prop(ctx_, static_cast<std::size_t>(na));
    std::int32_t* pp = prop.data();
    if (na <= team_max_) {  // small: decided in one team (commit_flips), proposed there or spread
      active_deferred_ = false;
      const bool spread = spread_propose(g);
      if (spread) propose_spread(A, na, pp, alen);
      return commit_flips(A, na, prop, with_log, defer_active(), !spread, alen) > 0;
    }
    team_work_.release();  // (a large iteration: not part of its peak)
    Buffer<std::int8_t, B> und(ctx_, static_cast<std::size_t>(na));
    // each decided proposal votes where it is made (vote_in_propose_): the tet's
    // neighbours are at hand there, where a pass of its own would fetch them again
    const bool vote_here = vote_in_propose_;
    std::uint64_t* vote = aux_key_.data();
    const std::uint64_t vstamp = vote_stamp();
    if (vote_here) marks_dirty_ = true;
    auto decided = [=] GDEL_LAMBDA(std::int64_t k, int p) {
      pp[k] = p;
      if (vote_here && p >= 0) cast_vote(m, A[k], p, vote, vstamp);
    };
    auto fast = [=] GDEL_LAMBDA(std::int64_t k) {
      if (alen && k >= *alen) {
        pp[k] = -1;  // past the active set: no proposal
        return true;
      }
      const int p = propose_flip<false>(g, m, A[k], nullptr);
      if (p == kUndecidedResult) return false;
      decided(k, p);
      return true;
    };
    if (g.int_all && split_exact_) {  // the undecided tets' exact proposals a face per thread
      auto part = [=] GDEL_LAMBDA(std::int64_t k, int i, auto work) {
        return face_proposal(g, m, A[k], i, work);
      };
      auto join = [=] GDEL_LAMBDA(std::int64_t k, const std::int8_t* r) { decided(k, join_face_proposals(r)); };
      st_.exact_evaluations += par::fast_then_split(ctx_, na, und.data(), fast, 4, part, join, exact_tally());
    } else {
      auto exact = [=] GDEL_LAMBDA(std::int64_t k, auto work) {
        const int p = propose_flip<true>(g, m, A[k], work);
        if (p == kUndecidedResult) return false;  // (work = nullptr: it needs the scratch)
        decided(k, p);
        return true;
      };
      st_.exact_evaluations += fast_then_exact(ctx_, g, na, und.data(), fast, exact, exact_tally(), scratch_threads());
    }
    par::mark(ctx_, "flip: propose");
    und.release();
    active_deferred_ = false;
    return commit_flips(A, na, prop, with_log, defer_active(), false, nullptr, vote_here) > 0;
  }

  // A large flip iteration's proposals vote in the proposing pass (flip_iteration), not
  // in a pass of their own (commit_flips); GDEL_VOTE_IN_PROPOSE=0 for measurements: the
  // pass (bench/RESULTS.md, session 57). The same flips either way.
  static bool vote_in_propose_setting() { return !par::knob_off("GDEL_VOTE_IN_PROPOSE"); }

  // On integer input (Geo::int_all) the large iterations' exact proposals run a face per
  // thread (par::fast_then_split: face_proposal, join_face_proposals), not a tet per
  // thread (bench/RESULTS.md, session 49); GDEL_SPLIT_EXACT=0 for measurements: a tet per
  // thread. (propose_spread's small iterations split too measured no better: session 49.)
  static bool split_exact_setting() { return !par::knob_off("GDEL_SPLIT_EXACT"); }

  // Active sets up to this many tets are proposed and decided in one team
  // (par::team_run: one block on the GPU) instead of some fifteen launches
  // (commit_flips). GDEL_TEAM_MAX sets it for measurements (0: never).
  static std::int64_t team_max_setting() {
    const char* e = std::getenv("GDEL_TEAM_MAX");
    return e ? std::atoll(e) : kTeamMax;
  }
  static constexpr std::int64_t kTeamMax = 1024;
  // Where a small active set is proposed (GDEL_TEAM_PROPOSE for measurements): "team" in
  // the team that decides, "spread" in a pass of its own over small blocks
  // (propose_spread), "auto" (the default) spread on input where ties are expected
  // (Geo::int_all: lattice points, the sphere), in the team otherwise.
  enum class ProposeAt { kTeam, kSpread, kAuto };
  static ProposeAt propose_at_setting() {
    const std::string v = par::knob_value("GDEL_TEAM_PROPOSE");
    return v == "team" ? ProposeAt::kTeam : v == "spread" ? ProposeAt::kSpread : ProposeAt::kAuto;
  }
  bool spread_propose(const Geo& g) const {
    return propose_at_ == ProposeAt::kSpread || (propose_at_ == ProposeAt::kAuto && g.int_all);
  }
  // propose_spread's CUDA blocks (GDEL_SPREAD_BLOCK for measurements): 32 threads, so that
  // a few hundred tets run on as many SMs as they fill warps (64 and 128 measured no
  // different on the H200: bench/RESULTS.md, session 29).
  static int spread_block_setting() {
    const char* e = std::getenv("GDEL_SPREAD_BLOCK");
    const int v = e ? std::atoi(e) : 0;
    return v >= 32 && v <= 1024 && v % 32 == 0 ? v : 32;
  }
  // A small active set's proposals (as commit_flips' team makes them: one thread per tet,
  // the fast form, then the exact one) in one launch of small blocks. In the one-block
  // team every exact tie runs on one SM (the sphere's insphere tests are all ties). The
  // gain is small: on the sphere at 10^6 the first team's share fell 44.4 -> 38.8 ms over
  // its 618 small iterations, on the grid 55.7 -> 50.5 ms (bench/RESULTS.md, session 29).
  // Positions from *alen on (a deferred set's length) propose nothing.
  void propose_spread(const tid_t* A, std::int64_t na, std::int32_t* pp, const std::int64_t* alen) {
    const MeshView m = mesh_.view();
    const Geo g = geo();
    std::int64_t* tally = counts_.data() + 3;
    par::for_each_with_scratch(
        ctx_, na, geom::kPredicateWork,
        [=] GDEL_LAMBDA(std::int64_t k, auto w) {
          std::int64_t nex = 0;
          pp[k] = alen && k >= *alen ? -1 : propose_flip_in_thread(g, m, A[k], w, nex);
          if (nex) par::atomic_add(tally, nex);
        },
        /*scratch_free=*/g.int_all, nullptr, -1, spread_block_);
    par::mark(ctx_, "flip: propose (spread)");
  }
  // The team's scratch for exact evaluations (a slice of geom::kPredicateWork doubles per
  // thread); none on input whose evaluations all run in the integer stage.
  double* team_work(const Geo& g) {
    if (g.int_all) return nullptr;
    const std::size_t want = static_cast<std::size_t>(par::team_size<B>()) * geom::kPredicateWork;
    if (team_work_.size() < want) team_work_.resize(want);
    return team_work_.data();
  }

  // Executes proposals: pp[k] (propose_flip's code, < 0: none) is the flip proposed by
  // tet A[k] (distinct tets). Votes so that the accepted flips touch disjoint tets (the
  // smallest proposer wins each tet), executes them, repairs adjacency, and makes the
  // rejected proposers and the new tets the active set. Returns the number of flips;
  // 0 (nothing changed) when there was no proposal.
  // The proposal codes (prop) are released once the records are built.
  // defer: the next active set's length stays on the backend (counts_[4], and
  // active_deferred_ set; active_ then has the set's bound as its size).
  // propose (na <= team_max_ only): the proposals are not made yet; the team that decides
  // makes them first, A[k] for k < min(na, *alen) (alen: a deferred active set's length).
  // voted (na > team_max_ only): the proposing pass has cast the votes (cast_vote with
  // vote_stamp(), flip_iteration) and set marks_dirty_.
  std::int64_t commit_flips(const tid_t* A, std::int64_t na, Buffer<std::int32_t, B>& prop, bool with_log,
                            bool defer = false, bool propose = false, const std::int64_t* alen = nullptr,
                            bool voted = false) {
    std::int32_t* pp = prop.data();
    MeshView m = mesh_.view();
    const Geo g = geo();
    // proposers, and with independent splits the stuck tets (kStuckResult: faces not
    // locally Delaunay, none flippable now). A stuck tet goes through as a proposer that
    // is never accepted, so it stays in the active set: a flip nearby, this round or
    // (through carry_) a later one, may make its face flippable. Without this a stuck
    // facet whose tets hold no points (the hollow of a thin shell) was never looked at
    // again (bench/RESULTS.md, session 11). Not under the original rule: on cospherical
    // input most facets are stuck ties, re-proposed (exactly, with SoS) every iteration.
    const bool keep_stuck = cfg_.independent_splits;
    // The proposer list (positions in A: na < 2^31, as tets). Over a large active set it
    // is counted first and sized exactly: in a flip loop over every tet (the terminal
    // variant's, or GDEL_FINAL_ALL_TETS) few of them propose, and a list sized by the
    // active set was 54 bytes per point of the run's peak (bench/RESULTS.md). Over a
    // smaller one (par::kUncountedListMax) it is sized by the set, which saves a pass and
    // a wait on the count in most iterations.
    // Up to the host's one read of the counts below, each step is bounded by what the
    // host knows (npb: the list's length) and cut by the counts on the backend (counts_):
    // the proposers, the accepted flips and the 2-3 flips among them come to the host
    // together, one wait instead of three (bench/RESULTS.md, session 19).
    std::int64_t* cn = counts_.data();
    const FlipVote fv0{m, A, pp, nullptr, nullptr, 0, keep_stuck};
    const std::int64_t npb =
        na > par::kUncountedListMax
            ? par::count_indices(ctx_, static_cast<std::size_t>(na), [=] GDEL_LAMBDA(std::int64_t k) { return fv0.is_proposer(k); })
            : na;
    if (npb == 0) {
      active_.release();
      return 0;
    }
    Buffer<std::int32_t, B> pl(ctx_, static_cast<std::size_t>(npb));
    std::int32_t* plp = pl.data();
    marks_dirty_ = true;
    // the votes: an atomic max in aux_key_ of vote_stamp() | INT_MAX - proposer
    // (flip::cast_vote). The stamp (this iteration's, above every earlier vote and flip
    // stamp) spares a pass that would reset the votes.
    const FlipVote fv{m, A, pp, plp, aux_key_.data(), vote_stamp(), keep_stuck};
    Buffer<std::int32_t, B> fl(ctx_, static_cast<std::size_t>(npb));  // positions in pl, then in A
    std::int32_t* flp = fl.data();
    // 2-3 flips: each needs one new slot (o23: their exclusive offsets; cn[2]: how many)
    // (int32: at most np < 2^31 flips)
    Buffer<std::int32_t, B> off23(ctx_, static_cast<std::size_t>(npb + 1));
    std::int32_t* o23 = off23.data();
    const bool team = na <= team_max_;  // every step of this iteration in one team, or each a pass
    if (team) {
      // One team does what the steps below do, with the same results: the lists come
      // out of sums in index order. A small iteration's fifteen-odd launches were most of
      // its time (bench/RESULTS.md, session 27: 29 kernels of 1.6-16 us each).
      double* work = propose ? team_work(g) : nullptr;
      par::team_run(ctx_, [=] GDEL_LAMBDA(const par::Team& tm) {
        if (propose) team_propose(tm, g, m, A, na, alen && *alen < na ? *alen : na, pp, work, cn + 3);
        const FlipVote::Counts c = fv.team(tm, na, flp, o23);
        if (tm.rank() == 0) {
          cn[0] = c.np;
          cn[1] = c.nf;
          cn[2] = c.n23;
        }
      });
      par::mark(ctx_, propose ? "flip: propose + vote (team)" : "flip: vote (team)");
    } else {
      par::select_indices_to(ctx_, static_cast<std::size_t>(na), plp, cn,
                             [=] GDEL_LAMBDA(std::int64_t k) { return fv.is_proposer(k); });
      par::mark(ctx_, "flip: select proposers");
      if (!voted) par::parallel_for_counted(ctx_, npb, cn, [=] GDEL_LAMBDA(std::int64_t j) { fv.vote_of(j); });
      // (the flags in a pass of their own: with accepted() as the selection's predicate
      // the step took 72 ms instead of 49 at 10^7 points, bench/RESULTS.md, session 57)
      Buffer<std::int8_t, B> acc(ctx_, static_cast<std::size_t>(npb));
      std::int8_t* ap = acc.data();
      par::parallel_for_counted(ctx_, npb, cn, [=] GDEL_LAMBDA(std::int64_t j) { ap[j] = fv.accepted(j) ? 1 : 0; });
      par::select_indices_to(ctx_, static_cast<std::size_t>(npb), flp, cn + 1,
                             [=] GDEL_LAMBDA(std::int64_t j) { return j < cn[0] && ap[j] != 0; });
      par::parallel_for(ctx_, npb + 1, [=] GDEL_LAMBDA(std::int64_t f) {
        o23[f] = f < cn[1] && prop_type(pp[plp[flp[f]]]) == 1 ? 1 : 0;
      });
      par::exclusive_scan(ctx_, o23, o23, static_cast<std::size_t>(npb + 1));
      par::parallel_for(ctx_, 1, [=] GDEL_LAMBDA(std::int64_t) { cn[2] = o23[cn[1]]; });
    }
    std::int64_t h[4];
    par::detail::Memory<B>::to_host(ctx_, h, cn, sizeof(h));
    const std::int64_t np = h[0];
    std::int64_t nfl = h[1], n23 = h[2];
    exact_seen_ = h[3] - tally_seen_;  // (the last records pass and this propose)
    tally_seen_ = h[3];
    if (trace_ > 1)  // (na: a bound where the active set was deferred; flips before any cap)
      std::fprintf(stderr, "gflip3d flip iteration: active %lld, flips %lld (2-3 %lld), %s, proposers %lld\n",
                   static_cast<long long>(na), static_cast<long long>(nfl), static_cast<long long>(n23),
                   team ? "team" : "large", static_cast<long long>(np));
    if (np == 0) {
      active_.release();
      return 0;
    }
    if (nfl == 0) {  // only stuck tets: they stay active
      Buffer<tid_t, B> act(ctx_, static_cast<std::size_t>(np));
      tid_t* acp = act.data();
      par::parallel_for(ctx_, np, [=] GDEL_LAMBDA(std::int64_t j) { acp[j] = A[plp[j]]; });
      active_ = std::move(act);
      return 0;
    }
    if (nfl > cfg_.max_flips_per_iteration) {  // the rest stand down (FlipConfig::max_flips_per_iteration)
      const std::int64_t keep = cfg_.max_flips_per_iteration;
      nfl = keep;  // (their proposers, whose tets no flip stamps, stay active)
      n23 = off23.get(static_cast<std::size_t>(keep));  // (the offsets before `keep` stand)
    }
    // flips' proposer positions in A
    par::parallel_for(ctx_, nfl, [=] GDEL_LAMBDA(std::int64_t f) { flp[f] = plp[flp[f]]; });
    par::mark(ctx_, "flip: vote + select accepted + count 2-3");
    if (debug_) {  // accepted flips must touch disjoint, alive tets
      Buffer<tid_t, B> tt(ctx_, static_cast<std::size_t>(3 * nfl));
      tid_t* ttp = tt.data();
      par::parallel_for(ctx_, nfl, [=] GDEL_LAMBDA(std::int64_t f) {
        tid_t ts[3] = {-1, -1, -1};
        prop_tets(m, A[flp[f]], pp[flp[f]], ts);
        for (int l = 0; l < 3; ++l) ttp[3 * f + l] = ts[l];
      });
      auto h = tt.to_host();
      auto st = mesh_.state().to_host();
      std::vector<tid_t> v;
      for (std::size_t f = 0; f < h.size() / 3; ++f)
        if (h[3 * f] == h[3 * f + 1] || h[3 * f] == h[3 * f + 2] || (h[3 * f + 2] >= 0 && h[3 * f + 1] == h[3 * f + 2]))
          throw Error("gflip3d debug: a flip touches one tet twice: " + std::to_string(h[3 * f]) + " " +
                      std::to_string(h[3 * f + 1]) + " " + std::to_string(h[3 * f + 2]));
      for (tid_t x : h)
        if (x >= 0) {
          if (!(st[x] & mesh::kAlive)) throw Error("gflip3d debug: flip touches a dead tet " + std::to_string(x));
          v.push_back(x);
        }
      std::sort(v.begin(), v.end());
      auto dup = std::adjacent_find(v.begin(), v.end());
      if (dup != v.end()) {
        std::vector<tid_t> Ah(static_cast<std::size_t>(na));
        std::vector<std::int32_t> pph(static_cast<std::size_t>(na));
        par::detail::Memory<B>::to_host(ctx_, Ah.data(), A, Ah.size() * sizeof(tid_t));
        par::detail::Memory<B>::to_host(ctx_, pph.data(), pp, pph.size() * sizeof(std::int32_t));
        auto flh = fl.to_host();
        std::string msg = "gflip3d debug: accepted flips overlap on tet " + std::to_string(*dup) + ":";
        for (std::size_t f = 0; f < h.size() / 3; ++f)
          if (h[3 * f] == *dup || h[3 * f + 1] == *dup || h[3 * f + 2] == *dup)
            msg += " [b=" + std::to_string(Ah[flh[f]]) + " pos " + std::to_string(flh[f]) + " prop " +
                   std::to_string(pph[flh[f]]) + " tets " + std::to_string(h[3 * f]) + "," +
                   std::to_string(h[3 * f + 1]) + "," + std::to_string(h[3 * f + 2]) + "]";
        throw Error(msg);
      }
    }
    st_.flips23 += n23;
    st_.flips32 += nfl - n23;
    // 3-2 flips free their third slot onto the free stack, in flip order (deterministic);
    // its room is made before the claim, whose slot source reads the stack
    mesh_.reserve_free(nfl - n23);
    const mesh::SlotSource src = claim(n23);
    m = mesh_.view();
    par::mark(ctx_, "flip: claim slots");
    // records; a log that this iteration's would take past its capacity is first
    // consumed (the points relocated through it: same result, one walk earlier)
    std::int64_t log0 = static_cast<std::int64_t>(log_.size());
    if (with_log && log0 > 0 && log0 + nfl > log_capacity()) {
      relocate_through_dag();
      log0 = 0;
    }
    if (log0 == 0 && static_cast<std::size_t>(nfl) > log_.capacity()) log_.release();  // no copy to keep
    log_.resize(static_cast<std::size_t>(log0 + nfl));
    FlipRec* rec = log_.data() + log0;
    // Every flip has 6 external faces (2-3: 2 old tets x 3; 3-2: 3 x 2): entries 6f..6f+5
    // of `ext` (flip_kernels.hpp's ExtFaces: which new facet replaces which old one, and
    // the old neighbour there). A flip's old tets are stamped with flip_stamp() | f in
    // aux_key_, so that a neighbour taken by another flip of this iteration finds its new
    // facet among that flip's entries.
    std::uint64_t* mark = aux_key_.data();
    const std::uint64_t stamp = flip_stamp();
    marks_dirty_ = true;
    Buffer<std::uint16_t, B> ext_code(ctx_, static_cast<std::size_t>(6 * nfl));
    Buffer<tid_t, B> ext_tet(ctx_, static_cast<std::size_t>(6 * nfl));
    const ExtFaces ext{ext_code.data(), ext_tet.data()};
    // The flips, each in one thread (ExecuteFlip): its record (a 3-2 flip's vertex order
    // may need an exact orientation: fast, then exact), its slots and its new tets, each
    // written whole, its external faces first to the old tet's neighbour there; the
    // adjacency step (link) corrects those whose neighbour another flip of this
    // iteration took, and links the others back.
    const ExecuteFlip xf{m, g, A, flp, pp, rec, src, o23, mark, stamp, ext};
    auto xfast = [=] GDEL_LAMBDA(std::int64_t f) { return xf.template run<false>(f, nullptr); };
    auto xexact = [=] GDEL_LAMBDA(std::int64_t f, auto work) { return xf.template run<true>(f, work); };
    // the adjacency across external faces, the 3-2 flips' third slots and the next
    // active set's candidates (FlipCommit)
    const int vbits = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(n_)));
    const int vshift = space_key_shift();
    const FlipCommit fc{xf, plp, np, mesh_.free_top(), static_cast<vid_t>(n_), vshift};
    // next active set: the rejected proposers (the stuck tets among them) that no flip
    // took, and the flips' new tets (FlipCommit::candidate), in stream, space or slot
    // order (stream_order, space_order; the default is stream order). In stream order
    // the candidates' tets are listed in the order of c, in the team or by one
    // compaction. Otherwise they are listed, then sorted: in a team (small iterations),
    // and on the GPU in a large iteration where the bound is below 1/kListedActiveRatio
    // of the slots (on the CPU a sort costs more than the pass). Otherwise each is marked
    // (kQueued) and the marked slots are gathered in order by one pass over the slots,
    // then unmarked (GDEL_ACTIVE_LISTED_LARGE=0: never listed in large iterations;
    // GDEL_ACTIVE_SLOTS=1: the pass in either; the same tets in the same order;
    // bench/RESULTS.md, session 52).
    const std::int64_t abound = np + 3 * nfl;  // the next active set's bound
    const bool list_in_team = team && !active_by_slots_;
    // in stream order (stream_order) the candidates are listed in their own order: no
    // marks, no pass over the slots, no sort
    const bool stream = stream_order();
    const bool list_large = !team && !active_by_slots_ &&
                            (stream || (B::is_device && active_listed_large_ && abound * kListedActiveRatio < mesh_.size()));
    // the next active set in space order (space_order): by the smallest finite vertex of
    // each tet (the points are in curve order), ties by tet id; else in stream or slot
    // order. The team sorts distinct 64-bit keys (vertex, tet id); the other paths put
    // the set in slot order first and then sort it stably by the vertex alone, a pair
    // sort of bit_width(n) bits (3 radix passes at 10^7 where the 64-bit key took 7): the
    // same order.
    const bool by_space = space_order();
    Buffer<tid_t, B> act(ctx_);
    if (team) {
      const FlipCommit::Order order = next_order();
      Buffer<tid_t, B> listed(ctx_, list_in_team && order != FlipCommit::Order::kStream ? static_cast<std::size_t>(abound) : 0);
      Buffer<std::uint64_t, B> skeys(ctx_, list_in_team && order == FlipCommit::Order::kSpace ? static_cast<std::size_t>(2 * abound) : 0);
      std::uint64_t* skp = skeys.data();
      if (list_in_team) act.resize(static_cast<std::size_t>(abound));
      tid_t* acp = act.data();
      tid_t* lp = listed.data();
      double* work = team_work(g);
      std::int64_t* tally = cn + 3;
      par::team_run(ctx_, [=] GDEL_LAMBDA(const par::Team& tm) {
        const std::int64_t k = fc.team(tm, nfl, work, tally, list_in_team, order, lp, acp, skp);
        if (list_in_team && tm.rank() == 0) cn[4] = k;
      });
      par::mark(ctx_, "flip: records + tets + adjacency (team)");
    } else {
      Buffer<std::int8_t, B> und2(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(nfl, 1)));
      st_.exact_evaluations += fast_then_exact(ctx_, g, nfl, und2.data(), xfast, xexact, exact_tally(), scratch_threads());
      par::mark(ctx_, "flip: records + write tets");
      prop.release();  // (the codes and the accepted list are the records' now)
      fl.release();
      und2.release();
      par::parallel_for(ctx_, 6 * nfl, [=] GDEL_LAMBDA(std::int64_t e) { fc.link(e); });
      par::mark(ctx_, "flip: adjacency");
      ext_code.release();  // not needed past here: room for the next active set's sort
      ext_tet.release();
      par::parallel_for(ctx_, nfl, [=] GDEL_LAMBDA(std::int64_t f) { fc.free_third(f); });
      if (!list_large) par::parallel_for(ctx_, abound, [=] GDEL_LAMBDA(std::int64_t c) { fc.queue(c); });
    }
    mesh_.pushed_free(nfl - n23);
    off23.release();
    // With `defer` its length stays on the backend (counts_[4]): the next iteration runs
    // over the bound, np + 3 nfl, without a wait here (bench/RESULTS.md, session 20).
    if (list_large && stream) {  // the candidates in their order (entries past the count unused)
      act.resize(static_cast<std::size_t>(abound));
      tid_t* acp = act.data();
      par::select_mapped_to(ctx_, static_cast<std::size_t>(abound), acp, cn + 4,
                            [=] GDEL_LAMBDA(std::int64_t c) { return fc.candidate(c); },
                            [=] GDEL_LAMBDA(tid_t t) { return t >= 0; });
    } else if (list_large) {  // unused entries (past the count) sort last, as the slot count
      act.resize(static_cast<std::size_t>(abound));
      tid_t* acp = act.data();
      const std::int64_t* cnt = cn + 4;
      const tid_t past = static_cast<tid_t>(mesh_.size());
      par::select_indices_to(ctx_, static_cast<std::size_t>(abound), acp, cn + 4,
                             [=] GDEL_LAMBDA(tid_t c) { return fc.candidate(c) >= 0; });
      par::parallel_for(ctx_, abound, [=] GDEL_LAMBDA(std::int64_t j) { acp[j] = j < *cnt ? fc.candidate(acp[j]) : past; });
      par::sort_keys(ctx_, acp, static_cast<std::size_t>(abound),
                     std::max(1, static_cast<int>(std::bit_width(static_cast<std::uint32_t>(past)))));
    } else if (!list_in_team) {  // the marked slots, in slot order
      act.resize(static_cast<std::size_t>(abound));
      tid_t* acp = act.data();
      par::select_indices_to(ctx_, static_cast<std::size_t>(mesh_.size()), acp, cn + 4,
                             [=] GDEL_LAMBDA(tid_t t) { return (m.state[t] & mesh::kQueued) != 0; });
      par::parallel_for_counted(ctx_, abound, cn + 4, [=] GDEL_LAMBDA(std::int64_t j) {
        m.state[acp[j]] &= static_cast<std::uint8_t>(~mesh::kQueued);
      });
    }
    if (by_space && !(team && list_in_team)) {  // the set in slot order, stably by vertex
      // (unused entries, past the count, get a key above every vertex and stay last)
      const std::int64_t* cnt = cn + 4;
      Buffer<std::uint32_t, B> key(ctx_, static_cast<std::size_t>(abound));
      std::uint32_t* kp = key.data();
      tid_t* acp = act.data();
      par::parallel_for(ctx_, abound, [=] GDEL_LAMBDA(std::int64_t j) { kp[j] = j < *cnt ? fc.space_vertex(acp[j]) : ~std::uint32_t(0); });
      par::sort_pairs(ctx_, key, act, static_cast<std::size_t>(abound), vbits - vshift);
    }
    if (defer) {
      active_deferred_ = true;
    } else {
      act.resize(static_cast<std::size_t>(counts_.get(4)));
    }
    active_ = std::move(act);
    par::mark(ctx_, "flip: next active set");
    if (with_log) log_iters_.push_back(static_cast<std::int64_t>(log_.size()));
    else log_.clear();
    st_.flip_iterations++;  // also the stamps (aux_key_) of the next iteration's votes and flips
    return nfl;
  }

  // --- the team flip loop ---------------------------------------------------------------
  // Small flip iterations (active sets of at most team_max_ tets, as the host counts them)
  // one after the other in one team, without the host between them: each makes its
  // proposals, votes, flips and next active set as commit_flips' two teams do
  // (team_propose, FlipVote::team, FlipCommit::team) and claims its slots from the free
  // stack and the high-water mark in the team. One launch and one wait for a run of
  // them, where each took two launches, a slot claim and a wait (bench/RESULTS.md,
  // session 71). The same flips in the same order with the same stamps as the host's
  // iterations, so the same triangulation (TeamLoopChangesNothing). A run stops before
  // an iteration whose active set's bound passes team_max_ or whose flips might not fit
  // the room reserved for them (tet slots, free stack, log records: a flip each at most),
  // and after kTeamLoopIterations; flip_loop goes on from there. finished: the last
  // iteration flipped nothing (flip_iteration's false), so the flip loop is over.
  // Off by default (team_loop_on, team_loop_; H100, session 71: uniform 10^7 -2.1 to
  // -2.6 ms, 10^6 -2.2 to -2.5 ms; the grid's 10^6 +12 ms with it).
  struct TeamLoopResult {
    std::int64_t iterations;
    bool finished;
  };
  static constexpr std::int64_t kTeamLoopIterations = 512;
  static constexpr int kLoopWords = 16;  // the run's counts (out[0, kLoopWords)), then the log's ends
  bool team_loop_on(const Geo& g) const {
    const bool on = team_loop_ == TeamLoop::kOn || (team_loop_ == TeamLoop::kAuto && !spread_propose(g));
    return on && !debug_ && trace_ < 2 && !active_by_slots_ && team_max_ > 0;
  }
  TeamLoopResult team_flip_loop(std::int64_t na, bool with_log, std::int64_t max_iterations) {
    const std::int64_t tmax = team_max_;
    const std::int64_t kmax = std::min(kTeamLoopIterations, max_iterations);
    if (kmax <= 0) return {0, false};
    // room: 4 team_max_ tet slots past the high-water mark (a run stops where an
    // iteration's 2-3 flips might not fit), 16 team_max_ free-stack entries, and the
    // log's records (with the log, up to its cap; without, team_max_ from 0 each time)
    if (mesh_.capacity() - mesh_.size() < 4 * tmax) mesh_.reserve(mesh_.size() + 4 * tmax);
    grow_aux();
    mesh_.reserve_free(16 * tmax);
    if (!with_log) {
      log_.clear();
      log_.reserve(static_cast<std::size_t>(tmax));
    }
    const std::int64_t log_room =
        with_log ? std::min<std::int64_t>(static_cast<std::int64_t>(log_.capacity()), log_capacity())
                 : static_cast<std::int64_t>(log_.capacity());
    const MeshView m = mesh_.view();
    const Geo g = geo();
    Buffer<std::int32_t, B> prop(ctx_, static_cast<std::size_t>(tmax)), pl(ctx_, static_cast<std::size_t>(tmax)),
        fl(ctx_, static_cast<std::size_t>(tmax)), off23(ctx_, static_cast<std::size_t>(tmax + 1));
    Buffer<std::uint16_t, B> ext_code(ctx_, static_cast<std::size_t>(6 * tmax));
    Buffer<tid_t, B> ext_tet(ctx_, static_cast<std::size_t>(6 * tmax));
    Buffer<tid_t, B> acts[2] = {Buffer<tid_t, B>(ctx_, static_cast<std::size_t>(4 * tmax)),
                                Buffer<tid_t, B>(ctx_, static_cast<std::size_t>(4 * tmax))};
    const FlipCommit::Order order = next_order();
    Buffer<tid_t, B> listed(ctx_, order != FlipCommit::Order::kStream ? static_cast<std::size_t>(4 * tmax) : 0);
    Buffer<std::uint64_t, B> skeys(ctx_, order == FlipCommit::Order::kSpace ? static_cast<std::size_t>(8 * tmax) : 0);
    Buffer<std::int64_t, B> state(ctx_, static_cast<std::size_t>(kLoopWords + kmax));
    std::int32_t *pp = prop.data(), *plp = pl.data(), *flp = fl.data(), *o23 = off23.data();
    const ExtFaces ext{ext_code.data(), ext_tet.data()};
    tid_t* act[2] = {acts[0].data(), acts[1].data()};
    tid_t* lp = listed.data();
    std::uint64_t* skp = skeys.data();
    std::int64_t* out = state.data();
    const tid_t* A0 = active_.data();
    const std::int64_t* alen = active_deferred_ ? counts_.data() + 4 : nullptr;
    std::int64_t* cn = counts_.data();
    tid_t* stack = mesh_.free_stack();
    const std::int64_t cap_slots = mesh_.capacity(), stack_room = mesh_.free_room();
    const std::int64_t size0 = mesh_.size(), top0 = mesh_.free_count();
    FlipRec* log = log_.data();
    const std::int64_t log0 = with_log ? static_cast<std::int64_t>(log_.size()) : 0;
    std::uint64_t* aux = aux_key_.data();
    const std::int64_t fi0 = st_.flip_iterations;
    const bool keep_stuck = cfg_.independent_splits;
    const std::int64_t max_flips = cfg_.max_flips_per_iteration;
    const bool defer = defer_active();
    const vid_t inf = static_cast<vid_t>(n_);
    const int vshift = space_key_shift();
    double* work = team_work(g);
    par::team_run(ctx_, [=] GDEL_LAMBDA(const par::Team& tm) {
      std::int64_t bound = na;                // the active set's length as the host counts it
      std::int64_t len = alen ? *alen : na;  // its length
      std::int64_t size = size0, top = top0, logn = log0, it = 0, f23 = 0, f32 = 0, proposed = 0, ex0 = 0;
      bool finished = false;
      int at = -1;  // the set: in A0 (-1) or act[at]
      const tid_t* cur = A0;
      while (it < kmax && bound <= tmax) {
        if (bound == 0 || len == 0) {  // (flip_loop's end, or an iteration that finds no proposer)
          if (bound > 0) proposed += bound;
          finished = true;
          len = 0;
          break;
        }
        if (size + len > cap_slots || top + len > stack_room || logn + len > log_room) break;
        proposed += bound;
        if (tm.rank() == 0) ex0 = cn[3];  // (read before this iteration's atomics: the sync below)
        tm.sync();
        team_propose(tm, g, m, cur, len, len, pp, work, cn + 3);
        const FlipVote fv{m, cur, pp, plp, aux, high_word(fi0 + it, 2), keep_stuck};
        FlipVote::Counts c = fv.team(tm, len, flp, o23);
        const int nx = at == 0 ? 1 : 0;  // the next set's buffer
        tid_t* next = act[nx];
        if (c.np == 0) {
          finished = true;
          len = 0;
          break;
        }
        if (c.nf == 0) {  // only stuck tets: they stay active (not deferred)
          for (std::int64_t j = tm.rank(); j < c.np; j += tm.size()) next[j] = cur[plp[j]];
          tm.sync();
          at = nx;
          len = bound = c.np;
          finished = true;
          break;
        }
        if (c.nf > max_flips) {  // the rest stand down (FlipConfig::max_flips_per_iteration)
          c.nf = max_flips;
          c.n23 = o23[max_flips];
        }
        for (std::int64_t f = tm.rank(); f < c.nf; f += tm.size()) flp[f] = plp[flp[f]];
        tm.sync();
        // the claim (TetMesh::claim): the 2-3 flips' slots from the free stack first
        const mesh::SlotSource src = mesh::claim_slots(stack, top, size, c.n23);
        const ExecuteFlip xf{m, g, cur, flp, pp, log + logn, src, o23, aux, high_word(fi0 + it, 3), ext};
        const FlipCommit fc{xf, plp, c.np, stack + top, inf, vshift};
        const std::int64_t k = fc.team(tm, c.nf, work, cn + 3, true, order, lp, next, skp);
        top += c.nf - c.n23;  // (the 3-2 flips' third slots, pushed)
        f23 += c.n23;
        f32 += c.nf - c.n23;
        if (with_log) {
          logn += c.nf;
          if (tm.rank() == 0) out[kLoopWords + it] = logn;
        }
        ++it;
        at = nx;
        cur = next;
        len = k;
        bound = defer ? c.np + 3 * c.nf : k;
      }
      if (tm.rank() == 0) {
        out[0] = it;
        out[1] = finished ? 1 : 0;
        out[2] = len;
        out[3] = bound;
        out[4] = size;
        out[5] = top;
        out[6] = logn;
        out[7] = f23;
        out[8] = f32;
        out[9] = proposed;
        out[10] = ex0;
        out[11] = at;
        out[12] = cn[3];  // (every thread's atomics came before the last sync)
        cn[4] = len;
      }
    });
    std::vector<std::int64_t> h(static_cast<std::size_t>(kLoopWords + kmax));
    par::detail::Memory<B>::to_host(ctx_, h.data(), out, h.size() * sizeof(std::int64_t));
    par::mark(ctx_, "flip: team loop");
    const std::int64_t iters = h[0];
    const bool finished = h[1] != 0;
    if (h[9] > 0) marks_dirty_ = true;  // (votes were cast)
    proposed_ += h[9];
    st_.flip_iterations += iters;
    st_.flips23 += h[7];
    st_.flips32 += h[8];
    mesh_.set_counts(h[4], h[5]);
    exact_seen_ = h[12] - h[10];
    tally_seen_ = h[12];
    if (with_log) {
      log_.resize(static_cast<std::size_t>(h[6]));
      for (std::int64_t j = 0; j < iters; ++j) log_iters_.push_back(h[static_cast<std::size_t>(kLoopWords + j)]);
    } else {
      log_.clear();
    }
    const int at = static_cast<int>(h[11]);
    if (finished && h[2] == 0) {
      active_.release();
      active_deferred_ = false;
    } else if (at >= 0) {
      active_ = std::move(acts[at]);
      active_deferred_ = !finished && defer;
      active_.resize(static_cast<std::size_t>(active_deferred_ ? h[3] : h[2]));
    }
    return {iters, finished};
  }

  // --- non-optimal flipping (Options::nonoptimal_flips; docs/gflip3d.md) -----------------
  // After the last flip loop, on the stuck triangulation. Each round: find the facets
  // that are not locally Delaunay (exact, all tets); let the tets on their sides propose
  // the ear cuts that remove the stuck facets' blocking edges (propose_nonoptimal,
  // flip_kernels.hpp), a few parallel steps of them; then normal flipping from those
  // tets, first trusting the ear cuts' internal faces (so that their own 3-2 undo is
  // not proposed before the 3-2 that removes the edge), then checking them too. The
  // state with the fewest non-locally-Delaunay facets is kept; rounds stop when one makes
  // no flip, after `patience` rounds without a new best, or at the cap.
  void nonoptimal_flipping() {
    constexpr int patience = 3;
    Buffer<tid_t, B> stuck(ctx_);
    std::int64_t cnt = non_ld_facets(stuck);
    st_.nonld_facets_stuck = cnt;
    if (static_cast<double>(cnt) > cfg_.nonoptimal_max_share * static_cast<double>(n_)) {
      st_.nonld_facets_kept = cnt;  // too many (cospherical input): left to the repair
      active_.resize(0);
      return;
    }
    std::int64_t best = cnt;
    mesh::TetMesh<B> kept(ctx_);
    bool saved = false;  // `kept` holds a state with `best` facets
    int stale = 0;
    for (int r = 0; r < cfg_.nonoptimal_rounds && cnt > 0; ++r) {
      if (cfg_.nonoptimal_keep_best && cnt == best && !saved) {
        kept.copy_from(mesh_);
        saved = true;
      }
      st_.nonoptimal_rounds++;
      const std::int64_t made = nonoptimal_round(stuck, /*with_log=*/false, /*other_edges=*/false);
      if (made == 0) break;  // nothing unlockable: unchanged
      cnt = non_ld_facets(stuck);
      if (trace_) std::fprintf(stderr, "non-optimal round %d: %lld ear cuts, %lld non-LD facets\n", r, (long long)made, (long long)cnt);
      if (cnt < best) {
        best = cnt;
        saved = false;
        stale = 0;
      } else if (++stale >= patience) {
        break;
      }
    }
    if (cfg_.nonoptimal_keep_best && cnt > best) {
      mesh_.copy_from(kept);
      grow_aux();
      cnt = best;
    }
    st_.nonld_facets_kept = cnt;
    active_.resize(0);
  }

  // Under independent splits, after an InsFlip round's flip loop: one non-optimal round
  // from the tets that loop left stuck (carry_), logged while points remain (the ear
  // cuts and the flips after them are nodes of the flip DAG like any flips); the tets
  // still stuck after it, and those it started from, are carried to the next round. No
  // exact count and no kept state here: later insertions and flips go on from whatever
  // it leaves. Skipped when more tets are stuck than 1 % of the points (or
  // nonoptimal_max_share, if smaller): on cospherical input nearly all of them are ties,
  // which no ear cut helps, and the round would cost a flip loop over them every time.
  void nonoptimal_midrun(bool with_log) {
    const std::size_t k = carry_.size();
    const double share = std::min(cfg_.nonoptimal_max_share, 0.01);
    if (k == 0 || static_cast<double>(k) > share * static_cast<double>(n_)) return;
    Buffer<tid_t, B> stuck(ctx_);
    append(stuck, carry_);
    set_of(stuck);
    st_.nonoptimal_rounds++;
    st_.nonoptimal_between_rounds++;
    nonoptimal_round(stuck, with_log, /*other_edges=*/true);
    carry_ = std::move(active_);  // what the last flip loop left stuck (or none: no ear cut)
    append(carry_, stuck);
    set_of(carry_);
  }

  // Facets not locally Delaunay (Geo::orient4, as the failed vertices): their number,
  // and in `sides` the tets on either side of them (sorted, no repeats).
  std::int64_t non_ld_facets(Buffer<tid_t, B>& sides) {
    const std::int64_t nt = mesh_.size();
    const MeshView m = mesh_.view();
    Buffer<std::int8_t, B> sg(ctx_, static_cast<std::size_t>(4 * std::max<std::int64_t>(nt, 1)));
    const std::int8_t* sp = sg.data();
    st_.exact_evaluations += facet_signs(ctx_, m, nt, geo(), sg.data());
    auto positive = [=] GDEL_LAMBDA(std::int64_t f) { return sp[f] > 0; };
    // (not const: see commit_flips' note on nvcc)
    std::int64_t k = par::count_indices(ctx_, static_cast<std::size_t>(4 * nt), positive);
    Buffer<std::int64_t, B> fl(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(k, 1)));
    std::int64_t* fp = fl.data();
    par::select_indices(ctx_, static_cast<std::size_t>(4 * nt), fp, positive);
    sides.resize(static_cast<std::size_t>(2 * k));
    tid_t* s = sides.data();
    par::parallel_for(ctx_, k, [=] GDEL_LAMBDA(std::int64_t j) {
      s[2 * j] = static_cast<tid_t>(fp[j] >> 2);
      s[2 * j + 1] = m.opp_tet(fp[j]);
    });
    set_of(sides);
    return k;
  }

  // The alive tets of `t`, sorted, without repeats.
  void set_of(Buffer<tid_t, B>& t) {
    tid_t* tp = t.data();
    par::sort_keys(ctx_, tp, t.size());
    const std::size_t nu = par::unique(ctx_, tp, t.size());
    const std::uint8_t* stp = mesh_.state().data();
    Buffer<tid_t, B> out(ctx_, std::max<std::size_t>(nu, 1));
    std::size_t na = par::copy_if(ctx_, tp, out.data(), nu, [=] GDEL_LAMBDA(tid_t x) { return (stp[x] & mesh::kAlive) != 0; });
    out.resize(na);
    t = std::move(out);
  }
  void append(Buffer<tid_t, B>& dst, const Buffer<tid_t, B>& src) {
    const std::size_t a = dst.size();
    dst.resize(a + src.size());
    par::detail::Memory<B>::copy(ctx_, dst.data() + a, src.data(), src.size() * sizeof(tid_t));
  }

  // One round from the tets beside the stuck facets; returns the non-optimal flips made.
  // with_log: between insertion rounds (points remain): the flips are logged (flip_loop
  // consumes a pending log before it starts its own).
  // other_edges: a stuck facet's other edges are removed too where its blocking ones
  // cannot be (in the rounds between insertion rounds; at the end their ear cuts churn:
  // 1 596 facets left on the 10^6 thin shell against 1 494, bench/RESULTS.md session 12).
  std::int64_t nonoptimal_round(const Buffer<tid_t, B>& stuck, bool with_log, bool other_edges) {
    Buffer<tid_t, B> touched(ctx_);
    std::int64_t made = 0;
    for (int step = 0; step < cfg_.nonoptimal_steps; ++step) {
      const std::int64_t f = nonoptimal_step(stuck, with_log, other_edges);
      if (f == 0) break;
      made += f;
      append(touched, active_);  // the new tets (and rejected proposers)
    }
    st_.nonoptimal_flips += made;
    if (made == 0) return 0;
    // normal flipping, the non-optimal flips' internal faces still trusted
    active_.resize(0);
    append(active_, stuck);
    append(active_, touched);
    set_of(active_);
    flip_loop(/*all_tets=*/false, with_log);
    // then those faces checked as well
    set_of(touched);
    MeshView m = mesh_.view();
    const tid_t* tp = touched.data();
    par::parallel_for(ctx_, static_cast<std::int64_t>(touched.size()), [=] GDEL_LAMBDA(std::int64_t j) {
      for (int i = 0; i < 4; ++i) m.set_face_flags(tp[j], i, 0);
    });
    active_ = std::move(touched);
    flip_loop(/*all_tets=*/false, with_log);
    return made;
  }

  // One parallel step of non-optimal flips proposed by the tets `from`: at most one per
  // proposer, at most one per tet that carries it (the earliest proposer), then voted and
  // executed like any flips. Returns the flips made.
  std::int64_t nonoptimal_step(const Buffer<tid_t, B>& from, bool with_log, bool other_edges) {
    const std::int64_t n = static_cast<std::int64_t>(from.size());
    if (n == 0) return 0;
    const MeshView m = mesh_.view();
    const Geo g = geo();
    const tid_t* F = from.data();
    Buffer<std::int64_t, B> prop(ctx_, static_cast<std::size_t>(n));
    std::int64_t* pp = prop.data();
    Buffer<std::int8_t, B> und(ctx_, static_cast<std::size_t>(n));
    st_.exact_evaluations += fast_then_exact(
        ctx_, g, n, und.data(),
        [=] GDEL_LAMBDA(std::int64_t k) {
          pp[k] = propose_nonoptimal<false>(g, m, F[k], other_edges, nullptr);
          return pp[k] != kUndecidedResult;
        },
        [=] GDEL_LAMBDA(std::int64_t k, auto work) {
          const std::int64_t p = propose_nonoptimal<true>(g, m, F[k], other_edges, work);
          if (p == kUndecidedResult) return false;  // (work = nullptr: it needs the scratch)
          pp[k] = p;
          return true;
        });
    Buffer<std::int64_t, B> sel(ctx_, static_cast<std::size_t>(n));
    std::int64_t* sl = sel.data();
    std::int64_t ns = static_cast<std::int64_t>(  // (not const: nvcc, as above)
        par::select_indices(ctx_, static_cast<std::size_t>(n), sl, [=] GDEL_LAMBDA(std::int64_t k) { return pp[k] >= 0; }));
    if (ns == 0) return 0;
    // one proposal per carrying tet: the smallest position wins (aux_pick_, an atomic
    // max of INT_MAX - position, reset after)
    std::int32_t* vote = aux_pick_.data();
    par::parallel_for(ctx_, ns, [=] GDEL_LAMBDA(std::int64_t j) {
      par::atomic_max(vote + proposal_tet(pp[sl[j]]), static_cast<std::int32_t>(INT_MAX - j));
    });
    Buffer<tid_t, B> A(ctx_, static_cast<std::size_t>(ns));
    Buffer<std::int32_t, B> code(ctx_, static_cast<std::size_t>(ns));
    tid_t* ap = A.data();
    std::int32_t* cp = code.data();
    par::parallel_for(ctx_, ns, [=] GDEL_LAMBDA(std::int64_t j) {
      const tid_t t = proposal_tet(pp[sl[j]]);
      ap[j] = t;
      cp[j] = vote[t] == static_cast<std::int32_t>(INT_MAX - j) ? proposal_code(pp[sl[j]]) : -1;
    });
    par::parallel_for(ctx_, ns, [=] GDEL_LAMBDA(std::int64_t j) { vote[ap[j]] = -1; });
    par::mark(ctx_, "non-optimal flips: propose");
    return commit_flips(ap, ns, code, with_log);
  }

  // --- re-ordering of tets -----------------------------------------------------------
  // Sorts the tets by their smallest finite vertex (a tet of ∞ with its smallest finite
  // one): the points are curve sorted, so tets near each other in space come near each
  // other in memory (FlipConfig::reorder_tets). Only when the sort's temporaries fit under
  // the run's memory peak so far (TetMesh::reorder_bytes): it never raises the peak.
  // Between rounds no flip log and no active set are alive: only the uninserted points'
  // tets and the stuck tets carried to the next round (carry_) need remapping; shrink
  // (the output, after release_work): the capacity becomes the alive tets. Returns
  // whether it sorted.
  bool reorder_tets(bool shrink) {
    auto& mem = ctx_.memory();
    // (whether it sorts is decided by the scatter's bytes, so that the gather's 4 bytes a
    // slot more never change which sorts run, nor so the triangulation: it moves the
    // arrays by the gather only where those fit too; the same for the records moved whole,
    // 16 bytes a slot more than as two halves)
    auto fit = [&](bool gather, bool whole) {
      return mem.current() + static_cast<std::size_t>(mesh_.reorder_bytes(gather, whole)) <= mem.peak();
    };
    const bool fits = fit(false, false);
    const bool gather = reorder_gather_ && fit(true, false);
    const bool whole = fit(gather, true);
    if (trace_)
      std::fprintf(stderr, "gflip3d tet reordering: %s%s (%.1f MiB held + %.1f MiB needed, peak %.1f MiB)\n",
                   fits ? (gather ? "done (gather" : "done (scatter") : "skipped",
                   fits ? (whole ? ", whole records)" : ", records in halves)") : "", mem.current() / 1048576.0,
                   mesh_.reorder_bytes() / 1048576.0, mem.peak() / 1048576.0);
    if (!fits) return false;
    const vid_t inf = static_cast<vid_t>(n_);
    auto remap = mesh_.reorder([=] GDEL_LAMBDA(const mesh::Tet& t) { return smallest_finite_vertex(t, inf); }, inf,
                               shrink, gather, whole);
    const tid_t* rm = remap.data();
    const vid_t* U = todo_.data();
    tid_t* vt = vert_tet_.data();
    par::parallel_for(ctx_, static_cast<std::int64_t>(todo_.size()), [=] GDEL_LAMBDA(std::int64_t i) { vt[U[i]] = rm[vt[U[i]]]; });
    // the tets the last flip loop left stuck (independent splits) are tet ids too: the
    // next round's flip loop starts from them
    if (carry_.size() > 0) {
      const tid_t* cp = carry_.data();
      Buffer<tid_t, B> moved(ctx_, carry_.size());
      tid_t* mp = moved.data();
      par::parallel_for(ctx_, static_cast<std::int64_t>(carry_.size()),
                        [=] GDEL_LAMBDA(std::int64_t i) { mp[i] = cp[i] >= 0 ? rm[cp[i]] : tid_t(-1); });
      carry_.resize(par::copy_if(ctx_, mp, carry_.data(), carry_.size(), [=] GDEL_LAMBDA(tid_t x) { return x >= 0; }));
    }
    // per-tet auxiliary state is all at its reset value between rounds, but for stale
    // flip stamps and (by default) DAG links, which never match a later
    // iteration (insert_round clears them)
    if (!shrink) grow_aux();
    par::mark(ctx_, "tet reordering");
    return true;
  }
  // The mesh for the output stage (after release_work): its alive tets in [0, alive),
  // the capacity cut to them; sorted as reorder_tets() when that is on and fits.
  void finish_mesh() {
    if (!(cfg_.reorder_tets && reorder_tets(/*shrink=*/true))) mesh_.compact(/*shrink=*/true);
  }

  // Records the flip log holds before the points are relocated through it (FlipConfig).
  std::int64_t log_capacity() const {
    if (cfg_.log_records > 0) return cfg_.log_records;
    const std::int64_t floor = n_ >= cfg_.log_floor_min_points ? cfg_.log_records_floor : std::int64_t(1) << 16;
    return std::max<std::int64_t>(floor, static_cast<std::int64_t>(cfg_.log_records_per_point * n_));
  }

  // --- relocation of uninserted points through the flip DAG --------------------------
  // The log's records become the DAG's nodes: out[o] is overwritten in place with the
  // next flip that consumed that slot (>= 0) or ~slot (< 0) when none did, so a walk
  // from a point's old slot ends at the slot holding it now. Needs fewer than 2^31
  // records (flip_loop keeps the log far below: log_records_per_point).
  void relocate_through_dag() {
    const std::int64_t nrec = static_cast<std::int64_t>(log_.size());
    if (nrec == 0) return;
    if (nrec > INT_MAX) throw Error("gflip3d: flip log of over 2^31 records");
    grow_aux();
    // The links: stamp | 1 + the flip, read as none unless the high word is the stamp's.
    // By default the links carry dag_stamp(), which no earlier value in aux_key_ has (a
    // stamp already used since the last clear_marks: zeroed first), and stay as stale
    // values below the next iteration's votes. Stamp 0 (GDEL_DAG_RESET=zero|sparse|dense,
    // for measurements) wants aux_key_ zeroed first and left so (the reset below).
    // (dag_stamp_used_ is set only with marks_dirty_, and both are reset by clear_marks)
    const bool stamped = dag_reset_ == DagReset::kStamp;
    const std::uint64_t dstamp = stamped ? dag_stamp() : 0;
    if (!stamped || dag_stamp_used_ == dstamp) clear_marks();
    std::uint64_t* next = aux_key_.data();
    auto link = [=] GDEL_LAMBDA(tid_t t) -> std::int64_t {  // the next flip consuming t, -1: none
      const std::uint64_t v = next[t];
      return (v & ~std::uint64_t(0xffffffffu)) == dstamp ? static_cast<std::int64_t>(v & 0xffffffffu) - 1 : -1;
    };
    FlipRec* rec = log_.data();
    // backwards: outputs point at the next flip consuming their slot (or ~slot)
    for (std::size_t it = log_iters_.size() - 1; it > 0; --it) {
      const std::int64_t lo = log_iters_[it - 1], hi = log_iters_[it];
      par::parallel_for(ctx_, hi - lo, [=] GDEL_LAMBDA(std::int64_t k) {
        const std::int64_t f = lo + k;
        FlipRec& r = rec[f];
        for (int o = 0; o < 3; ++o) {
          if (r.out[o] < 0) continue;  // no third output (3-2): never followed
          const std::int64_t nf = link(r.out[o]);
          r.out[o] = static_cast<tid_t>(nf >= 0 ? nf : ~std::int64_t(r.out[o]));
        }
        for (int o = 0; o < 3; ++o)
          if (r.in[o] >= 0) next[r.in[o]] = dstamp | static_cast<std::uint64_t>(f + 1);
      });
    }
    const vid_t* U = todo_.data();
    const std::int64_t u = static_cast<std::int64_t>(todo_.size());
    tid_t* vt = vert_tet_.data();
    const Geo g = geo();
    auto walk = [=] GDEL_LAMBDA(std::int64_t i, double* work, bool exact) -> bool {
      const vid_t q = U[i];
      std::int64_t node = link(vt[q]);
      if (node < 0) return true;
      while (node >= 0) {
        int c = exact ? dag_child<true>(g, rec[node], q, work) : dag_child<false>(g, rec[node], q, work);
        if (c < 0) return false;
        node = rec[node].out[c];
      }
      vt[q] = static_cast<tid_t>(~node);
      return true;
    };
    Buffer<std::int8_t, B> und(ctx_, static_cast<std::size_t>(std::max<std::int64_t>(u, 1)));
    st_.exact_evaluations += fast_then_exact(
        ctx_, g, u, und.data(), [=] GDEL_LAMBDA(std::int64_t i) { return walk(i, nullptr, false); },
        [=] GDEL_LAMBDA(std::int64_t i, double* work) { return walk(i, work, true); });
    par::mark(ctx_, "relocate: DAG walk");
    // Stamped: nothing to reset. Otherwise next[] back to 0: where the log is long against
    // the mesh, all of it (one sequential write of 8 bytes a slot) rather than the consumed
    // slots (up to three random writes a record, each a 32-byte sector;
    // GDEL_DAG_RESET=sparse/dense, bench/RESULTS.md, session 57)
    const std::int64_t cap = static_cast<std::int64_t>(aux_key_.size());
    if (stamped) {
      marks_dirty_ = true;  // the links stay (stale below every later vote; zeroed before an insertion)
      dag_stamp_used_ = dstamp;
    } else if (dag_reset_ == DagReset::kDense || (dag_reset_ == DagReset::kZero && 12 * nrec > cap)) {
      aux_key_.memset(0);
    } else {
      par::parallel_for(ctx_, nrec, [=] GDEL_LAMBDA(std::int64_t f) {
        for (int o = 0; o < 3; ++o)
          if (rec[f].in[o] >= 0) next[rec[f].in[o]] = 0;
      });
    }
    par::mark(ctx_, "relocate: reset DAG links");
    log_.clear();
    log_iters_.assign(1, 0);
  }

 private:
  Context<B>& ctx_;
  Buffer<double, B>& xyz_;
  Buffer<std::int64_t, B>& sid_;
  std::int64_t n_;
  bool int_points_ = false;      // Geo::int_points: every point is a point of the integer stage
  bool quarter_points_ = false;  // ... at the quarter scale
  bool int_all_ = false;         // Geo::int_all: those and the kernel point K (update_int_all)
  bool k_centroid_ = false;      // Geo::k_centroid: K is the exact centroid of kq_ (set_kernel_point)
  vid_t kq_[4] = {0, 0, 0, 0};
  FlipConfig cfg_;
  Stats& st_;
  mesh::TetMesh<B> mesh_;
  Buffer<tid_t, B> vert_tet_;  // per point: tet holding it while uninserted, -1 once inserted
  Buffer<vid_t, B> todo_;      // uninserted points
  Buffer<tid_t, B> active_;
  Buffer<tid_t, B> carry_;  // between rounds: the tets the last flip loop left stuck
  Buffer<double, B> team_work_;  // team_work(): the small flip iterations' exact scratch
  std::int64_t team_max_ = team_max_setting();
  ProposeAt propose_at_ = propose_at_setting();
  int spread_block_ = spread_block_setting();
  bool split_exact_ = split_exact_setting();
  bool vote_in_propose_ = vote_in_propose_setting();
  // kStamp, the default: stamped links, never zeroed (session 70); the others zero them
  // after each walk (GDEL_DAG_RESET=zero: by the log's size, sparse or dense; for measurements)
  enum class DagReset { kZero, kSparse, kDense, kStamp };
  static DagReset dag_reset_setting() {
    const std::string v = par::knob_value("GDEL_DAG_RESET");
    return v == "zero"     ? DagReset::kZero
           : v == "sparse" ? DagReset::kSparse
           : v == "dense"  ? DagReset::kDense
                           : DagReset::kStamp;
  }
  DagReset dag_reset_ = dag_reset_setting();
  std::uint64_t dag_stamp_used_ = 0;  // the last relocation's dag_stamp() since clear_marks (stamped links)
  // The tet sort moves the arrays by a gather (TetMesh::reorder) where its bytes fit, by a
  // scatter otherwise; GDEL_REORDER_GATHER=0: always the scatter (measurements). The
  // gather took "tet reordering" 82.9 -> 75.9 ms at 10^7 on an H100, faster in each of
  // three pairs and no slower at 10^6 (bench/RESULTS.md, session 58).
  bool reorder_gather_ = !par::knob_off("GDEL_REORDER_GATHER");
  bool active_by_slots_ = par::knob_on("GDEL_ACTIVE_SLOTS");
  // team_flip_loop: GDEL_TEAM_LOOP=1 on every input, =auto where small sets propose in
  // the team (spread_propose: not on integer input, whose proposals' exact ties in one
  // block made the grid's 10^6 points 12 ms slower); off by default: auto's 2.3 ms off
  // uniform 10^6 would put the grid at 2.00-2.01x of it (the 2x target; bench/RESULTS.md,
  // session 71)
  enum class TeamLoop { kOff, kOn, kAuto };
  TeamLoop team_loop_ = [] {
    const std::string v = par::knob_value("GDEL_TEAM_LOOP");
    return v == "1" ? TeamLoop::kOn : v == "auto" ? TeamLoop::kAuto : TeamLoop::kOff;
  }();
  // The order of a flip iteration's next active set. Slots are in space order only just
  // after a tet sort; within a round new tets take freed or fresh slots, so in slot order
  // a warp's active tets lie apart and share few neighbours and points.
  // * Stream order (stream_order): the candidates in their own order, the rejected
  //   proposers in the order of the set they came from, then the flips' new tets in the
  //   order of their proposers (a round's first set, the split's children, is in the
  //   curve order of the inserted points): two runs, each in the order of the last set,
  //   listed by one compaction (par::select_mapped_to) with no sort and no pass over the
  //   slots.
  // * Space order (space_order): sorted by each tet's smallest finite vertex (the points
  //   are in curve order), ties by tet id. Against slot order the proposals, the flips
  //   and their adjacency ran 31, 6 and 26 ms faster at 10^7 for 30 ms more in the set's
  //   step, −52 to −55 ms a run on the H100, and uniform 10^8 5.97 s where it took 7.33;
  //   at 10^6 a study's sort cost more than it saved (bench/RESULTS.md, sessions 63, 64).
  // GDEL_ACTIVE_SPACE: unset or "auto" (the default) stream order below stream_max_slots_
  // slots and space order from there, but slot order with independent splits, whose
  // studies were measured in slot order (space order forced on, its test's thin shells,
  // 3 x 20 000 points, left 126 facets stuck against 75 on the CPU backend); "stream"
  // stream order always; "sort" (session 64's default) space
  // order on a mesh of at least kSpaceOrderMinSlots slots (≈ 1.2 * 10^6 points), slot
  // order below it and with independent splits; "1" space order always; "0" slot order.
  // GDEL_ACTIVE_SLOTS=1 (the slots' pass) turns stream order into slot order.
  enum class SpaceOrder { kOff, kOn, kAuto, kSorted, kStream };
  static SpaceOrder space_order_setting() {
    const std::string v = par::knob_value("GDEL_ACTIVE_SPACE");
    return v == "1"        ? SpaceOrder::kOn
           : v == "0"      ? SpaceOrder::kOff
           : v == "sort"   ? SpaceOrder::kSorted
           : v == "stream" ? SpaceOrder::kStream
                           : SpaceOrder::kAuto;
  }
  SpaceOrder space_order_ = space_order_setting();
  // GDEL_SPACE_SHIFT=k (a measurement knob, default 0): the space order's key is the
  // vertex shifted right by k bits (blocks of 2^k points in curve order, ties by tet id):
  // fewer radix passes, coarser locality.
  int space_shift_ = [] {
    const char* e = std::getenv("GDEL_SPACE_SHIFT");
    return e ? std::clamp(std::atoi(e), 0, 31) : 0;
  }();
  static constexpr std::int64_t kSpaceOrderMinSlots = std::int64_t(1) << 23;
  // insert_round's scores through par::atomic_raise (GDEL_SCORE_RAISE=0: every key
  // through an atomic max, for measurements; bench/RESULTS.md, session 69)
  bool score_raise_ = !par::knob_off("GDEL_SCORE_RAISE");
  // auto's switch from stream to space order: at 10^8 points stream order ran 6.34 s
  // where space order ran 5.97 (at 10^7, whose meshes stay below 2^27 slots, it was
  // 16-20 ms faster; bench/RESULTS.md, session 65); with the switch 5.958 s against
  // 5.973 (session 67). GDEL_STREAM_MAX_SLOTS sets it for measurements.
  std::int64_t stream_max_slots_ = [] {
    const char* e = std::getenv("GDEL_STREAM_MAX_SLOTS");
    return e ? std::max<std::int64_t>(0, std::atoll(e)) : std::int64_t(1) << 27;
  }();
  bool space_order() const {
    if (space_order_ == SpaceOrder::kOn) return true;
    if (cfg_.independent_splits) return false;
    if (space_order_ == SpaceOrder::kSorted) return mesh_.size() >= kSpaceOrderMinSlots;
    return space_order_ == SpaceOrder::kAuto && mesh_.size() >= stream_max_slots_;
  }
  // FlipCommit's space keys' coarsening: GDEL_SPACE_SHIFT, below the vertex ids' bits
  int space_key_shift() const {
    return std::min(space_shift_, static_cast<int>(std::bit_width(static_cast<std::uint64_t>(n_))) - 1);
  }
  // the next active set's order in a team (FlipCommit::team)
  FlipCommit::Order next_order() const {
    return space_order() ? FlipCommit::Order::kSpace : stream_order() ? FlipCommit::Order::kStream : FlipCommit::Order::kSlot;
  }
  bool stream_order() const {
    if (active_by_slots_) return false;
    return space_order_ == SpaceOrder::kStream ||
           (space_order_ == SpaceOrder::kAuto && !cfg_.independent_splits && mesh_.size() < stream_max_slots_);
  }
  // insertion in SoS order (decide_sos_order): tets proposed so far, ties being counted
  // (counts_[5]), switched
  std::int64_t proposed_ = 0;
  bool counting_ties_ = false, sos_order_ = false;
  bool active_listed_large_ = !par::knob_off("GDEL_ACTIVE_LISTED_LARGE");
  // commit_flips lists and sorts a large iteration's next active set (no pass over the
  // slots) when its bound is below this fraction of the slots: the sort moves ≈ 32 bytes
  // a key where the pass reads one byte a slot.
  static constexpr std::int64_t kListedActiveRatio = 32;
  Buffer<std::uint64_t, B> aux_key_;  // per tet slot; see grow_aux for the three
  Buffer<std::int32_t, B> aux_pick_;
  bool marks_dirty_ = false;  // aux_key_ holds flip stamps
  Buffer<FlipRec, B> log_;
  std::vector<std::int64_t> log_iters_{0};
  // A flip iteration's counts on the backend, read by the host once (commit_flips):
  // [0] proposers, [1] accepted flips, [2] 2-3 flips among them, [3] the exact
  // evaluations of the flip loop (flushed into Stats at its end).
  Buffer<std::int64_t, B> counts_;
  std::int64_t tally_seen_ = 0;  // counts_[3] at the last read
  bool active_deferred_ = false;  // active_'s length is counts_[4], its size a bound (flip_loop)
  std::int64_t exact_seen_ = 0;  // exact items between the last two reads
  double t_insert_ = 0, t_flip_ = 0, t_relocate_ = 0, t_reorder_ = 0;
  bool debug_ = false;
  bool sequential_ran_ = false;
  std::unique_ptr<SequentialInsertion<B>> seq_;  // one point per round: the tets, until mesh() or the extract
  int tie_mode_ = kDefaultTieMode;  // tie_break's mode
  int trace_ = 0;  // GDEL_FLIP_TRACE=1: one line per InsFlip round on stderr; 2: and per flip iteration
  double inv_scale_ = 1.0;
};

}  // namespace gdel::flip
