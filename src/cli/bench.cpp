#include "cli/bench.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <string>

#include "cli/common.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"
#include "io/atomic_file.hpp"

namespace gdel::cli {
namespace {

struct Row {
  std::string dist;
  std::size_t n = 0;
  std::string algorithm, device;  // as run: "gdel3d", "cpu"
  std::vector<double> times;      // seconds per repeat, in run order
  double median = 0, min = 0, max = 0;
  std::int64_t tets = 0, failed_vertices = 0, peak_bytes = 0;
  std::vector<std::pair<std::string, double>> stages;  // of the last repeat
  bool verified = false, valid = false, delaunay = false;
  std::int64_t non_ld_facets = 0;
  double verify_s = 0;
};

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size();
  return k % 2 ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

// JSON string literal (the names here are plain ASCII, but escape anyway).
std::string quote(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      q += buf;
    } else {
      q += c;
    }
  }
  return q + "\"";
}

// Shortest round-trip form (JSON has no NaN/Inf; times are finite).
std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string json_of(const std::vector<Row>& rows) {
  std::string j = "[\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    j += "  {\"dist\": " + quote(r.dist) + ", \"n\": " + std::to_string(r.n) + ", \"method\": " +
         quote(r.algorithm + "-" + r.device) + ", \"algorithm\": " + quote(r.algorithm) + ", \"device\": " +
         quote(r.device) + ", \"repeat\": " + std::to_string(r.times.size()) + ",\n   \"median_s\": " + num(r.median) +
         ", \"min_s\": " + num(r.min) + ", \"max_s\": " + num(r.max) + ", \"times_s\": [";
    for (std::size_t k = 0; k < r.times.size(); ++k) j += (k ? ", " : "") + num(r.times[k]);
    j += "], \"points_per_s\": " + num(r.median > 0 ? static_cast<double>(r.n) / r.median : 0.0) +
         ",\n   \"tets\": " + std::to_string(r.tets) + ", \"failed_vertices\": " + std::to_string(r.failed_vertices) +
         ", \"peak_bytes\": " + std::to_string(r.peak_bytes) + ",\n   \"verified\": " + (r.verified ? "true" : "false") +
         ", \"valid\": " + (r.verified ? (r.valid ? "true" : "false") : "null") +
         ", \"delaunay\": " + (r.verified ? (r.delaunay ? "true" : "false") : "null") +
         ", \"non_ld_facets\": " + (r.verified ? std::to_string(r.non_ld_facets) : "null") +
         ", \"verify_s\": " + (r.verified ? num(r.verify_s) : "null") + ",\n   \"stages\": {";
    for (std::size_t k = 0; k < r.stages.size(); ++k) {
      j += (k ? ", " : "") + quote(r.stages[k].first) + ": " + num(r.stages[k].second);
    }
    j += "}}";
    j += i + 1 < rows.size() ? ",\n" : "\n";
  }
  return j + "]\n";
}

std::string count_label(std::size_t n) {
  // 100000 -> "1e5" when it is a power of ten times a single digit, else the number.
  std::size_t m = n;
  int e = 0;
  while (m >= 10 && m % 10 == 0) {
    m /= 10;
    ++e;
  }
  return (m < 10 && e >= 3) ? std::to_string(m) + "e" + std::to_string(e) : std::to_string(n);
}

}  // namespace

int run_bench(const BenchConfig& c, Progress& progress) {
  // Every argument is checked before the first measurement.
  if (c.repeat < 1) throw UsageError("--repeat must be at least 1");
  std::vector<gen::Distribution> dists;
  for (const auto& d : c.distributions) {
    try {
      dists.push_back(gen::parse_distribution(d));
    } catch (const InvalidInput& e) {
      throw UsageError(std::string("--dist: ") + e.what());
    }
  }
  std::vector<std::size_t> sizes;
  for (const auto& s : c.sizes) sizes.push_back(parse_count(s, "--n"));
  std::vector<Algorithm> algorithms;
  for (const auto& a : c.algorithms) algorithms.push_back(parse_algorithm(a));
  std::vector<Backend> devices;
  for (const auto& d : c.devices) {
    const Backend b = resolve_backend(parse_backend(d));  // BackendUnavailable: exit 4
    if (std::find(devices.begin(), devices.end(), b) == devices.end()) devices.push_back(b);
  }
  if (!c.json.empty()) preflight_output(c.json);

  std::vector<Row> rows;
  bool all_ok = true;
  if (!c.quiet) {
    progress.print([] {
      std::printf("%-10s %10s %-14s %10s %10s %10s %11s %11s  %s\n", "dist", "n", "method", "median_s", "min_s", "max_s",
                  "Mpoints/s", "tets", "verified");
    });
  }
  for (const auto d : dists) {
    for (const std::size_t n : sizes) {
      const std::string dn(gen::to_string(d));
      progress.phase("bench: generating " + dn + " " + count_label(n));
      const std::vector<double> points = gen::generate(d, n, c.seed);
      for (const Algorithm a : algorithms) {
        for (const Backend b : devices) {
          Row r;
          r.dist = dn;
          r.n = n;
          r.device = to_string(b);
          Options o;
          o.algorithm = a;
          o.backend = b;
          Triangulation t;
          for (int k = 0; k < c.repeat; ++k) {
            progress.phase("bench: " + dn + " " + count_label(n) + " " + to_string(a) + "-" + r.device + " run " +
                           std::to_string(k + 1) + "/" + std::to_string(c.repeat));
            t = Triangulation{};  // free the previous result before the next run
            const auto t0 = std::chrono::steady_clock::now();
            t = delaunay(points, o);
            r.times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
          }
          r.algorithm = t.stats.algorithm;
          r.median = median_of(r.times);
          r.min = *std::min_element(r.times.begin(), r.times.end());
          r.max = *std::max_element(r.times.begin(), r.times.end());
          r.tets = t.num_tets();
          r.failed_vertices = static_cast<std::int64_t>(t.failed_vertices.size());
          r.peak_bytes = t.stats.peak_bytes;
          r.stages = t.stats.stages;
          if (c.verify) {
            progress.phase("bench: verifying " + dn + " " + count_label(n) + " " + r.algorithm + "-" + r.device);
            const auto v0 = std::chrono::steady_clock::now();
            const VerifyReport v = verify(points, t.tets, {}, b);
            r.verify_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - v0).count();
            r.verified = true;
            r.valid = meets_contract(v, r.algorithm);
            r.delaunay = v.delaunay();
            r.non_ld_facets = v.non_delaunay_facets;
            all_ok = all_ok && r.valid;
            if (!r.valid) {
              const std::string why = failure_reason(v, r.algorithm);
              progress.print([&] {
                std::fprintf(stderr, "gdel: bench: %s %zu %s-%s: %s\n", dn.c_str(), n, r.algorithm.c_str(),
                             r.device.c_str(), why.c_str());
              });
            }
          }
          if (!c.quiet) {
            progress.print([&] {
              std::printf("%-10s %10zu %-14s %10.4f %10.4f %10.4f %11.3f %11lld  %s\n", r.dist.c_str(), r.n,
                          (r.algorithm + "-" + r.device).c_str(), r.median, r.min, r.max,
                          r.median > 0 ? static_cast<double>(r.n) / r.median / 1e6 : 0.0,
                          static_cast<long long>(r.tets),
                          !r.verified ? "-" : r.valid ? (r.delaunay ? "Delaunay" : "valid") : "FAILED");
            });
          }
          rows.push_back(std::move(r));
        }
      }
    }
  }
  if (!c.json.empty()) {
    progress.phase("bench: writing " + c.json);
    try {
      io::AtomicFileWriter w(c.json);
      w.write(json_of(rows));
      w.commit();
    } catch (const InvalidInput&) {
      throw;
    } catch (const Error& e) {
      throw OutputError(e.what());
    }
  }
  return all_ok ? kOk : kCheck;
}

}  // namespace gdel::cli
