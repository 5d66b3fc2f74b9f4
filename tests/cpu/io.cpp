// Tests of the point readers and the TetGen/xyz/off/ply writers (src/io).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/expect_error.hpp"
#include "gdel/errors.hpp"
#include "gen/generators.hpp"
#include "io/io.hpp"

namespace gdel::io {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("gdel_io_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path file(const std::string& name) const { return dir_ / name; }

  fs::path text(const std::string& name, const std::string& content) const {
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

  // Every file name in the test directory, sorted.
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

// Doubles that stress the round trip: tiny, huge, subnormal, negative zero, ...
std::vector<double> tricky_points() {
  return {0.1,
          -0.0,
          1e-300,
          std::numeric_limits<double>::denorm_min(),
          std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::min(),
          1.0 / 3.0,
          123456789.123456789,
          -2.5e-17,
          std::nextafter(1.0, 2.0),
          std::nextafter(1.0, 0.0),
          0.30000000000000004};
}

// Little helper to build binary PLY bodies in either byte order.
class Bytes {
 public:
  explicit Bytes(bool big_endian) : big_(big_endian) {}
  template <class T>
  Bytes& put(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_ == (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof(T));
    s_.append(reinterpret_cast<const char*>(b), sizeof(T));
    return *this;
  }
  const std::string& str() const { return s_; }

 private:
  bool big_;
  std::string s_;
};

// ---------------------------------------------------------------------------------------
// .xyz / .txt
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, XyzBasicSeparatorsCommentsAndBlankLines) {
  const auto p = text("a.xyz",
                      "# header comment\n"
                      "\n"
                      "1 2 3\n"
                      "  4.5\t5e1   -6  # trailing comment\r\n"
                      "7,8,9\n"
                      "10 , 11 ,12\n"
                      "   \n"
                      "+1.25 -0 .5");  // no final newline
  const PointSet ps = read_points(p);
  EXPECT_FALSE(ps.has_weights());
  EXPECT_EQ(ps.xyz, (std::vector<double>{1, 2, 3, 4.5, 50, -6, 7, 8, 9, 10, 11, 12, 1.25, -0.0, 0.5}));
  EXPECT_TRUE(std::signbit(ps.xyz[13]));
  EXPECT_EQ(ps.size(), 5u);
}

TEST_F(IoTest, XyzWeightsAndNonFiniteKept) {
  const auto p = text("w.txt", "0 0 0 1\n1 0 0 0.5\nnan inf -inf 2\n");
  const PointSet ps = read_points(p);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(ps.weights, (std::vector<double>{1, 0.5, 2}));
  EXPECT_TRUE(std::isnan(ps.xyz[6]));
  EXPECT_EQ(ps.xyz[7], INFINITY);
  EXPECT_EQ(ps.xyz[8], -INFINITY);
}

TEST_F(IoTest, XyzEmptyFileHasNoPoints) {
  EXPECT_EQ(read_points(text("e.xyz", "")).size(), 0u);
  EXPECT_EQ(read_points(text("c.xyz", "# only a comment\n\n")).size(), 0u);
}

TEST_F(IoTest, XyzRoundTrip) {
  auto xyz = gen::uniform(5000, 1);
  auto tricky = tricky_points();
  xyz.insert(xyz.end(), tricky.begin(), tricky.end());
  const auto w = gen::weights(xyz.size() / 3, 2, 3.0);
  write_xyz(file("r.xyz"), xyz);
  EXPECT_TRUE(same_bits(read_points(file("r.xyz")).xyz, xyz));
  write_xyz(file("rw.XYZ"), xyz, w);  // extension matched case-insensitively
  const PointSet ps = read_points(file("rw.XYZ"));
  EXPECT_TRUE(same_bits(ps.xyz, xyz));
  EXPECT_TRUE(same_bits(ps.weights, w));
}

TEST_F(IoTest, XyzMalformed) {
  expect_error<InvalidInput>([&] { read_xyz(text("a.xyz", "1 2 3\n4 5 6 7\n")); },
                             {"a.xyz:2:", "4 columns", "line 1", "has 3"});
  expect_error<InvalidInput>([&] { read_xyz(text("b.xyz", "# c\n1 2 3 4\n\n1 2 3\n")); }, {"b.xyz:4:", "line 2"});
  expect_error<InvalidInput>([&] { read_xyz(text("c.xyz", "1 2\n")); }, {"c.xyz:1:", "got 2"});
  expect_error<InvalidInput>([&] { read_xyz(text("d.xyz", "1 2 3 4 5\n")); }, {"d.xyz:1:", "got 5"});
  expect_error<InvalidInput>([&] { read_xyz(text("e.xyz", "1 2 3\n1 2.0abc 3\n")); },
                             {"e.xyz:2:", "y", "'2.0abc'", "not a valid number"});
  expect_error<InvalidInput>([&] { read_xyz(text("f.xyz", "1,,2,3\n")); }, {"f.xyz:1:", "empty field"});
  expect_error<InvalidInput>([&] { read_xyz(text("g.xyz", "1,2,3,\n")); }, {"g.xyz:1:", "trailing comma"});
  expect_error<InvalidInput>([&] { read_xyz(text("h.xyz", ",1,2,3\n")); }, {"h.xyz:1:", "leading comma"});
  expect_error<InvalidInput>([&] { read_xyz(text("i.xyz", "1 +-2 3\n")); }, {"i.xyz:1:", "'+-2'"});
  expect_error<InvalidInput>([&] { read_xyz(text("j.xyz", "1 1e999 3\n")); }, {"j.xyz:1:", "'1e999'"});
  expect_error<InvalidInput>([&] { read_xyz(text("k.xyz", "1 2 3 w\n")); }, {"k.xyz:1:", "weight"});
  expect_error<InvalidInput>([&] { read_xyz(text("l.xyz", "1 2 \x01\n")); }, {"l.xyz:1:", "\\x01"});
}

// ---------------------------------------------------------------------------------------
// .off
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, OffBasic) {
  const auto p = text("a.off",
                      "OFF\n"
                      "# a comment\n"
                      "4 2 0\n"
                      "0 0 0\n"
                      "1 0 0  # x axis\n"
                      "\n"
                      "0 1 0\n"
                      "0 0 1.5\n"
                      "3 0 1 2\n"
                      "3 0 1 3 255 0 0\n");
  const PointSet ps = read_points(p);
  EXPECT_EQ(ps.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.5}));
  EXPECT_FALSE(ps.has_weights());
  // Counts on the keyword line, two counts only, CRLF.
  EXPECT_EQ(read_points(text("b.OFF", "OFF 2 0 0\r\n1 2 3\r\n4 5 6\r\n")).xyz, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(read_off(text("c.off", "OFF\n1 0\n1 2 3\n")).xyz, (std::vector<double>{1, 2, 3}));
  // Variants with per-vertex extras (colours, normals): extras ignored.
  EXPECT_EQ(read_off(text("d.off", "COFF\n2 0 0\n1 2 3 255 0 0 255\n4 5 6 0 255 0 255\n")).xyz,
            (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(read_off(text("e.off", "CNOFF\n1 0 0\n1 2 3 0 0 1 9 9 9 9\n")).xyz, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(read_off(text("f.off", "OFF\n0 0 0\n")).size(), 0u);
}

TEST_F(IoTest, OffRoundTrip) {
  auto xyz = gen::ball(3000, 4);
  auto tricky = tricky_points();
  xyz.insert(xyz.end(), tricky.begin(), tricky.end());
  write_off(file("r.off"), xyz);
  EXPECT_TRUE(same_bits(read_points(file("r.off")).xyz, xyz));
}

TEST_F(IoTest, OffMalformed) {
  expect_error<InvalidInput>([&] { read_off(text("a.off", "")); }, {"a.off", "empty file"});
  expect_error<InvalidInput>([&] { read_off(text("b.off", "PLY\n1 0 0\n1 2 3\n")); },
                             {"b.off:1:", "keyword OFF", "'PLY'"});
  expect_error<InvalidInput>([&] { read_off(text("c.off", "OFF\n3 0 0\n1 2 3\n4 5 6\n")); },
                             {"c.off", "announces 3 vertices", "ends after 2"});
  expect_error<InvalidInput>([&] { read_off(text("d.off", "OFF\n1 0 0\n1 2 3 4\n")); },
                             {"d.off:3:", "vertex 0", "got 4"});
  expect_error<InvalidInput>([&] { read_off(text("e.off", "OFF\n1 0 0\n1 2\n")); }, {"e.off:3:", "got 2"});
  expect_error<InvalidInput>([&] { read_off(text("f.off", "OFF\n-1 0 0\n")); }, {"f.off:2:", "vertex count", "'-1'"});
  expect_error<InvalidInput>([&] { read_off(text("g.off", "OFF\nx 0 0\n")); }, {"g.off:2:", "'x'"});
  expect_error<InvalidInput>([&] { read_off(text("h.off", "OFF\n1\n")); }, {"h.off:2:", "counts"});
  expect_error<InvalidInput>([&] { read_off(text("i.off", "4OFF\n1 0 0\n1 2 3 4\n")); }, {"i.off:1:", "3-dimensional"});
  expect_error<InvalidInput>([&] { read_off(text("j.off", "OFF BINARY\n")); }, {"j.off:1:", "binary OFF"});
  expect_error<InvalidInput>([&] { read_off(text("k.off", "XOFF\n1 0 0\n1 2 3\n")); },
                             {"k.off:1:", "unknown OFF variant"});
  expect_error<InvalidInput>([&] { read_off(text("l.off", "OFF\n1 0 0\n1 zz 3\n")); }, {"l.off:3:", "'zz'"});
  expect_error<InvalidInput>([&] { read_off(text("m.off", "OFF\n")); }, {"m.off", "counts"});
}

// ---------------------------------------------------------------------------------------
// .ply
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, PlyAsciiWithOtherElementsAndProperties) {
  const auto p = text("a.ply",
                      "ply\n"
                      "format ascii 1.0\n"
                      "comment made by hand\n"
                      "obj_info nothing\n"
                      "element camera 2\n"
                      "property float view\n"
                      "property list uchar int ids\n"
                      "element vertex 3\n"
                      "property uchar red\n"
                      "property float x\n"
                      "property list ushort float normals\n"
                      "property double y\n"
                      "property int z\n"
                      "property float weight\n"
                      "element face 1\n"
                      "property list uchar int vertex_indices\n"
                      "end_header\n"
                      "1.5 3 1 2 3\n"
                      "2.5 0\n"
                      "255 0.5 2 1 1 1.25 -7 0.125\n"
                      "0 1e3 0 -2.5 2147483647 2\n"
                      "7 nan 1 9 inf -5 -1\n"
                      "3 0 1 2\n");
  const PointSet ps = read_points(p);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(ps.xyz[0], 0.5);
  EXPECT_EQ(ps.xyz[1], 1.25);
  EXPECT_EQ(ps.xyz[2], -7);
  EXPECT_EQ(ps.xyz[3], 1000);
  EXPECT_EQ(ps.xyz[4], -2.5);
  EXPECT_EQ(ps.xyz[5], 2147483647.0);
  EXPECT_TRUE(std::isnan(ps.xyz[6]));
  EXPECT_EQ(ps.xyz[7], INFINITY);
  EXPECT_EQ(ps.xyz[8], -5);
  EXPECT_EQ(ps.weights, (std::vector<double>{0.125, 2, -1}));
}

TEST_F(IoTest, PlyCrlfHeaderAndCountsOnly) {
  const auto p = text("crlf.ply",
                      "ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty double x\r\n"
                      "property double y\r\nproperty double z\r\nend_header\r\n1 2 3\r\n4 5 6\r\n");
  EXPECT_EQ(read_points(p).xyz, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  const auto q = text("zero.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n");
  EXPECT_EQ(read_points(q).size(), 0u);
}

// Builds a binary PLY with a leading element, vertex properties of many types, and faces.
std::string binary_ply(bool big, const std::vector<std::array<double, 3>>& pts) {
  std::string h = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\n"
                  "comment all the types\n"
                  "element material 2\n"
                  "property uint8 id\n"
                  "property list uint8 int16 stuff\n"
                  "property double shininess\n"
                  "element vertex " +
                  std::to_string(pts.size()) +
                  "\n"
                  "property char a\n"
                  "property float x\n"
                  "property short b\n"
                  "property double y\n"
                  "property list int uint c\n"
                  "property int z\n"
                  "property ushort d\n"
                  "property uint e\n"
                  "property float32 f\n"
                  "property int8 g\n"
                  "property float64 weight\n"
                  "element face 1\n"
                  "property list uchar int vertex_indices\n"
                  "end_header\n";
  Bytes b(big);
  b.put<std::uint8_t>(1).put<std::uint8_t>(2).put<std::int16_t>(-3).put<std::int16_t>(4).put<double>(0.5);
  b.put<std::uint8_t>(2).put<std::uint8_t>(0).put<double>(1.5);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    b.put<std::int8_t>(-1);
    b.put<float>(static_cast<float>(pts[i][0]));
    b.put<std::int16_t>(-300);
    b.put<double>(pts[i][1]);
    b.put<std::int32_t>(static_cast<std::int32_t>(i % 3));
    for (std::size_t k = 0; k < i % 3; ++k) b.put<std::uint32_t>(0xDEADBEEF);
    b.put<std::int32_t>(static_cast<std::int32_t>(pts[i][2]));
    b.put<std::uint16_t>(65535);
    b.put<std::uint32_t>(4000000000u);
    b.put<float>(3.25f);
    b.put<std::int8_t>(7);
    b.put<double>(static_cast<double>(i) * 0.25);
  }
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  return h + b.str();
}

TEST_F(IoTest, PlyBinaryBothEndiannessesAllTypes) {
  const std::vector<std::array<double, 3>> pts = {
      {0.5, 0.1, -7}, {1e30, -2.5, 2147483647}, {-0.0, 1e-300, -2147483647 - 1}, {3.0, 4.0, 5}};
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big endian" : "little endian");
    const auto p = text(big ? "be.ply" : "le.ply", binary_ply(big, pts));
    const PointSet ps = read_points(p);
    ASSERT_EQ(ps.size(), pts.size());
    ASSERT_EQ(ps.weights.size(), pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      EXPECT_EQ(ps.xyz[3 * i], static_cast<double>(static_cast<float>(pts[i][0])));
      EXPECT_EQ(ps.xyz[3 * i + 1], pts[i][1]);
      EXPECT_EQ(ps.xyz[3 * i + 2], pts[i][2]);
      EXPECT_EQ(ps.weights[i], static_cast<double>(i) * 0.25);
    }
    EXPECT_TRUE(std::signbit(ps.xyz[6]));
  }
}

TEST_F(IoTest, PlyIntegerAndFloatCoordinateTypes) {
  // x, y, z of every scalar type, in both byte orders.
  struct T {
    const char* name;
    std::function<void(Bytes&, int)> put;
  };
  const T types[] = {
      {"char", [](Bytes& b, int v) { b.put<std::int8_t>(static_cast<std::int8_t>(-v)); }},
      {"uchar", [](Bytes& b, int v) { b.put<std::uint8_t>(static_cast<std::uint8_t>(200 + v)); }},
      {"short", [](Bytes& b, int v) { b.put<std::int16_t>(static_cast<std::int16_t>(-30000 + v)); }},
      {"ushort", [](Bytes& b, int v) { b.put<std::uint16_t>(static_cast<std::uint16_t>(60000 + v)); }},
      {"int", [](Bytes& b, int v) { b.put<std::int32_t>(-2000000000 + v); }},
      {"uint", [](Bytes& b, int v) { b.put<std::uint32_t>(4000000000u + static_cast<unsigned>(v)); }},
      {"float", [](Bytes& b, int v) { b.put<float>(0.25f + static_cast<float>(v)); }},
      {"double", [](Bytes& b, int v) { b.put<double>(0.1 + v); }},
  };
  const double expected[][3] = {{-0.0, -1, -2},        {200, 201, 202},
                                {-30000, -29999, -29998}, {60000, 60001, 60002},
                                {-2000000000, -1999999999, -1999999998},
                                {4000000000.0, 4000000001.0, 4000000002.0},
                                {0.25, 1.25, 2.25},    {0.1, 1.1, 2.1}};
  for (bool big : {false, true}) {
    for (std::size_t t = 0; t < std::size(types); ++t) {
      SCOPED_TRACE(std::string(types[t].name) + (big ? " big" : " little"));
      std::string h = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 1\n";
      for (const char* c : {"x", "y", "z"}) h += std::string("property ") + types[t].name + " " + c + "\n";
      h += "end_header\n";
      Bytes b(big);
      for (int k = 0; k < 3; ++k) types[t].put(b, k);
      const PointSet ps = read_ply(text("t.ply", h + b.str()));
      ASSERT_EQ(ps.size(), 1u);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(ps.xyz[k], expected[t][k]) << k;
      EXPECT_FALSE(ps.has_weights());
    }
  }
}

TEST_F(IoTest, PlyRoundTripAllFormats) {
  auto xyz = gen::gaussian(4000, 6);
  auto tricky = tricky_points();
  xyz.insert(xyz.end(), tricky.begin(), tricky.end());
  const auto w = gen::weights(xyz.size() / 3, 7, 10.0);
  for (PlyFormat f : {PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
    SCOPED_TRACE(static_cast<int>(f));
    write_ply(file("r.ply"), xyz, {}, f);
    PointSet ps = read_points(file("r.ply"));
    EXPECT_TRUE(same_bits(ps.xyz, xyz));
    EXPECT_FALSE(ps.has_weights());
    write_ply(file("rw.Ply"), xyz, w, f);
    ps = read_points(file("rw.Ply"));
    EXPECT_TRUE(same_bits(ps.xyz, xyz));
    EXPECT_TRUE(same_bits(ps.weights, w));
  }
  write_ply(file("empty.ply"), {});
  EXPECT_EQ(read_points(file("empty.ply")).size(), 0u);
}

TEST_F(IoTest, PlyMalformedHeader) {
  const std::string ok_tail = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
  expect_error<InvalidInput>([&] { read_ply(text("a.ply", "")); }, {"a.ply", "not a PLY file"});
  expect_error<InvalidInput>([&] { read_ply(text("b.ply", "OFF\n")); }, {"b.ply", "not a PLY file"});
  expect_error<InvalidInput>(
      [&] { read_ply(text("c.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n")); },
      {"c.ply", "end_header"});
  expect_error<InvalidInput>([&] { read_ply(text("d.ply", "ply\n" + ok_tail)); }, {"d.ply", "no 'format'"});
  expect_error<InvalidInput>([&] { read_ply(text("e.ply", "ply\nformat binary_middle_endian 1.0\n" + ok_tail)); },
                             {"e.ply:2:", "unsupported PLY format", "binary_middle_endian"});
  expect_error<InvalidInput>([&] { read_ply(text("f.ply", "ply\nformat ascii 2.0\n" + ok_tail)); },
                             {"f.ply:2:", "version"});
  expect_error<InvalidInput>(
      [&] { read_ply(text("g.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n")); },
      {"g.ply:4:", "unsupported property type", "float128"});
  expect_error<InvalidInput>([&] { read_ply(text("h.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n")); },
                             {"h.ply:3:", "property before any element"});
  expect_error<InvalidInput>(
      [&] {
        read_ply(text("i.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int v\nend_header\n3 0 1 2\n"));
      },
      {"i.ply", "no 'element vertex'"});
  expect_error<InvalidInput>(
      [&] {
        read_ply(text("j.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float red\nend_header\n1 2 3\n"));
      },
      {"j.ply", "no property 'z'", "x, y, red"});
  expect_error<InvalidInput>(
      [&] {
        read_ply(text("k.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\n"
                               "property float y\nproperty float z\nend_header\n1 1 2 3\n"));
      },
      {"k.ply", "'x' must be a scalar"});
  expect_error<InvalidInput>(
      [&] {
        read_ply(text("l.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int q\n" + ok_tail.substr(17)));
      },
      {"l.ply:4:", "count type must be an integer"});
  expect_error<InvalidInput>([&] { read_ply(text("m.ply", "ply\nformat ascii 1.0\nelement vertex x\n")); },
                             {"m.ply:3:", "bad count"});
  expect_error<InvalidInput>([&] { read_ply(text("n.ply", "ply\nformat ascii 1.0\nelephant vertex 1\n")); },
                             {"n.ply:3:", "unknown PLY header keyword", "elephant"});
}

TEST_F(IoTest, PlyMalformedAsciiBody) {
  const std::string h = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                        "property float z\nproperty uchar red\nend_header\n";
  EXPECT_EQ(read_ply(text("ok.ply", h + "1 2 3 4\n5 6 7 255\n")).size(), 2u);
  expect_error<InvalidInput>([&] { read_ply(text("a.ply", h + "1 2 3 4\n5 6\n")); },
                             {"a.ply", "ends in element 'vertex' record 1", "property 'z'"});
  expect_error<InvalidInput>([&] { read_ply(text("b.ply", h + "1 2 3 4\n5 six 7 8\n")); },
                             {"b.ply:10:", "record 1", "'y'", "'six'"});
  expect_error<InvalidInput>([&] { read_ply(text("c.ply", h + "1 2 3 4\n5 6 7 256\n")); },
                             {"c.ply:10:", "'256'", "uint8"});
  expect_error<InvalidInput>([&] { read_ply(text("d.ply", h + "1 2 3 4.5\n5 6 7 8\n")); },
                             {"d.ply:9:", "'4.5'", "uint8"});
  const std::string hl = "ply\nformat ascii 1.0\nelement vertex 1\nproperty list char int n\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n";
  expect_error<InvalidInput>([&] { read_ply(text("e.ply", hl + "-2 1 2 3\n")); }, {"e.ply:9:", "negative item count"});
  expect_error<InvalidInput>([&] { read_ply(text("f.ply", hl + "3 1 2\n")); },
                             {"f.ply", "ends in element 'vertex' record 0"});
}

TEST_F(IoTest, PlyTruncatedBinary) {
  const std::vector<std::array<double, 3>> pts = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  for (bool big : {false, true}) {
    const std::string full = binary_ply(big, pts);
    const std::size_t body = full.find("end_header\n") + 11;
    // Cut inside the leading element, inside the vertices, and right after the vertices
    // (the faces are not read, so that one is fine).
    expect_error<InvalidInput>([&] { read_ply(text("a.ply", full.substr(0, body + 5))); },
                               {"a.ply", "element 'material'", "truncated"});
    expect_error<InvalidInput>([&] { read_ply(text("b.ply", full.substr(0, full.size() - 20))); },
                               {"b.ply", "element 'vertex' record 2", "truncated"});
    EXPECT_EQ(read_ply(text("c.ply", full.substr(0, full.size() - 13))).size(), 3u);
  }
  // A vertex count far beyond the data fails cleanly without a giant allocation.
  const std::string h = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                        "property double x\nproperty double y\nproperty double z\nend_header\n";
  expect_error<InvalidInput>([&] { read_ply(text("d.ply", h + std::string(48, '\0'))); },
                             {"d.ply", "record 2", "truncated"});
  // Fixed-size elements before the vertices are skipped in one jump; check the bound.
  const std::string h2 = "ply\nformat binary_big_endian 1.0\nelement junk 1000000000000\nproperty double a\n"
                         "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  expect_error<InvalidInput>([&] { read_ply(text("e.ply", h2 + std::string(100, '\0'))); },
                             {"e.ply", "element 'junk' record 12"});
  // A list longer than the data.
  const std::string h3 = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty list uint uchar l\n"
                         "property float x\nproperty float y\nproperty float z\nend_header\n";
  expect_error<InvalidInput>(
      [&] { read_ply(text("f.ply", h3 + Bytes(false).put<std::uint32_t>(4000000000u).str() + "abcd")); },
      {"f.ply", "record 0", "truncated"});
}

// ---------------------------------------------------------------------------------------
// TetGen .node / .ele / .neigh
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, NodeReadVariants) {
  // 1-based ids, attributes (the first is the weight), boundary markers, comments.
  const auto p = text("a.node",
                      "# TetGen node file\n"
                      "3 3 2 1\n"
                      "1 0 0 0 0.5 9 1\n"
                      "2 1 0 0 0.25 9 0  # comment\n"
                      "\n"
                      "3 0 1 0 0 9 -3\n");
  const PointSet ps = read_points(p);
  EXPECT_EQ(ps.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(ps.weights, (std::vector<double>{0.5, 0.25, 0}));
  // Minimal header, 0-based, no attributes.
  const PointSet q = read_node(text("b.node", "2 3\n0 1 2 3\n1 4 5 6\n"));
  EXPECT_EQ(q.xyz, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_FALSE(q.has_weights());
  EXPECT_EQ(read_node(text("c.node", "0 3 0 0\n")).size(), 0u);
}

TEST_F(IoTest, NodeRoundTrip) {
  auto xyz = gen::thin_shell(3000, 8);
  auto tricky = tricky_points();
  xyz.insert(xyz.end(), tricky.begin(), tricky.end());
  const auto w = gen::weights(xyz.size() / 3, 9, 1e-3);
  write_node(file("r.node"), xyz);
  PointSet ps = read_points(file("r.node"));
  EXPECT_TRUE(same_bits(ps.xyz, xyz));
  EXPECT_FALSE(ps.has_weights());
  write_node(file("rw.node"), xyz, w);
  ps = read_points(file("rw.node"));
  EXPECT_TRUE(same_bits(ps.xyz, xyz));
  EXPECT_TRUE(same_bits(ps.weights, w));
  // The exact text of a small file.
  write_node(file("s.node"), std::vector<double>{0.1, 2, -3e-5, 1, 1, 1}, std::vector<double>{0.5, 0});
  EXPECT_EQ(slurp(file("s.node")), "2 3 1 0\n0 0.1 2 -3e-05 0.5\n1 1 1 1 0\n");
}

TEST_F(IoTest, NodeMalformed) {
  expect_error<InvalidInput>([&] { read_node(text("a.node", "")); }, {"a.node", "empty file"});
  expect_error<InvalidInput>([&] { read_node(text("b.node", "2 2 0 0\n")); }, {"b.node:1:", "dimension must be 3"});
  expect_error<InvalidInput>([&] { read_node(text("c.node", "2 3 0 0\n0 0 0 0\n2 1 1 1\n")); },
                             {"c.node:3:", "consecutive", "expected 1, got 2"});
  expect_error<InvalidInput>([&] { read_node(text("d.node", "1 3 0 0\n5 0 0 0\n")); }, {"d.node:2:", "0 or 1"});
  expect_error<InvalidInput>([&] { read_node(text("e.node", "1 3 1 0\n0 0 0 0\n")); },
                             {"e.node:2:", "expected 5 values", "got 4"});
  expect_error<InvalidInput>([&] { read_node(text("f.node", "3 3 0 0\n0 0 0 0\n1 1 1 1\n")); },
                             {"f.node", "announces 3 points", "ends after 2"});
  expect_error<InvalidInput>([&] { read_node(text("g.node", "1 3 0 2\n")); }, {"g.node:1:", "boundary marker flag"});
  expect_error<InvalidInput>([&] { read_node(text("h.node", "1 3 0 1\n0 0 0 0 0.5\n")); },
                             {"h.node:2:", "boundary marker", "'0.5'"});
  expect_error<InvalidInput>([&] { read_node(text("i.node", "1\n")); }, {"i.node:1:", "header"});
  expect_error<InvalidInput>([&] { read_node(text("j.node", "1 3\n0 0 0 q\n")); }, {"j.node:2:", "z", "'q'"});
  expect_error<InvalidInput>([&] { read_node(text("k.node", "1.5 3\n")); }, {"k.node:1:", "point count"});
}

TEST_F(IoTest, TetgenRoundTrip) {
  const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<vid_t> tets = {0, 1, 2, 3, 1, 2, 3, 4};
  const std::vector<tid_t> neigh = {1, -1, -1, -1, -1, -1, -1, 0};
  write_tetgen(file("mesh"), xyz, tets, neigh);
  EXPECT_EQ(listing(), (std::vector<std::string>{"mesh.ele", "mesh.neigh", "mesh.node"}));
  EXPECT_EQ(read_points(file("mesh.node")).xyz, xyz);
  EXPECT_EQ(read_ele(file("mesh.ele")), tets);
  EXPECT_EQ(read_neigh(file("mesh.neigh")), neigh);
  EXPECT_EQ(slurp(file("mesh.ele")), "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n");
  EXPECT_EQ(slurp(file("mesh.neigh")), "2 4\n0 1 -1 -1 -1\n1 -1 -1 -1 0\n");
  // Without neighbours no .neigh is written.
  write_tetgen(file("m2"), xyz, tets, {});
  EXPECT_FALSE(fs::exists(file("m2.neigh")));
  // Large enough to need several buffer flushes.
  const std::size_t m = 300000;
  std::vector<vid_t> big_tets(4 * m);
  std::vector<tid_t> big_neigh(4 * m);
  for (std::size_t i = 0; i < 4 * m; ++i) {
    big_tets[i] = static_cast<vid_t>((i * 7919) % 5);
    big_neigh[i] = static_cast<tid_t>((i * 104729) % (m + 1)) - 1;
  }
  write_tetgen(file("big"), xyz, big_tets, big_neigh);
  EXPECT_EQ(read_ele(file("big.ele")), big_tets);
  EXPECT_EQ(read_neigh(file("big.neigh")), big_neigh);
}

TEST_F(IoTest, EleNeighOneBasedAndMalformed) {
  EXPECT_EQ(read_ele(text("a.ele", "# c\n2 4 1\n1 1 2 3 4 0.5\n2 2 3 4 5 7\n")), (std::vector<vid_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(read_neigh(text("a.neigh", "2 4\n1 2 -1 -1 -1\n2 -1 1 -1 -1\n")),
            (std::vector<tid_t>{1, -1, -1, -1, -1, 0, -1, -1}));
  expect_error<InvalidInput>([&] { read_ele(text("b.ele", "1 10 0\n")); }, {"b.ele:1:", "only 4 nodes"});
  expect_error<InvalidInput>([&] { read_ele(text("c.ele", "1 4 0\n1 0 1 2 3\n")); },
                             {"c.ele:2:", "vertex id 0", "1-based"});
  expect_error<InvalidInput>([&] { read_ele(text("d.ele", "2 4 0\n0 0 1 2 3\n")); },
                             {"d.ele", "announces 2 tetrahedra", "ends after 1"});
  expect_error<InvalidInput>([&] { read_ele(text("e.ele", "1 4 0\n0 0 1 2\n")); }, {"e.ele:2:", "expected 5 values"});
  expect_error<InvalidInput>([&] { read_ele(text("f.ele", "1 4 0\n0 0 1 2 99999999999\n")); },
                             {"f.ele:2:", "out of range"});
  expect_error<InvalidInput>([&] { read_neigh(text("b.neigh", "1 4\n0 1 -1 -1 -1\n")); },
                             {"b.neigh:2:", "neighbour 1"});
  expect_error<InvalidInput>([&] { read_neigh(text("c.neigh", "1 4\n1 0 -1 -1 -1\n")); },
                             {"c.neigh:2:", "neighbour 0"});
  expect_error<InvalidInput>([&] { read_neigh(text("d.neigh", "1 3\n")); }, {"d.neigh:1:", "expected 4 neighbours"});
  expect_error<InvalidInput>([&] { read_neigh(text("e.neigh", "1 4\n0 -2 -1 -1 -1\n")); },
                             {"e.neigh:2:", "neighbour -2"});
}

// ---------------------------------------------------------------------------------------
// Dispatch and file-level errors
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, DispatchAndFileErrors) {
  text("p.foo", "1 2 3\n");
  expect_error<InvalidInput>([&] { read_points(file("p.foo")); },
                             {"p.foo", "unknown point file extension", "'.foo'", ".ply"});
  text("noext", "1 2 3\n");
  expect_error<InvalidInput>([&] { read_points(file("noext")); }, {"noext", "(none)"});
  expect_error<InvalidInput>([&] { read_points(file("missing.xyz")); }, {"cannot read", "missing.xyz", "No such file"});
  expect_error<InvalidInput>([&] { read_ply(file("missing.ply")); }, {"missing.ply", "No such file"});
  fs::create_directories(file("adir.xyz"));
  expect_error<InvalidInput>([&] { read_points(file("adir.xyz")); }, {"adir.xyz", "directory"});
  // A .node extension with uppercase letters dispatches too.
  text("q.NoDe", "1 3\n0 1 2 3\n");
  EXPECT_EQ(read_points(file("q.NoDe")).xyz, (std::vector<double>{1, 2, 3}));
}

// ---------------------------------------------------------------------------------------
// Writers: argument checks and atomic replacement
// ---------------------------------------------------------------------------------------

TEST_F(IoTest, WriterArgumentChecks) {
  const std::vector<double> xyz = {0, 0, 0, 1, 1, 1};
  expect_error<InvalidInput>(
      [&] {
        write_node(file("a.node"), std::vector<double>{1, 2});
      },
      {"a.node", "multiple of 3"});
  expect_error<InvalidInput>([&] { write_xyz(file("b.xyz"), xyz, std::vector<double>{1}); },
                             {"b.xyz", "1 weights for 2 points"});
  expect_error<InvalidInput>(
      [&] {
        write_ply(file("c.ply"), std::vector<double>{0, NAN, 0});
      },
      {"c.ply", "point 0", "non-finite"});
  expect_error<InvalidInput>(
      [&] {
        write_node(file("d.node"), xyz, std::vector<double>{0, INFINITY});
      },
      {"d.node", "point 1", "non-finite weight"});
  expect_error<InvalidInput>(
      [&] {
        write_ele(file("e.ele"), std::vector<vid_t>{0, 1, 2});
      },
      {"e.ele", "multiple of 4"});
  expect_error<InvalidInput>(
      [&] {
        write_ele(file("f.ele"), std::vector<vid_t>{0, 1, 2, -3});
      },
      {"f.ele", "tetrahedron 0", "-3"});
  expect_error<InvalidInput>(
      [&] {
        write_ele(file("g.ele"), std::vector<vid_t>{0, 1, 2, 3}, 3);
      },
      {"g.ele", "vertex id 3"});
  expect_error<InvalidInput>(
      [&] {
        write_neigh(file("h.neigh"), std::vector<tid_t>{0, 1, -1, -1});
      },
      {"h.neigh", "neighbour 1"});
  expect_error<InvalidInput>(
      [&] {
        write_neigh(file("i.neigh"), std::vector<tid_t>{-2, -1, -1, -1});
      },
      {"i.neigh", "neighbour -2"});
  expect_error<InvalidInput>(
      [&] {
        write_tetgen(file("j"), xyz, std::vector<vid_t>{0, 1, 2, 3}, {});
      },
      {"j.ele", "vertex id 2"});
  expect_error<InvalidInput>(
      [&] {
        write_tetgen(file("k"), std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, std::vector<vid_t>{0, 1, 2, 3},
                     std::vector<tid_t>{-1, -1});
      },
      {"k.neigh", "multiple of 4"});
  // Nothing was created by the failed writers, not even temporary files.
  EXPECT_TRUE(listing().empty()) << listing().front();
}

TEST_F(IoTest, FailedWriterLeavesExistingFileIntact) {
  // Existing files with known content.
  const std::string old_node = "1 3 0 0\n0 7 7 7\n";
  const std::string old_ele = "1 4 0\n0 0 0 0 0\n";
  text("keep.node", old_node);
  text("keep.ele", old_ele);
  // A write that fails late: more than one buffer (1 MiB) has been flushed to the temporary
  // file when the bad value is met.
  const std::size_t n = 200000;
  std::vector<double> xyz = gen::uniform(n, 3);
  xyz[3 * (n - 1) + 1] = NAN;
  expect_error<InvalidInput>([&] { write_node(file("keep.node"), xyz); }, {"keep.node", "point 199999", "non-finite"});
  std::vector<vid_t> tets(4 * n, 1);
  tets[4 * (n - 1) + 2] = -1;
  expect_error<InvalidInput>([&] { write_ele(file("keep.ele"), tets); }, {"keep.ele", "tetrahedron 199999"});
  // write_tetgen validates up front: nothing of the set changes.
  text("set.node", old_node);
  expect_error<InvalidInput>(
      [&] {
        write_tetgen(file("set"), xyz, std::vector<vid_t>{0, 1, 2, 3}, {});
      },
      {"set.node", "non-finite"});
  EXPECT_EQ(slurp(file("keep.node")), old_node);
  EXPECT_EQ(slurp(file("keep.ele")), old_ele);
  EXPECT_EQ(slurp(file("set.node")), old_node);
  EXPECT_EQ(listing(), (std::vector<std::string>{"keep.ele", "keep.node", "set.node"}));
  // A successful write replaces the file.
  xyz[3 * (n - 1) + 1] = 0.5;
  write_node(file("keep.node"), xyz);
  EXPECT_TRUE(same_bits(read_points(file("keep.node")).xyz, xyz));
  EXPECT_EQ(listing(), (std::vector<std::string>{"keep.ele", "keep.node", "set.node"}));
}

TEST_F(IoTest, WriterFileSystemErrors) {
  // Missing directory: gdel::Error naming the target and the reason; nothing created.
  expect_error<Error>([&] { write_xyz(file("no/such/dir/p.xyz"), std::vector<double>{1, 2, 3}); },
                      {"p.xyz", "No such file or directory"});
  // Target is an existing directory: the rename fails, the directory survives, no temp left.
  fs::create_directories(file("d.xyz"));
  EXPECT_THROW(write_xyz(file("d.xyz"), std::vector<double>{1, 2, 3}), Error);
  EXPECT_TRUE(fs::is_directory(file("d.xyz")));
  EXPECT_EQ(listing(), (std::vector<std::string>{"d.xyz"}));
  // A path naming no file.
  EXPECT_THROW(write_xyz(dir_ / "", std::vector<double>{1, 2, 3}), Error);
}

}  // namespace
}  // namespace gdel::io
