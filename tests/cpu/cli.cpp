// Tests of the `gdel` command: the built binary (path from CMake, GDEL_CLI_PATH; the
// environment variable GDEL_CLI overrides it) is run as a user would run it. Checked: exit
// codes, exactly one "gdel: error: ..." line on stderr for every failure, no output file
// created or changed by a failed run, every format written on success, `gdel check`,
// `gdel generate`, `gdel bench` and its JSON, and the progress line on a terminal.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gdel/options.hpp"
#include "gdel/verify.hpp"
#include "gen/generators.hpp"
#include "io/io.hpp"

namespace {

namespace fs = std::filesystem;

std::string cli_path() {
  if (const char* env = std::getenv("GDEL_CLI")) return env;
#ifdef GDEL_CLI_PATH
  return GDEL_CLI_PATH;
#else
  return "";
#endif
}

struct Result {
  int rc = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    exe_ = cli_path();
    if (exe_.empty() || !fs::exists(exe_)) GTEST_SKIP() << "the gdel binary was not built (CLI11 missing?)";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("gdel_cli_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "work");
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  // Runs gdel with `args` in dir_/work; stdout and stderr captured (not a terminal).
  Result gdel(const std::vector<std::string>& args) const {
    // (appended piece by piece: GCC 12 warns falsely on "literal" + std::string&&)
    std::string cmd = "cd ";
    cmd += quote((dir_ / "work").string());
    cmd += " && OMP_WAIT_POLICY=PASSIVE ";
    cmd += quote(exe_);
    for (const auto& a : args) {
      cmd += ' ';
      cmd += quote(a);
    }
    cmd += " >";
    cmd += quote((dir_ / "out.txt").string());
    cmd += " 2>";
    cmd += quote((dir_ / "err.txt").string());
    cmd += " </dev/null";
    const int status = std::system(cmd.c_str());
    Result r;
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir_ / "out.txt");
    r.err = slurp(dir_ / "err.txt");
    return r;
  }

  fs::path work(const std::string& name) const { return dir_ / "work" / name; }

  void text(const std::string& name, const std::string& content) const {
    std::ofstream(work(name), std::ios::binary) << content;
  }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // Every file in the work directory, sorted (temporary files would show here).
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_ / "work")) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // A failure: the exit code, and exactly one line "gdel: error: ..." containing `part`.
  static void expect_failure(const Result& r, int rc, const std::string& part) {
    EXPECT_EQ(r.rc, rc) << "stderr: " << r.err;
    EXPECT_EQ(r.err.rfind("gdel: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(r.err.empty() || r.err.back() != '\n') << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << "stderr: " << r.err << "\nlacks: " << part;
  }

  void write_points(const std::string& name, std::size_t n, std::uint64_t seed) const {
    gdel::io::write_xyz(work(name), gdel::gen::uniform(n, seed));
  }

  std::string exe_;
  fs::path dir_;
};

// ---------------------------------------------------------------------------------------
// Success
// ---------------------------------------------------------------------------------------

TEST_F(CliTest, DelaunayWritesEveryFormatAndCheckAcceptsIt) {
  write_points("pts.xyz", 2000, 3);
  const auto pts = gdel::io::read_points(work("pts.xyz")).xyz;

  Result r = gdel({"delaunay", "pts.xyz", "-o", "mesh", "--device", "cpu", "--check"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.err, "");  // no terminal: no progress line, and no error
  EXPECT_NE(r.out.find("wrote mesh.node, mesh.ele, mesh.neigh"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("check: OK"), std::string::npos) << r.out;
  const auto tets = gdel::io::read_ele(work("mesh.ele"));
  EXPECT_TRUE(gdel::verify(pts, tets, {}, gdel::Backend::Cpu).delaunay());
  const auto neigh = gdel::io::read_neigh(work("mesh.neigh"));
  EXPECT_EQ(neigh.size(), tets.size());
  EXPECT_EQ(gdel::io::read_points(work("mesh.node")).xyz, pts);

  for (const char* out : {"m.vtu", "m.mesh", "m.npz", "m2.ele"}) {
    r = gdel({"delaunay", "pts.xyz", "-o", out, "-q", "--device", "cpu"});
    EXPECT_EQ(r.rc, 0) << out << ": " << r.err;
    EXPECT_EQ(r.out, "") << "--quiet prints nothing";
    EXPECT_EQ(r.err, "");
  }
  // Same triangulation in every format (the run is deterministic).
  EXPECT_EQ(gdel::io::read_ele(work("m2.ele")), tets);
  const std::string vtu = slurp(work("m.vtu"));
  EXPECT_NE(vtu.find("NumberOfPoints=\"2000\" NumberOfCells=\"" + std::to_string(tets.size() / 4) + "\""),
            std::string::npos);
  const std::string medit = slurp(work("m.mesh"));
  EXPECT_NE(medit.find("Tetrahedra\n" + std::to_string(tets.size() / 4) + "\n"), std::string::npos);
  EXPECT_EQ(slurp(work("m.npz")).substr(0, 4), std::string("PK\x03\x04"));

  r = gdel({"check", "pts.xyz", "mesh.ele"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("OK: valid and locally Delaunay"), std::string::npos) << r.out;
  EXPECT_EQ(listing(), (std::vector<std::string>{"m.mesh", "m.npz", "m.vtu", "m2.ele", "m2.neigh", "m2.node",
                                                 "mesh.ele", "mesh.neigh", "mesh.node", "pts.xyz"}));
}

// gflip3d's contract allows flat tets on degenerate input (and facets not locally
// Delaunay): a passing check says "OK for gflip3d", never "INVALID".
TEST_F(CliTest, CheckOfAGflip3dResultWithFlatTets) {
  std::string grid;
  for (int i = 0; i < 125; ++i)
    grid += std::to_string(i % 5) + " " + std::to_string(i / 5 % 5) + " " + std::to_string(i / 25) + "\n";
  text("grid.xyz", grid);
  Result r = gdel({"delaunay", "grid.xyz", "-o", "g.ele", "--device", "cpu", "--algorithm", "gflip3d", "--check"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto tets = gdel::io::read_ele(work("g.ele"));
  const auto pts = gdel::io::read_points(work("grid.xyz")).xyz;
  ASSERT_GT(gdel::verify(pts, tets, {}, gdel::Backend::Cpu).degenerate_tets, 0) << "the case needs flat tets";
  EXPECT_NE(r.out.find("check: OK for gflip3d"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("check: INVALID"), std::string::npos) << r.out;
}

TEST_F(CliTest, RegularWritesEveryPointAndTheRedundantList) {
  write_points("pts.xyz", 1500, 4);
  const auto pts = gdel::io::read_points(work("pts.xyz")).xyz;
  std::string w;
  std::vector<double> wv;
  for (int i = 0; i < 1500; ++i) {
    wv.push_back(((i * 7919) % 1000) * 2e-5);  // 0 .. 0.02: a share of the points hidden
    w += std::to_string(wv.back()) + "\n";
  }
  text("w.txt", w);
  wv = gdel::io::read_weights(work("w.txt"));  // what gdel reads
  Result r = gdel({"regular", "pts.xyz", "--weights", "w.txt", "-o", "reg", "--redundant", "hidden.txt",
                   "--device", "cpu", "--check"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("check: OK"), std::string::npos) << r.out;
  const auto node = gdel::io::read_points(work("reg.node"));
  EXPECT_EQ(node.xyz, pts);      // every input point, redundant ones included
  EXPECT_EQ(node.weights, wv);   // with its weight
  const auto tets = gdel::io::read_ele(work("reg.ele"));
  const auto rep = gdel::verify(pts, tets, wv, gdel::Backend::Cpu);
  EXPECT_TRUE(rep.delaunay()) << rep.summary();
  const auto hidden = gdel::io::read_weights(work("hidden.txt"));  // one number a line
  EXPECT_EQ(static_cast<std::int64_t>(hidden.size()), rep.redundant_points);
  EXPECT_GT(hidden.size(), 0u);
  // the weights may come from the .node file itself; then `gdel check` reads them there too
  r = gdel({"regular", "reg.node", "-o", "again.ele", "-q", "--device", "cpu"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(gdel::io::read_ele(work("again.ele")), tets);
  r = gdel({"check", "reg.node", "reg.ele"});
  EXPECT_EQ(r.rc, 0) << r.err;
  // failures: no weights (usage), wrong count (invalid input); nothing written
  const auto before = listing();
  expect_failure(gdel({"regular", "pts.xyz", "-o", "x.ele"}), 1, "no weights");
  expect_failure(gdel({"regular", "pts.xyz", "--weights", "w.txt", "--algorithm", "gdel3d", "-o", "x.ele"}), 1,
                 "--algorithm");
  text("short.txt", "1\n2\n");
  expect_failure(gdel({"regular", "pts.xyz", "--weights", "short.txt", "-o", "x.ele"}), 2, "2 weights for 1500");
  auto after = listing();
  after.erase(std::remove(after.begin(), after.end(), "short.txt"), after.end());
  EXPECT_EQ(after, before);
}

TEST_F(CliTest, NpyInputExampleInputAndStats) {
  gdel::io::write_npy(work("pts.npy"), gdel::gen::ball(500, 2));
  Result r = gdel({"delaunay", "pts.npy", "-o", "a.vtu", "--device", "cpu", "--stats"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("500 points ->"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("command: read"), std::string::npos) << r.out;
  r = gdel({"delaunay", "--example", "uniform:1e3", "-o", "ex", "--device", "cpu", "--algorithm", "gflip3d", "--check"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("1000 points ->"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gflip3d"), std::string::npos) << r.out;
  // the CPU backend inserts one point per round unless --cpu-rounds asks for the rounds
  r = gdel({"delaunay", "--example", "uniform:2e4", "-o", "c.vtu", "--device", "cpu", "--stats", "--check"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("one point per round"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("gdel3d repair"), std::string::npos) << r.out;
  r = gdel({"delaunay", "--example", "uniform:2e4", "-o", "d.vtu", "--device", "cpu", "--stats", "--check", "--cpu-rounds"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.out.find("one point per round"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gdel3d repair"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tet reordering"), std::string::npos) << r.out;  // on by default in the rounds
  r = gdel({"delaunay", "--example", "uniform:2e4", "-o", "e.vtu", "--device", "cpu", "--stats", "--check", "--cpu-rounds",
            "--no-tet-reorder"});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("gdel3d repair"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("tet reordering"), std::string::npos) << r.out;
}

TEST_F(CliTest, GenerateEveryPointFormat) {
  for (const char* out : {"g.xyz", "g.txt", "g.ply", "g.off", "g.node", "g.npy"}) {
    const Result r = gdel({"generate", "sphere", "300", "-o", out, "--seed", "4"});
    EXPECT_EQ(r.rc, 0) << out << ": " << r.err;
    EXPECT_EQ(gdel::io::read_points(work(out)).xyz, gdel::gen::sphere(300, 4)) << out;
  }
  expect_failure(gdel({"generate", "sphere", "300", "-o", "g.vtu"}), 1, "'.vtu'");
  expect_failure(gdel({"generate", "nosuch", "300", "-o", "h.xyz"}), 1, "nosuch");
  expect_failure(gdel({"generate", "uniform", "3.5", "-o", "h.xyz"}), 1, "'3.5' is not a point count");
  EXPECT_EQ(fs::exists(work("h.xyz")), false);
}

// ---------------------------------------------------------------------------------------
// Failures: exit code, one line, no file touched
// ---------------------------------------------------------------------------------------

TEST_F(CliTest, UsageErrors) {
  expect_failure(gdel({}), 1, "subcommand");
  expect_failure(gdel({"delaunay", "-o", "x"}), 1, "exactly one of an input file or --example");
  expect_failure(gdel({"delaunay", "p.xyz"}), 1, "--output");
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "x", "--device", "gpu"}), 1, "gpu");
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "x", "--algorithm", "qhull"}), 1, "qhull");
  expect_failure(gdel({"delaunay", "--example", "uniform", "-o", "x"}), 1, "DIST:N");
  expect_failure(gdel({"delaunay", "--example", "cube:10", "-o", "x"}), 1, "cube");
  expect_failure(gdel({"nosuch"}), 1, "subcommand");
  EXPECT_EQ(gdel({"--help"}).rc, 0);
  EXPECT_EQ(gdel({"delaunay", "--help"}).rc, 0);
  EXPECT_TRUE(listing().empty());
}

TEST_F(CliTest, BadOutputExtensionFailsBeforeReading) {
  // The input does not exist: a usage error (1), not an input error (2), proves that the
  // output is checked first.
  expect_failure(gdel({"delaunay", "missing.xyz", "-o", "mesh.foo"}), 1, "unknown mesh file extension '.foo'");
  expect_failure(gdel({"delaunay", "missing.xyz", "-o", "mesh.vtk"}), 1, ".vtu");
  EXPECT_TRUE(listing().empty());
}

TEST_F(CliTest, UnreadableOrMalformedInput) {
  expect_failure(gdel({"delaunay", "missing.xyz", "-o", "m.vtu"}), 2, "No such file");
  fs::create_directories(work("adir.xyz"));
  expect_failure(gdel({"delaunay", "adir.xyz", "-o", "m.vtu"}), 2, "directory");
  text("p.abc", "0 0 0\n");
  expect_failure(gdel({"delaunay", "p.abc", "-o", "m.vtu"}), 2, "unknown point file extension '.abc'");
  text("bad.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 x\n");
  expect_failure(gdel({"delaunay", "bad.xyz", "-o", "m.vtu"}), 2, "bad.xyz:4:");
  text("bad.npy", "not numpy");
  expect_failure(gdel({"delaunay", "bad.npy", "-o", "m.vtu"}), 2, "not a NumPy .npy file");
  EXPECT_EQ(listing(), (std::vector<std::string>{"adir.xyz", "bad.npy", "bad.xyz", "p.abc"}));
}

TEST_F(CliTest, NanRowAndDegenerateInputLeaveExistingOutputsUntouched) {
  text("nan.xyz", "0 0 0\n1 0 0\n0 1 0\nnan 0 1\n1 1 1\n");
  text("flat.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 3 0\n");
  text("three.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  // Existing outputs of every format.
  for (const char* f : {"old.node", "old.ele", "old.neigh", "old.vtu", "old.mesh", "old.npz"}) text(f, std::string("previous ") + f);
  for (const char* out : {"old", "old.vtu", "old.mesh", "old.npz"}) {
    SCOPED_TRACE(out);
    expect_failure(gdel({"delaunay", "nan.xyz", "-o", out, "--device", "cpu"}), 2, "row 3 has a non-finite coordinate");
    expect_failure(gdel({"delaunay", "flat.xyz", "-o", out, "--device", "cpu"}), 7, "coplanar");
    expect_failure(gdel({"delaunay", "three.xyz", "-o", out, "--device", "cpu"}), 7, "at least 4 distinct points");
  }
  for (const char* f : {"old.node", "old.ele", "old.neigh", "old.vtu", "old.mesh", "old.npz"}) {
    EXPECT_EQ(slurp(work(f)), std::string("previous ") + f);
  }
  EXPECT_EQ(listing(), (std::vector<std::string>{"flat.xyz", "nan.xyz", "old.ele", "old.mesh", "old.neigh", "old.node",
                                                 "old.npz", "old.vtu", "three.xyz"}));
  // The same runs succeed on good input and replace the files.
  write_points("good.xyz", 100, 1);
  EXPECT_EQ(gdel({"delaunay", "good.xyz", "-o", "old.vtu", "--device", "cpu"}).rc, 0);
  EXPECT_NE(slurp(work("old.vtu")), "previous old.vtu");
}

TEST_F(CliTest, UnwritableOutputFailsBeforeWork) {
  write_points("p.xyz", 50, 1);
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "no/such/dir/m.vtu"}), 8, "does not exist");
  fs::create_directories(work("m.vtu"));
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "m.vtu"}), 8, "is a directory");
  fs::create_directories(work("t.neigh"));
  text("t.node", "keep");
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "t"}), 8, "t.neigh");
  EXPECT_EQ(slurp(work("t.node")), "keep");
  expect_failure(gdel({"generate", "uniform", "10", "-o", "nodir/p.xyz"}), 8, "does not exist");
  expect_failure(gdel({"bench", "--n", "100", "--json", "nodir/b.json"}), 8, "does not exist");
  EXPECT_EQ(listing(), (std::vector<std::string>{"m.vtu", "p.xyz", "t.neigh", "t.node"}));
}

TEST_F(CliTest, BackendUnavailable) {
  if (gdel::cuda_device_available()) GTEST_SKIP() << "a CUDA device is present";
  write_points("p.xyz", 50, 1);
  expect_failure(gdel({"delaunay", "p.xyz", "-o", "m.vtu", "--device", "cuda"}), 4, "");
  EXPECT_FALSE(fs::exists(work("m.vtu")));
}

TEST_F(CliTest, CheckFailsOnABrokenMeshAndBadWeights) {
  write_points("p.xyz", 300, 2);
  ASSERT_EQ(gdel({"delaunay", "p.xyz", "-o", "m", "--device", "cpu"}).rc, 0);
  // Invert the first tet (swap two vertices) and drop the last one.
  auto tets = gdel::io::read_ele(work("m.ele"));
  std::swap(tets[0], tets[1]);
  tets.resize(tets.size() - 4);
  gdel::io::write_ele(work("broken.ele"), tets);
  Result r = gdel({"check", "p.xyz", "broken.ele", "--device", "cpu"});
  expect_failure(r, 5, "check failed: not a valid triangulation");
  EXPECT_NE(r.out.find("INVALID"), std::string::npos) << r.out;
  // Weights: the wrong count, a malformed file.
  text("w.txt", "1\n2\n");
  expect_failure(gdel({"check", "p.xyz", "m.ele", "--weights", "w.txt"}), 2, "2 weights for 300 points");
  text("w2.txt", "1 2\n");
  expect_failure(gdel({"check", "p.xyz", "m.ele", "--weights", "w2.txt"}), 2, "w2.txt:1:");
  // Zero weights: a regular triangulation equal to the Delaunay one.
  std::string zeros;
  for (int i = 0; i < 300; ++i) zeros += "0\n";
  text("w0.txt", zeros);
  EXPECT_EQ(gdel({"check", "p.xyz", "m.ele", "--weights", "w0.txt", "--device", "cpu"}).rc, 0);
}

// ---------------------------------------------------------------------------------------
// bench
// ---------------------------------------------------------------------------------------

TEST_F(CliTest, BenchTableAndJson) {
  const Result r = gdel({"bench", "--dist", "uniform,ball", "--n", "2e3", "--algorithm", "gdel3d,gflip3d", "--device",
                         "cpu", "--repeat", "2", "--json", "b.json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("median_s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gflip3d-cpu"), std::string::npos) << r.out;
  const std::string j = slurp(work("b.json"));
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j.front(), '[');
  // One object per (dist, n, algorithm, device): 4 rows, each verified and valid.
  auto count = [&](const std::string& s) {
    std::size_t c = 0;
    for (std::size_t p = j.find(s); p != std::string::npos; p = j.find(s, p + 1)) ++c;
    return c;
  };
  EXPECT_EQ(count("{\"dist\": "), 4u);
  EXPECT_EQ(count("\"n\": 2000,"), 4u);
  EXPECT_EQ(count("\"method\": \"gdel3d-cpu\""), 2u);
  EXPECT_EQ(count("\"method\": \"gflip3d-cpu\""), 2u);
  EXPECT_EQ(count("\"dist\": \"ball\""), 2u);
  EXPECT_EQ(count("\"repeat\": 2,"), 4u);
  EXPECT_EQ(count("\"verified\": true, \"valid\": true"), 4u);
  EXPECT_EQ(count("\"median_s\": "), 4u);
  EXPECT_EQ(count("\"times_s\": ["), 4u);
  EXPECT_EQ(count("\"stages\": {"), 4u);
  // gdel3d rows are Delaunay.
  EXPECT_EQ(count("\"method\": \"gdel3d-cpu\", \"algorithm\": \"gdel3d\""), 2u);
  EXPECT_EQ(listing(), (std::vector<std::string>{"b.json"}));

  expect_failure(gdel({"bench", "--n", "0"}), 1, "'0' is not a point count");
  expect_failure(gdel({"bench", "--dist", "cube"}), 1, "cube");
  expect_failure(gdel({"bench", "--repeat", "0", "--n", "10"}), 1, "--repeat");
}

// ---------------------------------------------------------------------------------------
// Progress display on a terminal
// ---------------------------------------------------------------------------------------

// Runs gdel with stderr on a pseudo-terminal and stdout to /dev/null; returns what the
// terminal received and the exit code.
std::pair<std::string, int> run_on_pty(const std::string& exe, const fs::path& cwd, const std::vector<std::string>& args) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) return {"", -2};
  const std::string slave_name = ::ptsname(master);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int slave = ::open(slave_name.c_str(), O_RDWR);
    const int null = ::open("/dev/null", O_RDWR);
    if (slave < 0 || null < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(120);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(slave, 2);
    ::close(master);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(exe.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
    ::execv(exe.c_str(), argv.data());
    ::_exit(121);
  }
  std::string got;
  char buf[4096];
  for (;;) {
    const ssize_t k = ::read(master, buf, sizeof buf);
    if (k <= 0) break;  // EIO once the child has closed the terminal
    got.append(buf, static_cast<std::size_t>(k));
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(master);
  return {got, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

TEST_F(CliTest, ProgressLineOnATerminalIsDrawnAndErased) {
  write_points("p.xyz", 50000, 6);
  // Delay 0: each phase is drawn as it starts (and then every 0.2 s), however short.
  auto [tty, rc] = run_on_pty(exe_, dir_ / "work",
                              {"delaunay", "p.xyz", "-o", "m.vtu", "--device", "cpu", "--check", "--progress-delay", "0"});
  if (rc == -2) GTEST_SKIP() << "no pseudo-terminal available";
  EXPECT_EQ(rc, 0) << tty;
  EXPECT_NE(tty.find("gdel: triangulating 50000 points"), std::string::npos) << tty;
  // Every drawing starts with a carriage return and ends with "erase to end of line"; the
  // last thing on the terminal is the erasure.
  EXPECT_NE(tty.find("\r\x1b[K"), std::string::npos);
  ASSERT_GE(tty.size(), 4u);
  EXPECT_EQ(tty.substr(tty.size() - 4), "\r\x1b[K") << tty;
  EXPECT_EQ(tty.find('\n'), std::string::npos) << "the line is updated in place";
  // --quiet: nothing on the terminal. A run shorter than the delay shows nothing (the
  // delay is 1 s by default; a long one here, so that a loaded machine cannot flake).
  auto [quiet, rc2] = run_on_pty(exe_, dir_ / "work",
                                 {"delaunay", "p.xyz", "-o", "m.vtu", "--device", "cpu", "-q", "--progress-delay", "0"});
  EXPECT_EQ(rc2, 0);
  EXPECT_EQ(quiet, "");
  auto [brief, rc3] = run_on_pty(exe_, dir_ / "work",
                                 {"delaunay", "p.xyz", "-o", "s.vtu", "--device", "cpu", "--progress-delay", "600"});
  EXPECT_EQ(rc3, 0);
  EXPECT_EQ(brief, "");
  // An error on a terminal is still one line, after the erased progress line.
  text("flat.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
  auto [err, rc4] = run_on_pty(exe_, dir_ / "work", {"delaunay", "flat.xyz", "-o", "f.vtu", "--progress-delay", "0"});
  EXPECT_EQ(rc4, 7);
  const std::size_t at = err.find("gdel: error: ");
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin() + at, err.end(), '\n'), 1) << err;
}

}  // namespace
