// The `gdel` command.
//
//   gdel delaunay IN -o OUT.ele [--algorithm A] [--device D] [--check] [--stats] [--quiet]
//   gdel delaunay --example DIST:N -o OUT.ele ...   (built-in generated input)
//   gdel check POINTS TETS.ele [--weights W]
//   gdel generate DIST N -o OUT.xyz [--seed S]
//
// Exit codes: 0 success; 1 usage error; 2 invalid or degenerate input / unreadable
// file; 3 out of memory; 4 backend unavailable; 5 verification failed; 6 other error.
// Every failure prints one line "gdel: error: ..." on stderr and writes no output
// file (writers write a temporary file and rename it on success).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "gdel/verify.hpp"
#include "gdel/version.hpp"
#include "gen/generators.hpp"
#include "io/io.hpp"

namespace {

enum Exit { kOk = 0, kUsage = 1, kInput = 2, kMemory = 3, kBackend = 4, kVerify = 5, kOther = 6 };

gdel::Backend parse_backend(const std::string& s) {
  if (s == "cpu") return gdel::Backend::Cpu;
  if (s == "cuda") return gdel::Backend::Cuda;
  if (s == "auto") return gdel::Backend::Auto;
  throw gdel::InvalidInput("--device must be cpu, cuda or auto, not '" + s + "'");
}

gdel::Algorithm parse_algorithm(const std::string& s) {
  if (s == "gflip3d") return gdel::Algorithm::gflip3d;
  if (s == "gdel3d") return gdel::Algorithm::gdel3d;
  if (s == "auto") return gdel::Algorithm::Auto;
  throw gdel::InvalidInput("--algorithm must be auto, gflip3d or gdel3d, not '" + s + "'");
}

// "uniform:100000" -> generated points
std::vector<double> example_points(const std::string& spec, std::uint64_t seed) {
  auto colon = spec.find(':');
  if (colon == std::string::npos) throw gdel::InvalidInput("--example expects DIST:N, e.g. uniform:100000");
  auto dist = gdel::gen::parse_distribution(spec.substr(0, colon));
  std::size_t n = std::stoull(spec.substr(colon + 1));
  return gdel::gen::generate(dist, n, seed);
}

// OUT.ele / OUT -> base path without the .ele extension
std::filesystem::path tetgen_base(const std::string& out) {
  std::filesystem::path p(out);
  if (p.extension() == ".ele" || p.extension() == ".node" || p.extension() == ".neigh") p.replace_extension();
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gdel: exact 3D Delaunay triangulation on GPUs and multi-core CPUs (version " +
               std::string(gdel::version()) + ")"};
  app.require_subcommand(1);

  std::string in, out, algorithm = "auto", device = "auto", example;
  bool check = false, stats = false, quiet = false, terminal = false;
  std::uint64_t seed = 1;
  auto* del = app.add_subcommand("delaunay", "triangulate points; writes TetGen OUT.node/.ele/.neigh");
  del->add_option("input", in, "points file (.xyz .txt .off .ply .node)");
  del->add_option("--example", example, "use generated points instead of a file: DIST:N (uniform, gaussian, ball, "
                                        "thin_shell, grid, sphere, skew_lines)");
  del->add_option("-o,--output", out, "output base or OUT.ele")->required();
  del->add_option("--algorithm", algorithm,
                  "auto (= gdel3d: exact Delaunay) | gdel3d | gflip3d (near-Delaunay, unrepaired)")
      ->capture_default_str();
  del->add_option("--device", device, "cpu | cuda | auto")->capture_default_str();
  del->add_option("--seed", seed, "seed for --example")->capture_default_str();
  del->add_flag("--check", check, "verify the result exactly; exit 5 if it is not Delaunay");
  del->add_flag("--terminal-flipping", terminal, "gFlip3D's insert-all-then-flip variant (for study)");
  del->add_flag("--stats", stats, "print time per stage and counts");
  del->add_flag("-q,--quiet", quiet, "print nothing on success");

  std::string cpoints, ctets, cweights;
  auto* chk = app.add_subcommand("check", "verify a triangulation exactly (validity, Delaunay/regular)");
  chk->add_option("points", cpoints, "points file")->required();
  chk->add_option("tets", ctets, "TetGen .ele file")->required();
  chk->add_option("--weights", cweights, "weights file (one per line) for a regular triangulation");
  chk->add_option("--device", device, "cpu | cuda | auto")->capture_default_str();

  std::string gdist;
  std::size_t gn = 0;
  auto* gen = app.add_subcommand("generate", "write generated points");
  gen->add_option("distribution", gdist, "uniform, gaussian, ball, thin_shell, grid, sphere, skew_lines")->required();
  gen->add_option("n", gn, "number of points")->required();
  gen->add_option("-o,--output", out, "output points file (.xyz, .ply, .off, .node)")->required();
  gen->add_option("--seed", seed, "seed")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kOk : kUsage;
  }

  try {
    if (*del) {
      if (in.empty() == example.empty())
        throw gdel::InvalidInput("give exactly one of an input file or --example DIST:N");
      std::vector<double> pts = example.empty() ? gdel::io::read_points(in).xyz : example_points(example, seed);
      gdel::Options o;
      o.algorithm = parse_algorithm(algorithm);
      o.backend = parse_backend(device);
      o.terminal_flipping = terminal;
      auto t0 = std::chrono::steady_clock::now();
      gdel::Triangulation t = gdel::delaunay(pts, o);
      double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      auto base = tetgen_base(out);
      gdel::io::write_tetgen(base, pts, t.tets, t.neighbors);
      if (!quiet)
        std::printf("%zu points -> %lld tets in %.3f s (%s, %s); wrote %s.node/.ele/.neigh\n", pts.size() / 3,
                    static_cast<long long>(t.num_tets()), secs, t.stats.algorithm.c_str(), t.stats.backend.c_str(),
                    base.string().c_str());
      if (!quiet && !t.failed_vertices.empty())
        std::printf("note: %zu vertices lie on facets that are not locally Delaunay (%s does not repair them)\n",
                    t.failed_vertices.size(), t.stats.algorithm.c_str());
      if (stats) std::printf("%s\n", t.stats.to_string().c_str());
      if (check) {
        // The check holds the algorithm to its contract: gdel3d (and later exact
        // algorithms) must be Delaunay; gflip3d must be a valid triangulation of the
        // hull, in which non-locally-Delaunay facets (listed as failed vertices) and,
        // on degenerate input, flat tets are allowed (the repair stage removes them).
        auto r = gdel::verify(pts, t.tets, {}, o.backend);
        bool ok = r.delaunay();
        if (t.stats.algorithm == "gflip3d") {
          gdel::VerifyReport v = r;
          v.degenerate_tets = 0;
          ok = v.valid();
        }
        if (!quiet || !ok) std::printf("check: %s\n", r.summary().c_str());
        if (!ok) return kVerify;
      }
      return kOk;
    }
    if (*chk) {
      auto ps = gdel::io::read_points(cpoints);
      auto tets = gdel::io::read_ele(ctets);
      std::vector<double> w;
      if (!cweights.empty()) {  // one weight per line
        FILE* f = std::fopen(cweights.c_str(), "r");
        if (!f) throw gdel::InvalidInput("cannot open weights file " + cweights);
        double x;
        while (std::fscanf(f, "%lf", &x) == 1) w.push_back(x);
        std::fclose(f);
      } else if (ps.has_weights()) {
        w = ps.weights;
      }
      auto r = gdel::verify(ps.xyz, tets, w, parse_backend(device));
      std::printf("%s\n", r.summary().c_str());
      return r.delaunay() ? kOk : kVerify;
    }
    if (*gen) {
      auto pts = gdel::gen::generate(gdel::gen::parse_distribution(gdist), gn, seed);
      std::filesystem::path p(out);
      auto ext = p.extension().string();
      if (ext == ".ply") gdel::io::write_ply(p, pts);
      else if (ext == ".off") gdel::io::write_off(p, pts);
      else if (ext == ".node") gdel::io::write_node(p, pts);
      else gdel::io::write_xyz(p, pts);
      return kOk;
    }
  } catch (const gdel::OutOfDeviceMemory& e) {
    std::fprintf(stderr, "gdel: error: %s\n", e.what());
    return kMemory;
  } catch (const gdel::BackendUnavailable& e) {
    std::fprintf(stderr, "gdel: error: %s\n", e.what());
    return kBackend;
  } catch (const gdel::InvalidInput& e) {
    std::fprintf(stderr, "gdel: error: %s\n", e.what());
    return kInput;
  } catch (const gdel::DegenerateInput& e) {
    std::fprintf(stderr, "gdel: error: %s\n", e.what());
    return kInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "gdel: error: out of host memory\n");
    return kMemory;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gdel: error: %s\n", e.what());
    return kOther;
  }
  return kOk;
}
