// NumPy .npy reader (read_npy, the .npy branch of read_weights) and header builder.
#include <bit>
#include <cstring>
#include <limits>
#include <string>

#include "gdel/errors.hpp"
#include "io/io.hpp"
#include "io/npy.hpp"
#include "io/parse.hpp"

namespace gdel::io {
namespace detail {
namespace {

constexpr std::string_view kMagic = "\x93NUMPY";

// ---------------------------------------------------------------------------------------
// The header: a Python dict literal
// ---------------------------------------------------------------------------------------

struct Header {
  bool has_descr = false, has_order = false, has_shape = false;
  std::string descr;
  bool fortran = false;
  std::vector<std::uint64_t> shape;
};

class DictParser {
 public:
  DictParser(std::string_view text, const std::filesystem::path& path) : s_(text), path_(path) {}

  Header parse() {
    Header h;
    ws();
    expect('{', "the header must be a Python dict starting with '{'");
    ws();
    while (!at('}')) {
      const std::string key = string_literal("a quoted key");
      ws();
      expect(':', "expected ':' after the key " + show(key));
      ws();
      if (key == "descr") {
        if (h.has_descr) fail("the key 'descr' appears twice");
        h.has_descr = true;
        if (at('[')) fail("structured dtypes (a list of fields in 'descr') are not supported; save a plain (n, 3) array");
        h.descr = string_literal("'descr' to be a dtype string such as '<f8'");
      } else if (key == "fortran_order") {
        if (h.has_order) fail("the key 'fortran_order' appears twice");
        h.has_order = true;
        h.fortran = boolean();
      } else if (key == "shape") {
        if (h.has_shape) fail("the key 'shape' appears twice");
        h.has_shape = true;
        h.shape = tuple();
      } else {
        fail("unexpected key " + show(key) + " (a .npy header has exactly 'descr', 'fortran_order' and 'shape')");
      }
      ws();
      if (at(',')) {
        ++pos_;
        ws();
      } else if (!at('}')) {
        fail("expected ',' or '}' after the value of " + show(key));
      }
    }
    ++pos_;  // '}'
    ws();
    if (pos_ != s_.size()) fail("unexpected text after the header dict: " + show(s_.substr(pos_)));
    if (!h.has_descr || !h.has_order || !h.has_shape) {
      fail(std::string("the header lacks the key '") + (!h.has_descr ? "descr" : !h.has_order ? "fortran_order" : "shape") +
           "'");
    }
    return h;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { fail_in_file(path_, "invalid .npy header: " + what); }

  bool at(char c) const { return pos_ < s_.size() && s_[pos_] == c; }
  void ws() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) ++pos_;
  }
  void expect(char c, const std::string& what) {
    if (!at(c)) fail(what);
    ++pos_;
  }

  std::string string_literal(const std::string& what) {
    if (!at('\'') && !at('"')) fail("expected " + what);
    const char quote = s_[pos_++];
    const std::size_t start = pos_;
    while (pos_ < s_.size() && s_[pos_] != quote) {
      if (s_[pos_] == '\\') fail("escape sequences in strings are not supported");
      ++pos_;
    }
    if (pos_ == s_.size()) fail("unterminated string");
    return std::string(s_.substr(start, pos_++ - start));
  }

  bool boolean() {
    if (s_.substr(pos_, 4) == "True") {
      pos_ += 4;
      return true;
    }
    if (s_.substr(pos_, 5) == "False") {
      pos_ += 5;
      return false;
    }
    fail("'fortran_order' must be True or False");
  }

  std::vector<std::uint64_t> tuple() {
    expect('(', "'shape' must be a tuple such as (100, 3)");
    std::vector<std::uint64_t> dims;
    ws();
    while (!at(')')) {
      const std::size_t start = pos_;
      while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_;
      std::uint64_t d;
      if (!parse_int(s_.substr(start, pos_ - start), d)) fail("'shape' must hold non-negative integers");
      if (at('L') || at('l')) ++pos_;  // Python 2 long suffix, as old NumPy wrote it
      if (dims.size() >= 32) fail("'shape' has more than 32 dimensions");
      dims.push_back(d);
      ws();
      if (at(',')) {
        ++pos_;
        ws();
      } else if (!at(')')) {
        fail("expected ',' or ')' in 'shape'");
      }
    }
    ++pos_;
    return dims;
  }

  std::string_view s_;
  const std::filesystem::path& path_;
  std::size_t pos_ = 0;
};

// ---------------------------------------------------------------------------------------
// dtypes
// ---------------------------------------------------------------------------------------

enum class Kind { Float, Int, UInt };

struct DType {
  Kind kind;
  std::size_t size;
  bool swap;  // byte order differs from this machine's
};

[[noreturn]] void unsupported_dtype(const std::filesystem::path& path, const std::string& descr,
                                    const std::string& what) {
  fail_in_file(path, "dtype " + show(descr) + (what.empty() ? "" : " (" + what + ")") +
                         " is not supported; use float64, float32 or an integer type");
}

DType parse_descr(const std::filesystem::path& path, const std::string& descr) {
  std::string_view d = descr;
  char order = '=';
  if (!d.empty() && (d.front() == '<' || d.front() == '>' || d.front() == '|' || d.front() == '=')) {
    order = d.front();
    d.remove_prefix(1);
  }
  const auto unsupported = [&](const std::string& what) { unsupported_dtype(path, descr, what); };
  if (d.empty()) unsupported("");
  const char k = d.front();
  switch (k) {
    case 'b': unsupported_dtype(path, descr, "boolean");
    case 'c': unsupported_dtype(path, descr, "complex");
    case 'O': unsupported_dtype(path, descr, "Python objects");
    case 'U':
    case 'S':
    case 'a': unsupported_dtype(path, descr, "strings");
    case 'M':
    case 'm': unsupported_dtype(path, descr, "dates/times");
    case 'V': unsupported_dtype(path, descr, "raw bytes");
    default: break;
  }
  std::size_t size = 0;
  if (!parse_int(d.substr(1), size)) unsupported("");
  Kind kind = Kind::Float;
  switch (k) {
    case 'f':
      if (size != 4 && size != 8) unsupported(size == 2 ? "float16" : "extended precision");
      kind = Kind::Float;
      break;
    case 'i':
    case 'u':
      if (size != 1 && size != 2 && size != 4 && size != 8) unsupported("");
      kind = k == 'i' ? Kind::Int : Kind::UInt;
      break;
    default: unsupported_dtype(path, descr, "");
  }
  if (order == '|' && size != 1) fail_in_file(path, "dtype " + show(descr) + ": '|' (no byte order) is only valid for 1-byte types");
  const bool little_file = order == '<' || (order == '=' && std::endian::native == std::endian::little);
  const bool swap = size > 1 && order != '|' && little_file != (std::endian::native == std::endian::little);
  return {kind, size, swap};
}

template <class U>
U load(const char* p, bool swap) {
  U v;
  std::memcpy(&v, p, sizeof v);
  if (swap) {
    U r = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) r = static_cast<U>((r << 8) | ((v >> (8 * i)) & 0xFF));
    v = r;
  }
  return v;
}

// True when the integer with magnitude m converts to a double exactly.
bool exact_magnitude(std::uint64_t m) {
  if (m == 0) return true;
  const int width = 64 - std::countl_zero(m) - std::countr_zero(m);  // significant bits
  return width <= 53;
}

std::string shape_string(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    s += std::to_string(shape[i]);
    if (shape.size() == 1 || i + 1 < shape.size()) s += shape.size() == 1 ? "," : ", ";
  }
  return s + ")";
}

}  // namespace

NpyArray parse_npy(std::string_view bytes, const std::filesystem::path& path, NpyShape expected) {
  if (bytes.size() < 10 || bytes.substr(0, 6) != kMagic) {
    fail_in_file(path, "not a NumPy .npy file (it does not start with the magic bytes \\x93NUMPY)");
  }
  const auto major = static_cast<unsigned char>(bytes[6]);
  const auto minor = static_cast<unsigned char>(bytes[7]);
  if ((major != 1 && major != 2 && major != 3) || minor != 0) {
    fail_in_file(path, ".npy format version " + std::to_string(major) + "." + std::to_string(minor) +
                           " is not supported (1.0, 2.0 and 3.0 are)");
  }
  std::size_t header_len, header_start;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) | (std::size_t{static_cast<unsigned char>(bytes[9])} << 8);
    header_start = 10;
  } else {
    if (bytes.size() < 12) fail_in_file(path, "truncated .npy header");
    header_len = 0;
    for (int i = 3; i >= 0; --i) header_len = (header_len << 8) | static_cast<unsigned char>(bytes[8 + i]);
    header_start = 12;
  }
  if (header_len > bytes.size() - header_start) {
    fail_in_file(path, "truncated .npy header: it announces " + std::to_string(header_len) + " bytes but the file has " +
                           std::to_string(bytes.size() - header_start) + " after the length field");
  }
  const std::string_view text = bytes.substr(header_start, header_len);
  if (major < 3) {
    for (char c : text) {
      if (static_cast<unsigned char>(c) >= 0x80) fail_in_file(path, "invalid .npy header: non-ASCII byte (version 1.0/2.0)");
    }
  }
  const Header h = DictParser(text, path).parse();
  const DType dt = parse_descr(path, h.descr);

  // Shape.
  const auto& sh = h.shape;
  if (expected == NpyShape::Points) {
    if (sh.size() != 2 || (sh[1] != 3 && sh[1] != 4)) {
      fail_in_file(path, "array of shape " + shape_string(sh) +
                             "; expected (n, 3) points x y z or (n, 4) points with a weight column");
    }
  } else if (!(sh.size() == 1 || (sh.size() == 2 && sh[1] == 1))) {
    fail_in_file(path, "array of shape " + shape_string(sh) + "; expected (n,) or (n, 1): one value per point");
  }
  const std::uint64_t rows = sh[0];
  const std::uint64_t cols = sh.size() == 2 ? sh[1] : 1;

  // Size.
  const std::size_t data_start = header_start + header_len;
  const std::size_t have = bytes.size() - data_start;
  if (rows > have / dt.size / cols) {
    fail_in_file(path, "the array data ends after " + std::to_string(have) + " bytes; shape " + shape_string(sh) + " of " +
                           show(h.descr) + " needs " +
                           (rows > std::numeric_limits<std::uint64_t>::max() / dt.size / cols
                                ? std::string("more")
                                : std::to_string(rows * cols * dt.size)) +
                           " (truncated file?)");
  }
  const std::size_t count = static_cast<std::size_t>(rows * cols);
  if (have != count * dt.size) {
    fail_in_file(path, std::to_string(have - count * dt.size) + " unexpected bytes after the array data of shape " +
                           shape_string(sh));
  }

  NpyArray a;
  a.shape = sh;
  a.descr = h.descr;
  a.fortran_order = h.fortran;
  a.values.resize(count);
  const char* data = bytes.data() + data_start;
  const auto at = [&](std::size_t k) -> double {
    const char* p = data + k * dt.size;
    if (dt.kind == Kind::Float) {
      return dt.size == 4 ? static_cast<double>(std::bit_cast<float>(load<std::uint32_t>(p, dt.swap)))
                          : std::bit_cast<double>(load<std::uint64_t>(p, dt.swap));
    }
    std::uint64_t u = 0;
    switch (dt.size) {
      case 1: u = load<std::uint8_t>(p, false); break;
      case 2: u = load<std::uint16_t>(p, dt.swap); break;
      case 4: u = load<std::uint32_t>(p, dt.swap); break;
      default: u = load<std::uint64_t>(p, dt.swap); break;
    }
    if (dt.kind == Kind::UInt) {
      if (!exact_magnitude(u)) {
        fail_in_file(path, "element " + std::to_string(k) + ": the integer " + std::to_string(u) +
                               " cannot be represented exactly as a double");
      }
      return static_cast<double>(u);
    }
    // Sign-extend from dt.size bytes.
    const int shift = static_cast<int>(64 - 8 * dt.size);
    const auto s = static_cast<std::int64_t>(u << shift) >> shift;
    const std::uint64_t mag = s < 0 ? ~static_cast<std::uint64_t>(s) + 1 : static_cast<std::uint64_t>(s);
    if (!exact_magnitude(mag)) {
      fail_in_file(path, "element " + std::to_string(k) + ": the integer " + std::to_string(s) +
                             " cannot be represented exactly as a double");
    }
    return static_cast<double>(s);
  };
  if (!h.fortran || cols == 1) {
    for (std::size_t k = 0; k < count; ++k) a.values[k] = at(k);
  } else {
    // Column-major: element (i, j) is stored at j * rows + i.
    for (std::size_t j = 0; j < cols; ++j) {
      for (std::size_t i = 0; i < rows; ++i) a.values[i * cols + j] = at(j * rows + i);
    }
  }
  return a;
}

std::string npy_header(std::string_view descr, const std::vector<std::uint64_t>& shape) {
  std::string dict = "{'descr': '" + std::string(descr) + "', 'fortran_order': False, 'shape': " + shape_string(shape) + ", }";
  // magic(6) + version(2) + length(2) + dict + padding + '\n' = a multiple of 64.
  const std::size_t unpadded = 10 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::string h(kMagic);
  h += '\x01';
  h += '\x00';
  h += static_cast<char>(dict.size() & 0xFF);
  h += static_cast<char>((dict.size() >> 8) & 0xFF);
  return h + dict;
}

const char* npy_descr_f8() { return std::endian::native == std::endian::little ? "<f8" : ">f8"; }
const char* npy_descr_i4() { return std::endian::native == std::endian::little ? "<i4" : ">i4"; }

}  // namespace detail

PointSet read_npy(const std::filesystem::path& path) {
  const std::string data = detail::read_file(path);
  detail::NpyArray a = detail::parse_npy(data, path, detail::NpyShape::Points);
  PointSet ps;
  const std::size_t n = a.shape[0];
  if (a.shape[1] == 3) {
    ps.xyz = std::move(a.values);
    return ps;
  }
  ps.xyz.resize(3 * n);
  ps.weights.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) ps.xyz[3 * i + c] = a.values[4 * i + c];
    ps.weights[i] = a.values[4 * i + 3];
  }
  return ps;
}

}  // namespace gdel::io
