// NumPy .npy arrays (host only): the parser behind read_npy / read_weights and the header
// builder behind write_npy / write_npz. Internal to src/io (tests and fuzz targets use it).
//
// The format (NumPy's "format.rst", versions 1.0, 2.0 and 3.0):
//   bytes 0..5   magic "\x93NUMPY"
//   bytes 6, 7   major, minor version (1.0, 2.0 or 3.0)
//   then         header length: uint16 little-endian (1.0) or uint32 little-endian (2.0, 3.0)
//   then         the header: a Python dict literal (ASCII; UTF-8 in 3.0) with exactly the
//                keys 'descr' (a dtype string such as '<f8'), 'fortran_order' (True/False)
//                and 'shape' (a tuple of non-negative ints), padded with spaces, ending '\n'
//   then         the raw array data, C (row-major) or Fortran (column-major) order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/conventions.hpp"

namespace gdel::io::detail {

// A parsed .npy array converted to doubles, in C (row-major) order whatever the file's
// order: element (i, j) of a 2-D array of shape (r, c) is values[i * c + j].
struct NpyArray {
  std::vector<std::uint64_t> shape;
  std::string descr;   // as in the file, e.g. "<f8"
  bool fortran_order = false;
  std::vector<double> values;
};

// Which shapes a caller accepts, checked before any data is converted.
enum class NpyShape {
  Points,   // (n, 3) or (n, 4): x y z [weight]
  Vector,   // (n,) or (n, 1): one value per row
};

// Parses a whole .npy file held in `bytes`. Supported element types: float32, float64,
// int8/16/32/64 and uint8/16/32/64, either byte order. Integers must be exactly
// representable as doubles (|v| <= 2^53, or more with enough trailing zero bits).
// Throws gdel::InvalidInput "<path>: ..." naming the problem (and the element for a value
// problem) for anything else: bad magic, unknown version, malformed header, a structured,
// complex, boolean, object, string or date dtype, a shape other than `expected`, data
// shorter or longer than the shape says.
NpyArray parse_npy(std::string_view bytes, const std::filesystem::path& path, NpyShape expected);

// The header (magic, version 1.0, length, dict, padding so that the data starts at a
// multiple of 64 bytes) of a C-order array with dtype `descr` and the given shape.
std::string npy_header(std::string_view descr, const std::vector<std::uint64_t>& shape);

// The dtype string of this machine's byte order: "<f8" / ">f8", "<i4" / ">i4".
const char* npy_descr_f8();
const char* npy_descr_i4();

// CRC-32 as zip uses it (reflected polynomial 0xEDB88320, initial/final 0xFFFFFFFF);
// chainable: crc32_update(crc32_update(0, a), b) is the CRC of a followed by b.
std::uint32_t crc32_update(std::uint32_t crc, const void* data, std::size_t n);

// write_npz, with Zip64 records on every member when force_zip64 (for tests: the records a
// multi-gigabyte archive needs, on a small one).
void write_npz_impl(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
                    std::span<const tid_t> neighbours, std::span<const double> weights, bool force_zip64);

}  // namespace gdel::io::detail
