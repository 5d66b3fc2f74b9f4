// Predicates of gFlip3D over internal vertex ids, with the point at infinity.
//
// Internal ids 0..n-1 are the (Hilbert-sorted, deduplicated) points; id n is the
// point at infinity, stored as the "kernel point" K: a point strictly inside the
// first tetrahedron, hence strictly inside every later hull (the hull only grows).
// Tets containing ∞ are the cones from K over hull facets; they partition the
// outside of the hull. Rules (ALGORITHMS.md §1.5):
//   orient3d with ∞ among the arguments = -orient3d with K in its place;
//   insphere(tet ∋ ∞, e) = orient3d(hull facet of the tet, e): inside iff beyond;
//   insphere(tet, ∞) = outside.
// When the first tetrahedron holds no double at all (Geo::k_centroid; docs/gflip3d.md), K
// is the exact centroid of its four vertices kq and orientations with ∞ are evaluated by
// geom::orient3d_centroid_sos (xyz's slot for K then holds the rounded centroid, which no
// predicate reads).
// Every decision has a fast form (floating-point filter; returns kUndecided when it
// cannot certify a non-zero sign) and an exact form (exact arithmetic, then
// simulation of simplicity by original input index: never 0). The exact forms take a
// scratch of geom::kPredicateWork doubles (as Work: double*, or std::nullptr_t for none at
// compile time, whose instances hold no expansions: geom's predicates.hpp); without one
// they decide only what the integer stage decides (Geo::int_all; or Geo::int_points and
// no ∞ among the points, whose kernel point K is then not known to be of the stage) and answer
// kUndecided otherwise, so that par::fast_then_exact_tiered can try them without a
// scratch first, and the star splaying engine on integer input runs without one
// (Geo::int_all, par::for_each_with_scratch's scratch_free). insphere ties are
// broken by perturbing the lifting first (insphere_lift_sos), so the exact Delaunay
// triangulation has no flat tets (see orient4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "core/macros.hpp"
#include "geometry/predicates.hpp"
#include "mesh/conventions.hpp"
#include "parallel/atomic.hpp"
#include "parallel/exact_batch.hpp"

namespace gdel::flip {

struct Geo {
  const double* xyz;        // n + 1 points (internal order), the last is K
  const std::int64_t* sid;  // SoS index per internal id (original input index; K: n_input)
  vid_t inf;                // internal id of ∞ (= n)
  // Weights per internal id (n + 1 values; nullptr = unweighted). With weights the
  // lifting is |p|^2 - w: orient4 without ∞ becomes the power test (lifted orientation
  // of the regular triangulation), and a star may die (star.hpp: every facet beyond).
  // Only the star splaying engine reads it; gFlip3D's tests (insphere) ignore it.
  const double* w = nullptr;
  // Every finite point (and weight) is a point of the integer stage at scale 1
  // (geom::integer_point; all_integer_points below): exact evaluations over finite
  // points then never touch the scratch.
  bool int_points = false;
  // Every point, ∞'s kernel point K included, is a point of the integer stage at the
  // quarter scale (integer input within 2^21, K the centroid of four of its points):
  // no exact evaluation touches the scratch.
  bool int_all = false;
  // Where insphere's exact form counts its exact ties (the unperturbed sign 0, decided by
  // the perturbation; atomic adds) of tets that are not flat, nullptr: not counted.
  // gFlip3D counts them in its first rounds (GFlip3D::decide_sos_order).
  std::int64_t* ties = nullptr;
  // K is the exact centroid of the points kq[0..3] (not a double; see the top of this
  // file). Never with int_all (integer input's centroid is a quarter-integer double).
  bool k_centroid = false;
  vid_t kq[4] = {0, 0, 0, 0};
  // -1: an orientation with ∞ among its points is minus the one with K in ∞'s place (the
  // rule above); +1: ∞'s id stands for K itself (gFlip3D's first location, whose cone
  // tests are orientations with K).
  int inf_sign = -1;
  // K as another Geo over the same points has it (k_centroid and kq).
  void take_kernel_point(const Geo& o) {
    k_centroid = o.k_centroid;
    for (int i = 0; i < 4; ++i) kq[i] = o.kq[i];
  }

  GDEL_HD const double* p(vid_t v) const { return xyz + 3 * static_cast<std::int64_t>(v); }
  // Whether an exact form may go on with work = nullptr (see the top of this file): over
  // finite points only, and over any points.
  GDEL_HD bool finite_scratch_free() const { return int_points || int_all; }
  GDEL_HD bool scratch_free(vid_t a, vid_t b, vid_t c, vid_t d, vid_t e = 0) const {
    return int_all || (int_points && a != inf && b != inf && c != inf && d != inf && e != inf);
  }

  // A predicate's sign as Geo's answer: kUncertain (a filter's, or an exact form's
  // without a scratch outside the integer stage) is kUndecided; so is a filter's 0,
  // should one return it (the exact form decides).
  GDEL_HD static int exact_answer(int s) { return s == geom::kUncertain ? int(par::kUndecided) : s; }
  GDEL_HD static int filter_answer(int s) { return (s == geom::kUncertain || s == 0) ? int(par::kUndecided) : s; }

  // Whether ∞ is among the four vertices.
  GDEL_HD bool has_inf(vid_t a, vid_t b, vid_t c, vid_t d) const {
    return (a == inf) | (b == inf) | (c == inf) | (d == inf);
  }
  // orient3d(a,b,c,d) > 0 iff (a,b,c,d) is positively oriented.
  GDEL_HD int orient_fast(vid_t a, vid_t b, vid_t c, vid_t d) const {
    const bool with_inf = has_inf(a, b, c, d);
    // (the exact form filters first: no call here, which slowed every fast kernel by up to
    // 14 % on an H100, bench/RESULTS.md session 56)
    if (k_centroid && with_inf) return par::kUndecided;
    const int s = geom::orient3d_filter(p(a), p(b), p(c), p(d));
    if (filter_answer(s) == par::kUndecided) return par::kUndecided;
    return with_inf ? inf_sign * s : s;
  }
  // Orientation with ∞ (times inf_sign) where K is the exact centroid of kq (k_centroid):
  // its filter, then exact with SoS (work: a scratch). Out of line: a rare path kept out of
  // the registers of the kernels that inline orient_exact.
  GDEL_NOINLINE GDEL_HD int centroid_orient(vid_t a, vid_t b, vid_t c, vid_t d, double* work) const {
    const vid_t v[4] = {a, b, c, d};
    const double* r[4];
    std::int64_t ids[4];
    int kpos = 0;
    for (int i = 0; i < 4; ++i) {
      r[i] = p(v[i]);
      ids[i] = sid[v[i]];
      if (v[i] == inf) kpos = i;
    }
    const double* q[4] = {p(kq[0]), p(kq[1]), p(kq[2]), p(kq[3])};
    return inf_sign * geom::orient3d_centroid_sos(r, kpos, q, ids, work);  // (never 0)
  }
  template <class Work>
  GDEL_HD int orient_exact(vid_t a, vid_t b, vid_t c, vid_t d, Work work) const {
    const bool with_inf = has_inf(a, b, c, d);
    if (k_centroid && with_inf) {
      if constexpr (std::is_same_v<Work, std::nullptr_t>) return par::kUndecided;
      else return work ? centroid_orient(a, b, c, d, work) : int(par::kUndecided);
    }
    if (geom::no_scratch(work) && !scratch_free(a, b, c, d)) return par::kUndecided;
    const int s = geom::orient3d_sos(p(a), p(b), p(c), p(d), sid[a], sid[b], sid[c], sid[d], work);
    if (exact_answer(s) == par::kUndecided) return par::kUndecided;  // (work = nullptr only)
    return with_inf ? inf_sign * s : s;
  }
  template <bool Exact, class Work>
  GDEL_HD int orient(vid_t a, vid_t b, vid_t c, vid_t d, Work work) const {
    if constexpr (Exact) return orient_exact(a, b, c, d, work);
    else return orient_fast(a, b, c, d);
  }

  // The plain orientation of four finite vertices, without SoS (0: exactly flat), for
  // dropping the flat tets of an output: the filter's sign or kUndecided, then exact.
  GDEL_HD std::int8_t volume_sign_fast(const vid_t* v) const {
    const int s = geom::orient3d_filter(p(v[0]), p(v[1]), p(v[2]), p(v[3]));
    return static_cast<std::int8_t>(filter_answer(s));
  }
  template <class Work>
  GDEL_HD std::int8_t volume_sign_exact(const vid_t* v, Work work) const {
    if (geom::no_scratch(work) && !scratch_free(v[0], v[1], v[2], v[3])) return par::kUndecided;
    const int s = geom::orient3d_exact(p(v[0]), p(v[1]), p(v[2]), p(v[3]), work);
    return static_cast<std::int8_t>(exact_answer(s));
  }

  GDEL_HD static int inf_slot(const vid_t* t, vid_t inf) {
    for (int i = 0; i < 4; ++i)
      if (t[i] == inf) return i;
    return -1;
  }

  // The one lifted orientation every star and repair decision uses (ALGORITHMS.md §4):
  // the sign, in insphere's convention, of the perturbed 5x5 determinant of the lifted
  // points v[0..4], ∞ included. For (s,a,b,c) a star facet oriented with the star's
  // points beneath, > 0 means v[4] is beyond it (in conflict). The perturbation is one
  // consistent scheme with priorities
  //   ∞'s height H  >>  its δ-perturbed 3-D terms  >>  exact lifted det  >>  lifting
  //   perturbation ε (Devillers-Teillaud, insphere_lift_sos)  >>  E-M position SoS δ;
  // hence: no ∞ → insphere_lift_sos; ∞ at slot j → move it last (odd permutation when
  // j < 4) where det = -H·orient3d_sos(the other four) decides. Finite flat tets never
  // survive as lower-hull facets under the lifting perturbation (docs/gdel3d.md).
  template <bool Exact, class Work>
  GDEL_HD int orient4(const vid_t* v, Work work) const {
    if constexpr (Exact) {  // (with ∞ the test is over the four finite points)
      if (geom::no_scratch(work) && !finite_scratch_free()) return par::kUndecided;
    }
    int j = -1;
    for (int i = 0; i < 5; ++i)
      if (v[i] == inf) j = i;
    if (j < 0 && w) {
      if constexpr (Exact) {
        const int s = geom::power_lift_sos(p(v[0]), p(v[1]), p(v[2]), p(v[3]), p(v[4]), w[v[0]], w[v[1]],
                                           w[v[2]], w[v[3]], w[v[4]], sid[v[0]], sid[v[1]], sid[v[2]], sid[v[3]],
                                           sid[v[4]], work);
        return exact_answer(s);
      } else {
        int s = geom::power_filter(p(v[0]), p(v[1]), p(v[2]), p(v[3]), p(v[4]), w[v[0]], w[v[1]], w[v[2]],
                                   w[v[3]], w[v[4]]);
        return filter_answer(s);
      }
    }
    if (j < 0) {
      if constexpr (Exact) {
        const int s = geom::insphere_lift_sos(p(v[0]), p(v[1]), p(v[2]), p(v[3]), p(v[4]), sid[v[0]], sid[v[1]],
                                              sid[v[2]], sid[v[3]], sid[v[4]], work);
        return exact_answer(s);
      } else {
        int s = geom::insphere_filter(p(v[0]), p(v[1]), p(v[2]), p(v[3]), p(v[4]));
        return filter_answer(s);
      }
    }
    vid_t u[4];  // (∞'s slot by a compare per slot: u[j] would put u in the stack)
    for (int i = 0; i < 4; ++i) u[i] = i == j ? v[4] : v[i];
    int s;
    if constexpr (Exact) {
      s = geom::orient3d_sos(p(u[0]), p(u[1]), p(u[2]), p(u[3]), sid[u[0]], sid[u[1]], sid[u[2]], sid[u[3]], work);
      if (exact_answer(s) == par::kUndecided) return par::kUndecided;
    } else {
      s = geom::orient3d_filter(p(u[0]), p(u[1]), p(u[2]), p(u[3]));
      if (filter_answer(s) == par::kUndecided) return par::kUndecided;
    }
    return j < 4 ? s : -s;
  }
  template <class Work>
  GDEL_HD int orient4_any(const vid_t* v, Work work) const {
    int s = orient4<false>(v, nullptr);
    return s != par::kUndecided ? s : orient4<true>(v, work);
  }

  // > 0 iff e is strictly inside the circumsphere of the positive tet t.
  template <bool Exact, class Work>
  GDEL_HD int insphere(const vid_t* t, vid_t e, Work work) const {
    if (e == inf) return -1;
    int j = inf_slot(t, inf);
    if (j >= 0)
      return orient<Exact>(pick4(t, face_vertex(j, 0)), pick4(t, face_vertex(j, 1)), pick4(t, face_vertex(j, 2)), e,
                           work);
    if constexpr (Exact) {
      if (geom::no_scratch(work) && !finite_scratch_free()) return par::kUndecided;
      bool tied = false;
      const int s = geom::insphere_lift_sos(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e), sid[t[0]], sid[t[1]],
                                            sid[t[2]], sid[t[3]], sid[e], work, ties ? &tied : nullptr);
      // a tie of a flat tet is not counted: four coplanar points (e.g. four collinear ones
      // among the five, as on two skew lines) tie with no cosphericity, and the count is
      // for cospherical input (GFlip3D::decide_sos_order; bench/RESULTS.md, session 54)
      if (tied && geom::orient3d(p(t[0]), p(t[1]), p(t[2]), p(t[3]), work) != 0)
        par::atomic_add(ties, std::int64_t(1));
      return exact_answer(s);
    } else {
      int s = geom::insphere_filter(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e));
      return filter_answer(s);
    }
  }
};

// Whether every point of xyz[0, n) (and weight of w, when not nullptr) is a point of the
// integer stage at `scale` (geom::integer_point): Geo::int_points (scale 1), and with
// the kernel point Geo::int_all (geom::kQuarterScale). GDEL_EXACT_TIERS=0 says no (for
// measurements: every exact evaluation then has its scratch, as before). Synchronizes.
template <class B>
bool all_integer_points(par::Context<B>& ctx, const double* xyz, const double* w, std::int64_t n,
                        double scale = 1.0) {
  if (par::knob_off("GDEL_EXACT_TIERS")) return false;
  if (n <= 0) return false;
  const std::int64_t off = par::count_indices(ctx, static_cast<std::size_t>(n), [=] GDEL_LAMBDA(std::int64_t i) {
    return !geom::integer_point(xyz + 3 * i, w ? w[i] : 0.0, scale);
  });
  return off == 0;
}

}  // namespace gdel::flip
