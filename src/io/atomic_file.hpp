// AtomicFileWriter: buffered output to a temporary file beside the target, renamed over
// the target by commit(). Destroying the writer without commit() (an exception while
// writing) removes the temporary file and leaves any existing target untouched.
// Also the number formatting shared by the writers (std::to_chars, no iostreams).
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gdel::io {

class AtomicFileWriter {
 public:
  // Creates the temporary file (exclusively). Throws gdel::Error when it cannot.
  explicit AtomicFileWriter(std::filesystem::path target);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view bytes) {
    if (bytes.size() > buffer_.size() - used_) flush_buffer();
    if (bytes.size() > buffer_.size()) {
      write_through(bytes.data(), bytes.size());
      return;
    }
    bytes.copy(buffer_.data() + used_, bytes.size());
    used_ += bytes.size();
  }
  void put(char c) {
    if (used_ == buffer_.size()) flush_buffer();
    buffer_[used_++] = c;
  }
  // Shortest decimal form that reads back to the same double.
  void number(double v) { format(v); }
  void number(std::int64_t v) { format(v); }
  void number(std::uint64_t v) { format(v); }
  void number(std::int32_t v) { format(v); }

  // Direct access for hot loops: a pointer to at least n (<= 64 KiB) writable bytes; write
  // there (e.g. with append_number) and hand the end back to advance().
  char* reserve(std::size_t n) {
    if (buffer_.size() - used_ < n) flush_buffer();
    return buffer_.data() + used_;
  }
  void advance(char* end) { used_ = static_cast<std::size_t>(end - buffer_.data()); }

  // Writes v at p (room for kMaxNumberChars needed) and returns the end.
  template <class T>
  static char* append_number(char* p, T v) {
    return std::to_chars(p, p + kMaxNumberChars, v).ptr;
  }
  static constexpr std::size_t kMaxNumberChars = 32;  // to_chars of any double/int64 fits

  // Raw bytes of a binary value.
  void raw(const void* p, std::size_t n) { write(std::string_view(static_cast<const char*>(p), n)); }

  // Flushes, syncs and closes the temporary file, without renaming it yet: a set of files
  // that must change together (TetGen's .node/.ele/.neigh) finishes every writer first and
  // then commits them, so a late write error leaves every target as it was. Throws
  // gdel::Error on failure (the temporary file is then removed).
  void finish();

  // finish() (unless done), then renames over the target. Throws gdel::Error on failure
  // (the temporary file is then removed).
  void commit();

  // Bytes handed to the writer so far (the position in the output file).
  std::uint64_t bytes_written() const { return flushed_ + used_; }

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temp_path() const { return temp_; }

 private:
  template <class T>
  void format(T v) {
    if (buffer_.size() - used_ < kMaxNumberChars) flush_buffer();
    char* begin = buffer_.data() + used_;
    const auto res = std::to_chars(begin, begin + kMaxNumberChars, v);
    used_ += static_cast<std::size_t>(res.ptr - begin);
  }

  void flush_buffer();
  void write_through(const char* p, std::size_t n);
  [[noreturn]] void fail(const std::string& what, int err);
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temp_;
  int fd_ = -1;
  bool committed_ = false;
  bool finished_ = false;
  std::uint64_t flushed_ = 0;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

}  // namespace gdel::io
