// PLY reader: ascii, binary_little_endian, binary_big_endian.
#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

#include "gdel/errors.hpp"
#include "io/io.hpp"
#include "io/parse.hpp"

namespace gdel::io {

using namespace detail;

namespace {

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class Encoding { Ascii, Little, Big };

struct TypeName {
  std::string_view name;
  PlyType type;
};
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

std::optional<PlyType> parse_type(std::string_view s) {
  for (const auto& t : kTypeNames) {
    if (t.name == s) return t.type;
  }
  return std::nullopt;
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool is_integer(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

const char* type_name(PlyType t) {
  switch (t) {
    case PlyType::Int8: return "int8";
    case PlyType::UInt8: return "uint8";
    case PlyType::Int16: return "int16";
    case PlyType::UInt16: return "uint16";
    case PlyType::Int32: return "int32";
    case PlyType::UInt32: return "uint32";
    case PlyType::Float32: return "float32";
    case PlyType::Float64: return "float64";
  }
  return "?";
}

// Range of an integer type, as int64.
std::pair<std::int64_t, std::int64_t> int_range(PlyType t) {
  switch (t) {
    case PlyType::Int8: return {-128, 127};
    case PlyType::UInt8: return {0, 255};
    case PlyType::Int16: return {-32768, 32767};
    case PlyType::UInt16: return {0, 65535};
    case PlyType::Int32: return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    case PlyType::UInt32: return {0, std::numeric_limits<std::uint32_t>::max()};
    default: return {0, 0};
  }
}

struct Property {
  std::string name;
  bool is_list = false;
  PlyType type = PlyType::Float32;        // scalar type, or list item type
  PlyType count_type = PlyType::UInt8;    // list count type
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;

  // Bytes per record when every property is a scalar; 0 otherwise.
  std::size_t fixed_size() const {
    std::size_t s = 0;
    for (const auto& p : props) {
      if (p.is_list) return 0;
      s += type_size(p.type);
    }
    return s;
  }
};

struct Header {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;  // first byte after "end_header\n"
  std::size_t body_line = 0;    // line number of the first body line (ascii)
};

Header parse_header(const std::filesystem::path& path, std::string_view data) {
  LineReader lines(data, /*hash_comments=*/false);
  std::string_view line;
  if (!lines.next(line) || line != "ply") {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line != "ply") fail_in_file(path, "not a PLY file: the first line must be 'ply'");
  }
  Header h;
  bool have_format = false, done = false;
  Fields f;
  while (lines.next(line)) {
    const std::size_t ln = lines.line_no();
    f.split(line);
    if (f.size() == 0) continue;
    const std::string_view kw = f[0];
    if (kw == "comment" || kw == "obj_info") continue;
    if (kw == "end_header") {
      done = true;
      break;
    }
    if (kw == "format") {
      if (f.size() != 3) fail_at_line(path, ln, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (f[1] == "ascii") {
        h.encoding = Encoding::Ascii;
      } else if (f[1] == "binary_little_endian") {
        h.encoding = Encoding::Little;
      } else if (f[1] == "binary_big_endian") {
        h.encoding = Encoding::Big;
      } else {
        fail_at_line(path, ln, "unsupported PLY format " + show(f[1]) +
                                   " (expected ascii, binary_little_endian or binary_big_endian)");
      }
      if (f[2] != "1.0" && f[2] != "1") fail_at_line(path, ln, "unsupported PLY version " + show(f[2]) + " (expected 1.0)");
      have_format = true;
    } else if (kw == "element") {
      if (f.size() != 3) fail_at_line(path, ln, "expected 'element <name> <count>'");
      Element e;
      e.name = std::string(f[1]);
      if (!parse_int(f[2], e.count)) fail_at_line(path, ln, "element " + show(f[1]) + ": bad count " + show(f[2]));
      h.elements.push_back(std::move(e));
    } else if (kw == "property") {
      if (h.elements.empty()) fail_at_line(path, ln, "property before any element");
      Property p;
      if (f.size() >= 2 && f[1] == "list") {
        if (f.size() != 5) fail_at_line(path, ln, "expected 'property list <count type> <item type> <name>'");
        const auto ct = parse_type(f[2]);
        const auto it = parse_type(f[3]);
        if (!ct) fail_at_line(path, ln, "unsupported property type " + show(f[2]));
        if (!it) fail_at_line(path, ln, "unsupported property type " + show(f[3]));
        if (!is_integer(*ct)) fail_at_line(path, ln, "list count type must be an integer type, got " + show(f[2]));
        p.is_list = true;
        p.count_type = *ct;
        p.type = *it;
        p.name = std::string(f[4]);
      } else {
        if (f.size() != 3) fail_at_line(path, ln, "expected 'property <type> <name>'");
        const auto t = parse_type(f[1]);
        if (!t) fail_at_line(path, ln, "unsupported property type " + show(f[1]));
        p.type = *t;
        p.name = std::string(f[2]);
      }
      h.elements.back().props.push_back(std::move(p));
    } else {
      fail_at_line(path, ln, "unknown PLY header keyword " + show(kw));
    }
  }
  if (!done) fail_in_file(path, "the PLY header has no 'end_header' line");
  if (!have_format) fail_in_file(path, "the PLY header has no 'format' line");
  h.body_offset = lines.offset();
  h.body_line = lines.line_no() + 1;
  return h;
}

// What the reader keeps of the vertex element.
struct VertexLayout {
  std::size_t element = 0;              // index among the header's elements
  std::size_t x = 0, y = 0, z = 0;      // property indices
  std::optional<std::size_t> weight;    // property index of "weight"
};

VertexLayout find_vertex(const std::filesystem::path& path, const Header& h) {
  VertexLayout v;
  bool found = false;
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    if (h.elements[i].name == "vertex") {
      v.element = i;
      found = true;
      break;
    }
  }
  if (!found) fail_in_file(path, "the PLY header declares no 'element vertex'");
  const Element& e = h.elements[v.element];
  auto find = [&](const char* name, bool required) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      if (e.props[k].name == name) {
        if (e.props[k].is_list) fail_in_file(path, std::string("vertex property '") + name + "' must be a scalar, not a list");
        return k;
      }
    }
    if (required) {
      std::string have;
      for (const auto& p : e.props) have += (have.empty() ? "" : ", ") + p.name;
      fail_in_file(path, std::string("element vertex has no property '") + name + "' (it has: " +
                             (have.empty() ? std::string("none") : have) + ")");
    }
    return std::nullopt;
  };
  v.x = *find("x", true);
  v.y = *find("y", true);
  v.z = *find("z", true);
  v.weight = find("weight", false);
  return v;
}

std::string record_name(const Element& e, std::uint64_t i) {
  return "element '" + e.name + "' record " + std::to_string(i) + " (0-based) of " + std::to_string(e.count);
}

// ---------------------------------------------------------------------------------------
// ASCII body
// ---------------------------------------------------------------------------------------

class AsciiBody {
 public:
  AsciiBody(const std::filesystem::path& path, std::string_view text, std::size_t first_line)
      : path_(path), text_(text), line_(first_line) {}

  // The next whitespace-separated token; fails when the text ends.
  std::string_view token(const Element& e, std::uint64_t rec, const Property& p) {
    while (pos_ < text_.size() && (is_blank(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ == text_.size()) {
      fail_in_file(path_, "the file ends in " + record_name(e, rec) + " before property '" + p.name + "' (truncated?)");
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }

  double value(PlyType t, const Element& e, std::uint64_t rec, const Property& p) {
    const std::string_view tok = token(e, rec, p);
    if (is_integer(t)) {
      std::int64_t v;
      const auto [lo, hi] = int_range(t);
      if (!parse_int(tok, v) || v < lo || v > hi) {
        fail_at_line(path_, line_, record_name(e, rec) + ", property '" + p.name + "': " + show(tok) +
                                       " is not a valid " + type_name(t));
      }
      return static_cast<double>(v);
    }
    double v;
    if (!parse_double(tok, v)) {
      fail_at_line(path_, line_, record_name(e, rec) + ", property '" + p.name + "': " + show(tok) +
                                     " is not a valid number");
    }
    return v;
  }

  // Reads one property of one record; returns the scalar value (0 for lists).
  double property(const Element& e, std::uint64_t rec, const Property& p) {
    if (!p.is_list) return value(p.type, e, rec, p);
    const double n = value(p.count_type, e, rec, p);
    if (n < 0) {
      fail_at_line(path_, line_, record_name(e, rec) + ", list '" + p.name + "': negative item count");
    }
    for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(n); ++k) value(p.type, e, rec, p);
    return 0.0;
  }

  std::size_t bytes_left() const { return text_.size() - pos_; }

 private:
  const std::filesystem::path& path_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

// ---------------------------------------------------------------------------------------
// Binary body
// ---------------------------------------------------------------------------------------

template <class U>
U byteswap(U v) {
  U r = 0;
  for (std::size_t i = 0; i < sizeof(U); ++i) {
    r = static_cast<U>((r << 8) | ((v >> (8 * i)) & 0xFF));
  }
  return r;
}

class BinaryBody {
 public:
  BinaryBody(const std::filesystem::path& path, std::string_view data, std::size_t offset, Encoding enc)
      : path_(path), data_(data), pos_(offset),
        swap_((enc == Encoding::Little) != (std::endian::native == std::endian::little)) {}

  // Decodes a value at p (which must have type_size(t) bytes).
  double decode(PlyType t, const char* p) const {
    switch (t) {
      case PlyType::Int8: return static_cast<double>(static_cast<std::int8_t>(*p));
      case PlyType::UInt8: return static_cast<double>(static_cast<std::uint8_t>(*p));
      case PlyType::Int16: return static_cast<double>(static_cast<std::int16_t>(load<std::uint16_t>(p)));
      case PlyType::UInt16: return static_cast<double>(load<std::uint16_t>(p));
      case PlyType::Int32: return static_cast<double>(static_cast<std::int32_t>(load<std::uint32_t>(p)));
      case PlyType::UInt32: return static_cast<double>(load<std::uint32_t>(p));
      case PlyType::Float32: return static_cast<double>(std::bit_cast<float>(load<std::uint32_t>(p)));
      case PlyType::Float64: return std::bit_cast<double>(load<std::uint64_t>(p));
    }
    return 0.0;
  }

  // Takes n bytes; fails if the data ends first.
  const char* take(std::size_t n, const Element& e, std::uint64_t rec) {
    if (n > data_.size() - pos_) {
      fail_in_file(path_, "binary data ends at byte " + std::to_string(data_.size()) + " inside " +
                              record_name(e, rec) + " (truncated file, or a wrong element count)");
    }
    const char* p = data_.data() + pos_;
    pos_ += n;
    return p;
  }

  double property(const Element& e, std::uint64_t rec, const Property& p) {
    if (!p.is_list) return decode(p.type, take(type_size(p.type), e, rec));
    const double n = decode(p.count_type, take(type_size(p.count_type), e, rec));
    if (n < 0) fail_in_file(path_, record_name(e, rec) + ", list '" + p.name + "': negative item count");
    const auto items = static_cast<std::uint64_t>(n);
    if (items > (data_.size() - pos_) / type_size(p.type)) take(data_.size() - pos_ + 1, e, rec);  // fails
    take(static_cast<std::size_t>(items) * type_size(p.type), e, rec);
    return 0.0;
  }

  // Skips `count` records of `size` bytes each, or fails naming the first incomplete one.
  void skip_fixed(const Element& e, std::size_t size) {
    const std::size_t left = data_.size() - pos_;
    if (size > 0 && e.count > left / size) take(left + 1, e, left / size);  // fails
    pos_ += static_cast<std::size_t>(e.count) * size;
  }

  std::size_t bytes_left() const { return data_.size() - pos_; }

 private:
  template <class U>
  U load(const char* p) const {
    U v;
    std::memcpy(&v, p, sizeof v);
    return swap_ ? byteswap(v) : v;
  }

  const std::filesystem::path& path_;
  std::string_view data_;
  std::size_t pos_;
  bool swap_;
};

template <class Body>
PointSet read_body(Body& body, const Header& h, const VertexLayout& v, std::size_t min_record_bytes) {
  PointSet ps;
  for (std::size_t ei = 0; ei <= v.element; ++ei) {
    const Element& e = h.elements[ei];
    const bool is_vertex = ei == v.element;
    if (is_vertex) {
      const std::size_t cap = static_cast<std::size_t>(
          std::min<std::uint64_t>(e.count, body.bytes_left() / std::max<std::size_t>(min_record_bytes, 1) + 1));
      ps.xyz.reserve(3 * cap);
      if (v.weight) ps.weights.reserve(cap);
    }
    // An element without properties has empty records: nothing to read, however many
    // (looping over a count such as 10^12 would hang; found by fuzz/ fuzz_ply).
    if (e.props.empty()) continue;
    if constexpr (std::is_same_v<Body, BinaryBody>) {
      if (!is_vertex && e.fixed_size() > 0) {
        body.skip_fixed(e, e.fixed_size());
        continue;
      }
    }
    double xyzw[4] = {0, 0, 0, 0};
    for (std::uint64_t r = 0; r < e.count; ++r) {
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        const double val = body.property(e, r, e.props[k]);
        if (!is_vertex) continue;
        if (k == v.x) xyzw[0] = val;
        if (k == v.y) xyzw[1] = val;
        if (k == v.z) xyzw[2] = val;
        if (v.weight && k == *v.weight) xyzw[3] = val;
      }
      if (is_vertex) {
        ps.xyz.insert(ps.xyz.end(), xyzw, xyzw + 3);
        if (v.weight) ps.weights.push_back(xyzw[3]);
      }
    }
  }
  return ps;
}

}  // namespace

PointSet read_ply(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  const Header h = parse_header(path, data);
  const VertexLayout v = find_vertex(path, h);
  const Element& ve = h.elements[v.element];
  if (h.encoding == Encoding::Ascii) {
    AsciiBody body(path, std::string_view(data).substr(h.body_offset), h.body_line);
    return read_body(body, h, v, 2 * ve.props.size());
  }
  BinaryBody body(path, data, h.body_offset, h.encoding);
  std::size_t min_bytes = 0;
  for (const auto& p : ve.props) min_bytes += type_size(p.is_list ? p.count_type : p.type);
  return read_body(body, h, v, min_bytes);
}

}  // namespace gdel::io
