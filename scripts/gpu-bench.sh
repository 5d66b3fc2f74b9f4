#!/usr/bin/env bash
# Benchmarks on a GPU machine (see bench/RESULTS.md for the recorded runs).
#
# The device machines have no CGAL, so the benchmark binary (with CGAL as a peer) is
# built on a machine that has it and carried:
#   here:   cmake --preset cuda && cmake --build --preset cuda --target gdel_bench
#           mkdir -p .bench-bin && cp build/cuda/gdel-bench .bench-bin/ &&
#           cp /lib/x86_64-linux-gnu/{libgmp.so.10,libtbb.so.12,libtbbmalloc.so.2} .bench-bin/
#   device: carry [".bench-bin"], command "bash scripts/gpu-bench.sh"
# Without .bench-bin it builds gdel-bench on the device (no CGAL peer there).
# Results: $OUT/*.json when OUT is set, else bench/out/.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${OUT:-bench/out}"
mkdir -p "$out"
if [ -x .bench-bin/gdel-bench ]; then
  bin=.bench-bin/gdel-bench
  export LD_LIBRARY_PATH="$PWD/.bench-bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
else
  cmake -S . -B build/cuda -G Ninja -DGDEL_CUDA=ON -DCMAKE_BUILD_TYPE=Release -DGDEL_BUILD_TESTS=OFF >/dev/null
  cmake --build build/cuda -j "$(nproc)" --target gdel_bench >/dev/null
  bin=build/cuda/gdel-bench
fi
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader || true
echo "host threads: $(nproc)"
run() { echo "== gdel-bench $*"; "$bin" "$@"; }
case "${1:-all}" in
  flip|all)
    run --dist uniform --n 100000,1000000,10000000 --methods gflip3d-cuda,gflip3d-terminal-cuda --repeat 3 \
      --json "$out/flip-uniform.json"
    run --dist uniform,gaussian,thin_shell,grid,sphere,ball --n 1000000 \
      --methods gflip3d-cuda,gflip3d-terminal-cuda,cgal,cgal-par --repeat 1 --json "$out/flip-dists.json"
    run --dist uniform --n 100000,1000000 --methods gflip3d-cpu,cgal,cgal-par --repeat 1 --json "$out/flip-cpu.json"
    ;;
  gdel3d)
    run --dist uniform --n 100000,1000000,10000000 --methods gdel3d-cuda,cgal,cgal-par --repeat 1 \
      --json "$out/gdel3d-uniform.json"
    run --dist gaussian,thin_shell,grid,sphere,ball --n 1000000 --methods gdel3d-cuda,cgal,cgal-par --repeat 1 \
      --json "$out/gdel3d-dists.json"
    ;;
  gstar4d)  # gStar4D against gDel3D and CGAL (bench/RESULTS.md 2026-11-23; scripts/gpu-run.sh
            # splits the same runs over calls that fit the device limit)
    run --dist uniform,gaussian,thin_shell,ball --n 100000,1000000 --methods gstar4d-cuda,gdel3d-cuda \
      --repeat 3 --json "$out/gstar4d-dists.json"
    run --dist uniform,gaussian,thin_shell,ball,grid --n 100000,1000000 --methods cgal,cgal-par --repeat 1 \
      --json "$out/gstar4d-dists-cgal.json"
    # degenerate input: gstar4d takes 7 s on grid 10^5, > 100 s on grid 10^6 and 3.8 s on 300
    # cospherical points (RESULTS.md): small sizes only
    run --dist grid --n 100000 --methods gstar4d-cuda,gdel3d-cuda --repeat 1 --json "$out/gstar4d-grid.json"
    run --dist sphere --n 300 --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1 \
      --json "$out/gstar4d-sphere.json"
    run --dist uniform,gaussian --n 10000000 --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1 \
      --json "$out/gstar4d-1e7.json"
    ;;
  *) run "$@" ;;
esac
