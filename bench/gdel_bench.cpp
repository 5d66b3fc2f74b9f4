// gdel-bench: times gdel's algorithms and the peers available in this build (CGAL
// sequential and parallel) in one process, on the same points, checks every gdel
// output with the exact verifier, prints a table and writes JSON. Its options: kUsage
// below (`gdel-bench --help`).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "gdel/regular.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"
#include "io/io.hpp"
#include "peers.hpp"

namespace {

constexpr const char* kUsage = R"(Usage: gdel-bench [OPTIONS]

Times gdel's algorithms and the peers in this build on the same points, in one process;
verifies every gdel result exactly; prints a table and writes JSON.

Options:
  -h, --help          print this text and exit
  --dist LIST         distributions, comma-separated (default: uniform,gaussian,
                      thin_shell,grid,sphere,ball); a name with a '.' is a point file
                      (.off .ply .xyz .node), and --n is then ignored for it
  --n LIST            sizes, comma-separated (default: 100000,1000000)
  --methods LIST      what to run, comma-separated (default: gflip3d-cuda and
                      gflip3d-terminal-cuda where a GPU is present, gflip3d-cpu, and
                      cgal and cgal-par where built with CGAL)
  --repeat N          timed runs per row; the median is reported (default: 3)
  --cpu-max N         skip gdel's CPU methods above N points (default: 1000000)
  --json FILE         also write the rows as JSON
  --no-verify         skip the exact verifier
  --seed N            seed of the generated points (default: 20261122)
  --weight-scale X    weighted methods: weights X * h^2 * U(0,1), h the mean spacing
                      of the points' bounding box (default: 3, about half the points
                      redundant on uniform input)

Methods:
  auto-cuda, auto-cpu                Algorithm::Auto
  gdel3d-cuda, gdel3d-cpu            gFlip3D + star splaying (exact Delaunay)
  gdel3d-cuda-dev                    the same with points and results in device memory
  gstar4d-cuda, gstar4d-cpu          gStar4D (failed column: certificate fallbacks)
  gflip3d-cuda, gflip3d-cpu          gFlip3D alone (near-Delaunay)
  gflip3d-terminal-cuda, -cpu        gFlip3D's insert-all-then-flip variant
    gflip3d-* and gdel3d-* with "-grid-" (e.g. gdel3d-grid-cuda): Options::initial = grid;
    with "nonopt" (gflip3d-nonopt-cpu): Options::nonoptimal_flips; with "-indsplit":
    Options::independent_splits; with "-random" or "-centroid": Options::insertion
  cgal, cgal-par                     CGAL Delaunay_triangulation_3, sequential / parallel
  greg3d-cuda, greg3d-cpu            regular triangulation of weighted points
  cgal-regular, cgal-regular-par     CGAL Regular_triangulation_3
)";

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

struct Row {
  std::string dist, method;
  std::size_t n = 0;
  double median_s = 0, min_s = 0;
  std::int64_t tets = 0, flips = 0, failed = 0, non_ld = -1, flat = -1, rounds = 0, iterations = 0, peak = 0;
  double nonld_fraction = -1;
  double flips_per_s = 0;  // flips / time spent in flipping stages
  bool valid = true;
  std::string stages;
  std::string note;
};

// A number given to option `opt`; the whole text must be one (InvalidInput otherwise).
double number(const std::string& opt, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || v < 0)
    throw gdel::InvalidInput(opt + " expects a non-negative number, got '" + text + "'");
  return v;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int bench_main(int argc, char** argv) {
  std::vector<std::string> dists = {"uniform", "gaussian", "thin_shell", "grid", "sphere", "ball"};
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::vector<std::string> methods;
  int repeat = 3;
  std::size_t cpu_max = 1000000;
  std::string json;
  bool do_verify = true;
  double weight_scale = 3.0;
  std::uint64_t seed = 20261122;  // of the generated points
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "gdel-bench: %s needs a value\n", a.c_str());
        std::exit(1);
      }
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (a == "--dist") dists = split(next());
    else if (a == "--n") {
      sizes.clear();
      for (auto& s : split(next())) sizes.push_back(static_cast<std::size_t>(number("--n", s)));
    } else if (a == "--methods") methods = split(next());
    else if (a == "--repeat") repeat = std::max(1, static_cast<int>(number("--repeat", next())));
    else if (a == "--cpu-max") cpu_max = static_cast<std::size_t>(number("--cpu-max", next()));
    else if (a == "--json") json = next();
    else if (a == "--no-verify") do_verify = false;
    else if (a == "--weight-scale") weight_scale = number("--weight-scale", next());
    else if (a == "--seed") {
      const std::string t = next();
      char* end = nullptr;
      seed = std::strtoull(t.c_str(), &end, 10);
      if (t.empty() || t[0] == '-' || end != t.c_str() + t.size())
        throw gdel::InvalidInput("--seed expects a non-negative integer, got '" + t + "'");
    }
    else {
      std::fprintf(stderr, "gdel-bench: unknown argument %s\n\n%s", a.c_str(), kUsage);
      return 1;
    }
  }
  const bool have_cuda = gdel::cuda_device_available();
  if (methods.empty()) {
    if (have_cuda) methods = {"gflip3d-cuda", "gflip3d-terminal-cuda"};
    methods.push_back("gflip3d-cpu");
    if (gdel::bench::cgal_built()) {
      methods.push_back("cgal");
      methods.push_back("cgal-par");
    }
  }
  // warm-up (CUDA context, pools)
  if (have_cuda) {
    gdel::Options o;
    o.backend = gdel::Backend::Cuda;
    o.algorithm = gdel::Algorithm::gflip3d;
    gdel::delaunay(gdel::gen::uniform(10000, 1), o);
  }
  std::vector<Row> rows;
  for (auto& dn : dists) {
    const bool is_file = dn.find('.') != std::string::npos;
    const std::vector<double> file_pts = is_file ? gdel::io::read_points(dn).xyz : std::vector<double>{};
    for (std::size_t n0 : sizes) {
      const auto pts = is_file ? file_pts : gdel::gen::generate(gdel::gen::parse_distribution(dn), n0, seed);
      const std::size_t n = pts.size() / 3;
      if (is_file && n0 != sizes.front()) break;
      std::vector<double> wts;  // for the regular-triangulation methods
      {
        double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], pts[3 * i + a]);
            hi[a] = std::max(hi[a], pts[3 * i + a]);
          }
        const double vol = std::max(1e-300, (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]));
        const double h = std::cbrt(vol / double(std::max<std::size_t>(n, 1)));
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        wts.resize(n);
        for (double& x : wts) x = weight_scale * h * h * u(rng);
      }
      for (auto& m : methods) {
        Row r;
        r.dist = dn;
        r.method = m;
        r.n = n;
        std::vector<double> times;
        if (m.rfind("gflip3d", 0) == 0 || m.rfind("gdel3d", 0) == 0 || m.rfind("gstar4d", 0) == 0 ||
            m.rfind("auto", 0) == 0) {
          const bool star = m.rfind("gstar4d", 0) == 0;
          const bool automatic = m.rfind("auto", 0) == 0;  // Algorithm::Auto (auto-cuda, auto-cpu)
          const bool exact = star || automatic || m.rfind("gdel3d", 0) == 0;
          gdel::Options o;
          o.algorithm = star        ? gdel::Algorithm::gstar4d
                        : automatic ? gdel::Algorithm::Auto
                        : exact     ? gdel::Algorithm::gdel3d
                                    : gdel::Algorithm::gflip3d;
          o.terminal_flipping = m.find("terminal") != std::string::npos;
          o.initial = m.find("-grid-") != std::string::npos ? gdel::Initial::grid : gdel::Initial::Default;
          o.nonoptimal_flips = m.find("nonopt") != std::string::npos;
          o.independent_splits = m.find("-indsplit") != std::string::npos;
          o.insertion = m.find("-random") != std::string::npos     ? gdel::InsertionRule::Random
                        : m.find("-centroid") != std::string::npos ? gdel::InsertionRule::Centroid
                                                                   : gdel::InsertionRule::Circumcenter;
          o.backend = m.find("cuda") != std::string::npos ? gdel::Backend::Cuda : gdel::Backend::Cpu;
          if (o.backend == gdel::Backend::Cuda && !have_cuda) continue;
          if (o.backend == gdel::Backend::Cpu && n > cpu_max) continue;
          gdel::Triangulation t;
          // "-dev" methods: points already in device memory, results left there
          // (gdel::delaunay_device); the upload is not timed, the results are copied back
          // only for the verifier.
          const bool dev = m.size() > 4 && m.compare(m.size() - 4, 4, "-dev") == 0;
          double upload_s = 0;
          for (int k = 0; k < repeat; ++k) {
            if (!dev) {
              t = gdel::delaunay(pts, o);
              times.push_back(t.stats.seconds);
              continue;
            }
            auto tu = std::chrono::steady_clock::now();
            gdel::DeviceArray<double> dp = gdel::copy_to_device(pts, o.device);
            upload_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - tu).count();
            gdel::DevicePoints in;
            in.data = dp.data();
            in.n = static_cast<std::int64_t>(n);
            in.device = o.device;
            gdel::DeviceTriangulation d = gdel::delaunay_device(in, o);
            times.push_back(d.stats.seconds);
            if (k + 1 == repeat) {
              t.tets = gdel::copy_to_host(d.tets);
              t.stats = d.stats;
            }
          }
          if (dev) r.note = "upload " + std::to_string(upload_s) + " s (not timed); ";
          if (o.initial == gdel::Initial::grid)
            r.note += "grid " + std::to_string(t.stats.grid) + "^3, sites " + std::to_string(t.stats.grid_sites) +
                      (t.stats.grid_fallbacks ? " (NOT USED: fallback)" : "") + "; ";
          if (star) r.note += "splay rounds " + std::to_string(t.stats.splay_rounds) + ", insertions " +
                              std::to_string(t.stats.splay_insertions) + "; ";
          r.tets = t.num_tets();
          r.flips = t.stats.flips23 + t.stats.flips32;
          r.failed = star ? t.stats.certificate_fallbacks : exact ? t.stats.repair_failed_vertices : t.stats.failed_vertices;
          r.rounds = t.stats.rounds;
          r.iterations = t.stats.flip_iterations;
          r.peak = t.stats.peak_bytes;
          std::ostringstream st;
          double flip_s = 0;
          for (auto& [name, s] : t.stats.stages) {
            st << name << "=" << s << ";";
            if (name.find("flipping") != std::string::npos) flip_s += s;
          }
          r.flips_per_s = flip_s > 0 ? double(r.flips) / flip_s : 0;
          r.stages = st.str();
          if (exact) {
            double rep = 0;
            for (auto& [name, s] : t.stats.stages)
              if (name.find("repair") != std::string::npos) rep = s;
            std::ostringstream nt;
            nt << r.note << "repair " << rep << " s, stars built " << t.stats.stars_built << " pulled " << t.stats.stars_pulled
               << ", rounds " << t.stats.splay_rounds;
            if (t.stats.points_deferred > 0) nt << ", insertions deferred between threads " << t.stats.points_deferred;
            r.note = nt.str();
          }
          if (do_verify) {
            auto v = gdel::verify(pts, t.tets, {}, have_cuda ? gdel::Backend::Cuda : gdel::Backend::Cpu);
            r.non_ld = v.non_delaunay_facets;
            r.flat = v.degenerate_tets;
            r.nonld_fraction = v.facets ? double(v.non_delaunay_facets) / double(v.facets) : 0;
            // validity apart from flat tets (which gFlip3D may leave for the repair stage)
            r.valid = v.bad_index == 0 && v.inverted_tets == 0 && v.overshared_facets == 0 &&
                      v.same_side_facets == 0 && v.hull_open_edges == 0 && v.unused_points == 0 &&
                      v.duplicate_vertices == 0 && v.euler_ok;
            if (exact) r.valid = v.delaunay() && v.degenerate_tets == 0;
            if (v.hull_reflex_edges) r.note += " reflex hull edges " + std::to_string(v.hull_reflex_edges);
          }
        } else if (m.rfind("greg3d", 0) == 0) {
          gdel::Options o;
          o.backend = m.find("cuda") != std::string::npos ? gdel::Backend::Cuda : gdel::Backend::Cpu;
          if (o.backend == gdel::Backend::Cuda && !have_cuda) continue;
          if (o.backend == gdel::Backend::Cpu && n > cpu_max) continue;
          gdel::RegularTriangulation t;
          for (int k = 0; k < repeat; ++k) {
            t = gdel::regular(pts, wts, o);
            times.push_back(t.stats.seconds);
          }
          r.tets = t.num_tets();
          r.failed = t.stats.certificate_fallbacks;
          r.peak = t.stats.peak_bytes;
          std::ostringstream st;
          for (auto& [name, s] : t.stats.stages) st << name << "=" << s << ";";
          r.stages = st.str();
          r.note = "hidden " + std::to_string(t.redundant.size()) + ", dead stars " + std::to_string(t.stats.dead_stars) +
                   ", rounds " + std::to_string(t.stats.splay_rounds);
          if (do_verify) {  // (gdel::regular certifies its result; this is the benchmark's own check)
            auto v = gdel::verify(pts, t.tets, wts, have_cuda ? gdel::Backend::Cuda : gdel::Backend::Cpu);
            r.non_ld = v.non_delaunay_facets;
            r.flat = v.degenerate_tets;
            r.valid = v.delaunay() && v.degenerate_tets == 0;
          }
        } else if (m == "cgal-regular" || m == "cgal-regular-par") {
          gdel::bench::PeerResult p;
          for (int k = 0; k < repeat; ++k) {
            p = gdel::bench::cgal_regular(pts, wts, m == "cgal-regular-par");
            if (!p.available) break;
            times.push_back(p.seconds);
          }
          if (!p.available) continue;
          r.tets = p.tets;
          r.note = p.note;
        } else if (m == "cgal" || m == "cgal-par") {
          gdel::bench::PeerResult p;
          for (int k = 0; k < repeat; ++k) {
            p = gdel::bench::cgal_delaunay(pts, m == "cgal-par");
            if (!p.available) break;
            times.push_back(p.seconds);
          }
          if (!p.available) continue;
          r.tets = p.tets;
        } else {
          std::fprintf(stderr, "gdel-bench: unknown method %s\n", m.c_str());
          return 1;
        }
        r.median_s = median(times);
        r.min_s = *std::min_element(times.begin(), times.end());
        rows.push_back(r);
        std::fprintf(stderr, "  %-10s %9zu %-22s %9.4f s\n", dn.c_str(), n, m.c_str(), r.median_s);
      }
    }
  }
  // table: time ratios against CGAL sequential / parallel of the same row group
  std::printf("%-10s %9s %-22s %9s %8s %8s %10s %9s %9s %9s %8s %6s %s\n", "dist", "n", "method", "median_s",
              "xCGAL", "xCGALpar", "tets", "flips", "Mflips/s", "failedV", "nonLD", "flat", "valid");
  for (auto& r : rows) {
    double cg = 0, cgp = 0;
    for (auto& q : rows)
      if (q.dist == r.dist && q.n == r.n) {
        const bool reg = r.method.rfind("greg3d", 0) == 0 || r.method.rfind("cgal-regular", 0) == 0;
        if (q.method == (reg ? "cgal-regular" : "cgal")) cg = q.median_s;
        if (q.method == (reg ? "cgal-regular-par" : "cgal-par")) cgp = q.median_s;
      }
    std::string dn = r.dist.substr(r.dist.find_last_of('/') + 1);
    std::printf("%-10s %9zu %-22s %9.4f %8.2f %8.2f %10lld %9lld %9.1f %9lld %8lld %6lld %s %s\n", dn.c_str(), r.n,
                r.method.c_str(), r.median_s, cg > 0 ? cg / r.median_s : 0.0, cgp > 0 ? cgp / r.median_s : 0.0,
                (long long)r.tets, (long long)r.flips, r.flips_per_s / 1e6, (long long)r.failed, (long long)r.non_ld,
                (long long)r.flat, r.valid ? "yes" : "NO", r.note.c_str());
  }
  if (!json.empty()) {
    std::ofstream f(json);
    f << "[\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      auto& r = rows[i];
      f << "  {\"dist\": \"" << r.dist << "\", \"n\": " << r.n << ", \"method\": \"" << r.method
        << "\", \"median_s\": " << r.median_s << ", \"min_s\": " << r.min_s << ", \"tets\": " << r.tets
        << ", \"flips\": " << r.flips << ", \"flips_per_s\": " << r.flips_per_s << ", \"failed_vertices\": " << r.failed << ", \"non_ld_facets\": " << r.non_ld
        << ", \"non_ld_fraction\": " << r.nonld_fraction << ", \"flat_tets\": " << r.flat
        << ", \"rounds\": " << r.rounds << ", \"flip_iterations\": " << r.iterations << ", \"peak_bytes\": " << r.peak
        << ", \"valid\": " << (r.valid ? "true" : "false") << ", \"stages\": \"" << r.stages << "\"}"
        << (i + 1 < rows.size() ? "," : "") << "\n";
    }
    f << "]\n";
  }
  return 0;
}

// Bad arguments (an unknown distribution, a file that cannot be read, a number that is
// not one) end with a message and status 1, not with std::terminate.
int main(int argc, char** argv) {
  try {
    return bench_main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gdel-bench: error: %s\n", e.what());
    return 1;
  }
}
