#!/usr/bin/env bash
# Installs what gdel needs to build and test, from Debian's packages, when missing.
# The CUDA toolkit (nvcc + CCCL) is expected at /usr/local/cuda or on PATH; without
# nvcc only the CPU backend is built (CCCL headers are still required: the CUDA
# toolkit's, or Debian's libthrust-dev/libcub-dev are NOT recent enough).
set -euo pipefail
pkgs=(cmake ninja-build g++ googletest libgtest-dev libgmp-dev libcgal-dev libmpfr-dev libboost-dev libtbb-dev libcli11-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "gdel: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq || true
  $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
if ! command -v nvcc >/dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  echo "gdel: nvcc found at /usr/local/cuda/bin (not on PATH)"
fi
