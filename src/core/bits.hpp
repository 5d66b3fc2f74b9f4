// Bit helpers for host and device code.
#pragma once

#include <cstdint>

#include "core/macros.hpp"

namespace gdel {

// Index of the lowest set bit of m ≠ 0. (Not std::countr_zero: nvcc compiles it to a
// constant in device code.)
GDEL_HD GDEL_FORCEINLINE int lowest_bit(std::uint64_t m) {
#if GDEL_DEVICE_PASS
  return __ffsll(static_cast<long long>(m)) - 1;
#else
  return __builtin_ctzll(m);
#endif
}

}  // namespace gdel
