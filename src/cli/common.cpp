#include "cli/common.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace gdel::cli {

std::size_t parse_count(const std::string& text, const std::string& what) {
  const char* s = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (text.empty() || end != s + text.size() || errno != 0 || !std::isfinite(v) || v != std::floor(v) || v < 1 ||
      v > 2147483647.0) {
    throw UsageError(what + ": '" + text + "' is not a point count (a whole number from 1 to 2^31-1, e.g. 100000 or 1e5)");
  }
  return static_cast<std::size_t>(v);
}

Backend parse_backend(const std::string& s) {
  if (s == "cpu") return Backend::Cpu;
  if (s == "cuda") return Backend::Cuda;
  if (s == "auto") return Backend::Auto;
  throw UsageError("--device must be cpu, cuda or auto, not '" + s + "'");
}

Algorithm parse_algorithm(const std::string& s) {
  if (s == "gflip3d") return Algorithm::gflip3d;
  if (s == "gdel3d") return Algorithm::gdel3d;
  if (s == "gstar4d") return Algorithm::gstar4d;
  if (s == "auto") return Algorithm::Auto;
  throw UsageError("--algorithm must be auto, gdel3d, gstar4d or gflip3d, not '" + s + "'");
}

std::string grid_stats_line(const gdel::Stats& s) {
  std::string l = "  initial grid: " + std::to_string(s.grid) + "^3, " + std::to_string(s.grid_sites) + " sites" +
                  (s.grid_fallbacks ? " (not used: default start, see the stages)" : "") + "; raw dual: " +
                  std::to_string(s.dual_tets) + " site tets, " + std::to_string(s.dual_flat) + " flat, " +
                  std::to_string(s.dual_inverted) + " inverted, " + std::to_string(s.dual_folded) + " folded, " +
                  std::to_string(s.dual_overshared_facets) + " facets in > 2 tets, " +
                  std::to_string(s.dual_overlapping_facets) + " overlapping, " +
                  std::to_string(s.dual_cospherical_pairs) + " cospherical / " +
                  std::to_string(s.dual_non_delaunay_pairs) + " non-Delaunay facet pairs";
  if (!s.grid_fallbacks)
    l += "; sites' Delaunay tets in the dual " + std::to_string(s.dual_delaunay_tets) + ", missing " +
         std::to_string(s.dual_missed_delaunay_tets);
  return l;
}

void preflight_output(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::string shown = "'";  // (built in steps: GCC 12 warns falsely on "'" + s + "'")
  shown += path.string();
  shown += '\'';
  if (path.filename().empty()) throw OutputError("cannot write " + shown + ": the path names no file");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw OutputError("cannot write " + shown + ": it is a directory");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::exists(dir, ec)) throw OutputError("cannot write " + shown + ": the directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec)) throw OutputError("cannot write " + shown + ": '" + dir.string() + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw OutputError("cannot write " + shown + ": directory '" + dir.string() + "': " + std::strerror(errno));
  }
}

bool meets_contract(const gdel::VerifyReport& r, const std::string& algorithm) {
  if (algorithm == "gflip3d") {
    gdel::VerifyReport v = r;
    v.degenerate_tets = 0;  // flat tets on degenerate input: removed by gdel3d's repair only
    return v.valid();
  }
  return r.delaunay();
}

std::string check_line(const gdel::VerifyReport& r, const std::string& algorithm) {
  const std::string s = r.summary();
  if (algorithm != "gflip3d" || r.delaunay() || !meets_contract(r, algorithm)) return s;
  // the summary's first line replaced (its counts below say the same)
  return "OK for gflip3d: a valid triangulation but for " + std::to_string(r.degenerate_tets) +
         " flat tets (degenerate input) and " + std::to_string(r.non_delaunay_facets) +
         " facets not locally Delaunay, which gflip3d leaves (gdel3d removes both)" + s.substr(s.find('\n'));
}

std::string failure_reason(const gdel::VerifyReport& r, const std::string& algorithm, bool weighted) {
  if (!r.valid() && !(algorithm == "gflip3d" && meets_contract(r, algorithm))) {
    std::string why = "not a valid triangulation (";
    bool first = true;
    auto item = [&](const char* name, std::int64_t v) {
      if (v == 0) return;
      why += (first ? "" : ", ") + std::to_string(v) + " " + name;
      first = false;
    };
    item("tets with bad vertex ids", r.bad_index);
    item("flat tets", r.degenerate_tets);
    item("inverted tets", r.inverted_tets);
    item("facets in more than two tets", r.overshared_facets);
    item("overlapping facets", r.same_side_facets);
    item("open hull edges", r.hull_open_edges);
    item("reflex hull edges", r.hull_reflex_edges);
    item("unused points", r.unused_points);
    item("duplicate points used", r.duplicate_vertices);
    if (!r.euler_ok) {
      why += (first ? "" : ", ") + std::string("Euler characteristic ") + std::to_string(r.euler) + " instead of 1";
      first = false;
    }
    if (first) why += "see the report";
    return why + ")";
  }
  return weighted ? "not regular: " + std::to_string(r.non_delaunay_facets) + " facets not locally regular"
                  : "not Delaunay: " + std::to_string(r.non_delaunay_facets) + " facets not locally Delaunay";
}

}  // namespace gdel::cli
