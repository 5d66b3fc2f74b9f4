#!/usr/bin/env bash
# The test command (README, CI): installs missing packages, builds the CPU preset
# and runs its tests, then compiles the CUDA code (preset cuda-check) when nvcc is
# present (GPU tests run on a GPU machine: scripts/gpu-check.sh), then the Python
# package's tests and the CPU tests under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/fetch-models.sh >/dev/null  # real scanned models used by the tests (.deps/models)
jobs=$(nproc)
cmake --preset cpu >/dev/null
cmake --build --preset cpu -j "$jobs"
ctest --preset cpu -j "$jobs"
if command -v nvcc >/dev/null 2>&1 || [ -x /usr/local/cuda/bin/nvcc ]; then
  # Device code is compiled to PTX only (preset cuda-check): ptxas, ≈ 1 CPU-hour for
  # the library and the GPU tests, runs in the GPU build (scripts/gpu-check.sh). The
  # CPU tests were built above; here the library, the programs and the GPU tests.
  echo "== CUDA backend: compile check to PTX (no GPU here; ${SECONDS}s so far)"
  export PATH="$PATH:/usr/local/cuda/bin"
  cmake --preset cuda-check >/dev/null
  gpu_tests=$(ninja -C build/cuda-check -t targets all | sed -n 's/^\(gpu_[a-z0-9_]*\): phony$/\1/p')
  # shellcheck disable=SC2086
  cmake --build --preset cuda-check -j "$jobs" --target gdel gdel_cli gdel_bench $gpu_tests
fi
echo "== python (${SECONDS}s so far)"
bash scripts/test-python.sh
echo "== CPU backend under AddressSanitizer + UBSan (${SECONDS}s so far)"
bash scripts/test-asan.sh
echo "== done in ${SECONDS}s"
