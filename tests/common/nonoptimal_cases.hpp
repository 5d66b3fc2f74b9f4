// Options::nonoptimal_flips (non-optimal flipping once gFlip3D is stuck), shared by the
// CPU and GPU test programs of gFlip3D.
#pragma once

#include <gtest/gtest.h>

#include "common/gdel3d_cases.hpp"

namespace gdel::test {

inline Options nonoptimal_options(Backend b, Algorithm a, bool terminal, bool nonoptimal) {
  Options o;
  o.backend = b;
  o.algorithm = a;
  o.terminal_flipping = terminal;
  o.nonoptimal_flips = nonoptimal;
  o.canonical_order = true;
  o.cpu_rounds = true;  // the rounds, also on the CPU (without non-optimal flips too)
  return o;
}

// Every generator, InsFlip and the terminal variant: gflip3d with the option gives a
// valid triangulation and keeps no more non-locally-Delaunay facets than flipping was
// stuck with; gdel3d with the option gives the exact Delaunay triangulation, the same
// tets as without it.
inline void nonoptimal_generator_cases(Backend b, std::size_t n) {
  for (gen::Distribution d : gen::kAllDistributions) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    const std::size_t nn = d == gen::Distribution::SkewLines ? std::min<std::size_t>(n / 10, 400) : n;
    auto pts = gen::generate(d, nn, 2718);
    for (bool terminal : {false, true}) {
      SCOPED_TRACE(terminal ? "terminal" : "insflip");
      Triangulation t = delaunay(pts, nonoptimal_options(b, Algorithm::gflip3d, terminal, true));
      expect_flip_output_valid(pts, t, b, terminal);
      EXPECT_LE(t.stats.nonld_facets_kept, t.stats.nonld_facets_stuck);
      if (t.stats.nonld_facets_stuck > 0) {
        EXPECT_GT(t.stats.nonoptimal_rounds, 0);
      }
      // every facet has a finite vertex: no failed vertex iff no such facet is kept
      EXPECT_EQ(t.failed_vertices.empty(), t.stats.nonld_facets_kept == 0);

      if (!terminal) {  // with independent splits: a round after every insertion round too
        Options oi = nonoptimal_options(b, Algorithm::gflip3d, false, true);
        oi.independent_splits = true;
        Triangulation ti = delaunay(pts, oi);
        expect_flip_output_valid(pts, ti, b);
        EXPECT_LE(ti.stats.nonld_facets_kept, ti.stats.nonld_facets_stuck);
      }
      Triangulation ref = delaunay(pts, nonoptimal_options(b, Algorithm::gdel3d, terminal, false));
      Triangulation t2 = delaunay(pts, nonoptimal_options(b, Algorithm::gdel3d, terminal, true));
      expect_exact_delaunay(pts, t2, b);
      EXPECT_EQ(t2.tets, ref.tets);
      EXPECT_EQ(t2.neighbors, ref.neighbors);
    }
  }
}

// Where flipping gets stuck (a thin shell; the terminal variant gets stuck much more),
// the option fires and leaves fewer facets that are not locally Delaunay (exact
// verifier) and fewer failed vertices than plain gFlip3D.
inline void nonoptimal_reduces_cases(Backend b) {
  auto pts = gen::generate(gen::Distribution::ThinShell, 20000, 1);
  for (bool terminal : {false, true}) {
    SCOPED_TRACE(terminal ? "terminal" : "insflip");
    Triangulation plain = delaunay(pts, nonoptimal_options(b, Algorithm::gflip3d, terminal, false));
    Triangulation t = delaunay(pts, nonoptimal_options(b, Algorithm::gflip3d, terminal, true));
    SCOPED_TRACE(plain.stats.to_string());
    SCOPED_TRACE(t.stats.to_string());
    expect_flip_output_valid(pts, t, b, terminal);
    EXPECT_EQ(plain.stats.nonoptimal_rounds, 0);
    EXPECT_GT(t.stats.nonoptimal_flips, 0);
    EXPECT_LT(t.stats.nonld_facets_kept, t.stats.nonld_facets_stuck);
    const auto rp = verify(pts, plain.tets, {}, b);
    const auto rt = verify(pts, t.tets, {}, b);
    EXPECT_GT(rp.non_delaunay_facets, 0);
    EXPECT_LT(rt.non_delaunay_facets, rp.non_delaunay_facets);
    EXPECT_LT(t.failed_vertices.size(), plain.failed_vertices.size());
    // the terminal variant: at least a fifth fewer (measured: 4566 -> 3230 on the CPU)
    if (terminal) {
      EXPECT_LT(5 * rt.non_delaunay_facets, 4 * rp.non_delaunay_facets);
    }
  }
}

// Algorithm::Auto: gdel3d with, on the CUDA backend, non-optimal flipping only when flipping
// is stuck on fewer facets than 1 % of the points — on uniform points it runs (0.1 %
// stuck), on the exactly cospherical sphere inserted by centroids (most facets are ties;
// 28 % stuck) it is skipped; on the CPU backend never; the tets are gdel3d's either way.
// (The default insertion rule switches to SoS order on the sphere, where 0.3 % are left
// stuck: bench/RESULTS.md, session 54.)
inline void nonoptimal_auto_cases(Backend b) {
  for (auto d : {gen::Distribution::Uniform, gen::Distribution::Sphere}) {
    SCOPED_TRACE(std::string(gen::to_string(d)));
    const std::size_t n = 20000;
    auto pts = gen::generate(d, n, 1);
    Options o;
    o.backend = b;
    o.canonical_order = true;
    if (d == gen::Distribution::Sphere) o.insertion = InsertionRule::Centroid;
    Triangulation a = delaunay(pts, o);  // Algorithm::Auto
    SCOPED_TRACE(a.stats.to_string());
    expect_exact_delaunay(pts, a, b);
    o.algorithm = Algorithm::gdel3d;
    Triangulation g = delaunay(pts, o);
    EXPECT_EQ(g.stats.nonoptimal_rounds, 0);
    EXPECT_EQ(a.tets, g.tets);
    EXPECT_EQ(a.neighbors, g.neighbors);
    if (b == Backend::Cpu) {  // Auto runs no non-optimal flips on the CPU backend: not even the count
      EXPECT_EQ(a.stats.nonld_facets_stuck, 0);
      EXPECT_EQ(a.stats.nonoptimal_rounds, 0);
      for (const auto& st : a.stats.stages) EXPECT_NE(st.first, "non-optimal flipping");
      continue;
    }
    EXPECT_GT(a.stats.nonld_facets_stuck, 0);
    const bool few = 100 * a.stats.nonld_facets_stuck < static_cast<std::int64_t>(n);
    EXPECT_EQ(few, d == gen::Distribution::Uniform);
    if (few) {
      EXPECT_GT(a.stats.nonoptimal_rounds, 0);
    } else {
      EXPECT_EQ(a.stats.nonoptimal_rounds, 0);
      EXPECT_EQ(a.stats.nonld_facets_kept, a.stats.nonld_facets_stuck);
    }
  }
}

// Options::nonoptimal_flips with independent splits: a non-optimal round also follows
// every insertion round's flipping, from the tets it left stuck. Thin shell, 2e5 points,
// seeds 1-3, exact verifier. Non-LD facets with independent splits alone / with the
// option, per seed: 401 / 134, 271 / 370, 458 / 205 in the slots' allocation order
// (session 12); 90 / 56, 416 / 150, 54 / 256 with tet reordering (Options::reorder_tets,
// session 24). The counts swing 5x from seed to seed and the option makes some seeds
// worse, so the sum is asserted, and only to fall (1130 -> 709 and 560 -> 462).
// Asserted, under the default options (tets reordered): valid output, non-optimal rounds
// run between insertion rounds (Stats::nonoptimal_between_rounds; until session 25 the
// total was asserted above the final stage's cap of 16 instead, which reordering, with
// fewer rounds leaving tets stuck, missed: GPU seed 1, 14), none without the option, and
// fewer facets left not locally Delaunay in all.
inline void nonoptimal_each_round_cases(Backend b) {
  std::int64_t plain = 0, with = 0;
  for (std::uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto pts = gen::generate(gen::Distribution::ThinShell, 200000, seed);
    Options o = nonoptimal_options(b, Algorithm::gflip3d, false, false);
    o.independent_splits = true;
    Triangulation ind = delaunay(pts, o);
    o.nonoptimal_flips = true;
    Triangulation t = delaunay(pts, o);
    SCOPED_TRACE(t.stats.to_string());
    expect_flip_output_valid(pts, t, b);
    EXPECT_GT(t.stats.nonoptimal_between_rounds, 0);
    EXPECT_GE(t.stats.nonoptimal_rounds, t.stats.nonoptimal_between_rounds);
    EXPECT_EQ(ind.stats.nonoptimal_rounds, 0);
    plain += verify(pts, ind.tets, {}, b).non_delaunay_facets;
    with += verify(pts, t.tets, {}, b).non_delaunay_facets;
  }
  EXPECT_GT(plain, 0);
  EXPECT_LT(with, plain);
}

}  // namespace gdel::test
