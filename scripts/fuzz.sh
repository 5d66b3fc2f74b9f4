#!/usr/bin/env bash
# Builds gdel's libFuzzer targets with clang (-fsanitize=fuzzer,address,undefined) in
# build/fuzz and runs each for SECONDS (default 30), starting from the seed corpus in
# fuzz/corpus/<target>/. Inputs that find new coverage go to build/fuzz/corpus/<target>/
# (the seeds in the repository are left as they are); a crashing input is saved as
# build/fuzz/crashes/<target>-crash-<sha1> and reproduces with
#   build/fuzz/fuzz/<target> build/fuzz/crashes/<target>-crash-<sha1>
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]      (default: every target)
#
# Targets: fuzz_xyz fuzz_off fuzz_ply fuzz_node fuzz_npy fuzz_ele fuzz_neigh fuzz_weights
# (one reader each) and fuzz_predicates (the exact predicates against GMP). Exit status: 0
# when no target found a problem, 1 otherwise. JOBS sets the build's parallelism (default 2).
set -euo pipefail

apt_install() {
  echo "fuzz.sh: installing $*"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq || true
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$@" >/dev/null
}

main() {
  local secs=${1:-30}
  shift || true
  local root build
  root=$(cd "$(dirname "$0")/.." && pwd)
  build=$root/build/fuzz
  local all=(fuzz_xyz fuzz_off fuzz_ply fuzz_node fuzz_npy fuzz_ele fuzz_neigh fuzz_weights fuzz_predicates)
  local targets=("$@")
  [ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")

  # clang and its libFuzzer runtime, from Debian's packages when missing (as scripts/deps.sh
  # does for the build).
  command -v clang++ >/dev/null || apt_install clang
  local probe
  probe=$(mktemp -d)
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$probe/p.cpp"
  if ! clang++ -fsanitize=fuzzer "$probe/p.cpp" -o "$probe/p" 2>/dev/null; then
    apt_install "libclang-rt-$(clang++ -dumpversion | cut -d. -f1)-dev"
  fi
  rm -rf "$probe"

  mkdir -p "$build/crashes"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DGDEL_FUZZ=ON -DGDEL_CUDA=OFF -DGDEL_BUILD_TESTS=OFF -DGDEL_BUILD_BENCH=OFF >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; exit 1; }
  cmake --build "$build" --target "${targets[@]}" -j "${JOBS:-2}"

  # The reader targets write every input to a temporary file: keep it in memory when possible.
  if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
  local failed=() summary=() t name log rc runs cov corpus seeds
  for t in "${targets[@]}"; do
    name=${t#fuzz_}
    mkdir -p "$build/corpus/$name"
    seeds=()
    [ -d "$root/fuzz/corpus/$name" ] && seeds=("$root/fuzz/corpus/$name")
    log=$build/$t.log
    echo "== $t: ${secs} s"
    set +e
    "$build/fuzz/$t" -max_total_time="$secs" -timeout=20 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$build/crashes/$t-" "$build/corpus/$name" "${seeds[@]}" >"$log" 2>&1
    rc=$?
    set -e
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
    corpus=$(find "$build/corpus/$name" -type f | wc -l)
    if [ $rc -eq 0 ]; then
      summary+=("$t: ok, $runs runs in $secs s, coverage $cov edges, corpus $corpus inputs")
    else
      failed+=("$t")
      summary+=("$t: FAILED (exit $rc), see $log")
      grep -E 'ERROR|==[0-9]+==|inconsistent|GMP says|Test unit written' "$log" | head -20 || true
    fi
  done
  echo "== summary"
  printf '%s\n' "${summary[@]}"
  [ ${#failed[@]} -eq 0 ]
}

main "$@"
