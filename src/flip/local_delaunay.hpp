// Which facets of a tetrahedral mesh are not locally Delaunay, under the one lifted test
// that every repair decision uses (Geo::orient4, ∞ included). Shared by gDel3D's failed
// vertices and gFlip3D's non-optimal flipping.
#pragma once

#include <cstdint>

#include "flip/flip_kernels.hpp"
#include "parallel/exact_batch.hpp"

namespace gdel::flip {

// sg[4t+i] = orient4 of (tet t, apex across its face i): > 0 iff that facet is not
// locally Delaunay. Each facet is evaluated once, from the tet of smaller index; the other
// side, faces without a neighbour and dead tets get 0. sg holds 4·nt entries. Returns the
// number of facets the exact pass decided.
template <class B>
std::int64_t facet_signs(par::Context<B>& ctx, mesh::MeshView mv, std::int64_t nt, Geo g, std::int8_t* sg) {
  auto tuple = [=] GDEL_LAMBDA(std::int64_t f, vid_t* v) -> bool {
    const fid_t o = mv.opp(f);
    const tid_t t = static_cast<tid_t>(f >> 2);
    if (o < 0 || facet_tet(o) < t || !mv.alive(t)) return false;
    for (int i = 0; i < 4; ++i) v[i] = mv.tet[t].v[i];
    v[4] = apex_of(mv, o);
    // facet test: both tets may hold ∞, but the 5-tuple must be 5 distinct vertices
    return true;
  };
  return par::two_stage_signs(
      ctx, 4 * nt, sg,
      [=] GDEL_LAMBDA(std::int64_t f) -> std::int8_t {
        vid_t v[5] = {0, 0, 0, 0, 0};
        if (!tuple(f, v)) return 0;
        return static_cast<std::int8_t>(g.orient4<false>(v, nullptr));
      },
      [=] GDEL_LAMBDA(std::int64_t f, double* work) -> std::int8_t {
        vid_t v[5] = {0, 0, 0, 0, 0};
        if (!tuple(f, v)) return 0;
        return static_cast<std::int8_t>(g.orient4<true>(v, work));
      },
      geom::kPredicateWork);
}

}  // namespace gdel::flip
