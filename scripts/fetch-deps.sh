#!/usr/bin/env bash
# Gathers the test dependencies that the device machine (no package registries)
# lacks into .deps/ (git-ignored), to be carried with a device run:
#   .deps/googletest  GoogleTest sources (Debian's googletest package)
#   .deps/gmp         GMP headers and static libraries (Debian's libgmp-dev)
#   .deps/cli11       CLI11 headers (Debian's libcli11-dev)
# Run on a machine with Debian's registries; idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p .deps
if [ ! -f .deps/googletest/CMakeLists.txt ]; then
  [ -d /usr/src/googletest ] || apt-get install -y googletest >/dev/null
  rm -rf .deps/googletest && cp -r /usr/src/googletest .deps/googletest
fi
if [ ! -f .deps/gmp/usr/include/gmpxx.h ] && [ ! -f .deps/gmp/usr/include/x86_64-linux-gnu/gmp.h ]; then
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download libgmp-dev >/dev/null)
  rm -rf .deps/gmp && mkdir -p .deps/gmp
  dpkg -x "$tmp"/libgmp-dev_*.deb .deps/gmp
  rm -rf "$tmp"
  # gmp.h lives in the multiarch folder; expose it beside gmpxx.h.
  cp .deps/gmp/usr/include/x86_64-linux-gnu/gmp.h .deps/gmp/usr/include/ 2>/dev/null || true
fi
if [ ! -f .deps/cli11/include/CLI/CLI.hpp ]; then
  [ -f /usr/include/CLI/CLI.hpp ] || apt-get install -y libcli11-dev >/dev/null
  mkdir -p .deps/cli11/include && cp -r /usr/include/CLI .deps/cli11/include/
fi
bash scripts/fetch-models.sh >/dev/null
du -sh .deps/* 
