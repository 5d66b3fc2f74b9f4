// libFuzzer target for one point/mesh file reader of src/io, chosen at build time by
// GDEL_FUZZ_READER (xyz, off, ply, node, npy, ele, neigh, weights). The input bytes are
// written to a temporary file with the reader's extension and read back. Contract checked:
// the reader returns a well-formed result or throws gdel::InvalidInput; anything else
// (another exception, a sanitizer report, an inconsistent result) is a crash.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "gdel/errors.hpp"
#include "io/io.hpp"

#ifndef GDEL_FUZZ_READER
#error "define GDEL_FUZZ_READER"
#endif
#define GDEL_STR2(x) #x
#define GDEL_STR(x) GDEL_STR2(x)

namespace {

const std::string kKind = GDEL_STR(GDEL_FUZZ_READER);

const std::filesystem::path& temp_path() {
  static const std::filesystem::path p = [] {
    const char* dir = std::getenv("TMPDIR");
    const std::string ext = kKind == "weights" ? "txt" : kKind;
    auto path = std::filesystem::path(dir && *dir ? dir : "/tmp") /
                ("gdel_fuzz_" + std::to_string(::getpid()) + "." + ext);
    std::atexit([] { std::remove(temp_path().c_str()); });
    return path;
  }();
  return p;
}

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz_%s: inconsistent result: %s\n", kKind.c_str(), what);
  std::abort();
}

void check(const gdel::io::PointSet& ps) {
  if (ps.xyz.size() % 3 != 0) broken("xyz.size() is not a multiple of 3");
  if (!ps.weights.empty() && ps.weights.size() != ps.size()) broken("weights.size() != number of points");
}

void read(const std::filesystem::path& p) {
  namespace io = gdel::io;
  if (kKind == "xyz") check(io::read_xyz(p));
  else if (kKind == "off") check(io::read_off(p));
  else if (kKind == "ply") check(io::read_ply(p));
  else if (kKind == "node") check(io::read_node(p));
  else if (kKind == "npy") check(io::read_npy(p));
  else if (kKind == "weights") io::read_weights(p);
  else if (kKind == "ele") {
    const auto tets = io::read_ele(p);
    if (tets.size() % 4 != 0) broken("tets.size() is not a multiple of 4");
    for (auto v : tets) {
      if (v < 0) broken("negative vertex id");
    }
  } else if (kKind == "neigh") {
    const auto nb = io::read_neigh(p);
    if (nb.size() % 4 != 0) broken("neighbours.size() is not a multiple of 4");
    const auto m = static_cast<std::int64_t>(nb.size() / 4);
    for (auto v : nb) {
      if (v < -1 || v >= m) broken("neighbour out of range");
    }
  } else {
    broken("unknown reader");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& p = temp_path();
  std::FILE* f = std::fopen(p.c_str(), "wb");
  if (!f) {
    std::perror("fuzz: cannot write the temporary file");
    std::abort();
  }
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    read(p);
  } catch (const gdel::InvalidInput&) {
    // the documented failure
  }
  return 0;
}
