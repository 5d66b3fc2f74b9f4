// A one-line progress display on stderr for long runs of the `gdel` command.
//
// The library's API has no progress callback today (gdel::delaunay runs to completion and
// returns its Stats), so the display shows the phases the command itself knows -- reading,
// triangulating, verifying, writing -- with the time spent in the current phase and in
// total, redrawn in place by a helper thread a few times a second and as each phase
// starts. Nothing is shown during the first `delay` seconds, so short runs print nothing
// extra; the line is erased when the run ends or before the command prints anything else
// (print()).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace gdel::cli {

class Progress {
 public:
  // enabled: show anything at all (the command passes isatty(stderr) && !quiet).
  explicit Progress(bool enabled, double delay_seconds = 1.0);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Starts a new phase ("reading cloud.ply").
  void phase(const std::string& text);

  // Runs `print` (which writes to stdout or stderr) with the status line erased; it is
  // redrawn at the next tick if the run goes on.
  void print(const std::function<void()>& print);

  // Erases the line and ends the helper thread (also done by the destructor).
  void stop();

 private:
  using Clock = std::chrono::steady_clock;
  void loop();
  void draw_locked();
  void erase_locked();

  bool enabled_;
  std::chrono::duration<double> delay_;
  Clock::time_point start_, phase_start_;
  std::string phase_;
  bool shown_ = false;
  bool stopping_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace gdel::cli
