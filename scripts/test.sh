#!/usr/bin/env bash
# The test command (README, CI): installs missing packages, builds the CPU preset
# and runs its tests, then builds the CUDA preset as a compile check when nvcc is
# present (GPU tests run on a GPU machine: scripts/gpu-check.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/fetch-models.sh >/dev/null  # real scanned models used by the tests (.deps/models)
jobs=$(nproc)
cmake --preset cpu >/dev/null
cmake --build --preset cpu -j "$jobs"
ctest --preset cpu -j "$jobs"
if command -v nvcc >/dev/null 2>&1 || [ -x /usr/local/cuda/bin/nvcc ]; then
  echo "== CUDA backend: compile check (no GPU here)"
  cmake --preset cuda >/dev/null
  cmake --build --preset cuda -j "$jobs"
fi
bash scripts/test-python.sh
echo "== CPU backend under AddressSanitizer + UBSan"
bash scripts/test-asan.sh
