#!/usr/bin/env bash
# The CPU backend under AddressSanitizer + UBSan (the `asan` preset): builds the test
# programs below and runs them. Part of scripts/test.sh (CI).
#
#   scripts/test-asan.sh [gtest filter]
#
# UBSan stops at the first report (halt_on_error), except for the suppressed third-party
# idiom in tests/sanitizers/ubsan.supp (Thrust binds a reference to a null policy
# pointer; the `null` check is built recoverable so that the suppression can apply).
set -euo pipefail
cd "$(dirname "$0")/.."
tests=(cpu_predicates cpu_parallel cpu_mesh cpu_io cpu_io_formats cpu_star_stage cpu_greg3d cpu_hostile)
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)" --target "${tests[@]}"
export OMP_WAIT_POLICY=PASSIVE
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$PWD/tests/sanitizers/ubsan.supp"
fail=0
for t in "${tests[@]}"; do
  start=$(date +%s)
  if build/asan/tests/"$t" --gtest_brief=1 ${1:+--gtest_filter="$1"} >"build/asan/$t.log" 2>&1; then
    echo "== asan $t: passed ($(( $(date +%s) - start )) s)"
  else
    echo "== asan $t: FAILED ($(( $(date +%s) - start )) s)"
    grep -E "ERROR|runtime error|SUMMARY|FAILED" "build/asan/$t.log" | head -20
    fail=1
  fi
done
exit $fail
