// Lockstep loops for per-thread work of uneven length (one GPU thread owns one star, and
// the stars of a warp take different numbers of steps).
//
// A loop whose body can end an iteration early (`continue`, a failure) has no point where
// the compiler must bring the warp's threads back together between iterations: once they
// drift apart by an iteration, a warp runs its threads one after the other through the
// same code. The star builds' Flip-Flop loop ran at 1.2 threads per warp instruction so,
// its exact orient4 tests (2 000 instructions each) included (bench/RESULTS.md, session 44).
//
// Lockstep makes the loop's condition a vote of the threads that entered it together:
//
//   const par::Lockstep group;           // where the threads are together (a function's entry)
//   while (group.any(more)) {            // every thread of the group iterates as long as one does
//     if (!more) continue;               // a thread that has finished idles through the vote
//     ...                                // no `return` / `break` out of the loop: set a flag
//   }
//
// Each iteration then starts with the group together (the vote waits for all of it), so
// the body's divergent paths reconverge once per iteration. Every thread of the group must
// reach every vote: a thread must not leave the loop by `return`, `break` or `goto`. On the
// host (CPU backend, one thread per item) any(p) is p: the same loop, no vote.
#pragma once

#include "core/macros.hpp"

namespace gdel::par {

struct Lockstep {
  unsigned mask = 0;  // the group: the threads of the warp that constructed it together
  GDEL_HD Lockstep() {
#if defined(__CUDA_ARCH__)
    mask = __activemask();
#endif
  }
  GDEL_HD bool any(bool p) const {
#if defined(__CUDA_ARCH__)
    return __any_sync(mask, p) != 0;
#else
    return p;
#endif
  }
};

}  // namespace gdel::par
