// Step profiler of the parallel layer (a measuring tool, off by default).
//
// With the environment variable GDEL_PROFILE set, algorithm code marks the end of each
// step with par::mark(ctx, "name"); the time from the previous mark to this one is
// charged to "name". On the CUDA backend a mark records an event on the context's stream
// (no synchronisation: the times are those of the GPU timeline, idle gaps included); on
// the CPU backend it reads the wall clock. Context::profile_report() (synchronizes)
// returns the totals per name in first-seen order; the API prints them to stderr at the
// end of a call. A mark costs one branch when profiling is off.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace gdel::par {

using ProfileTotals = std::vector<std::pair<std::string, double>>;  // (step, seconds)

inline bool profiling_requested() { return std::getenv("GDEL_PROFILE") != nullptr; }

// Totals per name: mark k (name names[k]) closes the interval (t[k], t[k+1]]; t holds
// one more entry than names (t[0]: the origin).
inline ProfileTotals profile_totals(const std::vector<const char*>& names, const std::vector<double>& t) {
  ProfileTotals out;
  for (std::size_t k = 0; k < names.size() && k + 1 < t.size(); ++k) {
    std::size_t j = 0;
    while (j < out.size() && out[j].first != names[k]) ++j;
    if (j == out.size()) out.push_back({names[k], 0.0});
    out[j].second += t[k + 1] - t[k];
  }
  return out;
}

inline std::string format_profile(const ProfileTotals& tot) {
  double sum = 0;
  for (auto& e : tot) sum += e.second;
  std::string r;
  char line[200];
  for (auto& e : tot) {
    std::snprintf(line, sizeof line, "  %-48s %10.3f ms %5.1f %%\n", e.first.c_str(), 1e3 * e.second,
                  sum > 0 ? 100 * e.second / sum : 0.0);
    r += line;
  }
  std::snprintf(line, sizeof line, "  %-48s %10.3f ms\n", "total", 1e3 * sum);
  return r + line;
}

}  // namespace gdel::par
