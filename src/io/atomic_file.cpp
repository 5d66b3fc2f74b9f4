#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "gdel/errors.hpp"

namespace gdel::io {
namespace {

std::atomic<std::uint64_t> g_temp_counter{0};

std::string quoted(const std::filesystem::path& p) {
  std::string s(1, '\'');
  s += p.string();
  s += '\'';
  return s;
}

}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target)
    : target_(std::move(target)), buffer_(std::size_t{1} << 20) {
  if (target_.filename().empty()) {
    throw InvalidInput("cannot write " + quoted(target_) + ": the path names no file");
  }
  // A unique name in the same directory, so that rename() is atomic (same file system).
  // O_EXCL: never reuse a file someone else created; retry with the next counter value.
  for (int attempt = 0;; ++attempt) {
    temp_ = target_;
    temp_ += ".tmp-" + std::to_string(::getpid()) + "-" +
             std::to_string(g_temp_counter.fetch_add(1, std::memory_order_relaxed));
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) break;
    const int err = errno;
    if (err != EEXIST || attempt >= 100) {
      throw Error("cannot write " + quoted(target_) + ": cannot create temporary file " +
                  quoted(temp_) + ": " + std::strerror(err));
    }
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!committed_) discard();
}

void AtomicFileWriter::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temp_.empty()) {
    ::unlink(temp_.c_str());
    temp_.clear();
  }
}

void AtomicFileWriter::fail(const std::string& what, int err) {
  const std::string message = "cannot write " + quoted(target_) + ": " + what + ": " + std::strerror(err);
  discard();
  committed_ = true;  // nothing left to clean up
  throw Error(message);
}

void AtomicFileWriter::write_through(const char* p, std::size_t n) {
  if (fd_ < 0) throw Error("cannot write " + quoted(target_) + ": writer already closed");
  while (n > 0) {
    const ssize_t k = ::write(fd_, p, n);
    if (k < 0) {
      if (errno == EINTR) continue;
      fail("write to " + quoted(temp_) + " failed", errno);
    }
    p += k;
    n -= static_cast<std::size_t>(k);
    flushed_ += static_cast<std::uint64_t>(k);
  }
}

void AtomicFileWriter::flush_buffer() {
  if (used_ == 0) return;
  const std::size_t n = used_;
  used_ = 0;
  write_through(buffer_.data(), n);
}

void AtomicFileWriter::finish() {
  if (finished_) return;
  flush_buffer();
  if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS) fail("fsync failed", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close failed", errno);
  finished_ = true;
}

void AtomicFileWriter::commit() {
  finish();
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    fail("cannot rename " + quoted(temp_) + " to it", errno);
  }
  committed_ = true;
  temp_.clear();
}

}  // namespace gdel::io
