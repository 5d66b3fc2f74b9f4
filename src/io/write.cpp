// Writers: TetGen .node/.ele/.neigh, .xyz, .off, .ply. All go through AtomicFileWriter.
#include <bit>
#include <cmath>
#include <optional>
#include <string>

#include "gdel/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/io.hpp"
#include "io/write_common.hpp"

namespace gdel::io {
namespace detail {

[[noreturn]] void bad_argument(const std::filesystem::path& path, const std::string& what) {
  throw InvalidInput("cannot write '" + path.string() + "': " + what);
}

// Number of points; checks the shapes of xyz and weights.
std::size_t check_points(const std::filesystem::path& path, std::span<const double> xyz,
                         std::span<const double> weights) {
  if (xyz.size() % 3 != 0) {
    bad_argument(path, "xyz has " + std::to_string(xyz.size()) + " values, not a multiple of 3");
  }
  const std::size_t n = xyz.size() / 3;
  if (!weights.empty() && weights.size() != n) {
    bad_argument(path, std::to_string(weights.size()) + " weights for " + std::to_string(n) + " points");
  }
  return n;
}

void check_finite(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights,
                  std::size_t i) {
  if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2])) {
    bad_argument(path, "point " + std::to_string(i) + " has a non-finite coordinate");
  }
  if (!weights.empty() && !std::isfinite(weights[i])) {
    bad_argument(path, "point " + std::to_string(i) + " has a non-finite weight");
  }
}

void check_tet_vertex(const std::filesystem::path& path, std::size_t t, vid_t v, std::size_t num_points) {
  if (v < 0 || static_cast<std::size_t>(v) >= num_points) {
    bad_argument(path, "tetrahedron " + std::to_string(t) + " has vertex id " + std::to_string(v) +
                           (num_points == kUncheckedCount ? std::string(" (must be >= 0)")
                                                          : " (must be in 0.." + std::to_string(num_points) + ")"));
  }
}

void check_neighbour(const std::filesystem::path& path, std::size_t t, tid_t v, std::size_t m) {
  if (v < -1 || (v >= 0 && static_cast<std::size_t>(v) >= m)) {
    bad_argument(path, "tetrahedron " + std::to_string(t) + " has neighbour " + std::to_string(v) +
                           " (must be -1 or in 0.." + std::to_string(m) + ")");
  }
}

void check_tets(const std::filesystem::path& path, std::span<const vid_t> tets) {
  if (tets.size() % 4 != 0) bad_argument(path, "tets has " + std::to_string(tets.size()) + " ids, not a multiple of 4");
}

void check_neighbours(const std::filesystem::path& path, std::span<const tid_t> neighbours) {
  if (neighbours.size() % 4 != 0) {
    bad_argument(path, "neighbours has " + std::to_string(neighbours.size()) + " entries, not a multiple of 4");
  }
}

std::size_t check_mesh(const std::filesystem::path& points_path, const std::filesystem::path& tets_path,
                       const std::filesystem::path& neighbours_path, std::span<const double> xyz,
                       std::span<const vid_t> tets, std::span<const tid_t> neighbours,
                       std::span<const double> weights) {
  const std::size_t n = check_points(points_path, xyz, weights);
  for (std::size_t i = 0; i < n; ++i) check_finite(points_path, xyz, weights, i);
  check_tets(tets_path, tets);
  for (std::size_t t = 0; t < tets.size() / 4; ++t) {
    for (int k = 0; k < 4; ++k) check_tet_vertex(tets_path, t, tets[4 * t + k], n);
  }
  if (!neighbours.empty()) {
    check_neighbours(neighbours_path, neighbours);
    if (neighbours.size() != tets.size()) {
      bad_argument(neighbours_path, std::to_string(neighbours.size() / 4) + " neighbour rows for " +
                                        std::to_string(tets.size() / 4) + " tetrahedra");
    }
    for (std::size_t t = 0; t < neighbours.size() / 4; ++t) {
      for (int k = 0; k < 4; ++k) check_neighbour(neighbours_path, t, neighbours[4 * t + k], neighbours.size() / 4);
    }
  }
  return n;
}

}  // namespace detail

using namespace detail;

namespace {

// Writes "[id ]x y z[ weight]\n" (id when with_id).
void point_line(AtomicFileWriter& w, std::span<const double> xyz, std::span<const double> weights, std::size_t i,
                bool with_id) {
  char* p = w.reserve(5 * (AtomicFileWriter::kMaxNumberChars + 1));
  if (with_id) {
    p = AtomicFileWriter::append_number(p, std::uint64_t{i});
    *p++ = ' ';
  }
  p = AtomicFileWriter::append_number(p, xyz[3 * i]);
  *p++ = ' ';
  p = AtomicFileWriter::append_number(p, xyz[3 * i + 1]);
  *p++ = ' ';
  p = AtomicFileWriter::append_number(p, xyz[3 * i + 2]);
  if (!weights.empty()) {
    *p++ = ' ';
    p = AtomicFileWriter::append_number(p, weights[i]);
  }
  *p++ = '\n';
  w.advance(p);
}

// Writes "t a b c d\n".
template <class Id>
void index_line(AtomicFileWriter& w, std::size_t t, const Id* v) {
  char* p = w.reserve(5 * (AtomicFileWriter::kMaxNumberChars + 1));
  p = AtomicFileWriter::append_number(p, std::uint64_t{t});
  for (int k = 0; k < 4; ++k) {
    *p++ = ' ';
    p = AtomicFileWriter::append_number(p, v[k]);
  }
  *p++ = '\n';
  w.advance(p);
}

std::filesystem::path with_suffix(const std::filesystem::path& base, const char* suffix) {
  std::filesystem::path p = base;
  p += suffix;
  return p;
}

}  // namespace

namespace {

// The bodies of the TetGen files; each checks its values as it goes (the single-file
// writers validate while writing, write_tetgen before).
void node_body(AtomicFileWriter& w, std::span<const double> xyz, std::span<const double> weights) {
  const std::size_t n = xyz.size() / 3;
  w.number(std::uint64_t{n});
  w.write(weights.empty() ? " 3 0 0\n" : " 3 1 0\n");
  for (std::size_t i = 0; i < n; ++i) {
    check_finite(w.target(), xyz, weights, i);
    point_line(w, xyz, weights, i, /*with_id=*/true);
  }
}

void ele_body(AtomicFileWriter& w, std::span<const vid_t> tets, std::size_t num_points) {
  const std::size_t m = tets.size() / 4;
  w.number(std::uint64_t{m});
  w.write(" 4 0\n");
  for (std::size_t t = 0; t < m; ++t) {
    for (int k = 0; k < 4; ++k) {
      const vid_t v = tets[4 * t + k];
      if (v < 0 || static_cast<std::size_t>(v) >= num_points) check_tet_vertex(w.target(), t, v, num_points);
    }
    index_line(w, t, &tets[4 * t]);
  }
}

void neigh_body(AtomicFileWriter& w, std::span<const tid_t> neighbours) {
  const std::size_t m = neighbours.size() / 4;
  w.number(std::uint64_t{m});
  w.write(" 4\n");
  for (std::size_t t = 0; t < m; ++t) {
    for (int k = 0; k < 4; ++k) {
      const tid_t v = neighbours[4 * t + k];
      if (v < -1 || (v >= 0 && static_cast<std::size_t>(v) >= m)) check_neighbour(w.target(), t, v, m);
    }
    index_line(w, t, &neighbours[4 * t]);
  }
}

}  // namespace

void write_node(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights) {
  check_points(path, xyz, weights);
  AtomicFileWriter w(path);
  node_body(w, xyz, weights);
  w.commit();
}

void write_ele(const std::filesystem::path& path, std::span<const vid_t> tets, std::size_t num_points) {
  check_tets(path, tets);
  AtomicFileWriter w(path);
  ele_body(w, tets, num_points);
  w.commit();
}

void write_neigh(const std::filesystem::path& path, std::span<const tid_t> neighbours) {
  check_neighbours(path, neighbours);
  AtomicFileWriter w(path);
  neigh_body(w, neighbours);
  w.commit();
}

void write_tetgen(const std::filesystem::path& base_path, std::span<const double> xyz, std::span<const vid_t> tets,
                  std::span<const tid_t> neighbours, std::span<const double> weights) {
  const auto node = with_suffix(base_path, ".node");
  const auto ele = with_suffix(base_path, ".ele");
  const auto neigh = with_suffix(base_path, ".neigh");
  // Validate everything first, so that a bad argument changes no file.
  const std::size_t n = check_mesh(node, ele, neigh, xyz, tets, neighbours, weights);
  // A folder in the way would fail its rename after the others succeeded: refuse up front.
  for (const auto* p : {&node, &ele, &neigh}) {
    std::error_code ec;
    if ((p != &neigh || !neighbours.empty()) && std::filesystem::is_directory(*p, ec)) {
      throw Error("cannot write '" + p->string() + "': it is a directory");
    }
  }
  // Write every file to its temporary, then rename them all: a write error (disk full) in
  // any of them leaves the whole previous set in place.
  AtomicFileWriter wn(node), we(ele);
  std::optional<AtomicFileWriter> wg;
  if (!neighbours.empty()) wg.emplace(neigh);
  node_body(wn, xyz, weights);
  ele_body(we, tets, n);
  if (wg) neigh_body(*wg, neighbours);
  wn.finish();
  we.finish();
  if (wg) wg->finish();
  wn.commit();
  we.commit();
  if (wg) wg->commit();
}

void write_xyz(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights) {
  const std::size_t n = check_points(path, xyz, weights);
  AtomicFileWriter w(path);
  for (std::size_t i = 0; i < n; ++i) {
    check_finite(path, xyz, weights, i);
    point_line(w, xyz, weights, i, false);
  }
  w.commit();
}

void write_off(const std::filesystem::path& path, std::span<const double> xyz) {
  const std::size_t n = check_points(path, xyz, {});
  AtomicFileWriter w(path);
  w.write("OFF\n");
  w.number(std::uint64_t{n});
  w.write(" 0 0\n");
  for (std::size_t i = 0; i < n; ++i) {
    check_finite(path, xyz, {}, i);
    point_line(w, xyz, {}, i, false);
  }
  w.commit();
}

void write_ply(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights,
               PlyFormat format) {
  const std::size_t n = check_points(path, xyz, weights);
  AtomicFileWriter w(path);
  w.write("ply\nformat ");
  w.write(format == PlyFormat::Ascii                ? "ascii"
          : format == PlyFormat::BinaryLittleEndian ? "binary_little_endian"
                                                    : "binary_big_endian");
  w.write(" 1.0\ncomment written by gdel\nelement vertex ");
  w.number(std::uint64_t{n});
  w.write("\nproperty double x\nproperty double y\nproperty double z\n");
  if (!weights.empty()) w.write("property double weight\n");
  w.write("end_header\n");
  const bool big = format == PlyFormat::BinaryBigEndian;
  const bool swap = big == (std::endian::native == std::endian::little);
  auto raw_double = [&](double v) {
    std::uint64_t u = std::bit_cast<std::uint64_t>(v);
    if (swap) {
      std::uint64_t r = 0;
      for (int b = 0; b < 8; ++b) r = (r << 8) | ((u >> (8 * b)) & 0xFF);
      u = r;
    }
    w.raw(&u, sizeof u);
  };
  for (std::size_t i = 0; i < n; ++i) {
    check_finite(path, xyz, weights, i);
    if (format == PlyFormat::Ascii) {
      point_line(w, xyz, weights, i, false);
    } else {
      for (int k = 0; k < 3; ++k) raw_double(xyz[3 * i + k]);
      if (!weights.empty()) raw_double(weights[i]);
    }
  }
  w.commit();
}

}  // namespace gdel::io
