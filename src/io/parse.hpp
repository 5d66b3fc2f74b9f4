// Internal helpers of the readers: whole-file loading, line iteration, field splitting,
// strict number parsing and error messages that name the file and line.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace gdel::io::detail {

// The whole file as bytes. Throws InvalidInput "cannot read '<path>': <reason>".
std::string read_file(const std::filesystem::path& path);

// "<path>:<line>: <message>" / "<path>: <message>", thrown as InvalidInput.
[[noreturn]] void fail_at_line(const std::filesystem::path& path, std::size_t line, const std::string& message);
[[noreturn]] void fail_in_file(const std::filesystem::path& path, const std::string& message);

// A token quoted for a message, shortened when long.
std::string show(std::string_view token);

// Lower-cased ASCII copy.
std::string lower(std::string_view s);

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Strict parsers: the whole token must be a number. A leading '+' is accepted. Doubles
// accept "nan", "inf", "infinity" in any case, with a sign. Out-of-range values fail.
template <class Number>
bool parse_number(std::string_view tok, Number& out) {
  if (!tok.empty() && tok.front() == '+') {
    tok.remove_prefix(1);
    if (tok.empty() || tok.front() == '+' || tok.front() == '-') return false;
  }
  const char* end = tok.data() + tok.size();
  const auto res = std::from_chars(tok.data(), end, out);
  return res.ec == std::errc() && res.ptr == end && !tok.empty();
}
inline bool parse_double(std::string_view tok, double& out) { return parse_number(tok, out); }
template <class Int>
bool parse_int(std::string_view tok, Int& out) {
  return parse_number(tok, out);
}

// Iterates over the lines of a text, numbering them from 1, with '\r' (CRLF files) and,
// if enabled, '#' comments stripped. A UTF-8 byte-order mark at the start is skipped.
class LineReader {
 public:
  LineReader(std::string_view text, bool hash_comments) : text_(text), comments_(hash_comments) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  // Next line (possibly empty); false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t nl = text_.find('\n', pos_);
    const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
    line = text_.substr(pos_, end - pos_);
    pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
    ++line_no_;
    if (comments_) {
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
    }
    return true;
  }

  // Next line with at least one non-blank character.
  bool next_nonblank(std::string_view& line) {
    while (next(line)) {
      for (char c : line) {
        if (!is_blank(c)) return true;
      }
    }
    return false;
  }

  std::size_t line_no() const { return line_no_; }
  // Byte offset of the start of the next line.
  std::size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  bool comments_;
  std::size_t pos_ = 0;
  std::size_t line_no_ = 0;
};

// Splits a line into blank-separated fields (and comma-separated ones if allow_comma: one
// comma between two fields, blanks around it allowed). Returns false with `error` set for
// an empty field (",," or a leading or trailing comma). The vector is reused from line to
// line, so splitting allocates only while it grows.
struct Fields {
  std::vector<std::string_view> f;

  std::size_t size() const { return f.size(); }
  std::string_view operator[](std::size_t i) const { return f[i]; }

  bool split(std::string_view line, bool allow_comma, std::string& error) {
    f.clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    bool need_field = false;  // just after a comma
    for (;;) {
      while (i < n && is_blank(line[i])) ++i;
      if (i == n) {
        if (need_field) {
          error = "trailing comma";
          return false;
        }
        return true;
      }
      if (allow_comma && line[i] == ',') {
        if (f.empty() || need_field) {
          error = f.empty() ? "leading comma" : "empty field between two commas";
          return false;
        }
        need_field = true;
        ++i;
        continue;
      }
      const std::size_t start = i;
      while (i < n && !is_blank(line[i]) && !(allow_comma && line[i] == ',')) ++i;
      f.push_back(line.substr(start, i - start));
      need_field = false;
    }
  }

  // Blank-separated only; no error possible.
  void split(std::string_view line) {
    std::string unused;
    split(line, false, unused);
  }
};

}  // namespace gdel::io::detail
