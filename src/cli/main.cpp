// The `gdel` command (docs/cli.md is its manual).
//
//   gdel delaunay IN -o OUT [--algorithm A] [--device D] [--check] [--stats] [--quiet]
//   gdel delaunay --example DIST:N -o OUT ...       (built-in generated input)
//   gdel regular IN --weights W -o OUT [--redundant R.txt] [--algorithm A] [--device D] [--check] [--stats] [--quiet]
//   gdel check POINTS TETS.ele [--weights W] [--device D]
//   gdel generate DIST N -o OUT [--seed S]
//   gdel bench [--dist D,..] [--n N,..] [--algorithm A,..] [--device D,..] [--repeat R] [--json F]
//
// OUT's extension picks the format: .ele or none (TetGen .node/.ele/.neigh), .vtu, .mesh,
// .npz. Exit codes: cli/common.hpp and docs/cli.md. Every failure prints one line
// "gdel: error: ..." on stderr and leaves every output file as it was: the output path is
// checked before any work, and writers write a temporary file that is renamed only once
// complete.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "cli/bench.hpp"
#include "cli/common.hpp"
#include "cli/progress.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/errors.hpp"
#include "gdel/regular.hpp"
#include "gdel/verify.hpp"
#include "gdel/version.hpp"
#include "gen/generators.hpp"
#include "io/atomic_file.hpp"
#include "io/io.hpp"

namespace {

namespace fs = std::filesystem;
using namespace gdel::cli;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// "uniform:100000" / "ball:1e6" -> generated points
std::vector<double> example_points(const std::string& spec, std::uint64_t seed) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw UsageError("--example expects DIST:N, e.g. uniform:100000");
  gdel::gen::Distribution dist;
  try {
    dist = gdel::gen::parse_distribution(spec.substr(0, colon));
  } catch (const gdel::InvalidInput& e) {
    throw UsageError(std::string("--example: ") + e.what());
  }
  return gdel::gen::generate(dist, parse_count(spec.substr(colon + 1), "--example"), seed);
}

// Runs a writer; a file-system failure (gdel::Error that is not a bad argument) becomes an
// OutputError (exit 8).
template <class F>
void writing(F&& write) {
  try {
    write();
  } catch (const gdel::InvalidInput&) {
    throw;
  } catch (const gdel::Error& e) {
    throw OutputError(e.what());
  }
}

std::string join(const std::vector<fs::path>& paths) {
  std::string s;
  for (const auto& p : paths) s += (s.empty() ? "" : ", ") + p.string();
  return s;
}

// One line: a message that spans lines is folded.
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Options every subcommand has.
struct Common {
  bool quiet = false;
  double progress_delay = 1.0;  // hidden: tests set 0 to see the display at once
};

void add_common(CLI::App* app, Common& c) {
  app->add_flag("-q,--quiet", c.quiet, "print nothing on success (errors still go to stderr)");
  app->add_option("--progress-delay", c.progress_delay, "seconds before the progress line appears")->group("");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gdel: exact 3D Delaunay triangulation on GPUs and multi-core CPUs (version " +
               std::string(gdel::version()) + ")"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(gdel::version()));
  app.footer("Output format by extension: .ele or none (TetGen), .vtu, .mesh, .npz. Exit codes: 0 ok, 1 usage, "
             "2 invalid input, 3 out of memory, 4 backend unavailable, 5 check failed, 6 other error, 7 degenerate "
             "input, 8 cannot write the output. A failed run writes no file. Manual: docs/cli.md");
  Common common;
  const std::vector<std::string> kDevices = {"cpu", "cuda", "auto"};
  const std::vector<std::string> kAlgorithms = {"auto", "gdel3d", "gstar4d", "gflip3d"};

  // delaunay ------------------------------------------------------------------------------
  std::string in, out, algorithm = "auto", device = "auto", example, initial = "default", rule = "circumcenter";
  bool check = false, stats = false, terminal = false, nonoptimal = false, independent = false, cpu_rounds = false,
       no_reorder = false;
  std::uint64_t seed = 1;
  auto* del = app.add_subcommand("delaunay", "triangulate points and write the mesh");
  del->add_option("input", in, "points file: .xyz .txt .off .ply .node .npy");
  del->add_option("--example", example,
                  "use generated points instead of a file: DIST:N (uniform, gaussian, ball, thin_shell, grid, "
                  "sphere, skew_lines; N like 100000 or 1e5)");
  del->add_option("-o,--output", out,
                  "output file; its extension picks the format: .ele or none (TetGen OUT.node/.ele/.neigh), "
                  ".vtu (VTK), .mesh (Medit), .npz (NumPy)")
      ->required();
  del->add_option("--algorithm", algorithm, "auto (= gdel3d, exact Delaunay; on the GPU with non-optimal flips when few facets are stuck) | gdel3d | gstar4d (exact, via 4-D star splaying) | gflip3d "
                  "(near-Delaunay, unrepaired)")
      ->check(CLI::IsMember(kAlgorithms))
      ->capture_default_str();
  del->add_option("--device", device, "cpu | cuda | auto")->check(CLI::IsMember(kDevices))->capture_default_str();
  del->add_option("--seed", seed, "seed for --example")->capture_default_str();
  del->add_flag("--check", check, "verify the result exactly before writing it; exit 5 (and write nothing) if it fails");
  del->add_flag("--terminal-flipping", terminal, "gFlip3D's insert-all-then-flip variant (for study)");
  del->add_flag("--nonoptimal-flips", nonoptimal,
                "gFlip3D: once flipping is stuck, non-improving flips that unlock stuck facets, keeping the "
                "triangulation with the fewest non-locally-Delaunay facets (experimental; docs/gflip3d.md)");
  del->add_flag("--independent-splits", independent,
                "gFlip3D: a tet waits while a neighbour splits in the same round, and stuck tets stay active: "
                "3-5x fewer facets left stuck, for 2-4x the rounds (a quality option; docs/gflip3d.md)");
  del->add_flag("--no-tet-reorder", no_reorder,
                "gFlip3D's parallel rounds: keep the tets in allocation order instead of sorting them by vertex "
                "between rounds and before the output (the sort is for memory locality; docs/gflip3d.md)");
  del->add_flag("--cpu-rounds", cpu_rounds,
                "CPU backend: run gFlip3D in the GPU's parallel rounds (then gDel3D's repair) instead of the default "
                "one point per round, which leaves the exact Delaunay triangulation and is several times faster on "
                "a few cores (for study; docs/gflip3d.md)");
  del->add_option("--initial", initial,
                  "what gFlip3D/gDel3D start from: default (one tetrahedron) | grid (the Delaunay triangulation of "
                  "a coarse grid's sample, from the dual of its digital Voronoi diagram; docs/grid.md)")
      ->check(CLI::IsMember(std::vector<std::string>{"default", "grid"}))
      ->capture_default_str();
  del->add_option("--insertion-rule", rule,
                  "gFlip3D: the point each tet inserts per round: circumcenter (nearest to the circumcentre) | "
                  "centroid | random | sos (the smallest input index; for study)")
      ->check(CLI::IsMember(std::vector<std::string>{"circumcenter", "centroid", "random", "sos"}))
      ->capture_default_str();
  del->add_flag("--stats", stats, "print time per stage, counts and memory");
  add_common(del, common);

  // regular -------------------------------------------------------------------------------
  std::string rin, rweights, rout, rredundant, rdevice = "auto", ralgorithm = "auto";
  bool rcheck = false, rstats = false;
  auto* reg = app.add_subcommand("regular", "regular (weighted Delaunay) triangulation of weighted points (gReg3D)");
  reg->add_option("input", rin, "points file: .xyz .txt .off .ply .node .npy (weights from --weights, or the "
                                "file's own: a .node attribute or a .ply 'weight' property)")
      ->required();
  reg->add_option("--weights", rweights, "weights (squared radii, any sign): one per line, or a .npy of shape (n,)");
  reg->add_option("-o,--output", rout,
                  "output mesh, format by extension as for `gdel delaunay`; every input point is in it (redundant "
                  "ones in no tet), with its weight where the format holds one")
      ->required();
  reg->add_option("--redundant", rredundant, "also write the ids of the redundant (hidden) points, one a line");
  reg->add_option("--algorithm", ralgorithm,
                  "auto | gstar4d: both run gReg3D (4-D star splaying with star death; the flip algorithms take no "
                  "weights)")
      ->check(CLI::IsMember(std::vector<std::string>{"auto", "gstar4d"}))
      ->capture_default_str();
  reg->add_option("--device", rdevice, "cpu | cuda | auto")->check(CLI::IsMember(kDevices))->capture_default_str();
  reg->add_flag("--check", rcheck, "verify the result exactly (regular mode) before writing; exit 5 if it fails");
  reg->add_flag("--stats", rstats, "print time per stage, counts and memory");
  add_common(reg, common);

  // check ---------------------------------------------------------------------------------
  std::string cpoints, ctets, cweights;
  auto* chk = app.add_subcommand("check", "verify a triangulation exactly (validity, Delaunay/regular); exit 5 if not");
  chk->add_option("points", cpoints, "points file: .xyz .txt .off .ply .node .npy")->required();
  chk->add_option("tets", ctets, "TetGen .ele file")->required();
  chk->add_option("--weights", cweights,
                  "weights (regular triangulation): one per line, or a .npy of shape (n,); default: the points "
                  "file's weight column, if any");
  chk->add_option("--device", device, "cpu | cuda | auto")->check(CLI::IsMember(kDevices))->capture_default_str();
  add_common(chk, common);

  // generate ------------------------------------------------------------------------------
  std::string gdist, gn;
  auto* gen = app.add_subcommand("generate", "write generated points");
  gen->add_option("distribution", gdist, "uniform, gaussian, ball, thin_shell, grid, sphere, skew_lines")->required();
  gen->add_option("n", gn, "number of points (100000 or 1e5)")->required();
  gen->add_option("-o,--output", out, "output points file: .xyz .txt .ply .off .node .npy")->required();
  gen->add_option("--seed", seed, "seed")->capture_default_str();
  add_common(gen, common);

  // bench ---------------------------------------------------------------------------------
  BenchConfig bc;
  auto* bench = app.add_subcommand("bench", "time gdel's algorithms on generated points, verify each result");
  bench->add_option("--dist", bc.distributions, "distributions, comma-separated (uniform, gaussian, ball, thin_shell, "
                                                "grid, sphere, skew_lines)")
      ->delimiter(',')
      ->capture_default_str();
  bench->add_option("--n", bc.sizes, "point counts, comma-separated (1e5,1e6)")->delimiter(',')->capture_default_str();
  bench->add_option("--algorithm", bc.algorithms, "algorithms, comma-separated (gdel3d, gstar4d, gflip3d, auto)")
      ->delimiter(',')
      ->check(CLI::IsMember(kAlgorithms))
      ->capture_default_str();
  bench->add_option("--device", bc.devices, "devices, comma-separated (cpu, cuda, auto)")
      ->delimiter(',')
      ->check(CLI::IsMember(kDevices))
      ->capture_default_str();
  bench->add_option("--repeat", bc.repeat, "runs per configuration (the median is reported)")->capture_default_str();
  bench->add_option("--seed", bc.seed, "seed of the generated points")->capture_default_str();
  bench->add_option("--json", bc.json, "also write the results to this JSON file");
  bench->add_flag_callback("--no-verify", [&] { bc.verify = false; }, "skip the exact verification");
  add_common(bench, common);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "gdel: error: %s (see gdel --help)\n", one_line(e.what()).c_str());
    return kUsage;
  }

  // The progress line: only on a terminal, never with --quiet.
  Progress progress(::isatty(STDERR_FILENO) == 1 && !common.quiet, common.progress_delay);
  const auto fail = [&](int code, const std::string& why) {
    progress.stop();
    std::fprintf(stderr, "gdel: error: %s\n", one_line(why).c_str());
    return code;
  };

  try {
    if (*del) {
      if (in.empty() == example.empty()) throw UsageError("give exactly one of an input file or --example DIST:N");
      // Everything about the output is settled before any work.
      try {
        gdel::io::mesh_format(out);
      } catch (const gdel::InvalidInput& e) {
        throw UsageError(e.what());
      }
      const std::vector<fs::path> outputs = gdel::io::mesh_outputs(out, /*with_neighbours=*/true);
      for (const auto& p : outputs) preflight_output(p);
      gdel::Options o;
      o.algorithm = parse_algorithm(algorithm);
      o.backend = parse_backend(device);
      o.terminal_flipping = terminal;
      o.nonoptimal_flips = nonoptimal;
      o.independent_splits = independent;
      o.reorder_tets = !no_reorder;
      o.cpu_rounds = cpu_rounds;
      o.initial = initial == "grid" ? gdel::Initial::grid : gdel::Initial::Default;
      o.insertion = rule == "random"     ? gdel::InsertionRule::Random
                    : rule == "centroid" ? gdel::InsertionRule::Centroid
                    : rule == "sos"      ? gdel::InsertionRule::SosOrder
                                         : gdel::InsertionRule::Circumcenter;
      const gdel::Backend backend = gdel::resolve_backend(o.backend);  // BackendUnavailable: exit 4, before reading

      auto t0 = Clock::now();
      progress.phase(example.empty() ? "reading " + in : "generating " + example);
      gdel::io::PointSet ps;
      if (example.empty()) {
        ps = gdel::io::read_points(in);
      } else {
        ps.xyz = example_points(example, seed);
      }
      const double read_s = since(t0);
      const std::size_t n = ps.size();

      progress.phase(std::string("triangulating ") + std::to_string(n) + " points (" + gdel::to_string(o.algorithm) +
                     ", " + gdel::to_string(backend) + ")");
      t0 = Clock::now();
      gdel::Triangulation t = gdel::delaunay(ps.xyz, o);
      const double tri_s = since(t0);

      double verify_s = 0;
      std::string check_summary;
      if (check) {
        progress.phase("verifying " + std::to_string(t.num_tets()) + " tets");
        t0 = Clock::now();
        const gdel::VerifyReport r = gdel::verify(ps.xyz, t.tets, {}, o.backend);
        verify_s = since(t0);
        check_summary = check_line(r, t.stats.algorithm);
        if (!meets_contract(r, t.stats.algorithm)) {
          progress.print([&] { std::printf("check: %s\n", check_summary.c_str()); });
          return fail(kCheck, "check failed: " + t.stats.algorithm + " result is " + failure_reason(r, t.stats.algorithm) +
                                  "; nothing written");
        }
      }

      progress.phase("writing " + join(outputs));
      t0 = Clock::now();
      writing([&] { gdel::io::write_mesh(out, ps.xyz, t.tets, t.neighbors); });
      const double write_s = since(t0);
      progress.stop();

      if (!common.quiet) {
        std::printf("%zu points -> %lld tets in %.3f s (%s, %s); wrote %s\n", n, static_cast<long long>(t.num_tets()),
                    tri_s, t.stats.algorithm.c_str(), t.stats.backend.c_str(), join(outputs).c_str());
        if (ps.has_weights()) {
          std::printf("note: the input's weights were ignored (gdel delaunay triangulates the points)\n");
        }
        if (!t.failed_vertices.empty()) {
          std::printf("note: %zu vertices lie on facets that are not locally Delaunay (%s does not repair them)\n",
                      t.failed_vertices.size(), t.stats.algorithm.c_str());
        }
        if (check) std::printf("check: %s\n", check_summary.c_str());
      }
      if (stats) {
        std::printf("%s\n", t.stats.to_string().c_str());
        if (o.initial == gdel::Initial::grid) std::printf("%s\n", grid_stats_line(t.stats).c_str());
        std::printf("  command: read %.3f s, triangulate %.3f s, verify %.3f s, write %.3f s\n", read_s, tri_s,
                    verify_s, write_s);
      }
      return kOk;
    }

    if (*reg) {
      try {
        gdel::io::mesh_format(rout);
      } catch (const gdel::InvalidInput& e) {
        throw UsageError(e.what());
      }
      std::vector<fs::path> outputs = gdel::io::mesh_outputs(rout, /*with_neighbours=*/true);
      if (!rredundant.empty()) outputs.push_back(rredundant);
      for (const auto& p : outputs) preflight_output(p);
      gdel::Options o;
      o.algorithm = parse_algorithm(ralgorithm);
      o.backend = parse_backend(rdevice);
      const gdel::Backend backend = gdel::resolve_backend(o.backend);
      auto t0 = Clock::now();
      progress.phase("reading " + rin);
      gdel::io::PointSet ps = gdel::io::read_points(rin);
      if (!rweights.empty()) {
        progress.phase("reading " + rweights);
        ps.weights = gdel::io::read_weights(rweights);
        if (ps.weights.size() != ps.size())
          throw gdel::InvalidInput(rweights + ": " + std::to_string(ps.weights.size()) + " weights for " +
                                   std::to_string(ps.size()) + " points in " + rin);
      } else if (!ps.has_weights()) {
        throw UsageError(rin + " holds no weights: give --weights W");
      }
      const double read_s = since(t0);
      progress.phase("triangulating " + std::to_string(ps.size()) + " weighted points (greg3d, " +
                     gdel::to_string(backend) + ")");
      t0 = Clock::now();
      gdel::RegularTriangulation t = gdel::regular(ps.xyz, ps.weights, o);
      const double tri_s = since(t0);
      double verify_s = 0;
      std::string check_summary;
      if (rcheck) {
        progress.phase("verifying " + std::to_string(t.num_tets()) + " tets");
        t0 = Clock::now();
        const gdel::VerifyReport r = gdel::verify(ps.xyz, t.tets, ps.weights, o.backend);
        verify_s = since(t0);
        check_summary = r.summary();
        if (!r.delaunay()) {
          progress.print([&] { std::printf("check: %s\n", check_summary.c_str()); });
          return fail(kCheck, "check failed: greg3d result is " + failure_reason(r, "greg3d", true) + "; nothing written");
        }
      }
      progress.phase("writing " + join(outputs));
      t0 = Clock::now();
      writing([&] {
        if (!rredundant.empty()) {
          gdel::io::AtomicFileWriter f(rredundant);
          for (std::int32_t v : t.redundant) {
            f.number(v);
            f.put('\n');
          }
          f.commit();
        }
        gdel::io::write_mesh(rout, ps.xyz, t.tets, t.neighbors, ps.weights);
      });
      const double write_s = since(t0);
      progress.stop();
      if (!common.quiet) {
        std::printf("%zu weighted points -> %lld tets, %zu redundant points, in %.3f s (greg3d, %s); wrote %s\n",
                    ps.size(), static_cast<long long>(t.num_tets()), t.redundant.size(), tri_s,
                    t.stats.backend.c_str(), join(outputs).c_str());
        if (rcheck) std::printf("check: %s\n", check_summary.c_str());
      }
      if (rstats) {
        std::printf("%s\n", t.stats.to_string().c_str());
        std::printf("  command: read %.3f s, triangulate %.3f s, verify %.3f s, write %.3f s\n", read_s, tri_s,
                    verify_s, write_s);
      }
      return kOk;
    }

    if (*chk) {
      progress.phase("reading " + cpoints);
      const gdel::io::PointSet ps = gdel::io::read_points(cpoints);
      progress.phase("reading " + ctets);
      const std::vector<std::int32_t> tets = gdel::io::read_ele(ctets);
      std::vector<double> w;
      if (!cweights.empty()) {
        progress.phase("reading " + cweights);
        w = gdel::io::read_weights(cweights);
        if (w.size() != ps.size()) {
          throw gdel::InvalidInput(cweights + ": " + std::to_string(w.size()) + " weights for " +
                                   std::to_string(ps.size()) + " points in " + cpoints);
        }
      } else if (ps.has_weights()) {
        w = ps.weights;
      }
      progress.phase("verifying " + std::to_string(tets.size() / 4) + " tets");
      const gdel::VerifyReport r = gdel::verify(ps.xyz, tets, w, parse_backend(device));
      progress.stop();
      if (!common.quiet || !r.delaunay()) std::printf("%s\n", r.summary().c_str());
      if (!r.delaunay()) {
        return fail(kCheck, "check failed: " + failure_reason(r, "gdel3d", !w.empty()));
      }
      return kOk;
    }

    if (*gen) {
      const fs::path p(out);
      const std::string ext = p.extension().string();
      if (ext != ".xyz" && ext != ".txt" && ext != ".ply" && ext != ".off" && ext != ".node" && ext != ".npy") {
        throw UsageError("cannot write '" + out + "': unknown points file extension '" + ext +
                         "'; supported: .xyz .txt .ply .off .node .npy");
      }
      gdel::gen::Distribution dist;
      try {
        dist = gdel::gen::parse_distribution(gdist);
      } catch (const gdel::InvalidInput& e) {
        throw UsageError(e.what());
      }
      const std::size_t count = parse_count(gn, "n");
      preflight_output(p);
      progress.phase("generating " + gdist + " " + gn);
      const auto pts = gdel::gen::generate(dist, count, seed);
      progress.phase("writing " + out);
      writing([&] {
        if (ext == ".ply") gdel::io::write_ply(p, pts);
        else if (ext == ".off") gdel::io::write_off(p, pts);
        else if (ext == ".node") gdel::io::write_node(p, pts);
        else if (ext == ".npy") gdel::io::write_npy(p, pts);
        else gdel::io::write_xyz(p, pts);
      });
      progress.stop();
      if (!common.quiet) std::printf("wrote %zu %s points to %s\n", count, gdist.c_str(), out.c_str());
      return kOk;
    }

    if (*bench) {
      bc.quiet = common.quiet;
      const int code = run_bench(bc, progress);
      progress.stop();
      if (code == kCheck) return fail(kCheck, "bench: some results failed verification (see above)");
      return code;
    }
  } catch (const UsageError& e) {
    return fail(kUsage, std::string(e.what()) + " (see gdel --help)");
  } catch (const OutputError& e) {
    return fail(kOutput, e.what());
  } catch (const gdel::InvalidInput& e) {
    return fail(kInput, e.what());
  } catch (const gdel::DegenerateInput& e) {
    return fail(kDegenerate, std::string("degenerate input: ") + e.what());
  } catch (const gdel::OutOfDeviceMemory& e) {
    return fail(kMemory, e.what());
  } catch (const gdel::BackendUnavailable& e) {
    return fail(kBackend, e.what());
  } catch (const std::bad_alloc&) {
    return fail(kMemory, "out of host memory");
  } catch (const std::exception& e) {
    return fail(kOther, e.what());
  }
  return kOk;
}
