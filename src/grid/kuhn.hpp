// The grid perturbation of the digital-grid dualization (ALGORITHMS.md §7, thesis ch. 5):
// every 2×2×2 cube of voxels is cut into the 6 Kuhn (Freudenthal) tetrahedra around its
// diagonal 000–111. All cubes use the same diagonal direction, so the tets of neighbouring
// cubes meet face to face and the voxel centres are triangulated; it is the triangulation
// a symbolic perturbation of the voxel centres would select, which is why a colouring of
// the grid has a well-defined dual here while the unperturbed grid (a 2×2×2 block with 5
// to 8 colours is a "digital Voronoi vertex" of degree > 4) has none (docs/grid.md).
//
// Corners of a cube are numbered dx + 2·dy + 4·dz. Tet j (0..5) is {000, 111, h_j,
// h_{j+1}} over the hexagon h = 011, 010, 110, 100, 101, 001, which circles the diagonal.
// A tet is "4-coloured" when its 4 voxels carry 4 distinct sites and none is the outside
// marker; it is then dual to the site tet of those 4 sites.
//
// (gStar4D's working-set scan, star4d/working_sets.hpp, walks the same 6 tets for their
// edges with its own copy of the hexagon; docs/grid.md names the shared rule.)
#pragma once

#include <cstdint>

#include "core/macros.hpp"

namespace gdel::grid {

// Corner k (0..3) of Kuhn tet j: 000, 111, then two consecutive hexagon corners.
GDEL_HD constexpr int kuhn_corner(int j, int k) {
  constexpr int hex[6] = {6, 2, 3, 1, 5, 4};  // 011, 010, 110, 100, 101, 001 as dx + 2dy + 4dz
  return k == 0 ? 0 : k == 1 ? 7 : hex[(j + k - 2) % 6];
}

// Orientation sign of Kuhn tet j with its corners in kuhn_corner order, as unit-cube
// points (orient3d convention of mesh/conventions.hpp: sign of det[b−a, c−a, d−a]).
constexpr int kuhn_orientation(int j) {
  int p[4][3] = {};
  for (int k = 0; k < 4; ++k) {
    const int c = kuhn_corner(j, k);
    p[k][0] = c & 1;
    p[k][1] = (c >> 1) & 1;
    p[k][2] = (c >> 2) & 1;
  }
  int m[3][3] = {};
  for (int r = 0; r < 3; ++r)
    for (int a = 0; a < 3; ++a) m[r][a] = p[r + 1][a] - p[0][a];
  const int det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det > 0 ? 1 : det < 0 ? -1 : 0;
}
// The 6 tets fill the cube (volume 6 · 1/6) with one orientation: the hexagon turns one
// way around the diagonal.
static_assert(kuhn_orientation(0) == kuhn_orientation(1) && kuhn_orientation(1) == kuhn_orientation(2) &&
                  kuhn_orientation(2) == kuhn_orientation(3) && kuhn_orientation(3) == kuhn_orientation(4) &&
                  kuhn_orientation(4) == kuhn_orientation(5) && kuhn_orientation(0) != 0,
              "Kuhn tets of one cube share an orientation");
inline constexpr int kKuhnSign = kuhn_orientation(0);

// Bit j set iff Kuhn tet j of the cube with corner colours c[0..7] is 4-coloured.
// `outside` is the marker colour of voxels outside the grid (never a site).
GDEL_HD inline int coloured_kuhn_tets(const std::int32_t c[8], std::int32_t outside) {
  if (c[0] == c[7] || c[0] == outside || c[7] == outside) return 0;  // every tet holds both
  int tets = 0;
  for (int j = 0; j < 6; ++j) {
    const std::int32_t a = c[kuhn_corner(j, 2)], b = c[kuhn_corner(j, 3)];
    if (a != b && a != c[0] && a != c[7] && b != c[0] && b != c[7] && a != outside && b != outside) tets |= 1 << j;
  }
  return tets;
}

}  // namespace gdel::grid
