#!/usr/bin/env bash
# GPU check, run on the device machine (see README "GPU tests"):
#   builds the cuda preset (CPU + CUDA backends, sm_90) and runs every test with the
#   ctest label "gpu". Test-only dependencies the device lacks (GoogleTest sources,
#   GMP) come from .deps/, made here by scripts/fetch-deps.sh and carried with the run:
#     device run: carry [".deps"], command "bash scripts/gpu-check.sh"
# Extra arguments are passed to ctest (e.g. -R Predicates). On a cold machine the build
# alone takes minutes; to stay within one call's limit, run it in two calls:
#   bash scripts/gpu-check.sh build      then      bash scripts/gpu-check.sh test [ctest args]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
mode=all
case "${1:-}" in build|test) mode=$1; shift ;; esac
echo "== device"; nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader || true
echo "== tools"; cmake --version | head -1; nvcc --version | tail -1; c++ --version | head -1
if [ "$mode" != test ]; then
cmake -S . -B build/cuda -G Ninja -DGDEL_CUDA=ON -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CUDA_ARCHITECTURES="${GDEL_CUDA_ARCH:-90}" -DGDEL_DEPS_DIR="$PWD/.deps" >build-cuda-configure.log 2>&1 \
  || { cat build-cuda-configure.log; exit 1; }
if ! cmake --build build/cuda -j "$jobs" >build-cuda.log 2>&1; then
  grep -E -B2 -A8 'error|FAILED' build-cuda.log | head -120
  exit 1
fi
fi
[ "$mode" = build ] && { echo "build done"; exit 0; }
ctest --test-dir build/cuda -L gpu --output-on-failure -j 4 --timeout 900 "$@"
