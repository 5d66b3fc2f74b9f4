// Step profiler of the parallel layer (a measuring tool, off by default).
//
// With the environment variable GDEL_PROFILE set, algorithm code marks the end of each
// step with par::mark(ctx, "name"); the time from the previous mark to this one is
// charged to "name". On the CUDA backend a mark records an event on the context's stream
// (no synchronisation: the times are those of the GPU timeline, idle gaps included); on
// the CPU backend it reads the wall clock. Each mark also records the highest count of
// bytes held in the context's buffers since the previous mark (MemoryStats'
// interval peak, host-side accounting, so both backends alike): the report gives, per
// name, the largest of these, which tells which step sets the call's peak memory.
// Context::profile_report() (synchronizes) returns the totals per name in first-seen
// order; the API prints them to stderr at the end of a call. A mark costs one branch
// when profiling is off. With GDEL_PROFILE_SERIES set as well, profile_report() also
// prints each interval in order ("profile series K NAME MS", K counting that name's
// intervals), all of them ("1") or those whose name holds one of the variable's
// comma-separated parts: to follow a step over the iterations of a loop.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace gdel::par {

struct ProfileEntry {
  std::string name;
  double seconds = 0;
  std::size_t peak_bytes = 0;  // the most bytes held at any time during one of its intervals
};
using ProfileTotals = std::vector<ProfileEntry>;

inline bool profiling_requested() { return std::getenv("GDEL_PROFILE") != nullptr; }
// A measurement knob's value: the variable `name`, "" when unset.
inline std::string knob_value(const char* name) {
  const char* e = std::getenv(name);
  return e ? e : "";
}
// A measurement knob that turns a default path off: the variable `name` set to "0".
inline bool knob_off(const char* name) { return knob_value(name) == "0"; }
// A measurement knob that turns a default-off path on: the variable `name` set to "1".
inline bool knob_on(const char* name) { return knob_value(name) == "1"; }

// Whether GDEL_PROFILE_SERIES (spec) asks for the intervals of step `name`.
inline bool series_wanted(const char* spec, const std::string& name) {
  const std::string sp(spec);
  if (sp == "1") return true;
  std::size_t a = 0;
  while (a <= sp.size()) {
    const std::size_t b = std::min(sp.find(',', a), sp.size());
    if (b > a && name.find(sp.substr(a, b - a)) != std::string::npos) return true;
    a = b + 1;
  }
  return false;
}

// Totals per name: mark k (name names[k]) closes the interval (t[k], t[k+1]], whose
// memory peak is peaks[k]; t holds one more entry than names (t[0]: the origin). Prints
// the series that GDEL_PROFILE_SERIES asks for to stderr.
inline ProfileTotals profile_totals(const std::vector<const char*>& names, const std::vector<double>& t,
                                    const std::vector<std::size_t>& peaks) {
  ProfileTotals out;
  std::vector<long long> seen;  // intervals so far, by entry of out
  const char* series = std::getenv("GDEL_PROFILE_SERIES");
  for (std::size_t k = 0; k < names.size() && k + 1 < t.size(); ++k) {
    std::size_t j = 0;
    while (j < out.size() && out[j].name != names[k]) ++j;
    if (j == out.size()) {
      out.push_back({names[k], 0.0, 0});
      seen.push_back(0);
    }
    if (series && series_wanted(series, out[j].name))
      std::fprintf(stderr, "profile series %lld %s %.4f\n", seen[j], names[k], 1e3 * (t[k + 1] - t[k]));
    ++seen[j];
    out[j].seconds += t[k + 1] - t[k];
    if (k < peaks.size()) out[j].peak_bytes = std::max(out[j].peak_bytes, peaks[k]);
  }
  return out;
}

inline std::string format_profile(const ProfileTotals& tot) {
  double sum = 0;
  std::size_t peak = 0;
  for (auto& e : tot) {
    sum += e.seconds;
    peak = std::max(peak, e.peak_bytes);
  }
  std::string r;
  char line[240];
  for (auto& e : tot) {
    std::snprintf(line, sizeof line, "  %-48s %10.3f ms %5.1f %%  peak %10.1f MiB\n", e.name.c_str(), 1e3 * e.seconds,
                  sum > 0 ? 100 * e.seconds / sum : 0.0, e.peak_bytes / 1048576.0);
    r += line;
  }
  std::snprintf(line, sizeof line, "  %-48s %10.3f ms         peak %10.1f MiB\n", "total", 1e3 * sum, peak / 1048576.0);
  return r + line;
}

}  // namespace gdel::par
