// Neighbours of an output tet list left open: faces whose neighbour an extraction could
// not name directly (star tets of the repair, faces of dropped flat tets), marked -2.
// Written once over the backend tag.
#pragma once

#include <cstdint>

#include "mesh/conventions.hpp"
#include "parallel/primitives.hpp"

namespace gdel::mesh {

// tp: 4 nout vertex ids; np: 4 nout neighbours (tet number, -1 on the hull, -2 open).
// Every open face gets the other tet with the same three vertices, found by sorting the
// open faces' sorted vertex triples (two stable passes: the largest vertex, then the
// other two), or -1 (a hull face) when it has no partner.
// (tp, np: backend memory; on host backends any host memory, e.g. the caller's arrays)
template <class B>
void match_open_faces(par::Context<B>& ctx, const vid_t* tp, std::int32_t* np, std::int64_t nout) {
  using I64 = std::int64_t;
  using U64 = std::uint64_t;
  auto open = [=] GDEL_LAMBDA(I64 f) { return np[f] == -2; };
  // counted first: few open faces beside the 4 nout faces
  const std::size_t k = static_cast<std::size_t>(par::count_indices(ctx, static_cast<std::size_t>(4 * nout), open));
  if (k == 0) return;
  par::Buffer<I64, B> faces(ctx, k);
  par::select_indices(ctx, static_cast<std::size_t>(4 * nout), faces.data(), open);
  const I64* fp = faces.data();
  auto face = [=] GDEL_LAMBDA(I64 f, vid_t* w) {
    const I64 t = f >> 2;
    const int i = static_cast<int>(f & 3);
    vid_t a = tp[4 * t + face_vertex(i, 0)], b = tp[4 * t + face_vertex(i, 1)], c = tp[4 * t + face_vertex(i, 2)];
    if (a > b) { vid_t x = a; a = b; b = x; }
    if (b > c) { vid_t x = b; b = c; c = x; }
    if (a > b) { vid_t x = a; a = b; b = x; }
    w[0] = a; w[1] = b; w[2] = c;
  };
  par::Buffer<U64, B> key(ctx, k);
  par::Buffer<I64, B> val(ctx, k);
  U64* kp = key.data();
  I64* vp = val.data();
  par::parallel_for(ctx, static_cast<I64>(k), [=] GDEL_LAMBDA(I64 j) {
    vid_t w[3];
    face(fp[j], w);
    kp[j] = static_cast<std::uint32_t>(w[2]);
    vp[j] = fp[j];
  });
  par::sort_pairs(ctx, kp, vp, k);
  par::parallel_for(ctx, static_cast<I64>(k), [=] GDEL_LAMBDA(I64 j) {
    vid_t w[3];
    face(vp[j], w);
    kp[j] = (static_cast<U64>(static_cast<std::uint32_t>(w[0])) << 32) | static_cast<std::uint32_t>(w[1]);
  });
  par::sort_pairs(ctx, kp, vp, k);
  const I64 kk = static_cast<I64>(k);
  par::parallel_for(ctx, kk, [=] GDEL_LAMBDA(I64 j) {
    vid_t w[3], x[3];
    face(vp[j], w);
    bool paired = false;
    if (j + 1 < kk) {
      face(vp[j + 1], x);
      if (x[0] == w[0] && x[1] == w[1] && x[2] == w[2]) {
        np[vp[j]] = static_cast<std::int32_t>(vp[j + 1] >> 2);
        paired = true;
      }
    }
    if (j > 0) {
      face(vp[j - 1], x);
      if (x[0] == w[0] && x[1] == w[1] && x[2] == w[2]) {
        np[vp[j]] = static_cast<std::int32_t>(vp[j - 1] >> 2);
        paired = true;
      }
    }
    if (!paired) np[vp[j]] = -1;
  });
}

}  // namespace gdel::mesh
