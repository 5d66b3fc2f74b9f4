// Mesh writers: VTK XML .vtu, Medit .mesh, NumPy .npz (and point .npy), and the dispatch by
// extension. All go through AtomicFileWriter and validate every argument first.
//
// .npz is a zip archive written here, not through a zip library: its members are STORED
// (uncompressed, as numpy.savez writes them), so the archive is a few fixed-layout records
// around the raw .npy bytes (PKWARE APPNOTE 6.3: local file header, central directory, end
// of central directory, and the Zip64 records past 4 GiB). Writing it directly streams the
// arrays through the same temporary-file-and-rename writer as every other format, without a
// second in-memory copy of a multi-gigabyte mesh (libzip would need the archive in memory or
// write its own temporary file) and without a new library dependency of libgdel. The CRC-32
// that zip requires is computed here too (the standard reflected polynomial 0xEDB88320,
// table-driven, eight bytes per step).
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <string>

#include "gdel/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/io.hpp"
#include "io/npy.hpp"
#include "io/parse.hpp"
#include "io/write_common.hpp"

namespace gdel::io {
namespace detail {

// ---------------------------------------------------------------------------------------
// CRC-32 (ISO-HDLC / zip): reflected, polynomial 0xEDB88320, initial and final value
// 0xFFFFFFFF. Table k maps a byte to its contribution k bytes further on, so eight input
// bytes are folded per step.
// ---------------------------------------------------------------------------------------

namespace {

struct CrcTables {
  std::uint32_t t[8][256];
};

constexpr CrcTables make_crc_tables() {
  CrcTables c{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t r = i;
    for (int b = 0; b < 8; ++b) r = (r & 1) ? (r >> 1) ^ 0xEDB88320u : r >> 1;
    c.t[0][i] = r;
  }
  for (int k = 1; k < 8; ++k) {
    for (std::uint32_t i = 0; i < 256; ++i) c.t[k][i] = (c.t[k - 1][i] >> 8) ^ c.t[0][c.t[k - 1][i] & 0xFF];
  }
  return c;
}

constexpr CrcTables kCrc = make_crc_tables();

std::uint32_t load_le32(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
}

}  // namespace

// Continues a CRC: crc32_update(0, a) then crc32_update(that, b) is the CRC of a followed by b.
std::uint32_t crc32_update(std::uint32_t crc, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint32_t c = ~crc;
  for (; n >= 8; n -= 8, p += 8) {
    const std::uint32_t a = load_le32(p) ^ c;
    const std::uint32_t b = load_le32(p + 4);
    c = kCrc.t[7][a & 0xFF] ^ kCrc.t[6][(a >> 8) & 0xFF] ^ kCrc.t[5][(a >> 16) & 0xFF] ^ kCrc.t[4][a >> 24] ^
        kCrc.t[3][b & 0xFF] ^ kCrc.t[2][(b >> 8) & 0xFF] ^ kCrc.t[1][(b >> 16) & 0xFF] ^ kCrc.t[0][b >> 24];
  }
  for (; n > 0; --n, ++p) c = (c >> 8) ^ kCrc.t[0][(c ^ *p) & 0xFF];
  return ~c;
}

}  // namespace detail

using namespace detail;

namespace {

// ---------------------------------------------------------------------------------------
// Base64 (RFC 4648 alphabet, '=' padding), streamed into a writer. finish() pads and ends a
// block: VTK encodes an array's byte-count header and its data as two separate blocks.
// ---------------------------------------------------------------------------------------

constexpr char kB64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

class Base64Writer {
 public:
  explicit Base64Writer(AtomicFileWriter& w) : w_(w) {}

  void put(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    while (n > 0 && held_ > 0 && held_ < 3) {
      hold_[held_++] = *p++;
      --n;
      if (held_ == 3) {
        char* o = w_.reserve(4);
        w_.advance(encode3(o, hold_));
        held_ = 0;
      }
    }
    constexpr std::size_t kGroups = 12288;  // 36 KiB in, 48 KiB out per step
    while (n >= 3) {
      const std::size_t g = std::min(n / 3, kGroups);
      char* o = w_.reserve(4 * g);
      for (std::size_t i = 0; i < g; ++i, p += 3) o = encode3(o, p);
      w_.advance(o);
      n -= 3 * g;
    }
    while (n > 0) {
      hold_[held_++] = *p++;
      --n;
    }
  }

  void finish() {
    if (held_ == 0) return;
    unsigned char last[3] = {hold_[0], held_ > 1 ? hold_[1] : std::uint8_t{0}, 0};
    char* o = w_.reserve(4);
    encode3(o, last);
    if (held_ == 1) o[2] = '=';
    o[3] = '=';
    w_.advance(o + 4);
    held_ = 0;
  }

 private:
  static char* encode3(char* o, const unsigned char* p) {
    const std::uint32_t v = (std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2];
    o[0] = kB64[(v >> 18) & 63];
    o[1] = kB64[(v >> 12) & 63];
    o[2] = kB64[(v >> 6) & 63];
    o[3] = kB64[v & 63];
    return o + 4;
  }

  AtomicFileWriter& w_;
  unsigned char hold_[3] = {0, 0, 0};
  int held_ = 0;
};

const char* native_byte_order() {
  return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
}

// One <DataArray format="binary">: base64(UInt64 byte count), then base64(values), the values
// produced by `fill(begin, count, out)` in chunks (for generated arrays) or given whole.
class VtuArray {
 public:
  VtuArray(AtomicFileWriter& w, const char* type, const char* name, int components, std::uint64_t bytes)
      : w_(w), b64_(w) {
    w_.write("        <DataArray type=\"");
    w_.write(type);
    w_.write("\"");
    if (name != nullptr) {
      w_.write(" Name=\"");
      w_.write(name);
      w_.write("\"");
    }
    if (components != 1) {
      w_.write(" NumberOfComponents=\"");
      w_.number(std::int64_t{components});
      w_.write("\"");
    }
    w_.write(" format=\"binary\">\n          ");
    b64_.put(&bytes, sizeof bytes);
    b64_.finish();
  }
  void put(const void* p, std::size_t n) { b64_.put(p, n); }
  void end() {
    b64_.finish();
    w_.write("\n        </DataArray>\n");
  }

 private:
  AtomicFileWriter& w_;
  Base64Writer b64_;
};

// Generated arrays: values f(i) for i in [0, count), converted to T, in chunks.
template <class T, class F>
void put_generated(VtuArray& a, std::size_t count, F f) {
  constexpr std::size_t kChunk = 4096;
  T buf[kChunk];
  for (std::size_t i = 0; i < count; i += kChunk) {
    const std::size_t k = std::min(kChunk, count - i);
    for (std::size_t j = 0; j < k; ++j) buf[j] = f(i + j);
    a.put(buf, k * sizeof(T));
  }
}

// ---------------------------------------------------------------------------------------
// Zip (STORED members) for .npz
// ---------------------------------------------------------------------------------------

void le16(std::string& s, std::uint16_t v) {
  s += static_cast<char>(v & 0xFF);
  s += static_cast<char>(v >> 8);
}
void le32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void le64(std::string& s, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}

constexpr std::uint32_t kMax32 = 0xFFFFFFFFu;
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01
constexpr std::uint16_t kDosTime = 0;                        // 00:00:00

struct Member {
  std::string name;    // "points.npy"
  std::string header;  // .npy header
  std::span<const unsigned char> data;
  // set while writing
  std::uint32_t crc = 0;
  std::uint64_t offset = 0;
  std::uint64_t size() const { return header.size() + data.size(); }
};

template <class T>
std::span<const unsigned char> bytes_of(std::span<const T> s) {
  return {reinterpret_cast<const unsigned char*>(s.data()), s.size_bytes()};
}

void write_zip(AtomicFileWriter& w, std::vector<Member>& members, bool force_zip64) {
  for (Member& m : members) {
    m.crc = crc32_update(crc32_update(0, m.header.data(), m.header.size()), m.data.data(), m.data.size());
    m.offset = w.bytes_written();
    const bool big = force_zip64 || m.size() >= kMax32;
    std::string h;
    le32(h, 0x04034b50);
    le16(h, big ? 45 : 20);  // version needed: 4.5 for Zip64, 2.0 otherwise
    le16(h, 0);              // flags
    le16(h, 0);              // method: stored
    le16(h, kDosTime);
    le16(h, kDosDate);
    le32(h, m.crc);
    le32(h, big ? kMax32 : static_cast<std::uint32_t>(m.size()));  // compressed size
    le32(h, big ? kMax32 : static_cast<std::uint32_t>(m.size()));  // uncompressed size
    le16(h, static_cast<std::uint16_t>(m.name.size()));
    le16(h, big ? 20 : 0);  // extra field length
    h += m.name;
    if (big) {  // Zip64 extended information: both sizes in the local header
      le16(h, 0x0001);
      le16(h, 16);
      le64(h, m.size());
      le64(h, m.size());
    }
    w.write(h);
    w.write(m.header);
    w.raw(m.data.data(), m.data.size());
  }
  const std::uint64_t cd_offset = w.bytes_written();
  for (const Member& m : members) {
    const bool big_size = force_zip64 || m.size() >= kMax32;
    const bool big_offset = force_zip64 || m.offset >= kMax32;
    std::string extra;
    if (big_size || big_offset) {
      le16(extra, 0x0001);
      le16(extra, static_cast<std::uint16_t>((big_size ? 16 : 0) + (big_offset ? 8 : 0)));
      if (big_size) {
        le64(extra, m.size());  // uncompressed, then compressed
        le64(extra, m.size());
      }
      if (big_offset) le64(extra, m.offset);
    }
    std::string c;
    le32(c, 0x02014b50);
    le16(c, (3 << 8) | 45);  // made by: Unix, spec 4.5
    le16(c, extra.empty() ? 20 : 45);
    le16(c, 0);
    le16(c, 0);
    le16(c, kDosTime);
    le16(c, kDosDate);
    le32(c, m.crc);
    le32(c, big_size ? kMax32 : static_cast<std::uint32_t>(m.size()));
    le32(c, big_size ? kMax32 : static_cast<std::uint32_t>(m.size()));
    le16(c, static_cast<std::uint16_t>(m.name.size()));
    le16(c, static_cast<std::uint16_t>(extra.size()));
    le16(c, 0);                // comment length
    le16(c, 0);                // disk number start
    le16(c, 0);                // internal attributes
    le32(c, 0100644u << 16);   // external attributes: regular file, rw-r--r--
    le32(c, big_offset ? kMax32 : static_cast<std::uint32_t>(m.offset));
    c += m.name;
    c += extra;
    w.write(c);
  }
  const std::uint64_t cd_end = w.bytes_written();
  const std::uint64_t cd_size = cd_end - cd_offset;
  const std::uint64_t count = members.size();
  const bool zip64_end = force_zip64 || cd_offset >= kMax32 || cd_size >= kMax32 || count >= 0xFFFF;
  std::string e;
  if (zip64_end) {
    le32(e, 0x06064b50);  // Zip64 end of central directory record
    le64(e, 44);          // size of the rest of this record
    le16(e, (3 << 8) | 45);
    le16(e, 45);
    le32(e, 0);
    le32(e, 0);
    le64(e, count);
    le64(e, count);
    le64(e, cd_size);
    le64(e, cd_offset);
    le32(e, 0x07064b50);  // Zip64 end of central directory locator
    le32(e, 0);
    le64(e, cd_end);      // offset of the Zip64 record
    le32(e, 1);
  }
  le32(e, 0x06054b50);  // end of central directory
  le16(e, 0);
  le16(e, 0);
  le16(e, zip64_end ? 0xFFFF : static_cast<std::uint16_t>(count));
  le16(e, zip64_end ? 0xFFFF : static_cast<std::uint16_t>(count));
  le32(e, zip64_end ? kMax32 : static_cast<std::uint32_t>(cd_size));
  le32(e, zip64_end ? kMax32 : static_cast<std::uint32_t>(cd_offset));
  le16(e, 0);
  w.write(e);
}

}  // namespace

namespace detail {

void write_npz_impl(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
                    std::span<const tid_t> neighbours, std::span<const double> weights, bool force_zip64) {
  const std::size_t n = check_mesh(path, path, path, xyz, tets, neighbours, weights);
  const std::uint64_t m = tets.size() / 4;
  std::vector<Member> members;
  members.push_back({"points.npy", npy_header(npy_descr_f8(), {n, 3}), bytes_of(xyz)});
  members.push_back({"tets.npy", npy_header(npy_descr_i4(), {m, 4}), bytes_of(tets)});
  if (!neighbours.empty()) members.push_back({"neighbors.npy", npy_header(npy_descr_i4(), {m, 4}), bytes_of(neighbours)});
  if (!weights.empty()) members.push_back({"weights.npy", npy_header(npy_descr_f8(), {n}), bytes_of(weights)});
  AtomicFileWriter w(path);
  write_zip(w, members, force_zip64);
  w.commit();
}

}  // namespace detail

// ---------------------------------------------------------------------------------------
// .npy points
// ---------------------------------------------------------------------------------------

void write_npy(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights) {
  const std::size_t n = check_points(path, xyz, weights);
  for (std::size_t i = 0; i < n; ++i) check_finite(path, xyz, weights, i);
  AtomicFileWriter w(path);
  w.write(npy_header(npy_descr_f8(), {n, weights.empty() ? 3u : 4u}));
  if (weights.empty()) {
    w.raw(xyz.data(), xyz.size_bytes());
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      w.raw(&xyz[3 * i], 3 * sizeof(double));
      w.raw(&weights[i], sizeof(double));
    }
  }
  w.commit();
}

// ---------------------------------------------------------------------------------------
// .vtu
// ---------------------------------------------------------------------------------------

void write_vtu(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
               std::span<const tid_t> neighbours, std::span<const double> weights) {
  const std::size_t n = check_mesh(path, path, path, xyz, tets, neighbours, weights);
  const std::size_t m = tets.size() / 4;
  AtomicFileWriter w(path);
  w.write("<?xml version=\"1.0\"?>\n<!-- written by gdel -->\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"");
  w.write(native_byte_order());
  w.write("\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"");
  w.number(std::uint64_t{n});
  w.write("\" NumberOfCells=\"");
  w.number(std::uint64_t{m});
  w.write("\">\n");
  if (!weights.empty()) {
    w.write("      <PointData Scalars=\"weight\">\n");
    VtuArray a(w, "Float64", "weight", 1, weights.size_bytes());
    a.put(weights.data(), weights.size_bytes());
    a.end();
    w.write("      </PointData>\n");
  }
  w.write("      <CellData Scalars=\"tet_id\">\n");
  {
    VtuArray a(w, "Int32", "tet_id", 1, m * sizeof(std::int32_t));
    put_generated<std::int32_t>(a, m, [](std::size_t i) { return static_cast<std::int32_t>(i); });
    a.end();
  }
  if (!neighbours.empty()) {
    VtuArray a(w, "Int32", "neighbors", 4, neighbours.size_bytes());
    a.put(neighbours.data(), neighbours.size_bytes());
    a.end();
  }
  w.write("      </CellData>\n      <Points>\n");
  {
    VtuArray a(w, "Float64", "Points", 3, xyz.size_bytes());
    a.put(xyz.data(), xyz.size_bytes());
    a.end();
  }
  w.write("      </Points>\n      <Cells>\n");
  {
    VtuArray a(w, "Int32", "connectivity", 1, tets.size_bytes());
    a.put(tets.data(), tets.size_bytes());
    a.end();
  }
  {
    VtuArray a(w, "Int64", "offsets", 1, m * sizeof(std::int64_t));
    put_generated<std::int64_t>(a, m, [](std::size_t i) { return static_cast<std::int64_t>(4 * (i + 1)); });
    a.end();
  }
  {
    VtuArray a(w, "UInt8", "types", 1, m);
    put_generated<std::uint8_t>(a, m, [](std::size_t) { return std::uint8_t{10}; });  // VTK_TETRA
    a.end();
  }
  w.write("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  w.commit();
}

// ---------------------------------------------------------------------------------------
// Medit .mesh
// ---------------------------------------------------------------------------------------

void write_medit(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets) {
  const std::size_t n = check_mesh(path, path, path, xyz, tets, {}, {});
  const std::size_t m = tets.size() / 4;
  AtomicFileWriter w(path);
  w.write("MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n");
  w.number(std::uint64_t{n});
  w.put('\n');
  for (std::size_t i = 0; i < n; ++i) {
    char* p = w.reserve(4 * (AtomicFileWriter::kMaxNumberChars + 1));
    for (int c = 0; c < 3; ++c) {
      p = AtomicFileWriter::append_number(p, xyz[3 * i + c]);
      *p++ = ' ';
    }
    *p++ = '0';
    *p++ = '\n';
    w.advance(p);
  }
  w.write("\nTetrahedra\n");
  w.number(std::uint64_t{m});
  w.put('\n');
  for (std::size_t t = 0; t < m; ++t) {
    char* p = w.reserve(5 * (AtomicFileWriter::kMaxNumberChars + 1));
    for (int k = 0; k < 4; ++k) {
      p = AtomicFileWriter::append_number(p, std::int64_t{tets[4 * t + k]} + 1);
      *p++ = ' ';
    }
    *p++ = '0';
    *p++ = '\n';
    w.advance(p);
  }
  w.write("\nEnd\n");
  w.commit();
}

// ---------------------------------------------------------------------------------------
// .npz and the dispatch
// ---------------------------------------------------------------------------------------

void write_npz(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
               std::span<const tid_t> neighbours, std::span<const double> weights) {
  write_npz_impl(path, xyz, tets, neighbours, weights, /*force_zip64=*/false);
}

MeshFormat mesh_format(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext.empty() || ext == ".ele" || ext == ".node" || ext == ".neigh") return MeshFormat::TetGen;
  if (ext == ".vtu") return MeshFormat::Vtu;
  if (ext == ".mesh") return MeshFormat::Medit;
  if (ext == ".npz") return MeshFormat::Npz;
  throw InvalidInput("cannot write '" + path.string() + "': unknown mesh file extension '" + ext +
                     "'; supported: .ele or none (TetGen .node/.ele/.neigh), .vtu (VTK), .mesh (Medit), "
                     ".npz (NumPy)");
}

namespace {
std::filesystem::path tetgen_base(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  std::filesystem::path base = path;
  if (ext == ".ele" || ext == ".node" || ext == ".neigh") base.replace_extension();
  return base;
}
}  // namespace

std::vector<std::filesystem::path> mesh_outputs(const std::filesystem::path& path, bool with_neighbours) {
  if (mesh_format(path) != MeshFormat::TetGen) return {path};
  const auto base = tetgen_base(path);
  std::vector<std::filesystem::path> out;
  for (const char* suffix : {".node", ".ele", ".neigh"}) {
    if (std::string_view(suffix) == ".neigh" && !with_neighbours) continue;
    auto p = base;
    p += suffix;
    out.push_back(p);
  }
  return out;
}

void write_mesh(const std::filesystem::path& path, std::span<const double> xyz, std::span<const vid_t> tets,
                std::span<const tid_t> neighbours, std::span<const double> weights) {
  switch (mesh_format(path)) {
    case MeshFormat::TetGen: write_tetgen(tetgen_base(path), xyz, tets, neighbours, weights); return;
    case MeshFormat::Vtu: write_vtu(path, xyz, tets, neighbours, weights); return;
    case MeshFormat::Medit:
      // Medit holds neither neighbours nor weights; they are still checked, as for the others.
      check_mesh(path, path, path, xyz, tets, neighbours, weights);
      write_medit(path, xyz, tets);
      return;
    case MeshFormat::Npz: write_npz(path, xyz, tets, neighbours, weights); return;
  }
}

}  // namespace gdel::io
