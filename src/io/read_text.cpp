// Text readers: .xyz/.txt, .off, TetGen .node/.ele/.neigh, and the dispatch by extension.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

#include "gdel/errors.hpp"
#include "io/io.hpp"
#include "io/npy.hpp"
#include "io/parse.hpp"

namespace gdel::io {
namespace detail {

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InvalidInput("cannot read '" + path.string() + "': it is a directory");
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw InvalidInput("cannot read '" + path.string() + "': " + std::strerror(errno));
  std::string data;
  const auto size_hint = std::filesystem::file_size(path, ec);
  if (!ec) {
    // One read of the announced size (+1 to see the end); the chunked loop below takes
    // over only if the file is longer than announced (a growing file, a pipe).
    data.resize(static_cast<std::size_t>(size_hint) + 1);
    const std::size_t got = std::fread(data.data(), 1, data.size(), f.get());
    data.resize(got);
    if (got <= static_cast<std::size_t>(size_hint)) {
      if (std::ferror(f.get())) throw InvalidInput("cannot read '" + path.string() + "': " + std::strerror(errno));
      return data;
    }
  }
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  for (;;) {
    const std::size_t old = data.size();
    data.resize(old + kChunk);
    const std::size_t got = std::fread(data.data() + old, 1, kChunk, f.get());
    data.resize(old + got);
    if (got < kChunk) {
      if (std::ferror(f.get())) {
        throw InvalidInput("cannot read '" + path.string() + "': " + std::strerror(errno));
      }
      break;
    }
  }
  return data;
}

void fail_at_line(const std::filesystem::path& path, std::size_t line, const std::string& message) {
  throw InvalidInput(path.string() + ":" + std::to_string(line) + ": " + message);
}

void fail_in_file(const std::filesystem::path& path, const std::string& message) {
  throw InvalidInput(path.string() + ": " + message);
}

std::string show(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string s;
  for (char c : token.substr(0, kMax)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7F) {
      s += c;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", u);
      s += buf;
    }
  }
  if (token.size() > kMax) s += "...";
  return "'" + s + "'";
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

}  // namespace detail

using namespace detail;

namespace {

// Reads the next non-blank line and splits it on blanks; false at the end of the text.
bool next_record(LineReader& lines, Fields& fields) {
  std::string_view line;
  if (!lines.next_nonblank(line)) return false;
  fields.split(line);
  return true;
}

double number_field(const std::filesystem::path& path, std::size_t line, std::string_view tok,
                    const char* what) {
  double v;
  if (!parse_double(tok, v)) fail_at_line(path, line, std::string(what) + ": " + show(tok) + " is not a valid number");
  return v;
}

template <class Int>
Int int_field(const std::filesystem::path& path, std::size_t line, std::string_view tok, const char* what) {
  Int v;
  if (!parse_int(tok, v)) {
    fail_at_line(path, line, std::string(what) + ": " + show(tok) + " is not a valid " +
                                 (std::numeric_limits<Int>::is_signed ? "integer" : "non-negative integer"));
  }
  return v;
}

// Capacity to reserve for `count` records announced by a header: never more than the file
// could hold (each record takes at least `min_bytes` bytes), so a corrupt count cannot
// trigger a huge allocation before the truncation is detected.
std::size_t reserve_for(std::uint64_t count, std::size_t file_bytes, std::size_t min_bytes) {
  return static_cast<std::size_t>(std::min<std::uint64_t>(count, file_bytes / min_bytes + 1));
}

// TetGen header and record helpers -------------------------------------------------------

// Reads a TetGen file's first record (the header). Fails on an empty file.
void tetgen_header(const std::filesystem::path& path, LineReader& lines, Fields& fields,
                   const char* expected) {
  if (!next_record(lines, fields)) fail_in_file(path, std::string("empty file; expected the header '") + expected + "'");
}

// Parses the id of record i and checks it against the base (0 or 1) set by the first one.
void tetgen_id(const std::filesystem::path& path, std::size_t line, std::string_view tok,
               std::uint64_t i, std::int64_t& base) {
  const auto id = int_field<std::int64_t>(path, line, tok, "id");
  if (i == 0) {
    if (id != 0 && id != 1) fail_at_line(path, line, "the first id must be 0 or 1, got " + std::to_string(id));
    base = id;
  } else if (id != base + static_cast<std::int64_t>(i)) {
    fail_at_line(path, line, "ids must be consecutive: expected " + std::to_string(base + static_cast<std::int64_t>(i)) +
                                 ", got " + std::to_string(id));
  }
}

[[noreturn]] void truncated(const std::filesystem::path& path, const char* what, std::uint64_t announced,
                                   std::uint64_t found) {
  fail_in_file(path, "the header announces " + std::to_string(announced) + " " + what + " but the file ends after " +
                         std::to_string(found));
}

}  // namespace

// ---------------------------------------------------------------------------------------
// .xyz / .txt
// ---------------------------------------------------------------------------------------

PointSet read_xyz(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineReader lines(data, /*hash_comments=*/true);
  Fields fields;
  std::string error;
  std::string_view line;
  std::size_t columns = 0, first_line = 0;
  PointSet ps;
  ps.xyz.reserve(3 * (data.size() / 32));  // a typical line has more than 32 bytes
  while (lines.next(line)) {
    if (!fields.split(line, /*allow_comma=*/true, error)) fail_at_line(path, lines.line_no(), error);
    if (fields.size() == 0) continue;
    if (columns == 0) {
      if (fields.size() != 3 && fields.size() != 4) {
        fail_at_line(path, lines.line_no(),
                     "expected 3 numbers (x y z) or 4 (x y z weight), got " + std::to_string(fields.size()));
      }
      columns = fields.size();
      first_line = lines.line_no();
    } else if (fields.size() != columns) {
      fail_at_line(path, lines.line_no(),
                   "has " + std::to_string(fields.size()) + " columns but the first point (line " +
                       std::to_string(first_line) + ") has " + std::to_string(columns) +
                       "; every point needs the same number of columns");
    }
    static const char* const kNames[4] = {"x", "y", "z", "weight"};
    for (std::size_t k = 0; k < 3; ++k) ps.xyz.push_back(number_field(path, lines.line_no(), fields[k], kNames[k]));
    if (columns == 4) ps.weights.push_back(number_field(path, lines.line_no(), fields[3], kNames[3]));
  }
  return ps;
}

// ---------------------------------------------------------------------------------------
// .off
// ---------------------------------------------------------------------------------------

PointSet read_off(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineReader lines(data, true);
  Fields fields;
  if (!next_record(lines, fields)) fail_in_file(path, "empty file; expected the keyword OFF");
  // Keyword: [ST][C][N][4][n]OFF.
  const std::string_view kw = fields[0];
  if (kw.size() < 3 || kw.substr(kw.size() - 3) != "OFF") {
    fail_at_line(path, lines.line_no(), "expected the keyword OFF, got " + show(kw) + " (not an OFF file?)");
  }
  std::string_view prefix = kw.substr(0, kw.size() - 3);
  bool extras = !prefix.empty();
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  if (!prefix.empty() && prefix.front() == 'C') prefix.remove_prefix(1);
  if (!prefix.empty() && prefix.front() == 'N') prefix.remove_prefix(1);
  if (!prefix.empty() && (prefix.front() == '4' || prefix.front() == 'n')) {
    fail_at_line(path, lines.line_no(), show(kw) + ": only 3-dimensional OFF files are supported");
  }
  if (!prefix.empty()) fail_at_line(path, lines.line_no(), "unknown OFF variant " + show(kw));
  std::size_t first = 1;  // the counts may follow the keyword on its line
  if (fields.size() > 1 && lower(fields[1]) == "binary") {
    fail_at_line(path, lines.line_no(), "binary OFF files are not supported; convert to ASCII OFF or PLY");
  }
  if (fields.size() == 1) {
    if (!next_record(lines, fields)) fail_in_file(path, "the file ends before the counts line 'vertices faces edges'");
    first = 0;
  }
  const std::size_t ncounts = fields.size() - first;
  if (ncounts != 2 && ncounts != 3) {
    fail_at_line(path, lines.line_no(), "expected the counts 'vertices faces edges', got " + std::to_string(ncounts) + " values");
  }
  const auto nv = int_field<std::uint64_t>(path, lines.line_no(), fields[first], "vertex count");
  int_field<std::uint64_t>(path, lines.line_no(), fields[first + 1], "face count");
  if (ncounts == 3) int_field<std::uint64_t>(path, lines.line_no(), fields[first + 2], "edge count");

  PointSet ps;
  ps.xyz.reserve(3 * reserve_for(nv, data.size(), 6));
  for (std::uint64_t i = 0; i < nv; ++i) {
    if (!next_record(lines, fields)) truncated(path, "vertices", nv, i);
    const std::size_t ln = lines.line_no();
    if (fields.size() < 3 || (!extras && fields.size() != 3)) {
      fail_at_line(path, ln, "vertex " + std::to_string(i) + ": expected 3 coordinates" +
                                 (extras ? std::string(" or more") : std::string(" (plain OFF has no per-vertex extras)")) +
                                 ", got " + std::to_string(fields.size()) + " values");
    }
    ps.xyz.push_back(number_field(path, ln, fields[0], "x"));
    ps.xyz.push_back(number_field(path, ln, fields[1], "y"));
    ps.xyz.push_back(number_field(path, ln, fields[2], "z"));
  }
  return ps;
}

// ---------------------------------------------------------------------------------------
// TetGen .node / .ele / .neigh
// ---------------------------------------------------------------------------------------

PointSet read_node(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineReader lines(data, true);
  Fields fields;
  tetgen_header(path, lines, fields, "points dimension attributes boundary-markers");
  const std::size_t hl = lines.line_no();
  if (fields.size() < 2 || fields.size() > 4) {
    fail_at_line(path, hl, "expected the header 'points dimension [attributes [boundary-markers]]', got " +
                               std::to_string(fields.size()) + " values");
  }
  const auto n = int_field<std::uint64_t>(path, hl, fields[0], "point count");
  const auto dim = int_field<std::uint64_t>(path, hl, fields[1], "dimension");
  if (dim != 3) fail_at_line(path, hl, "dimension must be 3, got " + std::to_string(dim));
  const std::uint64_t nattr = fields.size() > 2 ? int_field<std::uint64_t>(path, hl, fields[2], "attribute count") : 0;
  const std::uint64_t nbm = fields.size() > 3 ? int_field<std::uint64_t>(path, hl, fields[3], "boundary marker flag") : 0;
  if (nbm > 1) fail_at_line(path, hl, "the boundary marker flag must be 0 or 1, got " + std::to_string(nbm));
  if (nattr > 1000000) fail_at_line(path, hl, "implausible attribute count " + std::to_string(nattr));
  const std::size_t expected = 4 + static_cast<std::size_t>(nattr + nbm);

  PointSet ps;
  ps.xyz.reserve(3 * reserve_for(n, data.size(), 8));
  if (nattr > 0) ps.weights.reserve(reserve_for(n, data.size(), 8));
  std::int64_t base = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    if (!next_record(lines, fields)) truncated(path, "points", n, i);
    const std::size_t ln = lines.line_no();
    if (fields.size() != expected) {
      fail_at_line(path, ln, "expected " + std::to_string(expected) + " values (id x y z, " + std::to_string(nattr) +
                                 " attributes, " + std::to_string(nbm) + " boundary markers), got " +
                                 std::to_string(fields.size()));
    }
    tetgen_id(path, ln, fields[0], i, base);
    ps.xyz.push_back(number_field(path, ln, fields[1], "x"));
    ps.xyz.push_back(number_field(path, ln, fields[2], "y"));
    ps.xyz.push_back(number_field(path, ln, fields[3], "z"));
    for (std::uint64_t a = 0; a < nattr; ++a) {
      const double v = number_field(path, ln, fields[4 + a], "attribute");
      if (a == 0) ps.weights.push_back(v);
    }
    if (nbm == 1) int_field<std::int64_t>(path, ln, fields[expected - 1], "boundary marker");
  }
  return ps;
}

std::vector<vid_t> read_ele(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineReader lines(data, true);
  Fields fields;
  tetgen_header(path, lines, fields, "tetrahedra nodes-per-tet attributes");
  const std::size_t hl = lines.line_no();
  if (fields.size() < 2 || fields.size() > 3) {
    fail_at_line(path, hl, "expected the header 'tetrahedra nodes-per-tet [attributes]', got " +
                               std::to_string(fields.size()) + " values");
  }
  const auto m = int_field<std::uint64_t>(path, hl, fields[0], "tetrahedron count");
  const auto npt = int_field<std::uint64_t>(path, hl, fields[1], "nodes per tetrahedron");
  if (npt != 4) fail_at_line(path, hl, "only 4 nodes per tetrahedron are supported, got " + std::to_string(npt));
  const std::uint64_t nattr = fields.size() > 2 ? int_field<std::uint64_t>(path, hl, fields[2], "attribute count") : 0;
  if (nattr > 1000000) fail_at_line(path, hl, "implausible attribute count " + std::to_string(nattr));
  const std::size_t expected = 5 + static_cast<std::size_t>(nattr);

  std::vector<vid_t> tets;
  tets.reserve(4 * reserve_for(m, data.size(), 10));
  std::int64_t base = 0;
  for (std::uint64_t i = 0; i < m; ++i) {
    if (!next_record(lines, fields)) truncated(path, "tetrahedra", m, i);
    const std::size_t ln = lines.line_no();
    if (fields.size() != expected) {
      fail_at_line(path, ln, "expected " + std::to_string(expected) + " values (id, 4 vertices, " +
                                 std::to_string(nattr) + " attributes), got " + std::to_string(fields.size()));
    }
    tetgen_id(path, ln, fields[0], i, base);
    for (int k = 1; k <= 4; ++k) {
      const auto v = int_field<std::int64_t>(path, ln, fields[k], "vertex id");
      if (v < base || v - base > std::numeric_limits<vid_t>::max()) {
        fail_at_line(path, ln, "vertex id " + std::to_string(v) + " is out of range for " +
                                   std::to_string(base) + "-based ids");
      }
      tets.push_back(static_cast<vid_t>(v - base));
    }
    for (std::uint64_t a = 0; a < nattr; ++a) number_field(path, ln, fields[5 + a], "attribute");
  }
  return tets;
}

std::vector<tid_t> read_neigh(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineReader lines(data, true);
  Fields fields;
  tetgen_header(path, lines, fields, "tetrahedra 4");
  const std::size_t hl = lines.line_no();
  if (fields.size() != 2) {
    fail_at_line(path, hl, "expected the header 'tetrahedra 4', got " + std::to_string(fields.size()) + " values");
  }
  const auto m = int_field<std::uint64_t>(path, hl, fields[0], "tetrahedron count");
  const auto four = int_field<std::uint64_t>(path, hl, fields[1], "neighbours per tetrahedron");
  if (four != 4) fail_at_line(path, hl, "expected 4 neighbours per tetrahedron, got " + std::to_string(four));
  if (m > static_cast<std::uint64_t>(std::numeric_limits<tid_t>::max())) {
    fail_at_line(path, hl, "too many tetrahedra for int32 ids: " + std::to_string(m));
  }

  std::vector<tid_t> neigh;
  neigh.reserve(4 * reserve_for(m, data.size(), 10));
  std::int64_t base = 0;
  for (std::uint64_t i = 0; i < m; ++i) {
    if (!next_record(lines, fields)) truncated(path, "tetrahedra", m, i);
    const std::size_t ln = lines.line_no();
    if (fields.size() != 5) {
      fail_at_line(path, ln, "expected 5 values (id and 4 neighbours), got " + std::to_string(fields.size()));
    }
    tetgen_id(path, ln, fields[0], i, base);
    for (int k = 1; k <= 4; ++k) {
      const auto v = int_field<std::int64_t>(path, ln, fields[k], "neighbour");
      if (v == -1) {
        neigh.push_back(-1);
        continue;
      }
      if (v < base || v - base >= static_cast<std::int64_t>(m)) {
        fail_at_line(path, ln, "neighbour " + std::to_string(v) + " is neither -1 (hull) nor a tetrahedron id (" +
                                   std::to_string(base) + ".." + std::to_string(static_cast<std::int64_t>(m) - 1 + base) + ")");
      }
      neigh.push_back(static_cast<tid_t>(v - base));
    }
  }
  return neigh;
}

// ---------------------------------------------------------------------------------------
// Weights
// ---------------------------------------------------------------------------------------

std::vector<double> read_weights(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  if (lower(path.extension().string()) == ".npy") {
    return parse_npy(data, path, NpyShape::Vector).values;
  }
  LineReader lines(data, /*hash_comments=*/true);
  Fields fields;
  std::string_view line;
  std::vector<double> w;
  w.reserve(data.size() / 8);
  while (lines.next(line)) {
    fields.split(line);
    if (fields.size() == 0) continue;
    if (fields.size() != 1) {
      fail_at_line(path, lines.line_no(), "expected one weight per line, got " + std::to_string(fields.size()) + " values");
    }
    w.push_back(number_field(path, lines.line_no(), fields[0], "weight"));
  }
  return w;
}

// ---------------------------------------------------------------------------------------
// Dispatch
// ---------------------------------------------------------------------------------------

PointSet read_points(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".xyz" || ext == ".txt") return read_xyz(path);
  if (ext == ".off") return read_off(path);
  if (ext == ".ply") return read_ply(path);
  if (ext == ".node") return read_node(path);
  if (ext == ".npy") return read_npy(path);
  throw InvalidInput("cannot read '" + path.string() + "': unknown point file extension " +
                     (ext.empty() ? std::string("(none)") : "'" + ext + "'") +
                     "; supported: .xyz .txt (x y z [weight] per line), .off, .ply, .node (TetGen), "
                     ".npy (NumPy (n, 3) or (n, 4) array)");
}

}  // namespace gdel::io
