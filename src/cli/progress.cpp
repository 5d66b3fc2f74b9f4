#include "cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace gdel::cli {
namespace {

constexpr auto kPeriod = std::chrono::milliseconds(200);
constexpr std::size_t kMaxWidth = 78;  // keep the line on one row of an 80-column terminal

void write_stderr(const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t k = ::write(STDERR_FILENO, s.data() + done, s.size() - done);
    if (k <= 0) return;  // a display problem is never an error of the run
    done += static_cast<std::size_t>(k);
  }
}

std::string seconds(std::chrono::duration<double> d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", d.count());
  return buf;
}

}  // namespace

Progress::Progress(bool enabled, double delay_seconds)
    : enabled_(enabled), delay_(delay_seconds), start_(Clock::now()), phase_start_(start_) {
  if (enabled_) thread_ = std::thread([this] { loop(); });
}

Progress::~Progress() { stop(); }

void Progress::phase(const std::string& text) {
  std::lock_guard<std::mutex> lock(mutex_);
  phase_ = text;
  phase_start_ = Clock::now();
  // past the delay a new phase is drawn as it starts, not at the next tick (a phase
  // shorter than the period would otherwise never show)
  if (enabled_ && !stopping_ && (shown_ || phase_start_ - start_ >= delay_)) draw_locked();
}

void Progress::print(const std::function<void()>& print) {
  std::lock_guard<std::mutex> lock(mutex_);
  erase_locked();
  std::fflush(stdout);
  print();
  std::fflush(stdout);
  std::fflush(stderr);
}

void Progress::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
    erase_locked();
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Progress::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, kPeriod);
    if (stopping_) break;
    if (Clock::now() - start_ >= delay_) draw_locked();
  }
}

void Progress::draw_locked() {
  const auto now = Clock::now();
  std::string text = "gdel: " + phase_ + " ... " + seconds(now - phase_start_);
  if (phase_start_ != start_) text += " (total " + seconds(now - start_) + ")";
  if (text.size() > kMaxWidth) text.resize(kMaxWidth);
  // Carriage return, the text, then "erase to the end of the line" (ECMA-48 EL).
  write_stderr("\r" + text + "\x1b[K");
  shown_ = true;
}

void Progress::erase_locked() {
  if (!shown_) return;
  write_stderr("\r\x1b[K");
  shown_ = false;
}

}  // namespace gdel::cli
