// Tetrahedral mesh on a backend, for the flipping and repair stages. See
// mesh/conventions.hpp for the combinatorial conventions.
//
//   rec[t]    one 32-byte aligned record a tet slot (one L2 sector):
//     .t      4 vertex ids (internal ids; kInfinite for the point at infinity)
//     .n[i]   the neighbour tet across face i (kNoTet: none), with face i's one flag,
//             kInternal (created inside a split or flip: known locally Delaunay), in
//             the sign bit: u | 2^31 (MeshView::opp_tet and the other accessors decode;
//             slots stay below 2^31 - 1, TetMesh::kMaxSlots). A tet's vertices and
//             neighbours in one record: the flips read a tet and its neighbours in one
//             sector and write a new tet as one whole sector (bench/RESULTS.md, session
//             59). The neighbour's own face index is not stored: it is the one of its 4
//             entries that names this tet (MeshView::nb_face; two tets of a
//             triangulation share at most one face), in the record that a caller of the
//             neighbour's face reads anyway for its vertices; and the flag, in the entry
//             that a relink rewrites, is cleared by it without a write of its own
//             (bench/RESULTS.md, session 61: a byte a face was one more random sector a
//             tet read and written in every flip)
//   state[t]  TetState bits (alive, queued)
//
// Slots: a tet slot is alive or free. Free slots sit on a stack. Allocation and
// release are deterministic (so the same input gives the same slots, hence the same
// triangulation, on every run and backend): the host reserves k slots at once with
// TetMesh::claim(k), which returns a SlotSource mapping claim number j in [0, k) to
// a slot; slots are returned with TetMesh::release(list, k) in list order.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "gdel/errors.hpp"
#include "mesh/conventions.hpp"
#include "parallel/atomic.hpp"
#include "parallel/primitives.hpp"

namespace gdel::mesh {

struct alignas(16) Tet {
  vid_t v[4];
};

// A tet slot's record: its vertices and its neighbour tets (see the top of this file).
struct alignas(32) TetRec {
  Tet t;
  tid_t n[4];
};
static_assert(sizeof(TetRec) == 32);

// MeshView's indexers into the records: tet[t] the vertices of slot t, nraw[k] the entry
// of face k = 4t+i as stored (nb_entry).
struct TetsOf {
  TetRec* r;
  GDEL_HD Tet& operator[](std::int64_t t) const { return r[t].t; }
};
struct NeighboursOf {
  TetRec* r;
  GDEL_HD tid_t& operator[](std::int64_t k) const { return r[k >> 2].n[k & 3]; }
};
// A neighbour entry (TetRec::n): the tet, and with kInternal its sign bit set.
GDEL_HD constexpr tid_t nb_entry(tid_t u, bool internal) {
  return internal ? static_cast<tid_t>(static_cast<std::uint32_t>(u) | 0x80000000u) : u;
}
GDEL_HD constexpr tid_t nb_tet(tid_t e) { return e < kNoTet ? (e & 0x7fffffff) : e; }
GDEL_HD constexpr bool nb_internal(tid_t e) { return e < kNoTet; }

enum TetState : std::uint8_t {
  kAlive = 1,
  kQueued = 2,  // in the next active set being gathered (GFlip3D::commit_flips clears it)
};

// A face's flag (MeshView::face_flags): the sign bit of its neighbour entry.
enum FaceFlag : std::uint8_t {
  kInternal = 1,  // created inside a split/flip: known locally Delaunay
};
// The face flags (kInternal or 0) an entry as stored holds.
GDEL_HD constexpr std::uint8_t nb_flags(tid_t e) { return nb_internal(e) ? std::uint8_t(kInternal) : std::uint8_t(0); }

// The face of a tet with neighbour tets n (decoded entries) whose neighbour is t: the
// first of faces 0-2 that names t, else 3 (MeshView::nb_face; an inconsistent mesh, where
// none does, gets face 3 too and check_invariants reports it).
GDEL_HD constexpr int face_naming(const tid_t n[4], tid_t t) {
  int j = 3;
  for (int k = 2; k >= 0; --k)
    if (n[k] == t) j = k;
  return j;
}

// Plain pointers for use inside kernels (trivially copyable).
struct MeshView {
  TetRec* rec;
  std::uint8_t* state;  // TetState bits
  TetsOf tet;           // tet[t]: rec[t].t
  NeighboursOf nraw;    // nraw[k]: the entry of face k = 4t+i as stored (nb_entry: read it through opp_tet)

  MeshView() = default;
  GDEL_HD MeshView(TetRec* r, std::uint8_t* s) : rec(r), state(s), tet{r}, nraw{r} {}

  // The neighbour tet across face k (kNoTet: none).
  GDEL_HD tid_t opp_tet(std::int64_t k) const { return nb_tet(nraw[k]); }
  // The neighbour across face k as a packed facet (its tet, and that tet's face back),
  // -1 for none.
  GDEL_HD fid_t opp(std::int64_t k) const {
    const tid_t u = opp_tet(k);
    return u < 0 ? fid_t(-1) : pack_facet(u, nb_face(u, static_cast<tid_t>(k >> 2)));
  }
  // The neighbour across face k becomes the tet of packed facet f (-1: none), its flag
  // clear. Its face there is not stored (nb_face finds it).
  GDEL_HD void set_opp(std::int64_t k, fid_t f) const { nraw[k] = f < 0 ? kNoTet : facet_tet(f); }

  // The face of tet u whose neighbour is t (3 when none is: an inconsistent mesh, which
  // check_invariants reports). Concurrent: other threads may be rewriting u's other
  // entries meanwhile (an entry being rewritten holds the old or the new tet, neither of
  // them t, so the answer stands); on the host each entry is then read as a relaxed
  // atomic load, on the GPU the record's half by one vector load as always (32-bit words
  // do not tear).
  template <bool Concurrent = false>
  GDEL_HD int nb_face(tid_t u, tid_t t) const {
    tid_t n[4];
#if defined(__CUDA_ARCH__)
    get_opp_tets(u, n);
#else
    if constexpr (Concurrent) {
      for (int k = 0; k < 4; ++k) n[k] = nb_tet(par::atomic_load(&rec[u].n[k]));
    } else {
      get_opp_tets(u, n);
    }
#endif
    return mesh::face_naming(n, t);
  }

  // A tet's four entries as stored, as one access (16 bytes, 16-byte aligned).
  GDEL_HD void get_entries(tid_t t, tid_t e[4]) const {
#if defined(__CUDA_ARCH__)
    const int4 q = *reinterpret_cast<const int4*>(rec[t].n);
    e[0] = q.x, e[1] = q.y, e[2] = q.z, e[3] = q.w;
#else
    std::memcpy(e, rec[t].n, 4 * sizeof(tid_t));
#endif
  }
  // A tet's four neighbour tets (one access).
  GDEL_HD void get_opp_tets(tid_t t, tid_t nt[4]) const {
    get_entries(t, nt);
    for (int i = 0; i < 4; ++i) nt[i] = nb_tet(nt[i]);
  }
  // A tet's four neighbour tets and its faces' flags (kInternal or 0), from one access.
  GDEL_HD void get_adj(tid_t t, tid_t nt[4], std::uint8_t fl[4]) const {
    get_entries(t, nt);
    for (int i = 0; i < 4; ++i) {
      fl[i] = nb_flags(nt[i]);
      nt[i] = nb_tet(nt[i]);
    }
  }
  // Writes a tet's four entries (nb_entry: the tets with their faces' flags).
  GDEL_HD void put_entries(tid_t t, const tid_t e[4]) const {
#if defined(__CUDA_ARCH__)
    *reinterpret_cast<int4*>(rec[t].n) = make_int4(e[0], e[1], e[2], e[3]);
#else
    std::memcpy(rec[t].n, e, 4 * sizeof(tid_t));
#endif
  }
  // A whole new tet: its vertices and entries (the record's two halves, back to back,
  // so the sector is written whole).
  GDEL_HD void put_tet(tid_t t, const Tet& x, const tid_t e[4]) const {
    rec[t].t = x;  // (Tet is 16-byte aligned: one vector store)
    put_entries(t, e);
  }

  GDEL_HD bool alive(tid_t t) const { return (state[t] & kAlive) != 0; }
  GDEL_HD std::uint8_t face_flags(tid_t t, int i) const { return nb_flags(nraw[4 * std::int64_t(t) + i]); }
  // Sets or clears face i's kInternal flag. A face with no neighbour (kNoTet) holds no
  // flag: setting one there is a no-op, and face_flags reads 0.
  GDEL_HD void set_face_flags(tid_t t, int i, std::uint8_t f) const {
    tid_t& e = nraw[4 * std::int64_t(t) + i];
    e = nb_entry(nb_tet(e), e != kNoTet && (f & kInternal));
  }
  GDEL_HD void link(tid_t t, int i, tid_t u, int j) const {
    nraw[4 * std::int64_t(t) + i] = u;
    nraw[4 * std::int64_t(u) + j] = t;
  }
};

// Claim j of a batch of k: the top of the free stack first, then fresh slots past
// the high-water mark.
struct SlotSource {
  const tid_t* stack;
  std::int64_t top;         // free-stack size before the claim
  std::int64_t from_stack;  // min(k, top)
  std::int64_t size0;       // high-water mark before the claim
  GDEL_HD tid_t slot(std::int64_t j) const {
    return j < from_stack ? stack[top - 1 - j] : static_cast<tid_t>(size0 + (j - from_stack));
  }
};
// A claim of k slots, the free stack's (top entries at `stack`) first, then past the
// high-water mark `size`; both counts updated (the room past `size`: the caller's).
GDEL_HD inline SlotSource claim_slots(const tid_t* stack, std::int64_t& top, std::int64_t& size, std::int64_t k) {
  const std::int64_t from_stack = k < top ? k : top;
  const SlotSource src{stack, top, from_stack, size};
  top -= from_stack;
  size += k - from_stack;
  return src;
}

template <class B>
class TetMesh {
 public:
  // Slots below 2^31 - 1: an entry with the flag set (nb_entry) is then never kNoTet.
  static constexpr std::int64_t kMaxSlots = (std::int64_t(1) << 31) - 2;
  explicit TetMesh(par::Context<B>& ctx)
      : ctx_(&ctx), rec_(ctx), state_(ctx), free_(ctx) {}

  par::Context<B>& context() { return *ctx_; }
  std::int64_t capacity() const { return static_cast<std::int64_t>(rec_.size()); }

  std::int64_t size() const { return size_; }
  std::int64_t free_count() const { return free_count_; }
  std::int64_t alive_count() {
    const std::uint8_t* st = state_.data();
    return par::count_indices(*ctx_, static_cast<std::size_t>(size()),
                              [=] GDEL_LAMBDA(std::int64_t t) { return (st[t] & kAlive) != 0; });
  }

  // Capacity for at least n slots; contents kept; new slots are free and dead. Growth
  // is by a quarter at least (amortised), not by half: the mesh is most of a run's
  // memory, and each array is moved alone, so a growth step needs its largest array
  // (the records, 32 bytes a slot) once more, 1.25 times over.
  void reserve(std::int64_t n) {
    std::int64_t old = capacity();
    if (n <= old) return;
    if (n > kMaxSlots)
      throw Error("tet mesh: " + std::to_string(n) + " tet slots needed; tet ids are 32-bit (at most " +
                  std::to_string(kMaxSlots) + " slots, about 3*10^8 points)");
    std::int64_t cap = std::min(kMaxSlots, std::max<std::int64_t>(n, old + old / 4));
    auto grow = [cap](auto& buf, std::int64_t per) {
      buf.reserve(static_cast<std::size_t>(per * cap));
      buf.resize(static_cast<std::size_t>(per * cap));
    };
    grow(rec_, 1);
    grow(state_, 1);
    std::uint8_t* st = state_.data();
    par::parallel_for(*ctx_, cap - old, [=] GDEL_LAMBDA(std::int64_t k) { st[old + k] = 0; });
  }

  // Reserves k slots (growing the arrays if needed) and returns their source. The
  // claimed slots are dead until the caller fills them.
  SlotSource claim(std::int64_t k) {
    const std::int64_t fresh = k - std::min(k, free_count_);
    if (size_ + fresh > capacity()) reserve(size_ + fresh);
    return claim_slots(free_.data(), free_count_, size_, k);
  }
  // Marks the k slots of `slots` dead and pushes them on the free stack, in order.
  void release(const tid_t* slots, std::int64_t k) {
    if (k <= 0) return;
    if (free_.size() < static_cast<std::size_t>(free_count_ + k)) free_.resize(static_cast<std::size_t>(free_count_ + k));
    tid_t* st = free_.data();
    std::uint8_t* state = state_.data();
    const std::int64_t top = free_count_;
    par::parallel_for(*ctx_, k, [=] GDEL_LAMBDA(std::int64_t j) {
      state[slots[j]] = 0;
      st[top + j] = slots[j];
    });
    free_count_ += k;
  }

  // release() in parts, for a caller whose own kernel marks the slots dead and writes
  // them on the stack: reserve_free(k) makes room for k more entries (before a claim():
  // growing the stack moves it, and a claim's SlotSource reads it), free_top() is where
  // the next entry goes, pushed_free(k) counts k entries written there.
  void reserve_free(std::int64_t k) {
    if (free_.size() < static_cast<std::size_t>(free_count_ + k)) free_.resize(static_cast<std::size_t>(free_count_ + k));
  }
  tid_t* free_top() { return free_.data() + free_count_; }
  void pushed_free(std::int64_t k) { free_count_ += k; }
  // For a caller whose kernels claim and free slots over several steps without the host
  // (gFlip3D's team flip loop): the stack's base and room (entries it holds without
  // moving, after reserve_free), and the counts those kernels leave, set back here.
  tid_t* free_stack() { return free_.data(); }
  std::int64_t free_room() const { return static_cast<std::int64_t>(free_.size()); }
  void set_counts(std::int64_t size, std::int64_t free_count) {
    size_ = size;
    free_count_ = free_count;
  }

  // Makes this mesh a copy of o (same context): slots [0, o.size()), the free stack and
  // the high-water mark; this mesh's slots past o.size() become dead. Used to keep a
  // state to return to; copies only the used part, so a copy costs what the mesh holds.
  void copy_from(TetMesh& o) {
    using M = par::detail::Memory<B>;
    const std::int64_t n = o.size_;
    reserve(n);
    M::copy(*ctx_, rec_.data(), o.rec_.data(), static_cast<std::size_t>(n) * sizeof(TetRec));
    M::copy(*ctx_, state_.data(), o.state_.data(), static_cast<std::size_t>(n));
    if (free_.size() < static_cast<std::size_t>(o.free_count_)) free_.resize(static_cast<std::size_t>(o.free_count_));
    M::copy(*ctx_, free_.data(), o.free_.data(), static_cast<std::size_t>(o.free_count_) * sizeof(tid_t));
    if (size_ > n) {
      std::uint8_t* st = state_.data();
      par::parallel_for(*ctx_, size_ - n, [=] GDEL_LAMBDA(std::int64_t k) { st[n + k] = 0; });
    }
    size_ = n;
    free_count_ = o.free_count_;
  }

  MeshView view() {
    return MeshView(rec_.data(), state_.data());
  }

  // Moves alive tets to [0, alive) keeping their order, remaps neighbour references;
  // returns old->new map (-1 for dead slots). Free stack emptied. shrink: the capacity
  // becomes the alive count (for a finished mesh: the output stage).
  par::Buffer<tid_t, B> compact(bool shrink = false) {
    std::int64_t n = size();
    par::Buffer<tid_t, B> remap(*ctx_, static_cast<std::size_t>(n + 1));
    tid_t* rm = remap.data();
    const std::uint8_t* st = state_.data();
    par::parallel_for(*ctx_, n, [=] GDEL_LAMBDA(std::int64_t t) { rm[t] = (st[t] & kAlive) ? 1 : 0; });
    tid_t alive = par::counts_to_offsets(*ctx_, rm, static_cast<std::size_t>(n));
    par::parallel_for(*ctx_, n, [=] GDEL_LAMBDA(std::int64_t t) {
      if (!(st[t] & kAlive)) rm[t] = -1;
    });
    apply_remap(rm, alive, shrink);
    return remap;
  }

  // Moves alive tets to [0, alive) in the order of key(t) (ties: slot order), e.g.
  // by smallest vertex id, so that tets near each other in space (points are curve
  // sorted) are near each other in memory; returns old->new map (-1 for dead slots).
  // Keys lie in [0, dead_key) with dead_key < 2^31 (dead slots sort last under it).
  // shrink: as compact(). gather: each array moves by a gather (new slot j reads its old
  // slot; writes in order, reads at random) instead of a scatter (old slot t writes its
  // new one: partial sectors written at random per tet); the same mesh either way
  // (GFlip3D::reorder_gather_ says when gFlip3D asks for it). whole: the records move
  // whole through a scratch of 32 bytes per alive tet, not as two halves in turn through
  // one of 16. The temporaries: 16 bytes per slot during the sort, then the map (4 per
  // slot), with the gather the sorted ids too (4 per slot), and one scratch array (16 or,
  // whole, 32 per alive tet); see reorder_bytes().
  template <class Key>
  par::Buffer<tid_t, B> reorder(Key key, tid_t dead_key, bool shrink = false, bool gather = false,
                                bool whole = false) {
    const std::int64_t n = size();
    const std::size_t len = static_cast<std::size_t>(n + 1);
    par::Buffer<tid_t, B> k(*ctx_, len);  // the keys, then the map
    tid_t* kp = k.data();
    std::int64_t alive = 0;
    par::Buffer<tid_t, B> ids(*ctx_, len);  // the old slots in sorted order
    tid_t* ip = ids.data();
    {
      MeshView v = view();
      par::parallel_for(*ctx_, n, [=] GDEL_LAMBDA(std::int64_t t) {
        kp[t] = v.alive(static_cast<tid_t>(t)) ? key(v.tet[t]) : dead_key;
        ip[t] = static_cast<tid_t>(t);
      });
      const int bits = std::max(1, static_cast<int>(std::bit_width(static_cast<std::uint32_t>(dead_key))));
      par::sort_pairs(*ctx_, k, ids, static_cast<std::size_t>(n), bits);
      kp = k.data();  // (the sort may have moved them)
      ip = ids.data();
      alive = par::count_indices(*ctx_, static_cast<std::size_t>(n),
                                 [=] GDEL_LAMBDA(std::int64_t j) { return kp[j] != dead_key; });
      // the dead sort last: sorted position j < alive is the new slot (no reads of kp here)
      const tid_t na = static_cast<tid_t>(alive);
      par::parallel_for(*ctx_, n, [=] GDEL_LAMBDA(std::int64_t j) { kp[ip[j]] = tid_t(j) < na ? tid_t(j) : tid_t(-1); });
    }
    if (gather) {
      apply_remap(kp, alive, shrink, ip, whole);
    } else {
      ids.release();
      apply_remap(kp, alive, shrink, nullptr, whole);
    }
    return k;
  }
  // A bound on the bytes reorder() holds beyond the mesh: 16 per slot and the radix
  // sort's own scratch (below 4 per slot and 64 KiB: its histograms and look-back
  // counters) during the sort, then the map, the sorted ids with the gather, and the
  // scratch: at most 20 per slot after it (+4 with the gather, +16 whole).
  std::int64_t reorder_bytes(bool gather = false, bool whole = false) const {
    return (20 + (gather ? 4 : 0) + (whole ? 16 : 0)) * (size() + 1) + (std::int64_t(1) << 16);
  }
  // Rebuilds the arrays with tet t at slot rm[t] (rm[t] < 0: dropped), references
  // remapped; slots [0, alive) are then in use and the free stack is empty. One array at
  // a time through one scratch array of the alive tets, copied back in place (shrink:
  // the states replaced by a new array of `alive` slots instead, and the records too
  // when whole, else kept in their storage; the capacity is then `alive`).
  // The records move whole (through a scratch of 32 bytes per alive tet, which with
  // shrink becomes the records' array) or as their two halves in turn (16 bytes per alive
  // tet).
  // from: the old slot of each new slot in [0, alive) (rm's inverse), where the caller has
  // it: each array is then gathered instead of scattered.
  void apply_remap(const tid_t* rm, std::int64_t alive, bool shrink = false, const tid_t* from = nullptr,
                   bool whole = false) {
    const std::int64_t n = size();
    const std::size_t na = static_cast<std::size_t>(std::max<std::int64_t>(alive, 1));
    // (an entry keeps its flag: nb_entry)
    auto nb = [=] GDEL_LAMBDA(tid_t e) { return e == kNoTet ? e : nb_entry(rm[nb_tet(e)], nb_internal(e)); };
    if (whole) {
      par::Buffer<TetRec, B> scratch(*ctx_, na);
      remap_into(rec_.data(), scratch.data(), 1, alive, rm, from, [=] GDEL_LAMBDA(const TetRec& x) {
        TetRec y = x;
        for (int i = 0; i < 4; ++i) y.n[i] = nb(x.n[i]);
        return y;
      });
      if (shrink)
        rec_ = std::move(scratch);
      else
        par::detail::Memory<B>::copy(*ctx_, rec_.data(), scratch.data(), static_cast<std::size_t>(alive) * sizeof(TetRec));
    } else {
      // the halves in turn: the vertices, then the neighbour tets (each 16 bytes)
      par::Buffer<Tet, B> scratch(*ctx_, na);
      TetRec* r = rec_.data();
      Tet* sc = scratch.data();
      for (int half = 0; half < 2; ++half) {
        Tet* src = reinterpret_cast<Tet*>(r) + half;  // every other Tet-sized half
        remap_into(src, sc, 2, alive, rm, from, [=] GDEL_LAMBDA(const Tet& x) {
          if (half == 0) return x;
          Tet y;
          for (int i = 0; i < 4; ++i) y.v[i] = nb(x.v[i]);
          return y;
        });
        par::parallel_for(*ctx_, alive, [=] GDEL_LAMBDA(std::int64_t j) { src[2 * j] = sc[j]; });
      }
      // shrink: `alive` records in use (the storage stays; a later reserve() reuses it)
      if (shrink) rec_.resize(na);
    }
    remap_states(alive, shrink, rm, from);
    if (!shrink && n > alive) {  // the slots past the alive tets are dead
      std::uint8_t* st = state_.data();
      par::parallel_for(*ctx_, n - alive, [=] GDEL_LAMBDA(std::int64_t k) { st[alive + k] = 0; });
    }
    free_.release();
    size_ = alive;
    free_count_ = 0;
  }

  // apply_remap's step: elements src[stride * t] of slots t moved to dst[j] of their new
  // slots j (x: the new value); by slot t's new slot rm[t], or (from) by new slot j's old
  // slot from[j].
  template <class T, class X>
  void remap_into(const T* src, T* dst, std::int64_t stride, std::int64_t alive, const tid_t* rm, const tid_t* from,
                  X x) {
    if (from) {
      par::parallel_for(*ctx_, alive, [=] GDEL_LAMBDA(std::int64_t j) { dst[j] = x(src[stride * from[j]]); });
    } else {
      par::parallel_for(*ctx_, size(), [=] GDEL_LAMBDA(std::int64_t t) {
        const tid_t d = rm[t];
        if (d >= 0) dst[d] = x(src[stride * t]);
      });
    }
  }
  // apply_remap's step for the state bytes: moved through a scratch copied back, or
  // (shrink) into a new array of `alive` slots.
  void remap_states(std::int64_t alive, bool shrink, const tid_t* rm, const tid_t* from) {
    par::Buffer<std::uint8_t, B> nb(*ctx_, static_cast<std::size_t>(std::max<std::int64_t>(alive, 1)));
    std::uint8_t* dst = nb.data();
    remap_into(state_.data(), dst, 1, alive, rm, from, [] GDEL_LAMBDA(std::uint8_t v) { return v; });
    if (shrink)
      state_ = std::move(nb);
    else
      par::detail::Memory<B>::copy(*ctx_, state_.data(), dst, static_cast<std::size_t>(alive));
  }

  // The records (vertices and neighbour tets of each slot).
  par::Buffer<TetRec, B>& records() { return rec_; }
  // Slots [0, count) get the vertices of tets src (backend memory).
  void set_tets_from(const Tet* src, std::int64_t count) {
    TetRec* r = rec_.data();
    par::parallel_for(*ctx_, count, [=] GDEL_LAMBDA(std::int64_t t) { r[t].t = src[t]; });
  }
  // Adjacency: packed facets (4 per slot, -1: none) to / from the records. A neighbour
  // that does not name the tet back gets its face 3 here (MeshView::nb_face);
  // check_invariants reports it.
  std::vector<fid_t> opp_to_host() const {
    const std::vector<TetRec> r = rec_.to_host();
    std::vector<fid_t> o(4 * r.size());
    for (std::size_t k = 0; k < o.size(); ++k) {
      const tid_t t = nb_tet(r[k >> 2].n[k & 3]);
      int j = 3;
      if (t >= 0 && static_cast<std::size_t>(t) < r.size()) {
        tid_t n[4];
        for (int l = 0; l < 4; ++l) n[l] = nb_tet(r[static_cast<std::size_t>(t)].n[l]);
        j = face_naming(n, static_cast<tid_t>(k >> 2));
      }
      o[k] = t < 0 ? fid_t(-1) : pack_facet(t, j);
    }
    return o;
  }
  // Slots [0, count / 4) from count packed facets in backend memory (their tets; the
  // faces there are implied), their face flags cleared.
  void set_opp_from(const fid_t* src, std::int64_t count) {
    const MeshView v = view();
    par::parallel_for(*ctx_, count, [=] GDEL_LAMBDA(std::int64_t k) { v.set_opp(k, src[k]); });
  }
  // The output's tets from the records, in place: tet t with pos[t + 1] > pos[t] becomes
  // entries [4 pos[t], 4 pos[t] + 4) = vx(its vertex i), in an array of n (>= 4 pos[size])
  // 32-bit entries that takes over the records' storage (the mesh has none after this:
  // read its neighbours before). pos is an exclusive prefix count (pos[t] <= t), so entry
  // 4 pos[t] lies at or below byte 16 t, under record t's own vertices at byte 32 t: in
  // blocks of slots [m, 2m), whose entries lie under byte 32 m, below all of the block's
  // records, every record is read before its bytes are written (one pass a block, the
  // blocks in order: ≈ log2(size) passes).
  template <class P, class VX>
  par::Buffer<std::int32_t, B> take_tets(const P* pos, std::int64_t n, VX vx) {
    const std::int64_t nt = size();
    TetRec* r = rec_.data();
    std::int32_t* out = reinterpret_cast<std::int32_t*>(r);
    for (std::int64_t lo = 0, hi = 1; lo < nt; lo = hi, hi = 2 * hi) {
      const std::int64_t a = lo, b = std::min(hi, nt);
      par::parallel_for(*ctx_, b - a, [=] GDEL_LAMBDA(std::int64_t k) {
        const std::int64_t t = a + k;
        if (pos[t + 1] == pos[t]) return;
        const Tet x = r[t].t;
        for (int i = 0; i < 4; ++i) out[4 * std::int64_t(pos[t]) + i] = vx(x.v[i]);
      });
    }
    return std::move(rec_).template recast<std::int32_t>(static_cast<std::size_t>(n));
  }
  par::Buffer<std::uint8_t, B>& state() { return state_; }
  // Sets the high-water mark (slots [0, size) in use) and empties the free stack
  // (e.g. after building tets directly).
  void set_size(std::int64_t size) {
    reserve(size);
    size_ = size;
    free_count_ = 0;
  }

 private:
  par::Context<B>* ctx_;
  par::Buffer<TetRec, B> rec_;
  par::Buffer<std::uint8_t, B> state_;
  par::Buffer<tid_t, B> free_;  // the free stack: as long as it has ever been deep, not the capacity
  std::int64_t size_ = 0;        // high-water mark of used slots
  std::int64_t free_count_ = 0;  // entries on the free stack
};

// Result of the invariant checker: empty when everything holds.
struct MeshProblems {
  std::vector<std::string> items;
  bool ok() const { return items.empty(); }
};

// Structural invariants, checked on a host copy (debug / validate level 1):
// every alive tet has 4 distinct vertex ids in range (or kInfinite), each neighbour
// reference points to an alive tet whose reference points back, and the two tets
// share exactly the 3 vertices of the face. Geometric checks are the verifier's.
template <class B>
MeshProblems check_invariants(TetMesh<B>& m, std::int64_t num_points, std::size_t max_report = 20) {
  MeshProblems p;
  std::int64_t n = m.size();
  const auto rec = m.records().to_host();
  auto opp = m.opp_to_host();
  auto st = m.state().to_host();
  auto add = [&](const std::string& s) {
    if (p.items.size() < max_report) p.items.push_back(s);
  };
  for (std::int64_t t = 0; t < n; ++t) {
    if (!(st[t] & kAlive)) continue;
    const Tet& a = rec[t].t;
    for (int i = 0; i < 4; ++i) {
      vid_t v = a.v[i];
      if (v != kInfinite && (v < 0 || v >= num_points)) add("tet " + std::to_string(t) + ": vertex id out of range");
      for (int j = 0; j < i; ++j)
        if (a.v[j] == v) add("tet " + std::to_string(t) + ": repeated vertex");
      fid_t o = opp[4 * t + i];
      if (o < 0) continue;
      tid_t u = facet_tet(o);
      int j = facet_face(o);
      if (u < 0 || u >= n || !(st[u] & kAlive)) {
        add("tet " + std::to_string(t) + " face " + std::to_string(i) + ": neighbour dead or out of range");
        continue;
      }
      if (opp[4 * std::int64_t(u) + j] != pack_facet(static_cast<tid_t>(t), i))
        add("tet " + std::to_string(t) + " face " + std::to_string(i) + ": adjacency not symmetric (points to " +
            std::to_string(u) + "/" + std::to_string(j) + " which points to " +
            std::to_string(facet_tet(opp[4 * std::int64_t(u) + j])) + "/" +
            std::to_string(facet_face(opp[4 * std::int64_t(u) + j])) + ")");
      int shared = 0;
      for (int k = 0; k < 3; ++k) {
        vid_t w = a.v[face_vertex(i, k)];
        for (int l = 0; l < 3; ++l) shared += (rec[u].t.v[face_vertex(j, l)] == w);
      }
      if (shared != 3) add("tet " + std::to_string(t) + " face " + std::to_string(i) + ": neighbour's face differs");
      if (rec[u].t.v[j] == a.v[i]) add("tet " + std::to_string(t) + " face " + std::to_string(i) + ": same apex both sides");
    }
  }
  return p;
}

}  // namespace gdel::mesh
