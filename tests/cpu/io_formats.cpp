// Tests of the .npy reader, the weights reader and the .vtu / .mesh / .npz / .npy writers
// (src/io). Written files are read back by parsers written here from the format specs
// (base64 and XML for .vtu, the zip records for .npz, with an independent bitwise CRC-32),
// so a writer and a reader cannot share a mistake.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/expect_error.hpp"
#include "gdel/errors.hpp"
#include "gen/generators.hpp"
#include "io/io.hpp"
#include "io/npy.hpp"

namespace gdel::io {
namespace {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "these tests spell little-endian bytes");

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

class FormatTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("gdel_iofmt_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path file(const std::string& name) const { return dir_ / name; }

  fs::path bytes_file(const std::string& name, const std::string& content) const {
    const fs::path p = file(name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

using test::expect_error;

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

template <class T>
std::string raw_bytes(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <class T>
std::string swapped_bytes(const std::vector<T>& v) {
  std::string s = raw_bytes(v);
  for (std::size_t i = 0; i < s.size(); i += sizeof(T)) std::reverse(s.begin() + i, s.begin() + i + sizeof(T));
  return s;
}

// A .npy file made by hand: magic, version, little-endian length, the dict padded with
// spaces and ended by '\n' (16-byte alignment, as older NumPy wrote), then the data.
std::string npy(const std::string& dict, const std::string& data, int major = 1) {
  const std::size_t len_bytes = major == 1 ? 2 : 4;
  std::string d = dict;
  while ((6 + 2 + len_bytes + d.size() + 1) % 16 != 0) d += ' ';
  d += '\n';
  std::string s = "\x93NUMPY";
  s += static_cast<char>(major);
  s += '\0';
  for (std::size_t i = 0; i < len_bytes; ++i) s += static_cast<char>((d.size() >> (8 * i)) & 0xFF);
  return s + d + data;
}

std::string dict(const std::string& descr, const std::string& shape, bool fortran = false) {
  return "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") + ", 'shape': " + shape + ", }";
}

// Bitwise CRC-32 (reflected 0xEDB88320), independent of the writer's table-driven one.
std::uint32_t crc32_bitwise(const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int b = 0; b < 8; ++b) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::string base64_decode(std::string_view s) {
  auto val = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  EXPECT_EQ(s.size() % 4, 0u);
  for (std::size_t i = 0; i + 4 <= s.size(); i += 4) {
    int v[4];
    int pad = 0;
    for (int k = 0; k < 4; ++k) {
      if (s[i + k] == '=') {
        v[k] = 0;
        ++pad;
      } else {
        v[k] = val(s[i + k]);
        EXPECT_GE(v[k], 0) << "bad base64 character " << s[i + k];
      }
    }
    const std::uint32_t w = (v[0] << 18) | (v[1] << 12) | (v[2] << 6) | v[3];
    out += static_cast<char>(w >> 16);
    if (pad < 2) out += static_cast<char>((w >> 8) & 0xFF);
    if (pad < 1) out += static_cast<char>(w & 0xFF);
  }
  return out;
}

template <class T>
std::vector<T> from_bytes(const std::string& s) {
  EXPECT_EQ(s.size() % sizeof(T), 0u);
  std::vector<T> v(s.size() / sizeof(T));
  std::memcpy(v.data(), s.data(), v.size() * sizeof(T));
  return v;
}

// A small valid mesh: 5 points, 2 tets sharing the facet (1,2,3) (neighbours across it).
struct SmallMesh {
  std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  std::vector<vid_t> tets = {0, 1, 2, 3, 4, 3, 2, 1};
  std::vector<tid_t> neigh = {1, -1, -1, -1, 0, -1, -1, -1};
  std::vector<double> weights = {0.5, -1, 0, 2.25, 1e-300};
};

// A large mesh (for the chunked paths): points from the generator, arbitrary valid ids.
struct BigMesh {
  std::vector<double> xyz;
  std::vector<vid_t> tets;
  std::vector<tid_t> neigh;
  explicit BigMesh(std::size_t n, std::size_t m) : xyz(gen::uniform(n, 9)), tets(4 * m), neigh(4 * m) {
    std::mt19937_64 rng(5);
    for (auto& v : tets) v = static_cast<vid_t>(rng() % n);
    for (auto& v : neigh) v = static_cast<tid_t>(static_cast<std::int64_t>(rng() % (m + 1)) - 1);
  }
};

// ---------------------------------------------------------------------------------------
// .npy reader
// ---------------------------------------------------------------------------------------

TEST_F(FormatTest, NpyEveryDtypeAndByteOrder) {
  const std::vector<double> want = {1, 2, 3, -4, 5, 100, 0, 7, 8};
  auto check = [&](const std::string& descr, const std::string& data) {
    SCOPED_TRACE(descr);
    const auto p = bytes_file("a.npy", npy(dict(descr, "(3, 3)"), data));
    const PointSet ps = read_npy(p);
    EXPECT_EQ(ps.xyz, want);
    EXPECT_FALSE(ps.has_weights());
  };
  check("<f8", raw_bytes(want));
  check(">f8", swapped_bytes(want));
  check("<f4", raw_bytes(std::vector<float>(want.begin(), want.end())));
  check(">f4", swapped_bytes(std::vector<float>(want.begin(), want.end())));
  check("|i1", raw_bytes(std::vector<std::int8_t>(want.begin(), want.end())));
  check("<i2", raw_bytes(std::vector<std::int16_t>(want.begin(), want.end())));
  check(">i2", swapped_bytes(std::vector<std::int16_t>(want.begin(), want.end())));
  check("<i4", raw_bytes(std::vector<std::int32_t>(want.begin(), want.end())));
  check(">i8", swapped_bytes(std::vector<std::int64_t>(want.begin(), want.end())));
  // Unsigned: no negative values.
  const std::vector<double> pos = {1, 2, 3, 4, 5, 100, 0, 7, 255};
  auto check_u = [&](const std::string& descr, const std::string& data) {
    SCOPED_TRACE(descr);
    EXPECT_EQ(read_npy(bytes_file("u.npy", npy(dict(descr, "(3, 3)"), data))).xyz, pos);
  };
  check_u("|u1", raw_bytes(std::vector<std::uint8_t>(pos.begin(), pos.end())));
  check_u("<u2", raw_bytes(std::vector<std::uint16_t>(pos.begin(), pos.end())));
  check_u(">u4", swapped_bytes(std::vector<std::uint32_t>(pos.begin(), pos.end())));
  check_u("<u8", raw_bytes(std::vector<std::uint64_t>(pos.begin(), pos.end())));
  // float32 values convert exactly (0.1f is not 0.1).
  const std::vector<float> f = {0.1f, 1e-30f, 3.5f};
  EXPECT_EQ(read_npy(bytes_file("f.npy", npy(dict("<f4", "(1, 3)"), raw_bytes(f)))).xyz,
            (std::vector<double>{double(0.1f), double(1e-30f), 3.5}));
}

TEST_F(FormatTest, NpyFortranOrderWeightsVersionsAndOddHeaders) {
  // (2, 4) in Fortran order: columns stored one after another.
  const std::vector<double> cols = {1, 5, 2, 6, 3, 7, 4, 8};
  PointSet ps = read_npy(bytes_file("f.npy", npy(dict("<f8", "(2, 4)", true), raw_bytes(cols))));
  EXPECT_EQ(ps.xyz, (std::vector<double>{1, 2, 3, 5, 6, 7}));
  EXPECT_EQ(ps.weights, (std::vector<double>{4, 8}));
  // Fortran (3, 3) int32.
  const std::vector<std::int32_t> c3 = {1, 4, 7, 2, 5, 8, 3, 6, 9};
  EXPECT_EQ(read_npy(bytes_file("g.npy", npy(dict("<i4", "(3, 3)", true), raw_bytes(c3)))).xyz,
            (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  // Versions 2.0 and 3.0 (4-byte header length).
  const std::vector<double> one = {1, 2, 3};
  EXPECT_EQ(read_npy(bytes_file("v2.npy", npy(dict("<f8", "(1, 3)"), raw_bytes(one), 2))).xyz, one);
  EXPECT_EQ(read_npy(bytes_file("v3.npy", npy(dict("<f8", "(1, 3)"), raw_bytes(one), 3))).xyz, one);
  // Keys in another order, double quotes, no trailing comma, Python 2 long suffixes.
  EXPECT_EQ(read_npy(bytes_file("k.npy", npy("{\"shape\": (1L, 3L), \"fortran_order\": False, \"descr\": \"<f8\"}",
                                              raw_bytes(one))))
                .xyz,
            one);
  // An empty (0, 3) array is an empty point set.
  EXPECT_EQ(read_npy(bytes_file("e.npy", npy(dict("<f8", "(0, 3)"), ""))).size(), 0u);
  // NaN and Inf are kept (validation is the API's job).
  const std::vector<double> nan = {NAN, INFINITY, 1};
  const auto got = read_npy(bytes_file("n.npy", npy(dict("<f8", "(1, 3)"), raw_bytes(nan)))).xyz;
  EXPECT_TRUE(std::isnan(got[0]));
  EXPECT_EQ(got[1], INFINITY);
  // Integers: exactly representable ones pass (2^60 has one significant bit), others fail.
  const std::vector<std::int64_t> big = {std::int64_t{1} << 60, -(std::int64_t{1} << 53), 9007199254740992};
  EXPECT_EQ(read_npy(bytes_file("b.npy", npy(dict("<i8", "(1, 3)"), raw_bytes(big)))).xyz,
            (std::vector<double>{std::ldexp(1.0, 60), -std::ldexp(1.0, 53), std::ldexp(1.0, 53)}));
  const std::vector<std::int64_t> inexact = {1, 2, 9007199254740993};
  expect_error<InvalidInput>([&] { read_npy(bytes_file("c.npy", npy(dict("<i8", "(1, 3)"), raw_bytes(inexact)))); },
                             {"c.npy", "element 2", "9007199254740993", "exactly"});
  const std::vector<std::uint64_t> uinexact = {1, 2, ~std::uint64_t{0}};
  expect_error<InvalidInput>([&] { read_npy(bytes_file("d.npy", npy(dict("<u8", "(1, 3)"), raw_bytes(uinexact)))); },
                             {"d.npy", "element 2", "18446744073709551615"});
  // Dispatch by extension, any case.
  bytes_file("UP.NPY", npy(dict("<f8", "(1, 3)"), raw_bytes(one)));
  EXPECT_EQ(read_points(file("UP.NPY")).xyz, one);
}

TEST_F(FormatTest, NpyMalformed) {
  const std::string d3 = raw_bytes(std::vector<double>{1, 2, 3});
  auto bad = [&](const std::string& content, std::initializer_list<std::string_view> parts) {
    expect_error<InvalidInput>([&] { read_npy(bytes_file("x.npy", content)); }, parts);
  };
  bad("", {"x.npy", "magic"});
  bad("1 2 3\n", {"x.npy", "not a NumPy .npy file"});
  bad(npy(dict("<f8", "(1, 3)"), d3).replace(6, 1, "\x04"), {"version 4.0", "not supported"});
  bad(npy(dict("<f8", "(1, 3)"), d3).substr(0, 20), {"truncated .npy header"});
  bad(npy("[1, 2]", d3), {"invalid .npy header", "dict"});
  bad(npy("{'descr': '<f8', 'shape': (1, 3)}", d3), {"lacks the key 'fortran_order'"});
  bad(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 3), 'x': 1}", d3), {"unexpected key 'x'"});
  bad(npy("{'descr': '<f8', 'descr': '<f8', 'fortran_order': False, 'shape': (1, 3)}", d3), {"'descr' appears twice"});
  bad(npy("{'descr': [('x', '<f8'), ('y', '<f8')], 'fortran_order': False, 'shape': (1,)}", d3), {"structured"});
  bad(npy("{'descr': '<f8', 'fortran_order': 0, 'shape': (1, 3)}", d3), {"True or False"});
  bad(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, -3)}", d3), {"non-negative integers"});
  bad(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 3)} x", d3), {"after the header dict"});
  bad(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 3)", d3), {"invalid .npy header"});
  bad(npy("{'descr': '<f8, 'fortran_order': False}", d3), {"invalid .npy header"});
  bad(npy(dict("<c16", "(1, 3)"), d3 + d3), {"'<c16'", "complex", "not supported"});
  bad(npy(dict("|b1", "(1, 3)"), "\1\0\1"), {"boolean"});
  bad(npy(dict("|O", "(1, 3)"), d3), {"Python objects"});
  bad(npy(dict("<U8", "(1, 3)"), d3), {"strings"});
  bad(npy(dict("<f2", "(1, 3)"), "\0\0\0\0\0\0"), {"float16"});
  bad(npy(dict("<f16", "(1, 3)"), d3 + d3), {"extended precision"});
  bad(npy(dict("|f8", "(1, 3)"), d3), {"only valid for 1-byte types"});
  bad(npy(dict("<f8", "(3,)"), d3), {"shape (3,)", "expected (n, 3)"});
  bad(npy(dict("<f8", "(1, 2)"), d3.substr(0, 16)), {"shape (1, 2)"});
  bad(npy(dict("<f8", "(1, 3, 1)"), d3), {"shape (1, 3, 1)"});
  bad(npy(dict("<f8", "(2, 3)"), d3), {"ends after 24 bytes", "needs 48", "truncated"});
  bad(npy(dict("<f8", "(99999999999999999, 3)"), d3), {"ends after 24 bytes"});
  bad(npy(dict("<f8", "(1, 3)"), d3 + "xy"), {"2 unexpected bytes after the array data"});
  bad(npy("{'descr': 'caf\xC3\xA9', 'fortran_order': False, 'shape': (1, 3)}", d3), {"non-ASCII"});
}

TEST_F(FormatTest, NpyWriterRoundTripAndHeaderLayout) {
  const std::vector<double> xyz = gen::uniform(1000, 4);
  const std::vector<double> w = gen::weights(1000, 5, 0.25);
  write_npy(file("p.npy"), xyz);
  write_npy(file("pw.npy"), xyz, w);
  const PointSet a = read_npy(file("p.npy"));
  EXPECT_TRUE(same_bits(a.xyz, xyz));
  EXPECT_FALSE(a.has_weights());
  const PointSet b = read_points(file("pw.npy"));
  EXPECT_TRUE(same_bits(b.xyz, xyz));
  EXPECT_TRUE(same_bits(b.weights, w));
  // Header: version 1.0, dict as NumPy writes it, data 64-byte aligned, exact file size.
  const std::string s = slurp(file("pw.npy"));
  ASSERT_GE(s.size(), 10u);
  EXPECT_EQ(s.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t hlen = static_cast<unsigned char>(s[8]) | (static_cast<unsigned char>(s[9]) << 8);
  EXPECT_EQ((10 + hlen) % 64, 0u);
  EXPECT_EQ(s[10 + hlen - 1], '\n');
  const std::string dict_text = "{'descr': '<f8', 'fortran_order': False, 'shape': (1000, 4), }";
  EXPECT_EQ(s.substr(10, dict_text.size()), dict_text);
  EXPECT_EQ(s.size(), 10 + hlen + 1000 * 4 * 8);
  // Non-finite points are refused before any file exists.
  expect_error<InvalidInput>(
      [&] {
        write_npy(file("bad.npy"), std::vector<double>{0, NAN, 0});
      },
      {"bad.npy", "non-finite"});
  EXPECT_FALSE(fs::exists(file("bad.npy")));
}

// ---------------------------------------------------------------------------------------
// PLY regression (found by fuzz/fuzz_ply): an element without properties and a huge count
// has empty records; reading must not loop over the count.
// ---------------------------------------------------------------------------------------

TEST_F(FormatTest, PlyElementWithoutPropertiesAndHugeCountIsSkipped) {
  const std::string body_ascii = "1 2 3\n";
  double xyz[3] = {1, 2, 3};
  const std::string body_bin(reinterpret_cast<const char*>(xyz), sizeof xyz);
  for (const char* fmt : {"ascii", "binary_little_endian"}) {
    SCOPED_TRACE(fmt);
    const std::string ply = std::string("ply\nformat ") + fmt + " 1.0\nelement nothing 450000004662\n" +
                            "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n" +
                            (std::string(fmt) == "ascii" ? body_ascii : body_bin);
    EXPECT_EQ(read_ply(bytes_file("e.ply", ply)).xyz, (std::vector<double>{1, 2, 3}));
  }
}

// ---------------------------------------------------------------------------------------
// Weights reader
// ---------------------------------------------------------------------------------------

TEST_F(FormatTest, WeightsTextAndNpy) {
  EXPECT_EQ(read_weights(bytes_file("w.txt", "# weights\n0.5\n\n  -2e3  # comment\n\r\n7\r\n")),
            (std::vector<double>{0.5, -2000, 7}));
  EXPECT_TRUE(read_weights(bytes_file("empty.txt", "")).empty());
  expect_error<InvalidInput>([&] { read_weights(bytes_file("two.txt", "1\n2 3\n")); },
                             {"two.txt:2:", "one weight per line", "got 2"});
  expect_error<InvalidInput>([&] { read_weights(bytes_file("nan.txt", "1\nabc\n")); }, {"nan.txt:2:", "'abc'"});
  expect_error<InvalidInput>([&] { read_weights(file("missing.txt")); }, {"missing.txt", "No such file"});
  const std::vector<double> w = {1.5, -2, 0};
  EXPECT_EQ(read_weights(bytes_file("w.npy", npy(dict("<f8", "(3,)"), raw_bytes(w)))), w);
  EXPECT_EQ(read_weights(bytes_file("w1.npy", npy(dict("<f8", "(3, 1)"), raw_bytes(w)))), w);
  expect_error<InvalidInput>([&] { read_weights(bytes_file("w2.npy", npy(dict("<f8", "(1, 3)"), raw_bytes(w)))); },
                             {"w2.npy", "shape (1, 3)", "one value per point"});
}

// ---------------------------------------------------------------------------------------
// CRC-32
// ---------------------------------------------------------------------------------------

TEST(FormatCrc, KnownValueChainingAndAgreesWithBitwise) {
  EXPECT_EQ(detail::crc32_update(0, "123456789", 9), 0xCBF43926u);  // the standard check value
  EXPECT_EQ(crc32_bitwise("123456789", 9), 0xCBF43926u);
  EXPECT_EQ(detail::crc32_update(0, "", 0), 0u);
  std::mt19937_64 rng(1);
  std::string buf(5000, '\0');
  for (auto& c : buf) c = static_cast<char>(rng());
  for (std::size_t off = 0; off < 9; ++off) {
    for (std::size_t len : {0, 1, 7, 8, 9, 15, 16, 17, 100, 4000}) {
      const std::uint32_t want = crc32_bitwise(buf.data() + off, len);
      EXPECT_EQ(detail::crc32_update(0, buf.data() + off, len), want) << off << " " << len;
      const std::size_t cut = len / 3;
      EXPECT_EQ(detail::crc32_update(detail::crc32_update(0, buf.data() + off, cut), buf.data() + off + cut, len - cut),
                want);
    }
  }
}

// ---------------------------------------------------------------------------------------
// .vtu
// ---------------------------------------------------------------------------------------

struct VtuArray {
  std::map<std::string, std::string> attrs;
  std::string header, data;  // decoded
};

// Minimal reader of what write_vtu writes: the VTKFile/Piece attributes and every
// DataArray, whose text must be base64(8-byte count) followed by base64(data).
struct Vtu {
  std::map<std::string, std::string> file_attrs, piece_attrs;
  std::vector<std::string> sections;  // PointData, CellData, Points, Cells in order of appearance
  std::map<std::string, VtuArray> arrays;

  static std::map<std::string, std::string> attributes(std::string_view tag) {
    std::map<std::string, std::string> a;
    std::size_t i = 0;
    while ((i = tag.find('=', i)) != std::string_view::npos) {
      std::size_t k = i;
      while (k > 0 && tag[k - 1] != ' ') --k;
      const std::string key(tag.substr(k, i - k));
      const std::size_t q1 = tag.find('"', i);
      const std::size_t q2 = tag.find('"', q1 + 1);
      a[key] = std::string(tag.substr(q1 + 1, q2 - q1 - 1));
      i = q2 + 1;
    }
    return a;
  }

  explicit Vtu(const std::string& s) {
    EXPECT_EQ(s.rfind("<?xml version=\"1.0\"?>", 0), 0u);
    const auto tag_at = [&](const char* name) {
      const std::size_t b = s.find(std::string("<") + name + " ");
      EXPECT_NE(b, std::string::npos) << name;
      return std::string_view(s).substr(b, s.find('>', b) - b);
    };
    file_attrs = attributes(tag_at("VTKFile"));
    piece_attrs = attributes(tag_at("Piece"));
    for (const char* sec : {"<PointData", "<CellData", "<Points>", "<Cells>"}) {
      if (s.find(sec) != std::string::npos) sections.push_back(sec);
    }
    std::sort(sections.begin(), sections.end(), [&](const std::string& a, const std::string& b) { return s.find(a) < s.find(b); });
    std::size_t pos = 0;
    while ((pos = s.find("<DataArray ", pos)) != std::string::npos) {
      const std::size_t gt = s.find('>', pos);
      VtuArray a;
      a.attrs = attributes(std::string_view(s).substr(pos, gt - pos));
      const std::size_t end = s.find("</DataArray>", gt);
      std::string text = s.substr(gt + 1, end - gt - 1);
      text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\n'; }), text.end());
      EXPECT_EQ(a.attrs["format"], "binary");
      // The 8-byte header is its own base64 block: 12 characters ending in '='.
      EXPECT_GE(text.size(), 12u);
      EXPECT_EQ(text[11], '=');
      a.header = base64_decode(text.substr(0, 12));
      a.data = base64_decode(text.substr(12));
      EXPECT_EQ(a.header.size(), 8u);
      std::uint64_t count;
      std::memcpy(&count, a.header.data(), 8);
      EXPECT_EQ(count, a.data.size()) << a.attrs["Name"];
      arrays[a.attrs["Name"]] = a;
      pos = end;
    }
  }
};

TEST_F(FormatTest, VtuSmallMeshEveryArray) {
  const SmallMesh m;
  write_vtu(file("m.vtu"), m.xyz, m.tets, m.neigh, m.weights);
  const Vtu v(slurp(file("m.vtu")));
  EXPECT_EQ(v.file_attrs.at("type"), "UnstructuredGrid");
  EXPECT_EQ(v.file_attrs.at("version"), "1.0");
  EXPECT_EQ(v.file_attrs.at("byte_order"), "LittleEndian");
  EXPECT_EQ(v.file_attrs.at("header_type"), "UInt64");
  EXPECT_EQ(v.piece_attrs.at("NumberOfPoints"), "5");
  EXPECT_EQ(v.piece_attrs.at("NumberOfCells"), "2");
  EXPECT_EQ(v.sections, (std::vector<std::string>{"<PointData", "<CellData", "<Points>", "<Cells>"}));
  ASSERT_EQ(v.arrays.size(), 7u);
  EXPECT_EQ(v.arrays.at("Points").attrs.at("type"), "Float64");
  EXPECT_EQ(v.arrays.at("Points").attrs.at("NumberOfComponents"), "3");
  EXPECT_TRUE(same_bits(from_bytes<double>(v.arrays.at("Points").data), m.xyz));
  EXPECT_EQ(v.arrays.at("connectivity").attrs.at("type"), "Int32");
  EXPECT_EQ(from_bytes<std::int32_t>(v.arrays.at("connectivity").data), m.tets);
  EXPECT_EQ(v.arrays.at("offsets").attrs.at("type"), "Int64");
  EXPECT_EQ(from_bytes<std::int64_t>(v.arrays.at("offsets").data), (std::vector<std::int64_t>{4, 8}));
  EXPECT_EQ(v.arrays.at("types").attrs.at("type"), "UInt8");
  EXPECT_EQ(from_bytes<std::uint8_t>(v.arrays.at("types").data), (std::vector<std::uint8_t>{10, 10}));
  EXPECT_EQ(from_bytes<std::int32_t>(v.arrays.at("tet_id").data), (std::vector<std::int32_t>{0, 1}));
  EXPECT_EQ(v.arrays.at("neighbors").attrs.at("NumberOfComponents"), "4");
  EXPECT_EQ(from_bytes<std::int32_t>(v.arrays.at("neighbors").data), m.neigh);
  EXPECT_TRUE(same_bits(from_bytes<double>(v.arrays.at("weight").data), m.weights));
  // Without neighbours and weights: no such arrays, no PointData.
  write_vtu(file("plain.vtu"), m.xyz, m.tets);
  const Vtu p(slurp(file("plain.vtu")));
  EXPECT_EQ(p.arrays.size(), 5u);
  EXPECT_EQ(p.arrays.count("neighbors"), 0u);
  EXPECT_EQ(p.sections, (std::vector<std::string>{"<CellData", "<Points>", "<Cells>"}));
}

TEST_F(FormatTest, VtuLargeMeshCrossesEncoderChunks) {
  // Sizes that are not multiples of 3 bytes and span several 36 KiB encoder steps.
  const BigMesh m(20001, 30001);
  write_vtu(file("big.vtu"), m.xyz, m.tets, m.neigh);
  const Vtu v(slurp(file("big.vtu")));
  EXPECT_TRUE(same_bits(from_bytes<double>(v.arrays.at("Points").data), m.xyz));
  EXPECT_EQ(from_bytes<std::int32_t>(v.arrays.at("connectivity").data), m.tets);
  EXPECT_EQ(from_bytes<std::int32_t>(v.arrays.at("neighbors").data), m.neigh);
  const auto off = from_bytes<std::int64_t>(v.arrays.at("offsets").data);
  ASSERT_EQ(off.size(), 30001u);
  for (std::size_t i = 0; i < off.size(); ++i) ASSERT_EQ(off[i], static_cast<std::int64_t>(4 * (i + 1)));
  const auto ids = from_bytes<std::int32_t>(v.arrays.at("tet_id").data);
  for (std::size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], static_cast<std::int32_t>(i));
  const auto types = from_bytes<std::uint8_t>(v.arrays.at("types").data);
  EXPECT_EQ(types.size(), 30001u);
  EXPECT_TRUE(std::all_of(types.begin(), types.end(), [](std::uint8_t t) { return t == 10; }));
}

// ---------------------------------------------------------------------------------------
// Medit .mesh
// ---------------------------------------------------------------------------------------

TEST_F(FormatTest, MeditRoundTripOneBased) {
  const BigMesh m(3000, 5000);
  write_medit(file("m.mesh"), m.xyz, m.tets);
  std::istringstream in(slurp(file("m.mesh")));
  std::string kw;
  int version = 0, dim = 0;
  in >> kw >> version;
  EXPECT_EQ(kw, "MeshVersionFormatted");
  EXPECT_EQ(version, 2);
  in >> kw >> dim;
  EXPECT_EQ(kw, "Dimension");
  EXPECT_EQ(dim, 3);
  std::size_t n = 0, mt = 0;
  in >> kw >> n;
  EXPECT_EQ(kw, "Vertices");
  ASSERT_EQ(n, 3000u);
  std::vector<double> xyz(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    std::string x, y, z;
    int ref;
    in >> x >> y >> z >> ref;
    xyz[3 * i] = std::stod(x);  // shortest round-trip text: reads back exactly
    xyz[3 * i + 1] = std::stod(y);
    xyz[3 * i + 2] = std::stod(z);
    EXPECT_EQ(ref, 0);
  }
  EXPECT_TRUE(same_bits(xyz, m.xyz));
  in >> kw >> mt;
  EXPECT_EQ(kw, "Tetrahedra");
  ASSERT_EQ(mt, 5000u);
  for (std::size_t t = 0; t < mt; ++t) {
    std::int64_t v[4], ref;
    in >> v[0] >> v[1] >> v[2] >> v[3] >> ref;
    for (int k = 0; k < 4; ++k) ASSERT_EQ(v[k], std::int64_t{m.tets[4 * t + k]} + 1);
    EXPECT_EQ(ref, 0);
  }
  in >> kw;
  EXPECT_EQ(kw, "End");
  in >> kw;
  EXPECT_TRUE(in.eof());
}

// ---------------------------------------------------------------------------------------
// .npz
// ---------------------------------------------------------------------------------------

std::uint64_t le(const std::string& s, std::size_t at, int bytes) {
  EXPECT_LE(at + bytes, s.size());
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}

// Reads a STORED zip through its central directory (following Zip64 records where the
// 32-bit fields say 0xFFFFFFFF), checks each local header against it and every CRC, and
// returns name -> bytes.
std::map<std::string, std::string> unzip(const std::string& z, bool* used_zip64 = nullptr) {
  std::map<std::string, std::string> out;
  EXPECT_GE(z.size(), 22u);
  const std::size_t eocd = z.size() - 22;  // no archive comment
  EXPECT_EQ(le(z, eocd, 4), 0x06054b50u);
  std::uint64_t entries = le(z, eocd + 10, 2), cd_size = le(z, eocd + 12, 4), cd_off = le(z, eocd + 16, 4);
  bool z64 = false;
  if (entries == 0xFFFF || cd_size == 0xFFFFFFFF || cd_off == 0xFFFFFFFF) {
    z64 = true;
    const std::size_t loc = eocd - 20;
    EXPECT_EQ(le(z, loc, 4), 0x07064b50u);
    const std::size_t rec = le(z, loc + 8, 8);
    EXPECT_EQ(rec, loc - 56);
    EXPECT_EQ(le(z, rec, 4), 0x06064b50u);
    EXPECT_EQ(le(z, rec + 4, 8), 44u);
    entries = le(z, rec + 32, 8);
    cd_size = le(z, rec + 40, 8);
    cd_off = le(z, rec + 48, 8);
    EXPECT_EQ(cd_off + cd_size, rec);
  } else {
    EXPECT_EQ(cd_off + cd_size, eocd);
  }
  std::size_t p = cd_off;
  std::uint64_t next_local = 0;
  for (std::uint64_t e = 0; e < entries; ++e) {
    EXPECT_EQ(le(z, p, 4), 0x02014b50u);
    EXPECT_EQ(le(z, p + 10, 2), 0u);  // stored
    const std::uint32_t crc = static_cast<std::uint32_t>(le(z, p + 16, 4));
    std::uint64_t csize = le(z, p + 20, 4), usize = le(z, p + 24, 4);
    const std::size_t nlen = le(z, p + 28, 2), xlen = le(z, p + 30, 2), clen = le(z, p + 32, 2);
    std::uint64_t off = le(z, p + 42, 4);
    const std::string name = z.substr(p + 46, nlen);
    std::size_t x = p + 46 + nlen;
    const std::size_t xend = x + xlen;
    while (x < xend) {  // extra fields
      const auto tag = le(z, x, 2), len = le(z, x + 2, 2);
      std::size_t q = x + 4;
      if (tag == 1) {
        z64 = true;
        if (usize == 0xFFFFFFFF) usize = le(z, q, 8), q += 8;
        if (csize == 0xFFFFFFFF) csize = le(z, q, 8), q += 8;
        if (off == 0xFFFFFFFF) off = le(z, q, 8), q += 8;
        EXPECT_EQ(q, x + 4 + len);
      }
      x += 4 + len;
    }
    EXPECT_EQ(csize, usize);
    EXPECT_EQ(off, next_local) << "members are contiguous from offset 0";
    // Local header.
    EXPECT_EQ(le(z, off, 4), 0x04034b50u);
    EXPECT_EQ(le(z, off + 8, 2), 0u);
    EXPECT_EQ(le(z, off + 14, 4), crc);
    const std::size_t lnlen = le(z, off + 26, 2), lxlen = le(z, off + 28, 2);
    EXPECT_EQ(z.substr(off + 30, lnlen), name);
    if (le(z, off + 18, 4) == 0xFFFFFFFF) {
      EXPECT_EQ(le(z, off + 30 + lnlen, 2), 1u);
      EXPECT_EQ(le(z, off + 34 + lnlen, 8), usize);
      EXPECT_EQ(le(z, off + 42 + lnlen, 8), csize);
    } else {
      EXPECT_EQ(le(z, off + 18, 4), csize);
    }
    const std::size_t data = off + 30 + lnlen + lxlen;
    const std::string bytes = z.substr(data, usize);
    EXPECT_EQ(crc32_bitwise(bytes.data(), bytes.size()), crc) << name;
    out[name] = bytes;
    next_local = data + usize;
    p = xend + clen;
  }
  EXPECT_EQ(next_local, cd_off);
  if (used_zip64) *used_zip64 = z64;
  return out;
}

void expect_npz_contents(const std::map<std::string, std::string>& members, const std::vector<double>& xyz,
                         const std::vector<vid_t>& tets, const std::vector<tid_t>& neigh,
                         const std::vector<double>& weights) {
  std::vector<std::string> names;
  for (const auto& [k, v] : members) names.push_back(k);
  std::vector<std::string> want = {"points.npy", "tets.npy"};
  if (!neigh.empty()) want.push_back("neighbors.npy");
  if (!weights.empty()) want.push_back("weights.npy");
  std::sort(want.begin(), want.end());
  ASSERT_EQ(names, want);
  const auto pts = detail::parse_npy(members.at("points.npy"), "points.npy", detail::NpyShape::Points);
  EXPECT_EQ(pts.descr, "<f8");
  EXPECT_EQ(pts.shape, (std::vector<std::uint64_t>{xyz.size() / 3, 3}));
  EXPECT_TRUE(same_bits(pts.values, xyz));
  // tets/neighbors are (m, 4) int32: parse as "points with weights" and compare values.
  const auto t = detail::parse_npy(members.at("tets.npy"), "tets.npy", detail::NpyShape::Points);
  EXPECT_EQ(t.descr, "<i4");
  EXPECT_EQ(t.shape, (std::vector<std::uint64_t>{tets.size() / 4, 4}));
  EXPECT_EQ(t.values, std::vector<double>(tets.begin(), tets.end()));
  if (!neigh.empty()) {
    const auto nb = detail::parse_npy(members.at("neighbors.npy"), "neighbors.npy", detail::NpyShape::Points);
    EXPECT_EQ(nb.descr, "<i4");
    EXPECT_EQ(nb.values, std::vector<double>(neigh.begin(), neigh.end()));
  }
  if (!weights.empty()) {
    const auto w = detail::parse_npy(members.at("weights.npy"), "weights.npy", detail::NpyShape::Vector);
    EXPECT_EQ(w.shape, (std::vector<std::uint64_t>{weights.size()}));
    EXPECT_TRUE(same_bits(w.values, weights));
  }
}

TEST_F(FormatTest, NpzMembersCrcAndDeterminism) {
  const SmallMesh m;
  write_npz(file("m.npz"), m.xyz, m.tets, m.neigh, m.weights);
  bool z64 = true;
  const auto members = unzip(slurp(file("m.npz")), &z64);
  EXPECT_FALSE(z64);
  expect_npz_contents(members, m.xyz, m.tets, m.neigh, m.weights);
  // Without the optional members.
  write_npz(file("plain.npz"), m.xyz, m.tets);
  expect_npz_contents(unzip(slurp(file("plain.npz"))), m.xyz, m.tets, {}, {});
  // A bigger mesh; equal inputs give identical bytes (fixed timestamps).
  const BigMesh b(10000, 20000);
  write_npz(file("b1.npz"), b.xyz, b.tets, b.neigh);
  write_npz(file("b2.npz"), b.xyz, b.tets, b.neigh);
  const std::string b1 = slurp(file("b1.npz"));
  EXPECT_EQ(b1, slurp(file("b2.npz")));
  expect_npz_contents(unzip(b1), b.xyz, b.tets, b.neigh, {});
  // The point member also reads as a standalone .npy.
  std::ofstream(file("points.npy"), std::ios::binary) << unzip(b1).at("points.npy");
  EXPECT_TRUE(same_bits(read_points(file("points.npy")).xyz, b.xyz));
}

TEST_F(FormatTest, NpzZip64RecordsReadBack) {
  // The records a >4 GiB archive needs, forced on a small one.
  const SmallMesh m;
  detail::write_npz_impl(file("z64.npz"), m.xyz, m.tets, m.neigh, m.weights, /*force_zip64=*/true);
  const std::string z = slurp(file("z64.npz"));
  bool z64 = false;
  const auto members = unzip(z, &z64);
  EXPECT_TRUE(z64);
  expect_npz_contents(members, m.xyz, m.tets, m.neigh, m.weights);
  EXPECT_EQ(le(z, z.size() - 22 + 16, 4), 0xFFFFFFFFu);  // EOCD points to the Zip64 record
}

// ---------------------------------------------------------------------------------------
// Validation before writing, dispatch, atomic replacement
// ---------------------------------------------------------------------------------------

TEST_F(FormatTest, MeshWritersValidateBeforeCreatingAnyFile) {
  const SmallMesh m;
  const std::vector<vid_t> bad_tets = {0, 1, 2, 5};
  const std::vector<tid_t> bad_neigh = {2, -1, -1, -1, 0, -1, -1, -1};
  std::vector<double> nan_xyz = m.xyz;
  nan_xyz[7] = NAN;
  for (const char* name : {"a.vtu", "a.mesh", "a.npz", "a.ele"}) {
    SCOPED_TRACE(name);
    expect_error<InvalidInput>([&] { write_mesh(file(name), m.xyz, bad_tets); }, {"tetrahedron 0", "vertex id 5"});
    expect_error<InvalidInput>([&] { write_mesh(file(name), nan_xyz, m.tets); }, {"point 2", "non-finite"});
    expect_error<InvalidInput>([&] { write_mesh(file(name), m.xyz, m.tets, bad_neigh); }, {"neighbour 2"});
    expect_error<InvalidInput>(
        [&] {
          write_mesh(file(name), m.xyz, m.tets, std::vector<tid_t>{-1, -1, -1, -1});
        },
        {"1 neighbour rows for 2 tetrahedra"});
    expect_error<InvalidInput>([&] { write_mesh(file(name), m.xyz, std::vector<vid_t>{0, 1, 2}); }, {"multiple of 4"});
    expect_error<InvalidInput>([&] { write_mesh(file(name), m.xyz, m.tets, {}, std::vector<double>{1}); },
                               {"1 weights for 5 points"});
  }
  EXPECT_TRUE(listing().empty()) << listing().front();
}

TEST_F(FormatTest, MeshFormatDispatchAndOutputs) {
  EXPECT_EQ(mesh_format("out/mesh"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format("a.ele"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format("a.NODE"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format("a.VTU"), MeshFormat::Vtu);
  EXPECT_EQ(mesh_format("a.mesh"), MeshFormat::Medit);
  EXPECT_EQ(mesh_format("a.npz"), MeshFormat::Npz);
  expect_error<InvalidInput>([] { mesh_format("a.vtk"); },
                             {"a.vtk", "unknown mesh file extension '.vtk'", ".vtu", ".npz"});
  expect_error<InvalidInput>([] { mesh_format("a.tar.gz"); }, {"'.gz'"});
  EXPECT_EQ(mesh_outputs("d/m.ele", true), (std::vector<fs::path>{"d/m.node", "d/m.ele", "d/m.neigh"}));
  EXPECT_EQ(mesh_outputs("d/m", false), (std::vector<fs::path>{"d/m.node", "d/m.ele"}));
  EXPECT_EQ(mesh_outputs("m.vtu", true), (std::vector<fs::path>{"m.vtu"}));

  const SmallMesh m;
  for (const char* name : {"t.ele", "t.vtu", "t.mesh", "t.npz"}) write_mesh(file(name), m.xyz, m.tets, m.neigh);
  EXPECT_EQ(listing(), (std::vector<std::string>{"t.ele", "t.mesh", "t.neigh", "t.node", "t.npz", "t.vtu"}));
  EXPECT_TRUE(same_bits(read_points(file("t.node")).xyz, m.xyz));
  EXPECT_EQ(read_ele(file("t.ele")), m.tets);
  EXPECT_EQ(read_neigh(file("t.neigh")), m.neigh);
}

TEST_F(FormatTest, TetgenSetRefusesADirectoryInTheWayAndKeepsOldFiles) {
  const SmallMesh m;
  bytes_file("s.node", "old node");
  bytes_file("s.ele", "old ele");
  fs::create_directories(file("s.neigh"));
  EXPECT_THROW(write_mesh(file("s.ele"), m.xyz, m.tets, m.neigh), Error);
  EXPECT_EQ(slurp(file("s.node")), "old node");
  EXPECT_EQ(slurp(file("s.ele")), "old ele");
  EXPECT_EQ(listing(), (std::vector<std::string>{"s.ele", "s.neigh", "s.node"}));
  // Single-file formats: an existing file is replaced only by a complete new one.
  bytes_file("k.vtu", "old vtu");
  expect_error<InvalidInput>([&] { write_vtu(file("k.vtu"), m.xyz, std::vector<vid_t>{0, 1, 2, -1}); }, {"k.vtu"});
  EXPECT_EQ(slurp(file("k.vtu")), "old vtu");
  write_vtu(file("k.vtu"), m.xyz, m.tets);
  EXPECT_NE(slurp(file("k.vtu")), "old vtu");
  EXPECT_EQ(listing(), (std::vector<std::string>{"k.vtu", "s.ele", "s.neigh", "s.node"}));
}

}  // namespace
}  // namespace gdel::io
