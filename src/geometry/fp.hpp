// Explicitly rounded double-precision operations for the exact predicates.
//
// Every floating-point operation of src/geometry goes through these three functions.
// Their purpose is to make contraction impossible: a fused multiply-add computes
// a*b+c with ONE rounding, which silently breaks Dekker's split (c - a with c = s*a
// becomes fma(s, a, -a)), hence two_product, hence every exact stage, and invalidates
// the rounding-error counts that the filters' error bounds are derived from.
//
//  * Device code: the CUDA intrinsics __dadd_rn / __dsub_rn / __dmul_rn are never
//    merged into an FMA by nvcc, whatever --fmad says (CUDA C Programming Guide,
//    "Intrinsic Functions"). They round to nearest, ties to even, as IEEE 754 requires
//    for the error-free transformations.
//  * Host code: plain operators. The build compiles host code with -ffp-contract=off
//    (and device code with --fmad=false) as a second line of defence; see
//    cmake/GdelTargets.cmake. x86-64 SSE2 arithmetic is IEEE binary64 with
//    round-to-nearest-even; no x87 extended precision is involved.
#pragma once

#include "core/macros.hpp"

namespace gdel::geom::fp {

GDEL_HD GDEL_FORCEINLINE double add(double a, double b) {
#if defined(__CUDA_ARCH__)
  return __dadd_rn(a, b);
#else
  return a + b;
#endif
}

GDEL_HD GDEL_FORCEINLINE double sub(double a, double b) {
#if defined(__CUDA_ARCH__)
  return __dsub_rn(a, b);
#else
  return a - b;
#endif
}

GDEL_HD GDEL_FORCEINLINE double mul(double a, double b) {
#if defined(__CUDA_ARCH__)
  return __dmul_rn(a, b);
#else
  return a * b;
#endif
}

// |a| (exact; no rounding involved).
GDEL_HD GDEL_FORCEINLINE double abs(double a) { return a < 0.0 ? -a : a; }

}  // namespace gdel::geom::fp
