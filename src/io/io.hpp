// Point-set readers and mesh writers (host only).
//
// Readers return a PointSet and throw gdel::InvalidInput for every problem: a file that
// cannot be read, malformed text, a bad number, wrong counts, truncated binary data, an
// unsupported variant of a format. Messages start with the file name and name the line
// (text) or the record and byte offset (binary), e.g.
//   "cloud.xyz:12: expected 3 numbers like line 3, got 2".
// Readers keep NaN and Inf values as read ("nan", "inf" in text); validating the points is
// the job of the triangulation API.
//
// Writers write to a temporary file in the target's directory and rename it over the
// target only once everything is written and flushed, so an existing file is never left
// half-written. On failure the temporary file is removed and the writer throws:
// gdel::InvalidInput for bad arguments (sizes, non-finite values, ids out of range; possibly
// detected part-way through writing), gdel::Error for file-system failures (cannot create
// the temporary file, disk full, rename failed), with the path and the system's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <vector>

#include "mesh/conventions.hpp"

namespace gdel::io {

struct PointSet {
  std::vector<double> xyz;      // x0,y0,z0, x1,y1,z1, ...
  std::vector<double> weights;  // one per point, or empty when the file has none

  std::size_t size() const { return xyz.size() / 3; }
  bool has_weights() const { return !weights.empty(); }
};

// ---------------------------------------------------------------------------------------
// Readers
// ---------------------------------------------------------------------------------------

// Dispatches on the extension, case-insensitively: .xyz .txt -> read_xyz, .off -> read_off,
// .ply -> read_ply, .node -> read_node, .npy -> read_npy. Any other extension: InvalidInput.
PointSet read_points(const std::filesystem::path& path);

// NumPy .npy (format versions 1.0, 2.0, 3.0): a 2-D array of shape (n, 3) (x y z) or (n, 4)
// (x y z weight), C or Fortran order, dtype float64, float32 or any integer type
// (int8..int64, uint8..uint64) in either byte order. Integer values must convert to double
// exactly. Anything else (other shapes, structured/complex/bool/object dtypes, a truncated
// file, bytes after the data) is InvalidInput naming the problem.
PointSet read_npy(const std::filesystem::path& path);

// Weights for `gdel check --weights`: one number per line, '#' comments and blank lines
// skipped (as in .xyz); or, for a .npy file, an array of shape (n,) or (n, 1).
std::vector<double> read_weights(const std::filesystem::path& path);

// One point per line: "x y z" or "x y z weight", separated by blanks and/or commas
// ("1,2,3", "1, 2, 3", "1 2 3"). Blank lines and '#' comments (to the end of the line) are
// skipped. Every point line must have the number of columns of the first one (3 or 4).
PointSet read_xyz(const std::filesystem::path& path);

// OFF: header keyword OFF (or the per-vertex-extras variants COFF, NOFF, CNOFF, STOFF, ...,
// whose extra vertex values are ignored), then "nv nf [ne]" (on the keyword line or the
// next), then nv vertex lines "x y z"; '#' comments and blank lines skipped; faces ignored.
// 4OFF/nOFF (other dimensions) and binary OFF are rejected.
PointSet read_off(const std::filesystem::path& path);

// PLY, format ascii, binary_little_endian or binary_big_endian. The element "vertex" must
// have scalar properties x, y, z of any PLY scalar type (char/int8, uchar/uint8,
// short/int16, ushort/uint16, int/int32, uint/uint32, float/float32, double/float64); a
// scalar property "weight", if present, fills PointSet::weights. Other vertex properties
// (lists included) are skipped, elements before "vertex" are skipped, elements after it
// are not read.
PointSet read_ply(const std::filesystem::path& path);

// TetGen .node: "n dim [nattr [nbm]]" with dim = 3, then n lines "id x y z [attr...]
// [marker]". ids are consecutive from 0 or from 1. The first attribute, if any, is the
// weight. '#' comments and blank lines skipped.
PointSet read_node(const std::filesystem::path& path);

// TetGen .ele ("m 4 [nattr]", then "id a b c d [attr...]") -> 4 vertex ids per tet,
// converted to 0-based when the file's ids start at 1 (TetGen -z convention otherwise).
std::vector<vid_t> read_ele(const std::filesystem::path& path);

// TetGen .neigh ("m 4", then "id n0 n1 n2 n3", -1 on the hull) -> 4 neighbours per tet,
// 0-based (converted when the file's ids start at 1), -1 on the hull.
std::vector<tid_t> read_neigh(const std::filesystem::path& path);

// ---------------------------------------------------------------------------------------
// Writers. Coordinates and weights are written in the shortest form that reads back to the
// same double (std::to_chars), and must be finite.
// ---------------------------------------------------------------------------------------

inline constexpr std::size_t kUncheckedCount = std::numeric_limits<std::size_t>::max();

// TetGen .node: "n 3 nattr 0", then "i x y z [weight]" with 0-based ids; nattr = 1 when
// weights are given (weights.size() must then be the number of points).
void write_node(const std::filesystem::path& path, std::span<const double> xyz,
                std::span<const double> weights = {});

// TetGen .ele: "m 4 0", then "i a b c d", 0-based. Every vertex id must be >= 0 and, when
// num_points is given, < num_points.
void write_ele(const std::filesystem::path& path, std::span<const vid_t> tets,
               std::size_t num_points = kUncheckedCount);

// TetGen .neigh: "m 4", then "i n0 n1 n2 n3" (neighbour k opposite vertex k, -1 on the
// hull). Every entry must be -1 or a tet index < m.
void write_neigh(const std::filesystem::path& path, std::span<const tid_t> neighbours);

// Writes base.node, base.ele and (unless neighbours is empty) base.neigh, where base is
// `base_path` with ".node" etc. appended. All arguments are validated (and no target may be
// a directory) before any file is written; the three files are written to temporaries and
// renamed only when all are complete, so a failure while writing leaves the previous set.
void write_tetgen(const std::filesystem::path& base_path, std::span<const double> xyz,
                  std::span<const vid_t> tets, std::span<const tid_t> neighbours,
                  std::span<const double> weights = {});

// "x y z [weight]" per line.
void write_xyz(const std::filesystem::path& path, std::span<const double> xyz,
               std::span<const double> weights = {});

// "OFF", "n 0 0", then the points.
void write_off(const std::filesystem::path& path, std::span<const double> xyz);

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

// element vertex with double properties x, y, z [, weight].
void write_ply(const std::filesystem::path& path, std::span<const double> xyz,
               std::span<const double> weights = {},
               PlyFormat format = PlyFormat::BinaryLittleEndian);

// NumPy .npy, version 1.0, C order, this machine's byte order: float64 of shape (n, 3), or
// (n, 4) with the weight in the last column when weights are given.
void write_npy(const std::filesystem::path& path, std::span<const double> xyz,
               std::span<const double> weights = {});

// ---------------------------------------------------------------------------------------
// Mesh writers: points + tetrahedra (+ neighbours). Every argument is validated before the
// file is created (sizes, finite coordinates and weights, vertex ids in 0..n-1, neighbours
// -1 or in 0..m-1, neighbours.size() == tets.size() unless empty), so a bad argument
// creates no file; then the file is written to a temporary and renamed.
// ---------------------------------------------------------------------------------------

// VTK XML UnstructuredGrid (.vtu, version 1.0, header_type UInt64), every DataArray
// format="binary": base64 of [UInt64 byte count] followed, encoded separately, by the raw
// values in this machine's byte order (byte_order says which). Points Float64 x 3; cells
// VTK_TETRA (10) with Int32 connectivity and Int64 offsets; cell data "tet_id" (Int32, the
// row in tets) and, when given, "neighbors" (Int32 x 4); point data "weight" (Float64) when
// weights are given. VTK_TETRA's order (the base 0,1,2 counter-clockwise seen from vertex 3)
// is gdel's positive orientation, so tets are written as they are.
void write_vtu(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
               std::span<const tid_t> neighbours = {}, std::span<const double> weights = {});

// Medit / Gamma Mesh Format, ASCII (.mesh): "MeshVersionFormatted 2" (double precision),
// "Dimension 3", "Vertices" (n lines "x y z 0"), "Tetrahedra" (m lines "a b c d 0", 1-based
// vertex ids, in gdel's order), "End". Reference numbers are 0. Neighbours and weights are not
// part of the format and are not written.
void write_medit(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets);

// NumPy .npz (a zip archive of .npy members, STORED, i.e. uncompressed, like numpy.savez):
// "points.npy" float64 (n, 3), "tets.npy" int32 (m, 4), "neighbors.npy" int32 (m, 4) when
// given, "weights.npy" float64 (n,) when given; this machine's byte order. Zip64 records are
// used for members or offsets past 4 GiB. Member timestamps are fixed (1980-01-01 00:00) so
// that equal inputs give byte-identical files.
void write_npz(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
               std::span<const tid_t> neighbours = {}, std::span<const double> weights = {});

// Output format of a mesh file, by extension (case-insensitive).
enum class MeshFormat {
  TetGen,  // .ele, .node, .neigh or no extension: base.node/.ele/.neigh
  Vtu,     // .vtu
  Medit,   // .mesh
  Npz,     // .npz
};

// The format for `path`; InvalidInput naming the supported extensions for any other one.
MeshFormat mesh_format(const std::filesystem::path& path);

// The files write_mesh(path, ...) creates or replaces, in order (three for TetGen: the
// .neigh one only when with_neighbours; one otherwise).
std::vector<std::filesystem::path> mesh_outputs(const std::filesystem::path& path, bool with_neighbours);

// Writes a mesh in the format of mesh_format(path). TetGen: the base is `path` without a
// .ele/.node/.neigh extension; all three files are validated, written to temporaries and
// only then renamed, so a failure leaves the previous set of files as it was.
void write_mesh(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
                std::span<const tid_t> neighbours = {}, std::span<const double> weights = {});

}  // namespace gdel::io
