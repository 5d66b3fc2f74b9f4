// `gdel bench`: times gdel's algorithms through the public API on generated inputs,
// verifies every output exactly, prints a table and optionally writes JSON (docs/cli.md
// lists the fields; bench/gdel_bench.cpp, which adds CGAL peers, uses the same core names).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/progress.hpp"

namespace gdel::cli {

struct BenchConfig {
  std::vector<std::string> distributions = {"uniform"};
  std::vector<std::string> sizes = {"1e5"};
  std::vector<std::string> algorithms = {"gdel3d"};
  std::vector<std::string> devices = {"auto"};
  int repeat = 3;
  std::uint64_t seed = 1;
  std::string json;    // empty: no JSON file
  bool verify = true;
  bool quiet = false;  // no table (the JSON file is still written)
};

// Returns the exit code: kOk, or kCheck when some output failed verification (every row
// is still measured and written). Throws UsageError / OutputError / gdel errors.
int run_bench(const BenchConfig& config, Progress& progress);

}  // namespace gdel::cli
