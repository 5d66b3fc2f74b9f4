// Tet-mesh cases shared by the CPU and GPU test programs.
#pragma once

#include <gtest/gtest.h>

#include "mesh/tet_mesh.hpp"

namespace gdel::test {

// Two tets glued along a face, built through kernels, with slot claims/releases,
// compaction, the invariant checker and the output's tets written over the records; the
// sorts move the arrays by a gather or (gather false) a scatter, and the records whole or
// (whole false) as two halves (TetMesh::reorder).
template <class B>
void tet_mesh_cases(par::Context<B>& ctx, bool gather, bool whole) {
  using namespace gdel::mesh;
  TetMesh<B> m(ctx);
  SlotSource src = m.claim(2);
  EXPECT_GE(m.capacity(), 2);
  MeshView v = m.view();
  // claim two slots and glue them: t0 = (0,1,2,3), t1 = (1,0,2,4) share face (0,1,2)
  par::Buffer<tid_t, B> got(ctx, 2);
  tid_t* gp = got.data();
  par::parallel_for(ctx, 2, [=] GDEL_LAMBDA(std::int64_t k) { gp[k] = src.slot(k); });
  auto ids = got.to_host();
  EXPECT_NE(ids[0], ids[1]);
  EXPECT_EQ(m.size(), 2);
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) {
    tid_t a = gp[0] < gp[1] ? gp[0] : gp[1], b = gp[0] < gp[1] ? gp[1] : gp[0];
    v.tet[a] = Tet{{0, 1, 2, 3}};
    v.tet[b] = Tet{{1, 0, 2, 4}};
    for (int i = 0; i < 4; ++i) {
      v.set_opp(4 * a + i, -1);
      v.set_opp(4 * b + i, -1);
    }
    v.state[a] = v.state[b] = kAlive;
    v.set_face_flags(a, 2, kInternal);  // no neighbour there: no flag either
    v.link(a, 3, b, 3);                 // face opposite vertex 3 (= 0,1,2) in both
    v.set_face_flags(a, 3, kInternal);  // the neighbour, then the flag: both kept
    v.set_face_flags(b, 3, kInternal);
    v.nraw[4 * a + 3] = b;              // a relink clears the flag
  });
  auto probs = check_invariants(m, 5);
  EXPECT_TRUE(probs.ok()) << (probs.items.empty() ? "" : probs.items[0]);
  EXPECT_EQ(m.alive_count(), 2);
  {
    const tid_t lo = std::min(ids[0], ids[1]), hi = std::max(ids[0], ids[1]);
    par::Buffer<std::uint8_t, B> fl(ctx, 8);
    std::uint8_t* flp = fl.data();
    par::parallel_for(ctx, 4, [=] GDEL_LAMBDA(std::int64_t i) {
      flp[i] = v.face_flags(lo, static_cast<int>(i));
      flp[4 + i] = v.face_flags(hi, static_cast<int>(i));
    });
    const auto ff = fl.to_host();
    EXPECT_EQ(ff[2], 0);
    EXPECT_EQ(ff[3], 0);
    EXPECT_EQ(ff[4 + 3], kInternal);
    EXPECT_EQ(ff[0], 0);
    EXPECT_EQ(m.records().to_host()[hi].n[3], nb_entry(lo, true));  // the flag: the entry's sign bit
    const auto op = m.opp_to_host();
    EXPECT_EQ(op[4 * lo + 3], pack_facet(hi, 3));
    EXPECT_EQ(op[4 * hi + 3], pack_facet(lo, 3));
  }

  // Break symmetry (a neighbour that does not name the tet back): detected.
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { v.set_opp(4 * 1 + 3, -1); });
  EXPECT_FALSE(check_invariants(m, 5).ok());
  EXPECT_EQ(m.opp_to_host()[4 * 0 + 3], pack_facet(1, 3));  // (no face names slot 0: face 3)
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { v.set_opp(4 * 1 + 2, pack_facet(0, 3)); });
  EXPECT_FALSE(check_invariants(m, 5).ok());  // glued through faces 3 and 2: the faces differ
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { v.set_opp(4 * 1 + 2, -1); });
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { v.link(0, 3, 1, 3); });
  EXPECT_TRUE(check_invariants(m, 5).ok());

  // Release the first, claim three (one reused + two new), then compact.
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { v.set_opp(4 * 1 + 3, -1); });
  par::Buffer<tid_t, B> rel(ctx, 1);
  rel.memset(0);  // slot 0
  m.release(rel.data(), 1);
  EXPECT_EQ(m.free_count(), 1);
  SlotSource src3 = m.claim(3);
  v = m.view();
  par::Buffer<tid_t, B> got3(ctx, 3);
  tid_t* g3 = got3.data();
  par::parallel_for(ctx, 3, [=] GDEL_LAMBDA(std::int64_t k) { g3[k] = src3.slot(k); });
  EXPECT_EQ(got3.to_host(), (std::vector<tid_t>{0, 2, 3}));  // deterministic order
  // Mark slot 0 and 3 alive as isolated tets, 2 stays dead.
  par::parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) {
    v.tet[0] = Tet{{5, 6, 7, 8}};
    v.tet[3] = Tet{{9, 10, 11, kInfinite}};
    for (int i = 0; i < 4; ++i) {
      v.set_opp(i, -1);
      v.set_opp(12 + i, -1);
    }
    v.state[0] = v.state[3] = kAlive;
    v.state[2] = 0;
    v.link(1, 3, 3, 3);  // arbitrary glue for remap test (not geometric)
    v.set_face_flags(3, 3, kInternal);
  });
  // reorder by a key (largest first vertex first): slots follow the key, links follow the slots
  {
    auto rmk = m.reorder([] GDEL_LAMBDA(const Tet& t) { return tid_t(1000 - t.v[0]); }, 1024, false, gather, whole).to_host();
    EXPECT_EQ(m.size(), 3);
    EXPECT_EQ(rmk[2], -1);  // dead slot dropped
    auto tv = m.records().to_host();
    EXPECT_EQ(tv[0].t.v[0], 9);  // keys 991 < 995 < 999
    EXPECT_EQ(tv[1].t.v[0], 5);
    EXPECT_EQ(tv[2].t.v[0], 1);
    EXPECT_EQ(tv[0].t.v[3], kInfinite);
    auto op = m.opp_to_host();
    EXPECT_EQ(op[4 * 0 + 3], pack_facet(2, 3));  // old 3 <-> old 1 glued through face 3
    EXPECT_EQ(op[4 * 2 + 3], pack_facet(0, 3));
    // the per-tet bytes move with their tets (in place: the slot past them is dead)
    auto stv = m.state().to_host();
    EXPECT_EQ(stv[0] & kAlive, kAlive);
    EXPECT_EQ(stv[2] & kAlive, kAlive);
    EXPECT_EQ(stv[3], 0);
    // old slot 3's face 3: its flag moved with its entry, which names old slot 1's new slot
    EXPECT_EQ(tv[0].n[3], nb_entry(2, true));
    EXPECT_EQ(tv[2].n[3], 0);
    // and back to slot order for the compaction checks below
    m.reorder([] GDEL_LAMBDA(const Tet& t) { return tid_t(t.v[0] == 5 ? 0 : t.v[0] == 1 ? 1 : 3); }, 4, false, gather, whole);
  }
  auto remap = m.compact().to_host();
  EXPECT_EQ(m.size(), 3);
  EXPECT_EQ(remap[2], 2);  // already compact: identity
  auto opp = m.opp_to_host();
  EXPECT_EQ(opp[4 * 1 + 3], pack_facet(2, 3));
  EXPECT_EQ(opp[4 * 2 + 3], pack_facet(1, 3));
  // sorted with shrink (the output's form): the capacity is cut to the alive tets (the
  // records' storage too when they move whole)
  m.reorder([] GDEL_LAMBDA(const Tet& t) { return tid_t(t.v[0]); }, 1024, /*shrink=*/true, gather, whole);
  EXPECT_EQ(m.size(), 3);
  EXPECT_EQ(m.capacity(), 3);
  EXPECT_EQ(m.state().size(), 3u);
  if (whole) {
    EXPECT_EQ(m.records().capacity(), 3u);
  }
  auto ts = m.records().to_host();
  EXPECT_EQ(ts[0].t.v[0], 1);
  EXPECT_EQ(ts[1].t.v[0], 5);
  EXPECT_EQ(ts[2].t.v[0], 9);
  EXPECT_EQ(m.opp_to_host()[4 * 2 + 3], pack_facet(0, 3));  // {9,..} and {1,..} still glued
  EXPECT_EQ(m.alive_count(), 3);
  // the output's tets over the records: slots 0 and 2 kept (as output tets 0 and 1), the
  // vertices mapped
  {
    par::Buffer<tid_t, B> pos(ctx, 4);
    pos.assign(std::vector<tid_t>{0, 1, 1, 2});
    auto out = m.take_tets(pos.data(), 8, [] GDEL_LAMBDA(vid_t x) { return static_cast<std::int32_t>(x + 100); });
    EXPECT_EQ(out.size(), 8u);
    EXPECT_EQ(m.records().size(), 0u);
    EXPECT_EQ(out.to_host(), (std::vector<std::int32_t>{101, 100, 102, 104, 109, 110, 111, 100 + kInfinite}));
  }
}

}  // namespace gdel::test
