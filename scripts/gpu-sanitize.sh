#!/usr/bin/env bash
# compute-sanitizer on representative GPU runs of every algorithm (issue 8), on the device:
# memcheck (out-of-bounds and misaligned accesses, leaks of device memory) and racecheck
# (shared-memory races) over gflip3d, gdel3d, gstar4d and greg3d on small uniform input
#
#   device run: carry ["build/rg-bin"] (gdel-bench built here, see scripts/gpu-run.sh's
#   header), command "GDEL_BIN_DIR=build/rg-bin bash scripts/gpu-sanitize.sh [N]"
#
# Needs a runtime where compute-sanitizer works (the Firecracker machines: nvidia-h100-x1
# in .library/device/KINDS.md). Each tool's summary line ("ERROR SUMMARY: 0 errors" /
# "RACECHECK SUMMARY: 0 hazards") is printed; the script fails if either reports any.
set -uo pipefail
cd "$(dirname "$0")/.."
bin=${GDEL_BIN_DIR:-build/cuda}
export LD_LIBRARY_PATH="$PWD/$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
n=${1:-2000}
cs=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
args=(--dist uniform --n "$n" --methods gflip3d-cuda,gdel3d-cuda,gstar4d-cuda,greg3d-cuda --repeat 1 --no-verify)
fail=0
for tool in memcheck racecheck; do
  extra=()
  [ "$tool" = memcheck ] && extra=(--leak-check full)
  log=${OUT:-/tmp}/sanitize-$tool.txt
  timeout "${GDEL_SANITIZE_LIMIT:-240}" "$cs" --tool "$tool" "${extra[@]}" --error-exitcode 9 "$bin/gdel-bench" "${args[@]}" >"$log" 2>&1
  rc=$?
  echo "== $tool: rc=$rc"
  grep -E "ERROR SUMMARY|RACECHECK SUMMARY|LEAK SUMMARY|Invalid|Race reported" "$log" | head -10
  grep -E "^(uniform|sphere) " "$log" | head -8
  [ "$rc" = 0 ] || fail=1
done
exit $fail
