#!/usr/bin/env bash
# Set-up command 1 (README): installs missing packages, builds gdel, and runs the main
# job on a built-in example: triangulates 200 000 uniform random points, checks the
# result exactly and prints the statistics. Uses the GPU when one is present.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
jobs=$(nproc)
preset=cpu
if (command -v nvcc >/dev/null 2>&1 || [ -x /usr/local/cuda/bin/nvcc ]) && nvidia-smi >/dev/null 2>&1; then
  preset=cuda
fi
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$jobs" --target gdel_cli
mkdir -p out
"./build/$preset/gdel" delaunay --example "${1:-uniform:200000}" -o out/example --check --stats
