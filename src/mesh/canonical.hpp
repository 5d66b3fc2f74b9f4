// Canonical form of oriented tetrahedra, so that two triangulations of the same
// points (from gdel's backends, CGAL, a file) can be compared exactly.
//
// A tet (a,b,c,d) and any even permutation of it describe the same oriented cell
// (orient3d is invariant under even permutations, see mesh/conventions.hpp); an odd
// permutation describes the opposite orientation. canonical_tet() picks one
// representative of the 12 even permutations:
//
//   * the smallest index goes first, and
//   * the other three are rotated cyclically (an even permutation of them) so that
//     the smaller of those three comes second.
//
// Two tets therefore have equal canonical forms iff they have the same vertex set
// and the same orientation. canonical() additionally sorts the list, so two lists
// of tets compare equal iff they describe the same set of oriented cells.
//
// Host-only, header-only; no dependency other than the standard library.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace gdel {

// Even permutation of t with the smallest index first and the smaller of the
// remaining three second. Tets with repeated indices (never produced by a valid
// triangulation) are still mapped deterministically.
template <class Index>
constexpr std::array<Index, 4> canonical_tet(const std::array<Index, 4>& t) {
  int k = 0;
  for (int i = 1; i < 4; ++i)
    if (t[i] < t[k]) k = i;
  // Bring position k to the front with a double transposition (even): swap (0 k)
  // together with the swap of the other two positions.
  std::array<Index, 4> r = t;
  switch (k) {
    case 1: r = {t[1], t[0], t[3], t[2]}; break;
    case 2: r = {t[2], t[3], t[0], t[1]}; break;
    case 3: r = {t[3], t[2], t[1], t[0]}; break;
    default: break;
  }
  // Rotate the last three (a 3-cycle is even) so the smallest of them is second.
  if (r[2] < r[1] && r[2] <= r[3]) {
    r = {r[0], r[2], r[3], r[1]};
  } else if (r[3] < r[1] && r[3] < r[2]) {
    r = {r[0], r[3], r[1], r[2]};
  }
  return r;
}

// True iff a and b are the same oriented tet (same vertices, same orientation).
template <class Index>
constexpr bool same_oriented_tet(const std::array<Index, 4>& a, const std::array<Index, 4>& b) {
  return canonical_tet(a) == canonical_tet(b);
}

// Parity of the permutation taking tet a to tet b (same vertex set required):
// 0 = even (same orientation), 1 = odd (opposite), -1 = the vertex sets differ.
template <class Index>
constexpr int tet_permutation_parity(const std::array<Index, 4>& a, const std::array<Index, 4>& b) {
  const auto ca = canonical_tet(a);
  const auto cb = canonical_tet(b);
  if (ca == cb) return 0;
  const std::array<Index, 4> flipped = {cb[0], cb[1], cb[3], cb[2]};
  if (ca == canonical_tet(flipped)) return 1;
  return -1;
}

// Rewrites every tet in canonical form and sorts the list (lexicographically).
template <class Index>
void canonicalize(std::vector<std::array<Index, 4>>& tets) {
  for (auto& t : tets) t = canonical_tet(t);
  std::sort(tets.begin(), tets.end());
}

// Canonical copy of a tet list: canonical_tet on each, then sorted.
template <class Index>
std::vector<std::array<Index, 4>> canonical(std::vector<std::array<Index, 4>> tets) {
  canonicalize(tets);
  return tets;
}

}  // namespace gdel
