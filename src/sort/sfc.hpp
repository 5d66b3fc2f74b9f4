// Space-filling-curve keys for spatial sorting (host and device).
//
// A point is first quantized to a cell of a 2^21 x 2^21 x 2^21 grid laid over a
// bounding box (Quantizer), then the cell is mapped to a 63-bit key along a
// Morton (Z-order) curve or a Hilbert curve. Sorting points by key puts points that
// are close in space close in the order, which is what point insertion needs.
//
// Bit layout of both keys: level l (l = 0 is the coarsest) occupies bits
// 62-3l .. 60-3l, i.e. each level contributes a 3-bit digit and the coarsest
// level is the most significant. For Morton the digit is (x_bit, y_bit, z_bit)
// with x the most significant bit of the digit. Bit 63 is always 0, so keys fit
// a signed 64-bit integer too.
//
// Only the order matters to the algorithms; keys carry no geometric guarantee
// beyond the stated curve properties (tested in tests/cpu/sfc.cpp):
//   * morton_key is a bijection; morton_decode inverts it.
//   * hilbert_key(levels) is a bijection from the 2^levels cube onto
//     [0, 8^levels); hilbert_decode inverts it; cells with consecutive keys share
//     a face. The curve starts at cell (0,0,0), so the cells of the corner cube
//     [0,2^k)^3 have exactly the keys [0, 8^k) at every level count >= k.
#pragma once

#include <cstdint>

#include "core/macros.hpp"

namespace gdel::sfc {

inline constexpr int kBits = 21;                                  // bits per axis
inline constexpr int kKeyBits = 3 * kBits;                         // 63
inline constexpr std::uint32_t kCells = 1u << kBits;              // cells per axis
inline constexpr std::uint32_t kMaxCoord = kCells - 1;            // largest cell coordinate
inline constexpr std::uint64_t kMaxKey = (std::uint64_t{1} << kKeyBits) - 1;

// ---------------------------------------------------------------------------
// Quantization
// ---------------------------------------------------------------------------

// Maps coordinates to cells of the 2^21 grid over a box. Robust by construction:
//   * every input, NaN and +-inf included, yields a cell in [0, kMaxCoord];
//     NaN and values at or below the box's low end map to 0, values at or above the
//     high end map to kMaxCoord (clamping);
//   * the map is monotone (non-decreasing) in each coordinate, rounding included:
//     v -> v*0.5 - lo*0.5 -> times a positive scale -> truncation are each monotone;
//   * a box with zero (or negative, or non-finite) extent on an axis maps every
//     value on that axis to cell 0;
//   * coordinates are halved before subtracting, so boxes as wide as
//     [-DBL_MAX, DBL_MAX] do not overflow.
// `uniform` (the default) uses the largest extent on all three axes, so cells are
// cubes and the curve's locality is not distorted on flat or elongated inputs;
// otherwise each axis is stretched to the full grid independently.
struct Quantizer {
  double half_lo[3] = {0.0, 0.0, 0.0};  // lo * 0.5 (0 on axes with no extent)
  double scale[3] = {0.0, 0.0, 0.0};    // kCells / (half extent); 0 on degenerate axes

  GDEL_HD static Quantizer from_box(const double lo[3], const double hi[3], bool uniform = true) {
    Quantizer q;
    double half_extent[3];
    double largest = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double e = hi[a] * 0.5 - lo[a] * 0.5;  // NaN when lo or hi is NaN or both infinite
      // Usable iff finite and positive (the comparisons are false for NaN).
      half_extent[a] = (e > 0.0 && e <= 1.7976931348623157e308) ? e : 0.0;
      if (half_extent[a] > largest) largest = half_extent[a];
    }
    for (int a = 0; a < 3; ++a) {
      const double e = uniform ? (half_extent[a] > 0.0 ? largest : 0.0) : half_extent[a];
      if (e > 0.0) {
        q.half_lo[a] = lo[a] * 0.5;
        // 2^21 / e; may be +inf for subnormal extents, which still clamps monotonically.
        q.scale[a] = static_cast<double>(kCells) / e;
      }
    }
    return q;
  }

  GDEL_HD static Quantizer from_box(double lox, double loy, double loz, double hix, double hiy, double hiz,
                                    bool uniform = true) {
    const double lo[3] = {lox, loy, loz};
    const double hi[3] = {hix, hiy, hiz};
    return from_box(lo, hi, uniform);
  }

  // Cell coordinate of value v on axis a.
  GDEL_HD std::uint32_t axis(int a, double v) const {
    if (!(scale[a] > 0.0)) return 0u;                // degenerate axis
    const double t = (v * 0.5 - half_lo[a]) * scale[a];
    if (!(t > 0.0)) return 0u;                       // below the box, at lo, or NaN
    if (t >= static_cast<double>(kMaxCoord)) return kMaxCoord;  // above the box (or +inf)
    return static_cast<std::uint32_t>(t);            // truncation: t in (0, kMaxCoord)
  }

  GDEL_HD void operator()(double x, double y, double z, std::uint32_t cell[3]) const {
    cell[0] = axis(0, x);
    cell[1] = axis(1, y);
    cell[2] = axis(2, z);
  }
};

// ---------------------------------------------------------------------------
// Bit interleaving
// ---------------------------------------------------------------------------

// Spreads the low 21 bits of v so that bit i moves to bit 3i.
GDEL_HD constexpr std::uint64_t spread3(std::uint32_t v) {
  std::uint64_t x = v & kMaxCoord;
  // Each step halves the block size: blocks of 16, 8, 4, 2, 1 bits, each block
  // moved to its final stride-3 position (masks select the blocks kept).
  x = (x | (x << 32)) & 0x001F00000000FFFFull;
  x = (x | (x << 16)) & 0x001F0000FF0000FFull;
  x = (x | (x << 8)) & 0x100F00F00F00F00Full;
  x = (x | (x << 4)) & 0x10C30C30C30C30C3ull;
  x = (x | (x << 2)) & 0x1249249249249249ull;
  return x;
}

// Inverse of spread3: gathers bits 0, 3, 6, ... of v into the low 21 bits.
GDEL_HD constexpr std::uint32_t compact3(std::uint64_t v) {
  std::uint64_t x = v & 0x1249249249249249ull;
  x = (x | (x >> 2)) & 0x10C30C30C30C30C3ull;
  x = (x | (x >> 4)) & 0x100F00F00F00F00Full;
  x = (x | (x >> 8)) & 0x001F0000FF0000FFull;
  x = (x | (x >> 16)) & 0x001F00000000FFFFull;
  x = (x | (x >> 32)) & 0x00000000001FFFFFull;
  return static_cast<std::uint32_t>(x);
}

// ---------------------------------------------------------------------------
// Morton (Z-order)
// ---------------------------------------------------------------------------

GDEL_HD constexpr std::uint64_t morton_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return (spread3(x) << 2) | (spread3(y) << 1) | spread3(z);
}

GDEL_HD constexpr void morton_decode(std::uint64_t key, std::uint32_t cell[3]) {
  cell[0] = compact3(key >> 2);
  cell[1] = compact3(key >> 1);
  cell[2] = compact3(key);
}

// ---------------------------------------------------------------------------
// Hilbert
// ---------------------------------------------------------------------------
//
// The Hilbert index is computed in "transposed" form (Skilling, "Programming the
// Hilbert curve", AIP Conf. Proc. 707, 2004): the index's 3*levels bits, read
// most significant first, are bit (levels-1) of X[0], X[1], X[2], then bit
// (levels-2) of X[0], X[1], X[2], and so on. The transform from axes walks the
// levels from the coarsest down. At level bit Q (mask of the lower bits P = Q-1),
// a coordinate whose Q bit is set reflects the lower bits of X[0] (the sub-cube is
// entered from the far side), otherwise the lower bits of X[0] and X[i] are
// exchanged (the sub-cube is transposed); together these apply the rotation and
// reflection of each sub-cube's curve to everything finer. A Gray code then turns
// the per-level corner labels into positions along the curve. Written branch-free
// (masks instead of ifs) so GPU threads do not diverge.

namespace detail {

// All ones if bit `q` of v is set, else 0.
GDEL_HD constexpr std::uint32_t bit_mask(std::uint32_t v, std::uint32_t q) {
  return 0u - static_cast<std::uint32_t>((v & q) != 0u);
}

GDEL_HD constexpr void axes_to_transpose(std::uint32_t X[3], int levels) {
  const std::uint32_t top = 1u << (levels - 1);
  // Undo the excess work of the recursive definition, coarsest level first.
  for (std::uint32_t q = top; q > 1u; q >>= 1) {
    const std::uint32_t p = q - 1u;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t set = bit_mask(X[i], q);
      X[0] ^= p & set;                                  // reflect
      const std::uint32_t t = (X[0] ^ X[i]) & p & ~set; // exchange (no-op for i = 0)
      X[0] ^= t;
      X[i] ^= t;
    }
  }
  // Gray encode.
  X[1] ^= X[0];
  X[2] ^= X[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1u; q >>= 1) t ^= (q - 1u) & bit_mask(X[2], q);
  X[0] ^= t;
  X[1] ^= t;
  X[2] ^= t;
}

GDEL_HD constexpr void transpose_to_axes(std::uint32_t X[3], int levels) {
  const std::uint32_t end = 2u << (levels - 1);
  // Gray decode: H ^ (H >> 1) on the interleaved index.
  const std::uint32_t t = X[2] >> 1;
  X[2] ^= X[1];
  X[1] ^= X[0];
  X[0] ^= t;
  // Redo the excess work, finest level first.
  for (std::uint32_t q = 2; q != end; q <<= 1) {
    const std::uint32_t p = q - 1u;
    for (int i = 2; i >= 0; --i) {
      const std::uint32_t set = bit_mask(X[i], q);
      X[0] ^= p & set;
      const std::uint32_t s = (X[0] ^ X[i]) & p & ~set;
      X[0] ^= s;
      X[i] ^= s;
    }
  }
}

}  // namespace detail

// Hilbert key of cell (x,y,z) on a 2^levels grid (1 <= levels <= 21; coordinate
// bits at and above `levels` are ignored). The key lies in [0, 8^levels).
GDEL_HD constexpr std::uint64_t hilbert_key(std::uint32_t x, std::uint32_t y, std::uint32_t z,
                                            int levels = kBits) {
  const std::uint32_t m = (1u << levels) - 1u;
  std::uint32_t X[3] = {x & m, y & m, z & m};
  detail::axes_to_transpose(X, levels);
  return (spread3(X[0]) << 2) | (spread3(X[1]) << 1) | spread3(X[2]);
}

// Inverse of hilbert_key for the same `levels`.
GDEL_HD constexpr void hilbert_decode(std::uint64_t key, std::uint32_t cell[3], int levels = kBits) {
  std::uint32_t X[3] = {compact3(key >> 2), compact3(key >> 1), compact3(key)};
  detail::transpose_to_axes(X, levels);
  cell[0] = X[0];
  cell[1] = X[1];
  cell[2] = X[2];
}

// ---------------------------------------------------------------------------
// Point -> key
// ---------------------------------------------------------------------------

GDEL_HD inline std::uint64_t morton_key(const Quantizer& q, double x, double y, double z) {
  return morton_key(q.axis(0, x), q.axis(1, y), q.axis(2, z));
}

GDEL_HD inline std::uint64_t hilbert_key(const Quantizer& q, double x, double y, double z) {
  return hilbert_key(q.axis(0, x), q.axis(1, y), q.axis(2, z), kBits);
}

}  // namespace gdel::sfc
