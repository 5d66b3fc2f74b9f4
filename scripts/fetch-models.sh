#!/usr/bin/env bash
# Real scanned models for tests and benchmarks, from Debian's libcgal-demo package
# (CGAL's demo data: Stanford bunny, armadillo, Chinese dragon, a building scan, ...).
# They are not stored in this repository: this extracts them into .deps/models/.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=.deps/models
want=(meshes/bunny00.off meshes/armadillo.off meshes/ChineseDragon-10kv.off meshes/blade.off
      points_3/building.ply points_3/b9_training.ply)
have=1
for f in "${want[@]}"; do [ -f "$dest/$(basename "$f")" ] || have=0; done
[ "$have" = 1 ] && exit 0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && apt-get download libcgal-demo >/dev/null 2>&1) || { echo "fetch-models: apt-get download libcgal-demo failed" >&2; exit 1; }
dpkg -x "$tmp"/libcgal-demo_*.deb "$tmp/x"
mkdir -p "$dest"
tar xzf "$tmp/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$tmp" "${want[@]/#/data/}"
for f in "${want[@]}"; do cp "$tmp/data/$f" "$dest/"; done
ls -la "$dest"
