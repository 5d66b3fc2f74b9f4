// Shared pieces of the `gdel` command: exit codes, the command's own error types, argument
// parsing helpers and the output pre-flight check.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "gdel/delaunay.hpp"
#include "gdel/options.hpp"
#include "gdel/verify.hpp"

namespace gdel::cli {

// Exit codes (docs/cli.md). 0..6 kept from the first version of the command; a degenerate
// input (formerly 2) and a failure to write the output (formerly 6) got their own.
enum Exit : int {
  kOk = 0,
  kUsage = 1,        // bad command line: unknown option or value, unknown output extension
  kInput = 2,        // invalid input: unreadable or malformed file, NaN/Inf, wrong shape
  kMemory = 3,       // out of device or host memory
  kBackend = 4,      // the backend asked for is not available (--device cuda without a GPU)
  kCheck = 5,        // verification failed (--check, `gdel check`, a `gdel bench` row)
  kOther = 6,        // anything else (CUDA runtime error, internal error)
  kDegenerate = 7,   // no 3-D triangulation: fewer than 4 distinct points, all coplanar
  kOutput = 8,       // the output cannot be written (missing directory, permission, disk full)
};

// A command-line problem found by the command itself (exit 1).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The output cannot be written (exit 8).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "1e6", "100000" -> a point count in [1, 2^31 - 1]; UsageError naming `what` otherwise.
std::size_t parse_count(const std::string& text, const std::string& what);

// "cpu" | "cuda" | "auto" (CLI11 has checked the spelling).
Backend parse_backend(const std::string& s);
// "auto" | "gdel3d" | "gstar4d" | "gflip3d".
Algorithm parse_algorithm(const std::string& s);
// The `--stats` line of Options::initial = grid: the coarse grid, the sample, the raw dual.
std::string grid_stats_line(const gdel::Stats& s);

// Before any work: the folder of each path exists, is a folder and is writable, and the path
// itself is not a folder. OutputError naming the path otherwise. (A full disk or a race can
// still fail the write later; the writers then leave every target as it was.)
void preflight_output(const std::filesystem::path& path);

// Holds gdel's contract for an algorithm's output: gdel3d (exact algorithms) must be
// Delaunay; gflip3d a valid triangulation in which non-locally-Delaunay facets and, on
// degenerate input, flat tets are allowed.
bool meets_contract(const gdel::VerifyReport& r, const std::string& algorithm);
// The text after "check: ": the verifier's summary, which starts "OK", "VALID but not
// Delaunay/regular" or "INVALID"; for a gflip3d result that meets its contract but is
// not Delaunay (facets not locally Delaunay, flat tets on degenerate input) it is
// prefixed "OK for gflip3d", so that a passing check never reads "INVALID".
std::string check_line(const gdel::VerifyReport& r, const std::string& algorithm);

// A one-line reason for a failed verification ("2 facets not locally Delaunay", ...).
std::string failure_reason(const gdel::VerifyReport& r, const std::string& algorithm, bool weighted = false);

}  // namespace gdel::cli
