#!/usr/bin/env bash
# One device call: build only what is needed (or use carried binaries), run steps, log all.
#
#   bash scripts/gpu-run.sh PLAN            (PLAN: a case below, or "cmd" + a command)
#
# Binaries: if build/gs-bin/ exists (built HERE with CGAL, stripped, plus the shared libraries
# the device lacks; see "Carried binaries" below) they are used as they are; otherwise the
# targets the plan needs are configured and built in build/cuda like scripts/gpu-check.sh
# does (-DGDEL_DEPS_DIR=$PWD/.deps: carry [".deps"]) and the build time is printed.
# GDEL_SRC=DIR builds the sources in DIR instead of the working tree (a clean snapshot,
# `git archive HEAD | tar -x -C build/gs-src`, carried: others' unfinished edits stay out).
# Every step runs under its own timeout (all of them within GDEL_CALL_BUDGET seconds) and
# logs to $OUT/log.txt (bench/out/ without OUT); a summary line per step, failures and
# benchmark table rows go to stdout and $OUT/summary.txt; gdel-bench JSON merged into
# $OUT/bench.json
# (the device tool returns at most 8 files).
#
# Carried binaries (here, no device time):
#   cmake -S . -B build/gs-cuda -G Ninja -DGDEL_CUDA=ON -DCMAKE_BUILD_TYPE=Release \
#     -DCMAKE_CUDA_ARCHITECTURES=90 -DGDEL_DEPS_DIR=$PWD/.deps \
#     -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST
#   cmake --build build/gs-cuda --target gdel_bench gpu_gstar4d gpu_star_stage gpu_pba gpu_gdel3d
#   mkdir -p build/gs-bin && cp build/gs-cuda/gdel-bench build/gs-cuda/tests/gpu_star_stage build/gs-bin/
#   strip build/gs-bin/gdel-bench   (the fatbins dominate: the carry limit is 64 MiB in all)
#   cp /lib/x86_64-linux-gnu/{libgmp.so.10,libtbb.so.12,libtbbmalloc.so.2} build/gs-bin/
#   device: carry ["build/gs-bin", ".deps/models"], command "bash scripts/gpu-run.sh bench1"
# Recorded runs: bench/RESULTS.md, 2026-11-23.
set -uo pipefail
cd "$(dirname "$0")/.."
out="${OUT:-bench/out}"
mkdir -p "$out"
deadline=$(( $(date +%s) + ${GDEL_CALL_BUDGET:-570} ))  # the device kills a call at 600 s
plan="${1:-tests}"
shift || true
# an unknown plan fails here, before any build (the case labels below: "  a|b)  # ...")
if ! grep -qE "^  ([a-z0-9_]+\|)*${plan}(\|[a-z0-9_]+)*\)" "$0"; then
  echo "unknown plan $plan" >&2
  exit 1
fi
echo "== device: $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>/dev/null)" \
  | tee "$out/summary.txt"
echo "== host threads: $(nproc)" | tee -a "$out/summary.txt"

if [ -n "${GDEL_BIN_DIR:-}" ] || [ -d build/gs-bin ]; then  # carried binaries (GDEL_BIN_DIR names another folder)
  bin=${GDEL_BIN_DIR:-build/gs-bin}
  tbin=$bin
  export LD_LIBRARY_PATH="$PWD/$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
else
  targets="${GDEL_TARGETS:-gdel_bench gpu_gstar4d gpu_star_stage gpu_pba gpu_gdel3d}"
  t0=$(date +%s)
  cmake -S "${GDEL_SRC:-.}" -B build/cuda -G Ninja -DGDEL_CUDA=ON -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CUDA_ARCHITECTURES="${GDEL_CUDA_ARCH:-90}" -DGDEL_DEPS_DIR="$PWD/.deps" \
    -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST >"$out/build.log" 2>&1 \
    || { tail -40 "$out/build.log"; exit 1; }
  # shellcheck disable=SC2086
  if ! cmake --build build/cuda -j "$(nproc)" --target $targets >>"$out/build.log" 2>&1; then
    grep -E -B2 -A8 'error|FAILED' "$out/build.log" | head -120
    exit 1
  fi
  echo "== build ($targets): $(( $(date +%s) - t0 )) s" | tee -a "$out/summary.txt"
  bin=build/cuda
  tbin=build/cuda/tests
fi

# step NAME TIMEOUT_S COMMAND...: run with a timeout (cut to what is left of the call's
# budget, GDEL_CALL_BUDGET seconds from the script's start, build included, default 570),
# log, one summary line
step() {
  local name=$1 limit=$2
  shift 2
  local left=$(( deadline - $(date +%s) ))
  [ "$left" -lt "$limit" ] && limit=$left
  if [ "$limit" -le 5 ]; then
    echo "== step $name: skipped (call budget spent)" | tee -a "$out/summary.txt"
    return
  fi
  local t0 rc dt note=""
  t0=$(date +%s.%N)
  local log=/tmp/gpu-run-$name.log
  echo "== $name (limit ${limit}s): $*" >"$log"
  timeout --kill-after=5 "$limit" "$@" >>"$log" 2>&1
  rc=$?
  cat "$log" >>"$out/log.txt"
  dt=$(python3 -c "import sys; print(f'{float(sys.argv[2])-float(sys.argv[1]):.1f}')" "$t0" "$(date +%s.%N)")
  [ "$rc" = 124 ] && note=" TIMEOUT"
  if grep -q '^\[==========\]' "$log"; then
    note="$note | $(grep -E '^\[  PASSED  \]|^\[  FAILED  \]' "$log" | tr '\n' ' ')"
  fi
  echo "== step $name: rc=$rc ${dt}s$note" | tee -a "$out/summary.txt"
  grep -E '^\[  FAILED  \]|Failure$|^Expected|^Which is|^  Actual' "$log" | head -20
  grep -E '^[a-z_]+ +[0-9]+ (gstar4d|gdel3d|gflip3d|greg3d|auto|cgal)' "$log" | cut -c1-200
}
gb="$bin/gdel-bench"
jdir=/tmp/gpu-run-json
rm -rf "$jdir" && mkdir -p "$jdir"
# gdel-bench with its JSON merged into $OUT/bench.json after every run: bench NAME LIMIT ARGS
bench() {
  local name=$1 limit=$2
  shift 2
  step "$name" "$limit" "$gb" "$@" --json "$jdir/$name.json"
  python3 - "$jdir" "$out/bench.json" <<'PY'
import json, pathlib, sys
rows = []
for f in sorted(pathlib.Path(sys.argv[1]).glob("*.json"), key=lambda p: p.stat().st_mtime):
    try:
        for r in json.loads(f.read_text()):
            r["step"] = f.stem
            rows.append(r)
    except Exception:
        pass
pathlib.Path(sys.argv[2]).write_text(json.dumps(rows, indent=1))
PY
}

# the same with gdel-bench-old (beside gdel-bench in the binaries' folder): bench_old NAME LIMIT ARGS
bench_old() {
  local gb="$bin/gdel-bench-old"
  bench "$@"
}

# bench with every insertion score through an atomic max, not atomic_raise (session 69's
# default): bench_noraise NAME LIMIT ARGS
bench_noraise() { GDEL_SCORE_RAISE=0 bench "$@"; }

# bench with the flip DAG's links stamped, never zeroed (session 69's study, the default since session 70):
# bench_stamp NAME LIMIT ARGS
bench_stamp() { GDEL_DAG_RESET=stamp bench "$@"; }

# bench with the flip DAG's links zeroed after each walk (the default before session 70):
# bench_zero NAME LIMIT ARGS
bench_zero() { GDEL_DAG_RESET=zero bench "$@"; }

# bench with the flip log capped at 10, 20 or 40 million records (GDEL_FLIP_LOG_RECORDS;
# the default cap is half a record a point, 5 million at uniform 10^7; session 70's study,
# on binaries whose default is the stamped links): bench_logNN NAME LIMIT ARGS
bench_log10() { GDEL_FLIP_LOG_RECORDS=10000000 bench "$@"; }
bench_log20() { GDEL_FLIP_LOG_RECORDS=20000000 bench "$@"; }
bench_log40() { GDEL_FLIP_LOG_RECORDS=40000000 bench "$@"; }

# bench with the flip log's cap of half a record a point (5 million records at uniform
# 10^7: the default before session 71's floor of 2*10^7 from 10^7 points up):
# bench_log05 NAME LIMIT ARGS
bench_log05() { GDEL_FLIP_LOG_RECORDS=5000000 bench "$@"; }

# bench with one device pool kept for the process (GDEL_DEVICE_POOL=keep, session 72's
# study: later calls find their memory mapped): bench_keep NAME LIMIT ARGS
bench_keep() { GDEL_DEVICE_POOL=keep bench "$@"; }

# bench with the pool mapped at once to the memory estimate (GDEL_POOL_PRIME=1, session
# 73's study): bench_prime NAME LIMIT ARGS
bench_prime() { GDEL_POOL_PRIME=1 bench "$@"; }

# bench with runs of small flip iterations in one team (GDEL_TEAM_LOOP=1, session 71's
# study): bench_loop NAME LIMIT ARGS
bench_loop() { GDEL_TEAM_LOOP=1 bench "$@"; }

# old / new binary alternating, ROUNDS times (default 2), on the same arguments, both in
# the JSON: alternate TAG ARGS... (gdel-bench-old beside gdel-bench in the binaries' folder)
alternate() {
  local tag=$1
  shift
  for r in $(seq "${ROUNDS:-2}"); do
    bench_old "${tag}_old$r" 60 "$@"
    bench "${tag}_new$r" 60 "$@"
  done
}

# uniform 10^8 once, uniform 10^7 three times (the median): e8 NAME, e7 NAME (environment
# as given)
e8() { bench "$1" 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1; }
e7() { bench "$1" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3; }

# The GPU test binaries present in the binaries' folder, a step each, in the order given
# (default: all but gpu_predicates): gpu_tests [NAME...]
gpu_tests() {
  local names=("$@")
  [ ${#names[@]} -gt 0 ] || names=(gpu_gflip3d gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh gpu_parallel)
  for t in "${names[@]}"; do
    if [ -x "$tbin/$t" ]; then step "$t" 300 "$tbin/$t"; fi  # (gpu_gflip3d: 203 s on the H100)
  done
}

# gpu_tests, then gpu_predicates: all_gpu_tests
all_gpu_tests() {
  gpu_tests
  step gpu_predicates 60 "$tbin/gpu_predicates"
}

# Whether the card has more than 120 000 MiB (an H200: room for uniform 2*10^8): big_gpu
big_gpu() {
  [ "$(nvidia-smi --query-gpu=memory.total --format=csv,noheader,nounits | head -1)" -gt 120000 ]
}

# uniform 10^7 (medians of 3) R7 times and uniform, grid and sphere 10^6 (medians of 5) R6
# times, gdel-bench-old then gdel-bench, and at 10^7 also each runner given after them
# (bench_NAME, as bench: steps TAG_e7_NAME1, ...): old_new TAG R7 R6 [bench_NAME...]
old_new() {
  local tag=$1 r7=$2 r6=$3
  shift 3
  for r in $(seq "$r7"); do
    bench_old "${tag}_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench "${tag}_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    for x in "$@"; do
      "$x" "${tag}_e7_${x#bench_}$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
  done
  for r in $(seq "$r6"); do
    bench_old "${tag}_e6_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench "${tag}_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
  done
}

# Runner A then runner B (then C, ...: bench, bench_old or a bench_NAME wrapper) on
# uniform 10^7 (medians of 3) R7 times and on uniform, grid and sphere 10^6 (medians of 5)
# R6 times; the steps are TAG_e7_NAME<r> and TAG_e6_NAME<r>, NAME "new" for bench, "old"
# for bench_old, else the wrapper's name without "bench_": ab TAG R7 R6 A B [C...]
ab() {
  local tag=$1 r7=$2 r6=$3
  shift 3
  local runners=("$@")
  ab_round() {  # ab_round SIZE_TAG ROUND ARGS... (tag, runners: ab's)
    local sz=$1 r=$2 x nm
    shift 2
    for x in "${runners[@]}"; do
      nm=${x#bench_}
      [ "$x" = bench ] && nm=new
      [ "$x" = bench_old ] && nm=old
      "$x" "${tag}_${sz}_$nm$r" 60 "$@"
    done
  }
  for r in $(seq "$r7"); do
    ab_round e7 "$r" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
  done
  for r in $(seq "$r6"); do
    ab_round e6 "$r" --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
  done
}

# uniform, grid and sphere 10^6 (medians of 5) under each GDEL_SPLIT_EXACT value given,
# ROUNDS times (session 49): split_rounds TAG VALUES...
split_rounds() {
  local tag=$1
  shift
  for r in $(seq "${ROUNDS:-2}"); do
    for v in "$@"; do
      GDEL_SPLIT_EXACT=$v bench "${tag}_split${v}_$r" 60 --dist uniform,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 5
    done
  done
}

# The registers and stack per thread of each binary's heaviest kernels (cuobjdump), and of
# flip_iteration's exact passes: res_usage BINARY... (names in the binaries' folder)
res_usage() {
  for b in "$@"; do
    cuobjdump -res-usage "$bin/$b" >"/tmp/res-$b.txt" 2>&1
    python3 - "$b" "/tmp/res-$b.txt" <<'PY' | tee -a "$out/summary.txt"
import re, subprocess, sys
items = re.findall(r"Function ([^\s:]+):\s*\n\s*REG:(\d+) STACK:(\d+)", open(sys.argv[2]).read())
names = subprocess.run(["c++filt"], input="\n".join(i[0] for i in items), capture_output=True, text=True).stdout.split("\n")
rows = sorted(((int(s), int(r), n) for (_, r, s), n in zip(items, names)), reverse=True)
print(f"== {sys.argv[1]}: {len(rows)} kernels, {sum(r == 255 for _, r, _ in rows)} at 255 registers")
for s, r, n in rows[:8]:
    m = re.findall(r"(GFlip3D|Splayer|GDel3D|GStar4D)<[^>]*>::(\w+)", n)
    print(f"   stack {s:6d} B  regs {r:3d}  {m[-1] if m else n[:80]}")
for s, r, n in rows:
    if n.startswith("void gdel::par::detail::scratch_kernel") and "flip_iteration" in n:
        free = " (scratch-free)" if n.startswith("void gdel::par::detail::scratch_kernel<true") else ""
        print(f"   stack {s:6d} B  regs {r:3d}  flip_iteration's exact pass{free}")
for free in ("true", "false"):  # the exact passes' kernels, scratch-free (session 42) and with a scratch
    ks = [(r, s) for s, r, n in rows if n.startswith(f"void gdel::par::detail::scratch_kernel<{free}")]
    if ks:
        regs = sorted(r for r, _ in ks)
        print(f"   scratch_kernel<{free}>: {len(ks)} kernels, {sum(r == 255 for r in regs)} at 255 registers, "
              f"median {regs[len(regs) // 2]} registers, most stack {max(s for _, s in ks)} B")
PY
  done
}

# gdel-bench-old against gdel-bench: alternating, two rounds, at 10^6 on uniform, grid,
# sphere (medians of 5); uniform 10^7 both; a step profile of each on sphere and grid;
# both binaries' registers and stacks: oldnew TAG
oldnew() {
  local tag=$1
  alternate "$tag" --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
  ROUNDS=1 alternate "${tag}_e7" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
  GDEL_PROFILE=1 ROUNDS=1 alternate "${tag}_prof" --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
  res_usage gdel-bench-old gdel-bench
}

# The gFlip3D/gDel3D comparison of an old and a new binary: tests, alternate on uniform,
# grid and sphere 10^6, uniform 10^7 old then new, step profiles of new: flipcmp TAG
flipcmp() {
  local tag=$1
  step gflip3d 150 "$tbin/gpu_gflip3d"
  step gdel3d 200 "$tbin/gpu_gdel3d"
  alternate "$tag" --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
  step "${tag}_old7" 60 "$bin/gdel-bench-old" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
  bench "${tag}_new7" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
  GDEL_PROFILE=1 bench "${tag}_prof" 60 --dist sphere,grid,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
}

# The flip kernels' resources (cuobjdump: registers, stack) and counters (ncu: 48 of
# commit_flips' kernels of a uniform 10^6 run, past its first 1 200) for each binary
# named: ncu_flips TAG BINARY...
ncu_flips() {
  local tag=$1
  shift
  local ncu
  ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
  for b in "$@"; do
    { echo "== $b"; cuobjdump -res-usage "$bin/$b" 2>&1 | grep -A1 commit_flips; } >>"$out/resusage.txt"
    step "${tag}_ncu_$b" 120 "$ncu" --clock-control none --kernel-name-base mangled -k regex:commit_flips --launch-skip 1200 --launch-count 48 \
      --csv --metrics gpu__time_duration.sum,dram__bytes_read.sum,dram__bytes_write.sum,launch__registers_per_thread,sm__warps_active.avg.pct_of_peak_sustained_active,l1tex__t_bytes_pipe_lsu_mem_local_op_ld.sum,l1tex__t_bytes_pipe_lsu_mem_local_op_st.sum,launch__grid_size \
      "$bin/$b" --dist uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    cp "/tmp/gpu-run-${tag}_ncu_$b.log" "$out/ncu_$b.csv" 2>/dev/null
  done
}

# Per-kernel GPU time (ncu, gpu__time_duration of the kernels whose mangled name matches
# REGEX, summed by kernel) of each binary named, on the same arguments; NCU_METRICS=LIST adds
# metrics, summed alike (smsp__inst_executed.sum with smsp__thread_inst_executed.sum also
# prints the threads per warp instruction):
# ncu_kernels TAG REGEX "BINARY..." ARGS...
ncu_kernels() {
  local tag=$1 regex=$2 bins=$3
  shift 3
  local ncu
  ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
  for b in $bins; do
    step "${tag}_ncu_$b" 170 "$ncu" --clock-control none --kernel-name-base mangled -k "regex:$regex" --csv \
      --metrics "gpu__time_duration.sum${NCU_METRICS:+,$NCU_METRICS}" "$bin/$b" "$@"
    python3 - "$b" "/tmp/gpu-run-${tag}_ncu_$b.log" <<'PY' | tee -a "$out/summary.txt"
import collections, csv, os, re, subprocess, sys
lines = [l for l in open(sys.argv[2], errors="replace") if l.startswith('"')]
tot, cnt = collections.defaultdict(collections.Counter), collections.Counter()
ms = {"ns": 1e-6, "nsecond": 1e-6, "us": 1e-3, "usecond": 1e-3, "ms": 1, "msecond": 1, "s": 1e3, "second": 1e3}
for r in csv.DictReader(lines):
    m, v = r.get("Metric Name"), float(r["Metric Value"].replace(",", "") or 0)
    if m == "gpu__time_duration.sum":
        v *= ms.get(r.get("Metric Unit"), 1e-6)
        cnt[r["Kernel Name"]] += 1
    tot[r["Kernel Name"]][m] += v
names = list(tot)
dem = subprocess.run(["c++filt"], input="\n".join(names), capture_output=True, text=True).stdout.split("\n")
T = lambda n: tot[n]["gpu__time_duration.sum"]
print(f"== {sys.argv[1]}: {sum(cnt.values())} launches, {sum(T(n) for n in names):.2f} ms in all")
for n, d in sorted(zip(names, dem), key=lambda x: -T(x[0]))[:int(os.environ.get("NCU_TOP", "12"))]:
    kind = "free " if "scratch_kernel<true" in d else "scratch " if "scratch_kernel<false" in d else ""
    m = re.findall(r"(Splayer|GDel3D|GFlip3D|TetMesh)<[^>]*>::(\w+)", d)
    lam = re.findall(r"lambda\(([^)]*)\)#(\d+)", d)
    where = "::".join(m[-1]) if m else d[:60]
    extra = ""
    for k, v in tot[n].items():
        if k != "gpu__time_duration.sum":
            extra += f"  {k.split('.')[0]} {v / 1e9:.2f} G" if v >= 1e6 else f"  {k.split('.')[0]} {v:.0f}"
    wi, ti = tot[n].get("smsp__inst_executed.sum"), tot[n].get("smsp__thread_inst_executed.sum")
    if wi and ti:
        extra += f"  {ti / wi:.2f} thr/inst"
    print(f"   {T(n):8.2f} ms {cnt[n]:5d}x  {kind}{where} {('lambda#' + lam[-1][1]) if lam else ''}{extra}")
PY
  done
}

case "$plan" in
  tests)  # the GPU tests of gstar4d and its stages, and the gdel3d regression tests
    step star_stage 120 "$tbin/gpu_star_stage"
    step gstar4d_million 150 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    step pba 120 "$tbin/gpu_pba"
    step gdel3d 150 "$tbin/gpu_gdel3d"
    step gstar4d_generators 400 "$tbin/gpu_gstar4d" --gtest_filter='*AllGenerators*'
    ;;
  bench1)  # all generators at 10^5 and 10^6, sphere small, the scanned models; gpu_star_stage under cuda-gdb
    if [ -x "$tbin/gpu_star_stage" ]; then
      step star_stage_gdb 60 cuda-gdb -batch -ex run -ex bt -ex 'info threads' --args "$tbin/gpu_star_stage"
    fi
    d=uniform,gaussian,thin_shell,ball
    bench gpu_dists 100 --dist $d --n 100000,1000000 --methods gstar4d-cuda,gdel3d-cuda --repeat 3
    bench gpu_grid 120 --dist grid --n 100000,1000000 --methods gdel3d-cuda,gstar4d-cuda --repeat 1
    bench cgal_dists 110 --dist $d,grid --n 100000,1000000 --methods cgal,cgal-par --repeat 1
    bench sphere 80 --dist sphere --n 2000,10000 --methods gdel3d-cuda,cgal,cgal-par,gstar4d-cuda --repeat 1
    m=.deps/models
    bench models 60 --dist $m/bunny00.off,$m/armadillo.off,$m/ChineseDragon-10kv.off,$m/blade.off,$m/building.ply,$m/b9_training.ply \
      --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 3
    ;;
  bench7)  # 10^7 (gstar4d at 10^7 is plan star7), plus the leftovers of bench1
    bench sphere_small 40 --dist sphere --n 300,1000 --methods gstar4d-cuda,gdel3d-cuda --repeat 1
    m=.deps/models
    bench models2 40 --dist $m/building.ply,$m/b9_training.ply --methods cgal,cgal-par,gdel3d-cuda,gstar4d-cuda --repeat 1
    if [ -x "$tbin/gpu_star_stage" ]; then  # caller of the null-pointer call (bt cannot unwind from pc 0)
      step star_stage_gdb 40 cuda-gdb -batch -ex run -ex 'x/8a $sp' -ex 'info registers rip rsp' --args "$tbin/gpu_star_stage"
    fi
    bench e7_gdel3d 60 --dist uniform,gaussian --n 10000000 --methods gdel3d-cuda --repeat 1
    bench e7_cgal 190 --dist uniform,gaussian --n 10000000 --methods cgal-par,cgal --repeat 1
    ;;
  star7)  # gstar4d at 3*10^6 and 10^7 (a first try took the device machine down with it), memory logged
    nvidia-smi --query-gpu=memory.used --format=csv,noheader -lms 500 >"$out/gpu_mem.txt" 2>&1 &
    bench s3_gpu 60 --dist uniform --n 3000000 --methods gstar4d-cuda --repeat 1
    bench e7_gstar4d 150 --dist uniform,gaussian --n 10000000 --methods gstar4d-cuda --repeat 1
    kill %1 2>/dev/null
    ;;
  greg3d)  # gReg3D's GPU tests, the hostile-input regressions, gReg3D against CGAL Regular_triangulation_3
    step greg3d_tests 200 "$tbin/gpu_greg3d"
    step hostile 170 "$tbin/gpu_hostile"
    bench reg_1e5_1e6 120 --dist uniform,gaussian,ball --n 100000,1000000 \
      --methods greg3d-cuda,cgal-regular,cgal-regular-par --repeat 1
    bench reg_1e7 150 --dist uniform --n 10000000 --methods greg3d-cuda,cgal-regular-par,cgal-regular --repeat 1
    ;;
  perf)  # step profiles (GDEL_PROFILE=1, parallel/profile.hpp) of gFlip3D and gDel3D, output on the
          # host and in device memory; the CPU backend on 2 host cores against CGAL on the same cores
    export GDEL_PROFILE=1
    bench p_e6 90 --dist uniform,thin_shell,gaussian --n 1000000 --methods gflip3d-cuda,gdel3d-cuda,gdel3d-cuda-dev --repeat 1
    bench p_e7 120 --dist uniform --n 10000000 --methods gdel3d-cuda-dev,gdel3d-cuda,gflip3d-cuda --repeat 1
    step p_cpu2 200 taskset -c 0,1 env OMP_NUM_THREADS=2 OMP_WAIT_POLICY=PASSIVE "$gb" --dist uniform \
      --n 100000,1000000 --methods gdel3d-cpu,cgal --repeat 1
    unset GDEL_PROFILE
    ;;
  s5tests)  # 2026-11-24: gStar4D with ∞ (all generators, 10^6 incl. grid and sphere, models), the grid start
    step gstar4d_generators 150 "$tbin/gpu_gstar4d" --gtest_filter='*AllGenerators*'
    step gstar4d_million 120 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    step gstar4d_grid_sphere 150 "$tbin/gpu_gstar4d" --gtest_filter='*MillionGrid*:*MillionSphere*'
    step models 100 "$tbin/gpu_models"
    step grid_initial 150 "$tbin/gpu_grid"
    ;;
  s5million)  # the 10^6 gStar4D tests alone
    step gstar4d_million 120 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    step gstar4d_grid_sphere 150 "$tbin/gpu_gstar4d" --gtest_filter='*MillionGrid*:*MillionSphere*'
    ;;
  s5bench)  # gStar4D vs gDel3D vs CGAL, every generator at 10^5 and 10^6, same run and points
    bench s5_e5 100 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 100000 \
      --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s5_e6 300 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 \
      --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s5_skew 60 --dist skew_lines --n 10000 --methods gstar4d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    ;;
  s5e7)  # 10^7: gStar4D vs gDel3D vs CGAL parallel and sequential (uniform), gStar4D memory logged
    nvidia-smi --query-gpu=memory.used --format=csv,noheader -lms 500 >"$out/gpu_mem.txt" 2>&1 &
    bench s5_e7 300 --dist uniform,gaussian,grid --n 10000000 --methods gstar4d-cuda,gdel3d-cuda,cgal-par --repeat 1
    bench s5_e7_cgal 150 --dist uniform --n 10000000 --methods cgal --repeat 1
    kill %1 2>/dev/null
    ;;
  s5grid)  # Options::initial = grid against the default start, 10^6 of every generator (skew lines 10^4)
    bench s5_grid 300 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 \
      --methods gflip3d-cuda,gflip3d-grid-cuda,gdel3d-cuda,gdel3d-grid-cuda --repeat 1
    bench s5_grid_skew 60 --dist skew_lines --n 10000 \
      --methods gflip3d-cuda,gflip3d-grid-cuda,gdel3d-cuda,gdel3d-grid-cuda --repeat 1
    ;;
  s5checks)  # after the non-optimal flips and the memory estimate: the GPU tests they touch, the grid start
             # again, compute-sanitizer on gReg3D (racecheck) and on the two new options
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 100 "$tbin/gpu_gdel3d"
    step hostile 170 "$tbin/gpu_hostile"
    step grid_initial 80 "$tbin/gpu_grid" --gtest_filter='*AllGenerators*'
    cs=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
    step racecheck_greg3d 60 "$cs" --tool racecheck --error-exitcode 9 "$gb" --dist uniform --n 2000 \
      --methods greg3d-cuda --repeat 1 --no-verify
    step memcheck_options 60 "$cs" --tool memcheck --leak-check full --error-exitcode 9 "$gb" --dist uniform --n 2000 \
      --methods gflip3d-grid-cuda,gdel3d-grid-cuda,gflip3d-nonopt-cuda,gflip3d-terminal-nonopt-cuda --repeat 1 --no-verify
    step racecheck_options 60 "$cs" --tool racecheck --error-exitcode 9 "$gb" --dist uniform --n 2000 \
      --methods gflip3d-grid-cuda,gflip3d-nonopt-cuda --repeat 1 --no-verify
    ;;
  s5options)  # grid start and non-optimal flips against the defaults, 10^6 of every generator; 10^7 gStar4D
    bench s5_grid 170 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 \
      --methods gflip3d-cuda,gflip3d-grid-cuda,gdel3d-cuda,gdel3d-grid-cuda --repeat 1
    bench s5_nonopt 170 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 \
      --methods gflip3d-nonopt-cuda,gflip3d-terminal-cuda,gflip3d-terminal-nonopt-cuda,gdel3d-nonopt-cuda --repeat 1
    bench s5_e7 200 --dist uniform --n 10000000 --methods gstar4d-cuda,gdel3d-cuda,gflip3d-grid-cuda,gdel3d-grid-cuda,cgal-par --repeat 1
    ;;
  s5race)  # compute-sanitizer racecheck where the gdel-bench runs were too slow under it: gReg3D and the two
           # new options, through the gdel command on 500 points (no warm-up run)
    cs=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
    "$bin/gdel" generate uniform 500 -o /tmp/race.xyz >/dev/null
    awk '{print 0.001*(NR%7)}' /tmp/race.xyz >/tmp/race_w.txt
    step racecheck_greg3d 200 "$cs" --tool racecheck --error-exitcode 9 "$bin/gdel" regular /tmp/race.xyz \
      --weights /tmp/race_w.txt -o /tmp/race_r.ele --device cuda --check
    step racecheck_options 150 "$cs" --tool racecheck --error-exitcode 9 "$bin/gdel" delaunay --example uniform:500 \
      --initial grid --nonoptimal-flips --algorithm gdel3d --device cuda -o /tmp/race_g.ele --check
    ;;
  s5auto)  # Auto (gdel3d + non-optimal flips when few facets are stuck): the GPU tests it touches, and the
           # gDel3D benchmark of issue 4 in one process per table: uniform 10^5..10^7 and 10^6 of every other
           # generator (skew lines 10^4: Θ(n²) tets), against CGAL sequential and parallel
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 60 "$tbin/gpu_gdel3d"
    step grid_initial 60 "$tbin/gpu_grid" --gtest_filter='*AllGenerators*'
    bench s5_auto_u 130 --dist uniform --n 100000,1000000,10000000 --methods auto-cuda,gdel3d-cuda,cgal-par,cgal --repeat 1
    bench s5_auto_d 90 --dist gaussian,thin_shell,ball,grid --n 1000000 --methods auto-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s5_auto_skew 30 --dist skew_lines --n 10000 --methods auto-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s5_auto_sphere 170 --dist sphere --n 1000000 --methods auto-cuda,gdel3d-cuda,cgal --repeat 1
    ;;
  s6skew)  # 2026-11-24 (session 6): two skew lines after the tie-break and CPU serial-cutoff changes: the
            # 10^4 structural test (Θ(n²) = 25 M tets), gdel vs CGAL on skew lines, 10^6 uniform / thin
            # shell to see that the tie-break changed nothing there, then the gFlip3D/gDel3D tests
    step gdel3d_skew 150 "$tbin/gpu_gdel3d" --gtest_filter='*SkewLines*'
    bench s6_skew 100 --dist skew_lines --n 2000,4000 --methods gflip3d-cuda,gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s6_skew_e4 120 --dist skew_lines --n 10000 --methods gdel3d-cuda,cgal,cgal-par --repeat 1
    bench s6_e6 50 --dist uniform,thin_shell --n 1000000 --methods gflip3d-cuda,gdel3d-cuda --repeat 1
    step gdel3d 80 "$tbin/gpu_gdel3d" --gtest_filter='-*SkewLines*'
    step gflip3d 120 "$tbin/gpu_gflip3d"
    ;;
  s6tie)  # the three tie-break modes of gFlip3D's insertion key (GDEL_TIE_BREAK, src/flip/gflip3d.hpp) on
           # every generator at 10^6 (Auto and gdel3d) and on skew lines; then the tests with the default
    for mode in hash dyadic first; do
      export GDEL_TIE_BREAK=$mode
      bench "t_${mode}" 90 --dist grid,sphere,uniform,thin_shell --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
      bench "t_${mode}_skew" 30 --dist skew_lines --n 2000 --methods gdel3d-cuda --repeat 1
      step "gdel3d_${mode}" 30 "$tbin/gpu_gdel3d" --gtest_filter='-*SkewLines*'
    done
    unset GDEL_TIE_BREAK
    ;;
  s6hybrid)  # the default tie-break "hybrid" (hash among zero scores, smallest id otherwise): the generators
              # that decided it, the skew-lines 10^4 test and the gFlip3D / gDel3D tests
    bench h_e6 90 --dist grid,sphere,uniform,thin_shell,gaussian,ball --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
    bench h_skew 40 --dist skew_lines --n 2000 --methods gdel3d-cuda --repeat 1
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    ;;
  s7hash)  # 2026-11-25 (session 7): "hash" the default tie-break again (hybrid dropped): where the grid's
           # repair spends its time (GDEL_SPLAY_DEBUG laps, GDEL_PROFILE steps; "first" for contrast), the
           # skew lines, the gFlip3D / gDel3D tests, every generator at 10^6
    export GDEL_SPLAY_DEBUG=1 GDEL_PROFILE=1
    bench g_hash 90 --dist grid --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
    GDEL_TIE_BREAK=first bench g_first 60 --dist grid --n 1000000 --methods auto-cuda --repeat 1
    unset GDEL_SPLAY_DEBUG GDEL_PROFILE
    bench h_skew 40 --dist skew_lines --n 2000 --methods gdel3d-cuda --repeat 1
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    bench h_e6 90 --dist uniform,gaussian,ball,thin_shell,sphere --n 1000000 --methods auto-cuda --repeat 1
    ;;
  s7star)  # star insertion with O(beyond + fan) bookkeeping: the grid's huge hull-vertex star (repair laps), every
           # generator at 10^6, then the tests of everything that inserts into stars (gDel3D incl. issue 4's
           # sizes 10^4..10^6, gStar4D, gReg3D)
    GDEL_SPLAY_DEBUG=1 bench s_grid 60 --dist grid --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
    bench s_e6 60 --dist uniform,gaussian,ball,thin_shell,sphere --n 1000000 --methods auto-cuda --repeat 1
    step gdel3d 240 "$tbin/gpu_gdel3d"
    step gstar4d 150 "$tbin/gpu_gstar4d"
    step greg3d 100 "$tbin/gpu_greg3d"
    ;;
  s7host)  # huge failed stars (working set > 512) built on the host: the grid's repair laps, every generator
           # at 10^6 with CGAL in the same run, and the tests of everything that builds stars
    GDEL_SPLAY_DEBUG=1 bench h_grid 60 --dist grid --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
    bench h_e6 120 --dist grid,uniform,gaussian,ball,thin_shell --n 1000000 --methods auto-cuda,cgal,cgal-par --repeat 1
    bench h_sphere 90 --dist sphere --n 1000000 --methods auto-cuda,cgal,cgal-par --repeat 1
    step gdel3d 240 "$tbin/gpu_gdel3d"
    step gstar4d 120 "$tbin/gpu_gstar4d"
    step greg3d 100 "$tbin/gpu_greg3d"
    ;;
  s7min)  # where the grid's failed-star build spends its time: the host-build threshold GDEL_HOST_STAR_MIN swept
    export GDEL_SPLAY_DEBUG=1
    for m in 1000000 2048 512 128 32; do
      GDEL_HOST_STAR_MIN=$m bench "m_$m" 40 --dist grid --n 1000000 --methods gdel3d-cuda --repeat 1
    done
    GDEL_HOST_STAR_MIN=32 bench m_32_sphere 40 --dist sphere --n 1000000 --methods gdel3d-cuda --repeat 1
    bench m_def_sphere 40 --dist sphere --n 1000000 --methods gdel3d-cuda --repeat 1
    unset GDEL_SPLAY_DEBUG
    ;;
  s7fix)  # after the sorted in-T check of rebuilt stars: grid laps, every generator at 10^6, the gDel3D tests
    GDEL_SPLAY_DEBUG=1 bench f_grid 60 --dist grid --n 1000000 --methods auto-cuda,gdel3d-cuda --repeat 1
    bench f_e6 90 --dist uniform,gaussian,ball,thin_shell,sphere,grid --n 1000000 --methods auto-cuda --repeat 3
    step gdel3d 240 "$tbin/gpu_gdel3d"
    ;;
  s8ff)  # Flip-Flop convexification of failed stars vs their rebuild; the gDel3D tests; the models
    GDEL_SPLAY_DEBUG=1 bench ff_laps 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda --repeat 1
    bench ff_e6 100 --dist uniform,gaussian,ball,thin_shell,sphere,grid --n 1000000 --methods auto-cuda --repeat 3
    GDEL_STAR_BUILD=rebuild bench rb_e6 100 --dist uniform,gaussian,ball,thin_shell,sphere,grid --n 1000000 \
      --methods auto-cuda --repeat 3
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step models 100 "$tbin/gpu_models"
    ;;
  s8tests)  # after s8ff: the rebuild's laps on sphere and grid; the engine's other users' GPU tests
    GDEL_STAR_BUILD=rebuild GDEL_SPLAY_DEBUG=1 bench rb_laps 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda \
      --repeat 1
    step gstar4d 200 "$tbin/gpu_gstar4d"
    step greg3d 150 "$tbin/gpu_greg3d"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    ;;
  s8cgal)  # issue 4's benchmark with Flip-Flop the default: gdel3d against CGAL sequential and parallel
    bench c_uniform 200 --dist uniform --n 100000,1000000,10000000 --methods gdel3d-cuda,cgal,cgal-par --repeat 1
    bench c_e6 120 --dist gaussian,ball,thin_shell,grid --n 1000000 --methods gdel3d-cuda,cgal,cgal-par --repeat 1
    bench c_sphere 200 --dist sphere --n 1000000 --methods gdel3d-cuda,cgal --repeat 1
    ;;
  s9mem)  # 2026-11-25 session 9, memory: the GPU tests of the changed gFlip3D/mesh code, every generator
           # at 10^6 and uniform 10^7 (time and peak bytes per point; CGAL-par beside), one step profile
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    bench s9_e6 150 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 \
      --methods auto-cuda,gdel3d-cuda-dev --repeat 3
    bench s9_e7 90 --dist uniform --n 10000000 --methods gdel3d-cuda-dev,auto-cuda,cgal-par --repeat 1
    GDEL_PROFILE=1 step s9_e7_profile 40 "$gb" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s9scale)  # 10^8 uniform points on one GPU (no verification: the verifier needs ≈ 1.5 KB per point), step
            # profile with memory; 3*10^7 verified
    GDEL_PROFILE=1 step s9_e8 300 "$gb" --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    bench s9_3e7 100 --dist uniform --n 30000000 --methods gdel3d-cuda-dev --repeat 1
    # the issue's anchors were taken on an H200: the same table there
    bench s9h_e6 90 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods auto-cuda,gdel3d-cuda-dev \
      --repeat 3
    bench s9h_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev,auto-cuda --repeat 3
    ;;
  s10tests)  # 2026-11-25 session 10: the chunked verifier (GPU against CPU, tiny chunks), the flip cap, the
              # output that consumes the mesh, the new memory estimate
    step verify_grid 90 "$tbin/gpu_verify_grid"
    step gflip3d 180 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step hostile_estimate 90 "$tbin/gpu_hostile" --gtest_filter='*MemoryEstimate*'
    ;;
  s10scale)  # 10^8 uniform, verified in the same run (chunked verifier), with the step profile; 10^7 and 10^6
    GDEL_PROFILE=1 bench s10_e8 420 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    bench s10_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s10_e6 60 --dist uniform,sphere --n 1000000 --methods gdel3d-cuda-dev,auto-cuda --repeat 3
    ;;
  s10final)  # the session's last binaries in one call (within GDEL_CALL_BUDGET): 10^8 verified with the step
              # profile first, then the GPU tests of the changed code, then 10^7
    GDEL_PROFILE=1 bench s10f_e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    step verify_grid 40 "$tbin/gpu_verify_grid"
    step gflip3d 100 "$tbin/gpu_gflip3d"
    step gdel3d 140 "$tbin/gpu_gdel3d"
    step hostile_estimate 40 "$tbin/gpu_hostile" --gtest_filter='*MemoryEstimate*'
    bench s10f_e7 40 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s10apex)  # the apex across a face from the neighbour's vertices: gFlip3D tests (the resized flip-cap test),
             # gDel3D at scale, 10^7 time (a short call: little device time was left)
    step gflip3d 60 "$tbin/gpu_gflip3d" --gtest_filter='*FlipCap*:*AllGenerators:*LogFlushes*'
    step gdel3d 40 "$tbin/gpu_gdel3d" --gtest_filter='*AllGeneratorsAtScale*:*Degenerate*'
    bench s10a_e7 30 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s11splits)  # 2026-11-25 session 11: independent splits + stuck tets kept active. gFlip3D's stuck facets
               # (exact verifier) with and without, then the time of gdel3d / Auto both ways, then the tests
    bench s11_q 120 --dist uniform,gaussian,thin_shell --n 1000000 \
      --methods gflip3d-cuda,gflip3d-allsplit-cuda,gflip3d-nonopt-cuda --repeat 1
    bench s11_t6 150 --dist uniform,thin_shell,grid,sphere --n 1000000 \
      --methods gdel3d-cuda-dev,gdel3d-allsplit-cuda-dev,auto-cuda --repeat 3
    bench s11_t7 80 --dist uniform --n 10000000 --methods gdel3d-cuda-dev,gdel3d-allsplit-cuda-dev --repeat 3
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step gdel3d 150 "$tbin/gpu_gdel3d"
    ;;
  s11b)  # independent splits on for gflip3d only: the GPU tests, then the exact algorithms' time (back to
          # the original rule) and gflip3d on the degenerate inputs
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    bench s11b_t6 120 --dist uniform,thin_shell,grid,sphere --n 1000000 --methods gdel3d-cuda-dev,auto-cuda,gflip3d-cuda \
      --repeat 3
    bench s11b_t7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev,gflip3d-cuda --repeat 3
    ;;
  s11c)  # the final binaries (independent splits an option, off by default): 10^8 with the option and the
          # step profile (its smaller rounds hold less memory), verified; then the GPU tests
    GDEL_PROFILE=1 bench s11c_e8 250 --dist uniform --n 100000000 --methods gdel3d-indsplit-cuda-dev --repeat 1
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step gdel3d 160 "$tbin/gpu_gdel3d"
    ;;
  s12)  # non-optimal flips by any valid ring triangulation of any edge of a stuck facet, and under
         # independent splits a non-optimal round after every InsFlip round: the 10^6 quality table
         # (four seeds on the thin shell), sphere and grid time, then the GPU tests
    bench s12_q 150 --dist thin_shell,uniform,gaussian --n 1000000 \
      --methods gflip3d-cuda,gflip3d-nonopt-cuda,gflip3d-indsplit-cuda,gflip3d-indsplit-nonopt-cuda --repeat 1
    for s in 1 2 3; do
      bench "s12_seed$s" 40 --dist thin_shell --n 1000000 --seed "$s" \
        --methods gflip3d-indsplit-cuda,gflip3d-indsplit-nonopt-cuda --repeat 1
    done
    bench s12_t 90 --dist uniform,sphere,grid --n 1000000 --methods gdel3d-cuda-dev,gflip3d-indsplit-nonopt-cuda --repeat 1
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step gdel3d 160 "$tbin/gpu_gdel3d"
    ;;
  s12b)  # the final binaries (the rounds at the end remove blocking edges only) against those of s12
          # (carried as build/s12: the rounds at the end removed other edges too), Auto included,
          # in the same call; then the thin-shell seeds again and the GPU tests
    old=build/s12/gdel-bench
    for v in new old; do
      g=$gb
      [ "$v" = old ] && g=$old
      step "s12b_$v" 150 "$g" --dist uniform,thin_shell,grid --n 1000000 \
        --methods gdel3d-cuda-dev,auto-cuda,gflip3d-nonopt-cuda,gflip3d-indsplit-nonopt-cuda --repeat 3 \
        --json "$jdir/s12b_$v.json"
    done
    for s in 1 2 3; do
      bench "s12b_seed$s" 30 --dist thin_shell --n 1000000 --seed "$s" --methods gflip3d-indsplit-nonopt-cuda --repeat 1
    done
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step gdel3d 160 "$tbin/gpu_gdel3d"
    ;;
  s12c)  # issue 3's other criteria with the final binaries: the scanned models (carry .deps/models), gFlip3D's
          # stages and flips/s at 10^5..10^7, InsFlip against the terminal variant at 10^6
    export GDEL_MODELS_DIR="$PWD/.deps/models"
    step models 120 "$tbin/gpu_models"
    bench s12c_stages 120 --dist uniform --n 100000,1000000,10000000 --methods gflip3d-cuda --repeat 3
    bench s12c_term 120 --dist uniform,gaussian,thin_shell --n 1000000 --methods gflip3d-cuda,gflip3d-terminal-cuda \
      --repeat 1
    ;;
  s13)  # the flip loop's temporaries (exact-size 4-byte lists, the log reserved once and flushed before it
         # would grow): 10^8 uniform with the step profile, verified; then the GPU tests
    GDEL_PROFILE=1 bench s13_e8 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step gdel3d 160 "$tbin/gpu_gdel3d"
    ;;
  s13b)  # time against the binary before the change (carried as build/s13base), same call: 10^7 and 10^6
    old=build/s13base/gdel-bench
    for v in new old; do
      g=$gb
      [ "$v" = old ] && g=$old
      step "s13b_$v" 150 "$g" --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev,gflip3d-cuda --repeat 3 \
        --json "$jdir/s13b_$v.json"
    done
    ;;
  s14)  # the context's own memory pool (freed memory kept until the context ends) against the device's default
         # pool (GDEL_DEVICE_POOL=default: unused memory back to the driver at every host sync) and against the
         # binary before the change (7d969e5's gdel-bench carried as build/s14old), same call: 10^6 and 10^7 uniform, the
         # step profiles at 10^7, the other generators at 10^6
    old=build/s14old/gdel-bench
    for v in pool default old; do
      g=$gb
      [ "$v" = old ] && g=$old
      pool=own
      [ "$v" = default ] && pool=default
      step "s14_$v" 120 env GDEL_DEVICE_POOL=$pool "$g" --dist uniform --n 1000000,10000000 \
        --methods gdel3d-cuda-dev,gflip3d-cuda-dev --repeat 3 --json "$jdir/s14_$v.json"
    done
    for pool in own default; do
      step "s14_prof_$pool" 40 env GDEL_PROFILE=1 GDEL_DEVICE_POOL=$pool "$gb" --dist uniform --n 10000000 \
        --methods gdel3d-cuda-dev --repeat 1 --json "$jdir/s14_prof_$pool.json"
    done
    for pool in own default; do
      step "s14_gen_$pool" 90 env GDEL_DEVICE_POOL=$pool "$gb" --dist gaussian,thin_shell,ball,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev,auto-cuda-dev --repeat 1 --json "$jdir/s14_gen_$pool.json"
    done
    ;;
  s14c)  # the splaying rounds' insertions into huge stars on the host, against the binary before (s14's,
          # carried as build/s14prev), same call: grid, sphere, uniform at 10^6; then 10^8 and the GPU tests
    old=build/s14prev/gdel-bench
    for v in new old; do
      g=$gb
      [ "$v" = old ] && g=$old
      step "s14c_$v" 100 "$g" --dist grid,sphere,uniform --n 1000000 --methods gdel3d-cuda-dev,auto-cuda-dev \
        --repeat 3 --json "$jdir/s14c_$v.json"
    done
    GDEL_PROFILE=1 bench s14c_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    step gdel3d 120 "$tbin/gpu_gdel3d"
    step gflip3d 100 "$tbin/gpu_gflip3d"
    step hostile 60 "$tbin/gpu_hostile"
    ;;
  s14d)  # after the host jobs' refactor (one HostStar record and write-back): grid and uniform at 10^6, gpu_gdel3d
    bench s14d 60 --dist grid,uniform --n 1000000 --methods gdel3d-cuda-dev,auto-cuda-dev --repeat 3
    step gdel3d 120 "$tbin/gpu_gdel3d"
    ;;
  s15)  # after the CPU backend's one point per round: GPU tests (their cases changed), GPU uniform as in s14, CPU backend on the host's threads against CGAL
    step gdel3d 150 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step hostile 90 "$tbin/gpu_hostile"
    bench s15gpu 90 --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s15cpu 120 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal,cgal-par --repeat 3
    ;;
  s16a)  # session 16's GPU-facing changes: filters' cheap bound (predicates vs GMP), one-sort prepare (parallel), match_open_faces (star stage; its test binary has crashed at start since session 11: RESULTS 2026-11-24), the regression tests
    step parallel 60 "$tbin/gpu_parallel"
    step predicates 90 "$tbin/gpu_predicates"
    step star_stage 120 "$tbin/gpu_star_stage"
    step gdel3d 150 "$tbin/gpu_gdel3d"
    ;;
  s16b)  # the rest of the regression tests (two calls: the carry limit); GPU uniform as in s15; CPU backend on the host's threads with blocks held 4 points (default) and 1, against CGAL
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step hostile 90 "$tbin/gpu_hostile"
    step gstar4d_million 60 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    bench s16gpu 90 --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s16cpu 120 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal,cgal-par --repeat 3
    GDEL_CPU_HOLD=1 bench s16cpu_hold1 60 --dist uniform --n 1000000 --methods gdel3d-cpu --repeat 3
    ;;
  s16c)  # the other generators at 10^6 on the GPU (targets table), and the CPU backend with blocks held 8 points
    bench s16gen 200 --dist gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_CPU_HOLD=8 bench s16cpu_hold8 60 --dist uniform --n 1000000 --methods gdel3d-cpu --repeat 3
    ;;
  s16d)  # the CPU backend (a CPU-only gdel-bench built here) on the host's 16 threads after the OpenMP team change, against CGAL
    bench s16d_cpu 150 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal,cgal-par --repeat 3
    ;;
  s16e)  # the same, session 15's last CPU build (gdel-bench-old, b63c253) and this one in one call, alternating
    for r in 1 2; do
      step "s16e_old$r" 60 "$bin/gdel-bench-old" --dist uniform --n 1000000 --methods gdel3d-cpu,cgal-par --repeat 3
      bench "s16e_new$r" 60 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal-par --repeat 3
    done
    ;;
  s16f)  # after par::on_host_threads (the splayer's host jobs on OpenMP's team): the regression tests on the final binaries
    step parallel 60 "$tbin/gpu_parallel"
    step gdel3d 150 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step hostile 90 "$tbin/gpu_hostile"
    ;;
  s16g)  # after the review (lexicographic_sort, Geo::volume_sign_*): the regression tests and gStar4D's extract on the device
    step parallel 60 "$tbin/gpu_parallel"
    step gdel3d 150 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step hostile 90 "$tbin/gpu_hostile"
    step gstar4d_million 60 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    ;;
  s17a)  # session 17: __device__ lambdas (gpu_star_stage), the predicates' integer stage on the device (GMP), and
          # its effect on grid and sphere: gdel-bench-old (7099925: no integer stage), this build with the integer
          # decision of the fast forms off (GDEL_INTEGER_FAST=0: the integer stage in the deferred exact pass only)
          # and on (default), alternating
    step predicates 90 "$tbin/gpu_predicates"
    step star_stage 120 "$tbin/gpu_star_stage"
    step parallel 60 "$tbin/gpu_parallel"
    for r in 1 2; do
      step "s17a_old$r" 90 "$bin/gdel-bench-old" --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
      GDEL_INTEGER_FAST=0 bench "s17a_slow$r" 90 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
      bench "s17a_new$r" 90 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    done
    step s17a_old_uniform 60 "$bin/gdel-bench-old" --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s17a_uniform 60 --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s17b)  # session 17: the regression tests on the final binaries (regular triangulation and gStar4D use the integer stage too)
    step gdel3d 150 "$tbin/gpu_gdel3d"
    step gflip3d 120 "$tbin/gpu_gflip3d"
    step hostile 90 "$tbin/gpu_hostile"
    step greg3d 120 "$tbin/gpu_greg3d"
    step gstar4d_million 60 "$tbin/gpu_gstar4d" --gtest_filter='*MillionPoints*'
    ;;
  s17c)  # session 17, final binaries (integer stage only): uniform against gdel-bench-old (7099925) alternating, then
          # every generator at 10^6 for the targets table
    for r in 1 2; do
      step "s17c_old$r" 90 "$bin/gdel-bench-old" --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s17c_new$r" 90 --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    bench s17c_gen 200 --dist gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s18a)  # session 18: step profiles (GDEL_PROFILE) of sphere, grid and uniform at 10^6 and uniform 10^7
    for d in sphere grid uniform; do
      GDEL_PROFILE=1 bench "s18a_$d" 120 --dist $d --n 1000000 --methods gdel3d-cuda-dev --repeat 2
    done
    GDEL_PROFILE=1 bench s18a_u7 120 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s18b)  # session 18: tests; old (gdel-bench-old) / new alternating on uniform, grid, sphere; the new binary
          # without the tiered exact pass (GDEL_EXACT_TIERS=0); step profiles of grid and sphere
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    alternate s18b --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_EXACT_TIERS=0 bench s18b_notiers 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
    step s18b_old7 60 "$bin/gdel-bench-old" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s18b_new7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s18b_prof 60 --dist sphere,grid,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s18c)  # session 18: tests of the quarter scale and scratch-free passes; thread counts of the exact passes
          # (GDEL_FREE_PER_SM without a scratch, GDEL_EXACT_PER_SM with one) on grid and sphere; step profiles
    step predicates 120 "$tbin/gpu_predicates"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    for v in "GDEL_EXACT_TIERS=0" "GDEL_FREE_PER_SM=128" "GDEL_FREE_PER_SM=512" "GDEL_FREE_PER_SM=2048" \
             "GDEL_EXACT_TIERS=0 GDEL_EXACT_PER_SM=256" "GDEL_FREE_PER_SM=64"; do
      tag=$(echo "$v" | tr ' =' '__')
      timeout 90 env $v "$gb" --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3 --json "$jdir/s18c_$tag.json" \
        >"/tmp/s18c_$tag.log" 2>&1
      echo "== s18c $v" | tee -a "$out/summary.txt"
      grep -E '^(grid|sphere) ' "/tmp/s18c_$tag.log" | tee -a "$out/summary.txt"
      cat "/tmp/s18c_$tag.log" >>"$out/log.txt"
    done
    bench s18c_uniform 60 --dist uniform --n 1000000,10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s18c_prof 60 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    step gstar4d 120 "$tbin/gpu_gstar4d"
    step greg3d 120 "$tbin/gpu_greg3d"
    # per-kernel counters of 60 launches in the middle of a uniform 10^6 run (the flip loop)
    step ncu 150 ncu --clock-control none --launch-skip 2500 --launch-count 60 --section SpeedOfLight \
      --section Occupancy --section LaunchStats --section MemoryWorkloadAnalysis \
      "$gb" --dist uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s19a)  # session 19: a flip iteration's counts read by the host once (the exact passes counted on the device);
          # tests; old (gdel-bench-old) / new alternating on uniform, grid, sphere 10^6 and uniform 10^7; profiles.
          # GDEL_S19_ENV: environment for every step (the defaults chosen from s18c)
    # shellcheck disable=SC2086
    [ -n "${GDEL_S19_ENV:-}" ] && export ${GDEL_S19_ENV}
    step parallel 60 "$tbin/gpu_parallel"
    flipcmp s19a
    # the repair's star builds: which stars the host builds (working sets above GDEL_HOST_STAR_MIN), and sizes
    for hm in 512 128 48 24; do
      GDEL_HOST_STAR_MIN=$hm GDEL_SPLAY_DEBUG=1 GDEL_PROFILE=1 step "s19a_host$hm" 40 "$gb" --dist grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 1
      grep -E "largest working set|stars of failed|gdel3d repair:|splay: insert round" "/tmp/gpu-run-s19a_host$hm.log" \
        | tee -a "$out/summary.txt"
    done
    ;;
  s19b)  # session 19: s19a's change with the scratch sized by the items where the host waits anyway and one block
          # for the scratch pass on Geo::int_all input; stars above 128 built on the host. Old (e4ef07d) at its defaults
    flipcmp s19b
    ;;
  s20a)  # session 20: the repair's host stars capped (at most 4 per host thread per build or round, the largest)
          # and their scalars gathered in one copy; threshold 48. gpu_gdel3d; threshold x cap on grid and sphere
          # 10^6 (128 without a cap: session 19's setting); every generator at 10^6; uniform 10^7; 10^8 last
    step gdel3d 200 "$tbin/gpu_gdel3d"
    for v in "GDEL_HOST_STAR_MIN=128 GDEL_HOST_STAR_CAP=1000000000" "GDEL_HOST_STAR_MIN=48" \
             "GDEL_HOST_STAR_MIN=48 GDEL_HOST_STAR_CAP=16" "GDEL_HOST_STAR_MIN=48 GDEL_HOST_STAR_CAP=256" \
             "GDEL_HOST_STAR_MIN=32" "GDEL_HOST_STAR_MIN=24" "GDEL_HOST_STAR_MIN=128 GDEL_HOST_STAR_CAP=1000000000"; do
      tag=$(echo "$v" | tr ' =' '__')
      echo "== s20a $v" | tee -a "$out/summary.txt"
      # shellcheck disable=SC2086
      (export $v; bench "s20a_$tag" 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3)
    done
    bench s20a_gen 150 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_SPLAY_DEBUG=1 GDEL_PROFILE=1 step s20a_debug 40 "$gb" --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    grep -E "largest working set|gdel3d repair:|host" /tmp/gpu-run-s20a_debug.log | head -40 | tee -a "$out/summary.txt"
    bench s20a_u7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s20a_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s20b)  # session 20: s20a's binaries as gdel-bench-old; new = those plus the host path's gate (a star above 128)
          # and the next active set's length left on the device. Three columns alternating, twice: old and new
          # with session 19's host setting (128, no cap), new at its defaults; 10^6 and 10^7; profiles; 10^8
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    s19host="GDEL_HOST_STAR_MIN=128 GDEL_HOST_STAR_CAP=1000000000"
    for n in 1000000 10000000; do
      d=uniform,grid,sphere
      [ "$n" = 10000000 ] && d=uniform
      for r in 1 2; do
        # shellcheck disable=SC2086
        (export $s19host; step "s20b_old128_${n}_$r" 60 "$bin/gdel-bench-old" --dist $d --n $n --methods gdel3d-cuda-dev --repeat 3)
        # shellcheck disable=SC2086
        (export $s19host; bench "s20b_new128_${n}_$r" 60 --dist $d --n $n --methods gdel3d-cuda-dev --repeat 3)
        bench "s20b_new_${n}_$r" 60 --dist $d --n $n --methods gdel3d-cuda-dev --repeat 3
      done
    done
    GDEL_PROFILE=1 bench s20b_prof 60 --dist sphere,grid,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s20b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s20c)  # session 20, on an H100 (s20b's binaries): tests; 10^8 at the defaults (does it fit 80 GB?); then the
          # one-wait change alone (old and new at 128, no cap) in four alternating rounds, and new at its defaults
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    GDEL_PROFILE=1 bench s20c_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    s19host="GDEL_HOST_STAR_MIN=128 GDEL_HOST_STAR_CAP=1000000000"
    for r in 1 2 3 4; do
      # shellcheck disable=SC2086
      (export $s19host; step "s20c_old128_$r" 60 "$bin/gdel-bench-old" --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5)
      # shellcheck disable=SC2086
      (export $s19host; bench "s20c_new128_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5)
      bench "s20c_new_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    ;;
  s21a)  # session 21: gFlip3D's flips write each new tet whole from the record's fixed face pattern (write_flip), and
          # the adjacency pass writes a new tet's face only where another flip took its neighbour. Old = 79d2393's
          # gdel-bench. Tests; four alternating rounds at 10^6 (medians of 5), two at 10^7; step profiles at 10^7
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    ROUNDS=4 alternate s21a --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    alternate s21a_7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 step s21a_oldprof 60 "$bin/gdel-bench-old" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s21a_newprof 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ncu_flips s21a gdel-bench-old gdel-bench
    ;;
  s21b)  # session 21: B = A plus the votes stamped with the iteration (no reset pass) and propose's vector loads;
          # old = A (s21a's new). Tests; four alternating rounds at 10^6, two at 10^7; profile; ncu; 10^8 last
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    ROUNDS=4 alternate s21b --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    alternate s21b_7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s21b_newprof 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ncu_flips s21b gdel-bench
    GDEL_PROFILE=1 bench s21b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s22a)  # session 22: register-only face tables and selects (no stack in the flip kernels), records and
          # write tets fused (ExecuteFlip), compact external-face entries, the fast passes of propose and
          # ExecuteFlip at 3 and 4 resident blocks; old = s21b's code (edbea9f). Tests; resources; four
          # alternating rounds at 10^6, two at 10^7; resident blocks off against on; profile; reorder
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    for b in gdel-bench-old gdel-bench; do
      { echo "== $b"; cuobjdump -res-usage "$bin/$b" 2>&1 | grep -A1 -E 'commit_flips|flip_iteration'; } >>"$out/resusage.txt"
    done
    ROUNDS=4 alternate s22a --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    alternate s22a_7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    for r in 1 2; do
      GDEL_RESIDENT_BLOCKS=0 bench "s22a_rb0_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s22a_rb1_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    GDEL_PROFILE=1 bench s22a_prof 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_RESIDENT_BLOCKS=0 bench s22a_prof_rb0 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s22b)  # session 22, second call: tet reordering (Options::reorder_tets) at 10^7 and 10^6; 10^8 last
    for r in 1 2; do
      GDEL_TET_REORDER=1 bench "s22b_reorder_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s22b_plain_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    GDEL_PROFILE=1 bench s22b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s22c)  # session 22, third call: tet reordering at 10^6 (two pairs), its 10^7 profile, 10^8 with it
          # (run as these same gdel-bench commands typed into the call; the plan written after)
    for r in 1 2; do
      GDEL_TET_REORDER=1 bench "s22c_reorder6_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s22c_plain6_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 GDEL_TET_REORDER=1 bench s22c_prof_reorder 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_TET_REORDER=1 bench s22c_e8_reorder 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s22d)  # session 22, fourth call (s22a's binaries): every generator at 10^6, plain and reordered (two
          # rounds); resident blocks off/on at 10^7, four rounds; the GPU tests with resident blocks off
    for r in 1 2; do
      bench "s22d_gen_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_TET_REORDER=1 bench "s22d_gen_reorder_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    for r in 1 2 3 4; do
      GDEL_RESIDENT_BLOCKS=0 bench "s22d_rb0_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s22d_rb1_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    GDEL_RESIDENT_BLOCKS=0 step gflip3d_rb0 150 "$tbin/gpu_gflip3d"
    GDEL_RESIDENT_BLOCKS=0 step gdel3d_rb0 200 "$tbin/gpu_gdel3d"
    ;;
  s23a)  # session 23: lean tet reordering (a sort only under the memory peak so far; the output's
          # compaction sorted too) and resident blocks removed. old = s22a's new binary (056138a) with
          # resident blocks off, i.e. session 22's final code. Tests, plain and with GDEL_TET_REORDER=1;
          # uniform 10^7 old / new / reorder / reorder of the output only, two rounds; trace; profile
    export GDEL_RESIDENT_BLOCKS=0  # (read by the old binary only)
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    GDEL_TET_REORDER=1 step gflip3d_re 150 "$tbin/gpu_gflip3d"
    GDEL_TET_REORDER=1 step gdel3d_re 200 "$tbin/gpu_gdel3d"
    for r in 1 2; do
      step "s23a_old7_$r" 60 "$bin/gdel-bench-old" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s23a_new7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_TET_REORDER=1 bench "s23a_re7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_TET_REORDER=1 GDEL_REORDER_EVERY=0 bench "s23a_out7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    GDEL_FLIP_TRACE=1 GDEL_TET_REORDER=1 step s23a_trace7 60 "$gb" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "tet reordering" /tmp/gpu-run-s23a_trace7.log | tee -a "$out/summary.txt"
    GDEL_PROFILE=1 GDEL_TET_REORDER=1 bench s23a_prof_re 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s23b)  # session 23, second call: every generator at 10^6, plain and reordered (two rounds); 10^8 reordered
    for r in 1 2; do
      bench "s23b_gen_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_TET_REORDER=1 bench "s23b_gen_re_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_FLIP_TRACE=1 GDEL_TET_REORDER=1 bench s23b_e8_re 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "tet reordering" /tmp/gpu-run-s23b_e8_re.log | tee -a "$out/summary.txt"
    ;;
  s23c)  # session 23, third call: 10^8 plain and reordered, one run each
    bench s23c_e8 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_TET_REORDER=1 bench s23c_e8_re 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s23d)  # session 23, second call made: 10^8 reordered (trace: which sorts fit), then every generator at
          # 10^6 plain and reordered, one round, as the call's budget allows
    GDEL_FLIP_TRACE=1 GDEL_TET_REORDER=1 bench s23d_e8_re 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "tet reordering" /tmp/gpu-run-s23d_e8_re.log | tee -a "$out/summary.txt"
    bench s23d_gen 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_TET_REORDER=1 bench s23d_gen_re 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ;;
  s24a)  # session 24: tet reordering on by default (its remap now carries the stuck tets of independent
          # splits). GPU tests under the default, gpu_gflip3d also with GDEL_TET_REORDER=0
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    GDEL_TET_REORDER=0 step gflip3d_off 150 "$tbin/gpu_gflip3d"
    ;;
  s24c)  # session 24, the other GPU tests the default touches (binaries in their own folder: the carry
          # limit is 64 MiB)
    step grid 120 "$tbin/gpu_grid"
    GDEL_MODELS_DIR="$PWD/.deps/models" step models 120 "$tbin/gpu_models"  # carry .deps/models
    step hostile 200 "$tbin/gpu_hostile"
    ;;
  s24b)  # session 24, second call: uniform 10^7 default (reordered) / off / a sort every round, two
          # rounds; the independent-split seed sweep (thin shell 2e5, seeds 1-12, without and with
          # non-optimal flips, reordering off and on); every generator at 10^6; 10^8 once
    for r in 1 2; do
      bench "s24b_def7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_TET_REORDER=0 bench "s24b_off7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_EVERY=1 bench "s24b_ev1_7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for re in 0 1; do
      for s in $(seq 12); do
        GDEL_TET_REORDER=$re bench "s24b_sweep${re}_$s" 40 --dist thin_shell --n 200000 --seed "$s" \
          --methods gflip3d-indsplit-cuda,gflip3d-indsplit-nonopt-cuda --repeat 1
      done
    done
    bench s24b_gen 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_FLIP_TRACE=1 bench s24b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "tet reordering" /tmp/gpu-run-s24b_e8.log | tee -a "$out/summary.txt"
    ;;
  s25a|s27a)  # session 25: a tet sort after every round by default (every second before); the
          # independent-splits test asserts Stats::nonoptimal_between_rounds under the default
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    GDEL_TET_REORDER=0 step gflip3d_off 150 "$tbin/gpu_gflip3d"
    ;;
  s25c|s27c|s28c)  # session 25 (and 27, 28), the other GPU tests (their own folder: the carry limit is 64 MiB)
    step grid 120 "$tbin/gpu_grid"
    GDEL_MODELS_DIR="$PWD/.deps/models" step models 120 "$tbin/gpu_models"  # carry .deps/models
    step hostile 200 "$tbin/gpu_hostile"
    ;;
  s25b)  # session 25, benchmarks: uniform 10^7 default (a sort every round) against every second
          # round, two rounds; every generator at 10^6; 10^8 once (trace: which sorts fit)
    for r in 1 2; do
      bench "s25b_def7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_EVERY=2 bench "s25b_ev2_7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    bench s25b_gen 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_REORDER_EVERY=2 bench s25b_gen_ev2 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_FLIP_TRACE=1 bench s25b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "tet reordering" /tmp/gpu-run-s25b_e8.log | tee -a "$out/summary.txt"
    ;;
  s25d)  # session 25, second benchmark call: s25b saw uniform and gaussian 10^6 12 % slower with a sort
          # every round; the A/B again with every second round first, two rounds, and at 3*10^6
    for r in 1 2; do
      GDEL_REORDER_EVERY=2 bench "s25d_ev2_$r" 120 --dist uniform,gaussian,ball --n 1000000,3000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s25d_def_$r" 120 --dist uniform,gaussian,ball --n 1000000,3000000 --methods gdel3d-cuda-dev --repeat 5
    done
    ;;
  s27b)  # session 27 (binaries of 5715df1, whose default was every second round below 5*10^6 points;
          # with later binaries set GDEL_REORDER_EVERY=2 on the def steps), benchmarks: the default (by size) against a sort every round, alternating, two
          # rounds, every generator at 10^6 and uniform 3*10^6; uniform 10^7 (the default is every
          # round there); per-round traces of sphere and grid 10^6 (where the flip iterations go)
    for r in 1 2; do
      bench "s27b_def_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_REORDER_EVERY=1 bench "s27b_ev1_$r" 120 --dist uniform,gaussian,thin_shell,ball,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s27b_def3_$r" 60 --dist uniform --n 3000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_REORDER_EVERY=1 bench "s27b_ev1_3_$r" 60 --dist uniform --n 3000000 --methods gdel3d-cuda-dev --repeat 5
    done
    bench s27b_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    for d in sphere grid; do
      GDEL_FLIP_TRACE=1 bench "s27b_trace_$d" 60 --dist "$d" --n 1000000 --methods gdel3d-cuda-dev --repeat 1
      grep -h "gflip3d round" "/tmp/gpu-run-s27b_trace_$d.log" | tee -a "$out/summary.txt"
    done
    ;;
  s27d)  # session 27, s27b resolved no sign at 10^6 (uniform and gaussian each way once, ball
          # 9-12 % slower with every second round): four more alternating rounds, the order swapped
    for r in 1 2 3 4; do
      GDEL_REORDER_EVERY=1 bench "s27d_ev1_$r" 60 --dist uniform,gaussian,ball --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_REORDER_EVERY=2 bench "s27d_ev2_$r" 60 --dist uniform,gaussian,ball --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    ;;
  s27e)  # session 27: the small rounds' flip iterations (sphere 10^6 rounds 1-9: ~500 iterations,
          # ~0.13 s for 0.44 M flips): kernel durations and grids of 200 launches past the first
          # 3 000 (sphere, inside its small rounds) and of uniform 10^6 at the same depth
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for d in sphere uniform; do
      step "s27e_ncu_$d" 200 "$ncu" --clock-control none --kernel-name-base mangled --launch-skip 3000 --launch-count 200 \
        --csv --metrics gpu__time_duration.sum,launch__grid_size,launch__block_size \
        "$gb" --dist "$d" --n 1000000 --methods gdel3d-cuda-dev --repeat 1
      cp "/tmp/gpu-run-s27e_ncu_$d.log" "$out/ncu_$d.csv" 2>/dev/null
    done
    ;;
  s27f)  # session 27: the large flip iterations of uniform 10^7 (bytes a flip moves per kernel): ncu
          # durations, DRAM bytes and grids of 120 launches past the first 9 000
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    step s27f_ncu 300 "$ncu" --clock-control none --kernel-name-base mangled --launch-skip 9000 --launch-count 120 \
      --csv --metrics gpu__time_duration.sum,dram__bytes_read.sum,dram__bytes_write.sum,launch__grid_size,lts__t_sectors_srcunit_tex.sum \
      "$gb" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    cp /tmp/gpu-run-s27f_ncu.log "$out/ncu_e7.csv" 2>/dev/null
    GDEL_FLIP_TRACE=1 bench s27f_trace 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "gflip3d round" /tmp/gpu-run-s27f_trace.log | tee -a "$out/summary.txt"
    ;;
  s28a)  # session 28: the small flip iterations in two teams (GDEL_TEAM_MAX, default 2048); the GPU
          # tests under the default, with the team on every set (multi-chunk team sums) and never
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    GDEL_TEAM_MAX=100000000 step gflip3d_all 150 "$tbin/gpu_gflip3d"
    GDEL_TEAM_MAX=0 step gflip3d_none 150 "$tbin/gpu_gflip3d"
    step parallel 60 "$tbin/gpu_parallel"
    ;;
  s28b)  # session 28, benchmarks: the team (default 2048, and 1024) against none (GDEL_TEAM_MAX=0),
          # alternating, two rounds, at 10^6 on uniform, grid, sphere; uniform 10^7; 10^8 once (peak)
    for r in 1 2; do
      GDEL_TEAM_MAX=0 bench "s28b_none_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s28b_def_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_TEAM_MAX=1024 bench "s28b_1k_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_TEAM_MAX=0 bench s28b_none7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s28b_def7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s28b_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s29a)  # session 29: small iterations' proposals spread over small blocks (GDEL_TEAM_PROPOSE:
          # auto = spread on integer input, the default; spread; team); the GPU tests under each,
          # and with the teams on every set (spread then covers large sets and float input's scratch)
    step gflip3d 150 "$tbin/gpu_gflip3d"
    GDEL_TEAM_PROPOSE=spread step gflip3d_spread 150 "$tbin/gpu_gflip3d"
    GDEL_TEAM_PROPOSE=team step gflip3d_team 150 "$tbin/gpu_gflip3d"
    GDEL_TEAM_PROPOSE=spread GDEL_TEAM_MAX=100000000 step gflip3d_spread_all 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    step parallel 60 "$tbin/gpu_parallel"
    ;;
  s29b)  # session 29, benchmarks: auto (the default) against team and spread, alternating, two
          # rounds, at 10^6 on uniform, grid, sphere
    for r in 1 2; do
      GDEL_TEAM_PROPOSE=team bench "s29b_team_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s29b_auto_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_TEAM_PROPOSE=spread bench "s29b_spread_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    ;;
  s29c)  # session 29, benchmarks: the spread's block size (32 default, 64, 128) on grid and sphere;
          # the other generators at 10^6; uniform 10^7; a step profile of sphere and grid
    GDEL_SPREAD_BLOCK=64 bench s29c_b64 90 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_SPREAD_BLOCK=128 bench s29c_b128 90 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s29c_b32 90 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s29c_others 90 --dist uniform,gaussian,ball,thin_shell --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s29c_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s29c_prof 60 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s40a)  # session 40: the integer stage's narrow form (minors.hpp): the GPU tests that evaluate exact
          # predicates on integer input, in two folders (the carry limit): predicates against GMP with
          # the narrow-limit cases, the flips, the repair, gReg3D's power tests (s40a); gStar4D, the star
          # stage, hostile input (s40e)
    step predicates 200 "$tbin/gpu_predicates"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step greg3d 150 "$tbin/gpu_greg3d"
    ;;
  s40e)  # session 40: the rest of s40a's tests; then a window of the sphere's large flip iterations
          # under ncu (durations and grids only: one pass; s40c's six metrics took 3 passes a kernel and
          # did not finish in 300 s), 300 flip_iteration kernels past the first 1 800 of them
    step gstar4d 150 "$tbin/gpu_gstar4d"
    step star_stage 100 "$tbin/gpu_star_stage"
    step hostile 200 "$tbin/gpu_hostile"
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    step s40e_ncu 200 "$ncu" --clock-control none --kernel-name-base demangled --kernel-name regex:flip_iteration \
      --launch-skip 1800 --launch-count 300 --csv --metrics gpu__time_duration.sum,launch__grid_size,launch__block_size,launch__registers_per_thread \
      "$gb" --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    cp /tmp/gpu-run-s40e_ncu.log "$out/ncu_sphere.csv" 2>/dev/null
    ;;
  s40b)  # session 40, benchmarks: gdel-bench-old (the build of HEAD before the narrow form) against
          # gdel-bench, alternating, two rounds, at 10^6 on uniform, grid, sphere; then the other
          # generators and uniform 10^7 with the new binary, and step profiles of both on grid and sphere
    for r in 1 2; do
      bench_old "s40b_old_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s40b_new_$r" 90 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 bench_old s40b_prof_old 60 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s40b_prof_new 60 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s40c)  # session 40: the other generators and uniform 10^7 (new binary); the CPU backend on the host's
          # threads, old against new, on grid and sphere 10^6 (the same predicates on the host)
    bench s40c_others 90 --dist gaussian,ball,thin_shell --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s40c_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench_old s40c_cpu_old 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    bench s40c_cpu_new 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    # where the sphere's large propose goes (its tie arithmetic did not matter on the GPU, s40b): every
    # kernel of flip_iteration (the fast pass, the undecided lists, the exact tiers), summed per kernel.
    # It timed out at 300 s in session 40 (six metrics: 3 passes a kernel); s40e's one-pass window works
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    step s40c_ncu 300 "$ncu" --clock-control none --kernel-name-base demangled --kernel-name regex:flip_iteration \
      --print-summary per-kernel --metrics gpu__time_duration.sum,launch__registers_per_thread,launch__grid_size,sm__warps_active.avg.pct_of_peak_sustained_active,l1tex__t_sectors_pipe_lsu_mem_local_op_ld.sum,smsp__sass_inst_executed.sum \
      "$gb" --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    cp /tmp/gpu-run-s40c_ncu.log "$out/ncu_sphere.txt" 2>/dev/null
    ;;
  s40f)  # session 40: a probe (reverted: bench/RESULTS.md) with the rare exact paths out of line (det_int_wide_sign,
          # det_ones_expansion_sign): gdel-bench-old (6195bda) against gdel-bench, alternating, two rounds,
          # at 10^6 on uniform, grid, sphere; uniform 10^7 both; a step profile of each on sphere and grid;
          # the registers and stacks of both binaries' heaviest kernels (cuobjdump)
    oldnew s40f
    ;;
  s27g)  # session 27: the CPU backend on the device host's 16 threads since the cavity insertion
          # (session 26), against CGAL sequential and parallel in the same process; the flips alongside
    for r in 1 2; do
      bench "s27g_cav$r" 150 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal,cgal-par --repeat 3
      GDEL_CPU_INSERT=flip bench "s27g_flip$r" 60 --dist uniform --n 1000000 --methods gdel3d-cpu --repeat 3
    done
    ;;
  smoke)  # the script's own plumbing, in seconds (also on a machine without a GPU)
    bench smoke 60 --dist uniform --n 2000 --methods gdel3d-cpu,gstar4d-cpu --repeat 1
    ;;
  s41a)  # session 41: the lift SoS's minors through minor_sign (predicates.hpp): gdel-bench-old (6195bda's
          # code) against gdel-bench, alternating, two rounds, at 10^6 on uniform, grid, sphere; uniform
          # 10^7 both; a step profile of each on sphere and grid; both binaries' registers and stacks
    oldnew s41a
    ;;
  s41b)  # session 41: the GPU tests whose exact decisions go through the lift SoS: predicates against GMP,
          # the flips (insphere), the repair (orient4 of the stars)
    step predicates 200 "$tbin/gpu_predicates"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    ;;
  s41c)  # session 41: the rest of the tests that decide by the lift SoS: gReg3D (power, its star deaths),
          # gStar4D, hostile input
    step greg3d 150 "$tbin/gpu_greg3d"
    step gstar4d 150 "$tbin/gpu_gstar4d"
    step hostile 200 "$tbin/gpu_hostile"
    ;;
  s41d)  # session 41: the other generators (new binary, GPU); the CPU backend on the host's threads, old
          # against new, on grid and sphere 10^6 (the same lift SoS on the host)
    bench s41d_others 90 --dist gaussian,ball,thin_shell --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench_old s41d_cpu_old 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    bench s41d_cpu_new 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    ;;
  s41e)  # session 41: the scratch-free exact passes' threads per SM (GDEL_FREE_PER_SM; default 2 048) now
          # that they hold 224-255 registers (256-288 resident a SM): grid and sphere 10^6, new binary
    for f in 256 512 1024 2048; do
      GDEL_FREE_PER_SM=$f bench "s41e_free$f" 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 3
    done
    ;;
  s42a)  # session 42: the scratch-free exact passes as their own kernels, work the constant nullptr, and the
          # SoS walks on integers converted once (predicates.hpp, exact_batch.hpp): gdel-bench-old (211af19's
          # code) against gdel-bench, as s41a
    oldnew s42a
    ;;
  s42b)  # session 42: the GPU tests of the predicates (against GMP, with and without a scratch) and of the
          # flips, whose scratch-free passes are the new instances
    step predicates 200 "$tbin/gpu_predicates"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    ;;
  s42c)  # session 42: the repair (star splaying engine, its scratch-free instances), gReg3D (power), gStar4D,
          # hostile input
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step greg3d 150 "$tbin/gpu_greg3d"
    step gstar4d 150 "$tbin/gpu_gstar4d"
    step hostile 200 "$tbin/gpu_hostile"
    ;;
  s42d)  # session 42: the splay engine's functions out of line in device code (GDEL_STAR_NOINLINE): old
          # against new as s42a; then the other generators (new binary)
    oldnew s42d
    bench s42d_others 90 --dist gaussian,ball,thin_shell --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ;;
  s42e)  # session 42: the walks' one evaluator (WalkMinor: orient3d's filter on the first terms, integers
          # converted at the first minor that needs them): old against new as s42a; the other generators
    oldnew s42e
    bench s42e_others 90 --dist gaussian,ball,thin_shell --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ;;
  s42f)  # session 42: the CPU backend on the host's threads, old against new, grid and sphere 10^6 (the same
          # walks and work types on the host)
    bench_old s42f_cpu_old 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    bench s42f_cpu_new 150 --dist grid,sphere --n 1000000 --methods gdel3d-cpu --repeat 3
    ;;
  s42g)  # session 42: the CPU backend on uniform 10^6 (float input: few ties), old against new, twice
    for r in 1 2; do
      bench_old "s42g_cpu_old$r" 100 --dist uniform --n 1000000 --methods gdel3d-cpu --repeat 3
      bench "s42g_cpu_new$r" 100 --dist uniform --n 1000000 --methods gdel3d-cpu --repeat 3
    done
    ;;
  s43a)  # session 43: the integer stage's one conversion (int_point), the walks' gathers by index on the host:
          # gdel-bench-old (d6eb052's code) against gdel-bench as s42a
    oldnew s43a
    ;;
  s43b)  # session 43: the CPU backend on the host's threads, old (d6eb052) against new, alternating, two
          # rounds, sphere, grid and uniform 10^6
    for r in 1 2; do
      bench_old "s43b_cpu_old$r" 120 --dist sphere,grid,uniform --n 1000000 --methods gdel3d-cpu --repeat 3
      bench "s43b_cpu_new$r" 120 --dist sphere,grid,uniform --n 1000000 --methods gdel3d-cpu --repeat 3
    done
    ;;
  s43c)  # session 43: the GPU tests, predicates and flips (build/s43t)
    step predicates 200 "$tbin/gpu_predicates"
    step gflip3d 150 "$tbin/gpu_gflip3d"
    ;;
  s43d)  # session 43: where the star builds' time went (RESULTS session 42: +15 to +26 %): the kernels of
          # Splayer::build_stars and GDel3D's seeded builds, timed by ncu, 211af19 (gdel-bench-s41), d6eb052
          # (gdel-bench-old) and new, sphere 10^6
    ncu_kernels s43d 'build_stars|TSeed' "gdel-bench-s41 gdel-bench-old gdel-bench" --dist sphere --n 1000000 \
      --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s43e)  # session 43: the star-build kernel's counters (ncu), 211af19 / d6eb052 / new, sphere 10^6: time,
          # instructions, SIMT efficiency, local memory traffic (spills), registers, occupancy
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for b in ${S43E_BINS:-gdel-bench-s41 gdel-bench-old gdel-bench}; do
      step "s43e_ncu_$b" 120 "$ncu" --clock-control none --kernel-name-base mangled -k 'regex:scratch_kernel.*build_stars' \
        --csv --metrics gpu__time_duration.sum,smsp__inst_executed.sum,smsp__thread_inst_executed_per_inst_executed.ratio,l1tex__t_bytes_pipe_lsu_mem_local_op_ld.sum,l1tex__t_bytes_pipe_lsu_mem_local_op_st.sum,launch__registers_per_thread,launch__stack_size,sm__warps_active.avg.pct_of_peak_sustained_active \
        "$bin/$b" --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
      grep -E '^"' "/tmp/gpu-run-s43e_ncu_$b.log" | python3 -c "
import csv, sys
for r in csv.reader(sys.stdin):
    if len(r) > 14 and r[12] != 'Metric Name': print(f'   {sys.argv[1]:16s} {r[12]:62s} {r[13]:8s} {r[14]}')
" "$b" | tee -a "$out/summary.txt"
    done
    ;;
  s43f)  # session 43: seeded_build on the double* instance in the scratch-free pass too (a null pointer):
          # old (1511102, gdel-bench-old) against new as s42a, then the star-build kernel's counters (s43e)
    oldnew s43f
    OUT="$out/e" bash "$0" s43e
    ;;
  s44a)  # session 44: where the star-build kernel's warps diverge: ncu source counters (per SASS instruction:
          # warp and thread instructions executed) of its one launch, sphere 10^6, written as CSV for
          # scripts/sass-split.py (per function and address range), and the launch's summary lines
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for b in ${S44_BINS:-gdel-bench}; do
      step "s44a_ncu_$b" 200 "$ncu" --clock-control none --kernel-name-base mangled \
        -k "regex:${S44A_REGEX:-scratch_kernel.*build_stars}" --launch-skip "${S44A_SKIP:-0}" --launch-count 1 --section SourceCounters --import-source no -f -o "/tmp/s44a_$b" \
        "$bin/$b" --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
      step "s44a_src_$b" 120 "$ncu" -i "/tmp/s44a_$b.ncu-rep" --page source --csv --print-source sass
      cp "/tmp/gpu-run-s44a_src_$b.log" "$out/sass_$b.csv" 2>/dev/null
      gzip -f "$out/sass_$b.csv"
      step "s44a_det_$b" 60 "$ncu" -i "/tmp/s44a_$b.ncu-rep" --page details --csv
      grep -E 'Duration|Instructions|Threads|Divergen|Branch' "/tmp/gpu-run-s44a_det_$b.log" | head -20 | tee -a "$out/summary.txt"
    done
    ;;
  s44b)  # session 44: the Flip-Flop loop in lockstep (par::Lockstep): old (0cf74a8, gdel-bench-old) against
          # new as s42a, the star-build kernel's counters (s43e) of both, new's source counters (s44a)
    oldnew s44b
    OUT="$out/e" S43E_BINS="gdel-bench-old gdel-bench" bash "$0" s43e
    OUT="$out/a" bash "$0" s44a
    ;;
  s44c)  # session 44: lockstep in the proofs' scan, the insertion loops and star_insert's flood fill, the star
          # builds largest working set first: old (s44b's new, gdel-bench-old) against new as s42a, the
          # star-build kernel's counters (s43e), the repair's kernels timed by ncu, sphere 10^6
    oldnew s44c
    OUT="$out/e" S43E_BINS="gdel-bench-old gdel-bench" bash "$0" s43e
    ncu_kernels s44c 'scratch_kernel.*(Splayer|GDel3D)' "gdel-bench-old gdel-bench" --dist sphere --n 1000000 \
      --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s44d)  # session 44: the repair's kernels' counters (ncu: time, warp and thread instructions, local memory),
          # summed by kernel over a sphere 10^6 run, for each of S44_BINS (default old and new)
    NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum,l1tex__t_bytes_pipe_lsu_mem_local_op_ld.sum \
      ncu_kernels s44d "${S44_REGEX:-scratch_kernel.*(Splayer|GDel3D)}" "${S44_BINS:-gdel-bench-old gdel-bench}" \
      --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s44e)  # session 44: what is kept (Flip-Flop in lockstep, star builds largest first, the proofs by a walk):
          # old (0cf74a8, gdel-bench-old) against new as s42a; the repair's kernels (s44d) of s44c's build
          # (gdel-bench-s44c: the proofs by the scan) and new
    oldnew s44e
    OUT="$out/d" S44_BINS="gdel-bench-s44c gdel-bench" bash "$0" s44d
    ;;
  s44t)  # session 44: the GPU tests (gpu_predicates, gpu_gflip3d, gpu_gdel3d, gpu_greg3d, gpu_gstar4d, gpu_hostile)
    for t in gpu_predicates gpu_gflip3d gpu_gdel3d gpu_greg3d gpu_gstar4d gpu_hostile; do
      [ -x "$tbin/$t" ] && step "$t" 200 "$tbin/$t"  # (the carry limit: two calls, two folders)
    done
    ;;
  s44f)  # session 44: insert_round's stars most insertions first, and the history's own profile stage: old
          # (0cf74a8, gdel-bench-old) against new on every generator at 10^6 (the targets table), 10^7,
          # profiles of new, the repair's kernels (s44d) of s44e's build (gdel-bench-s44e) and new
    alternate s44f --dist uniform,gaussian,ball,thin_shell,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ROUNDS=1 alternate s44f_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s44f_prof 60 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    OUT="$out/d" S44_BINS="gdel-bench-s44e gdel-bench" bash "$0" s44d
    ;;
  s44g)  # session 44: the code as committed (s44e's + most_first, the history stage; insert_round in memory
          # order again) against 0cf74a8 (gdel-bench-old) as s42a, then the GPU tests carried beside it (s44t)
    oldnew s44g
    OUT="$out/t" bash "$0" s44t
    ;;
  s45a)  # session 45: where grid and sphere 10^6 and uniform 10^6 / 10^7 spend their time now (step profiles,
          # the repair's laps), and the repair's kernels on the grid by ncu (time, threads per instruction;
          # S45_REGEX: which kernels, default the exact passes; S45_ONLY=ncu: the ncu step alone)
    [ "${S45_ONLY:-}" = ncu ] || {
    GDEL_PROFILE=1 GDEL_SPLAY_DEBUG=1 bench s45a_prof 120 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s45a_u6 40 --dist uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s45a_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    }
    NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels s45a_grid \
      "${S45_REGEX:-scratch_kernel.*(Splayer|GDel3D)}" "${S44_BINS:-gdel-bench}" --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s46a)  # session 46: session 45's change measured (seeds and the T check one thread per tet): gpu_gdel3d first
          # (in the binaries' folder), then medians of 5 on grid, sphere, uniform at 10^6, of 3 at uniform 10^7,
          # and the step profiles of grid and sphere (the repair's laps)
    [ -x "$tbin/gpu_gdel3d" ] && step gpu_gdel3d 200 "$tbin/gpu_gdel3d"
    bench s46a_m6 120 --dist grid,sphere,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s46a_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 GDEL_SPLAY_DEBUG=1 bench s46a_prof 120 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s46b)  # session 46: the star builds' own profile marks ("stars: ...", "repair: failed stars' ..."): grid and
          # sphere 10^6 step profiles, then the GPU tests in the binaries' folder (s44t)
    GDEL_PROFILE=1 bench s46b_prof 120 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    OUT="$out/t" bash "$0" s44t
    ;;
  s46e)  # session 46: the GPU tests in the binaries' folder (s44t's list), then s46a's medians and profiles
    for t in gpu_predicates gpu_gflip3d gpu_gdel3d gpu_greg3d gpu_gstar4d gpu_hostile; do
      [ -x "$tbin/$t" ] && step "$t" 200 "$tbin/$t"
    done
    bench s46e_m6 120 --dist grid,sphere,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s46e_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 GDEL_SPLAY_DEBUG=1 bench s46e_prof 120 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s47a)  # session 47: where the grid's flip loop costs twice uniform's for the same flips: per-round traces
          # and step profiles of grid and uniform 10^6, medians of 5, the small-iteration knobs on the grid
          # (GDEL_TEAM_MAX, GDEL_TEAM_PROPOSE), the exact passes' kernels on the grid (ncu)
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench s47a_prof 90 --dist grid,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    bench s47a_m6 90 --dist grid,uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_TEAM_MAX=0 bench s47a_team0 60 --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_TEAM_MAX=8192 bench s47a_team8k 60 --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_TEAM_PROPOSE=team bench s47a_pteam 60 --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ncu_kernels s47a 'flip_iteration|propose_spread' gdel-bench --dist grid --n 1000000 \
      --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s47b|s47c|s47d)  # session 47: the small-integer stage in the fast forms (s47c: its second step, the h column
          # and the walks out of line; s47d: gFlip3D only): the GPU tests it touches (in the binaries' folder), then
          # oldnew against s47a's binary (gdel-bench-old)
    for t in gpu_predicates gpu_gflip3d gpu_gdel3d; do
      [ -x "$tbin/$t" ] && step "$t" 200 "$tbin/$t"
    done
    oldnew "$plan"
    ;;
  s47e)  # session 47: where the grid's small launches wait (ncu stall reasons per issued instruction, mean over
          # 20 launches each): propose_spread, and the proposals' scratch-free exact pass
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for k in propose_spread 'exact_after_fast.*flip_iteration'; do
      tag=s47e_$(echo "$k" | tr -c 'a-z\n' '_' | cut -c1-16)
      step "$tag" 150 "$ncu" --clock-control none --kernel-name-base mangled -k "regex:$k" --launch-skip 40 \
        --launch-count 20 --csv --metrics \
        "gpu__time_duration.sum,smsp__inst_executed.sum,regex:smsp__average_warps_issue_stalled_.*_per_issue_active.ratio" \
        "$bin/gdel-bench" --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
      python3 - "/tmp/gpu-run-$tag.log" "$k" <<'PY' | tee -a "$out/summary.txt"
import collections, csv, sys
rows = [l for l in open(sys.argv[1], errors="replace") if l.startswith('"')]
acc, cnt = collections.defaultdict(float), collections.Counter()
for r in csv.DictReader(rows):
    try:
        acc[r["Metric Name"]] += float(r["Metric Value"].replace(",", ""))
        cnt[r["Metric Name"]] += 1
    except (KeyError, ValueError):
        pass
print(f"== {sys.argv[2]}: mean over {max(cnt.values(), default=0)} launches (grid 10^6)")
for m, v in sorted(acc.items(), key=lambda x: -x[1] / max(cnt[x[0]], 1))[:14]:
    print(f"   {v / cnt[m]:14.2f}  {m}")
PY
    done
    ;;
  s48a)  # session 48: the scratch-free passes spread their items over the resident warps (par's scratch_kernel):
          # the GPU tests in the binaries' folder, then oldnew with gdel-bench-old a wrapper that runs the same
          # binary with GDEL_SPREAD_ITEMS=0 (the plain mapping, one item per thread)
    for t in gpu_gflip3d gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh; do
      [ -x "$tbin/$t" ] && step "$t" 200 "$tbin/$t"
    done
    printf '#!/bin/sh\nGDEL_SPREAD_ITEMS=0 exec "$(dirname "$0")/gdel-bench" "$@"\n' >"$bin/gdel-bench-old"
    chmod +x "$bin/gdel-bench-old"
    alternate s48a --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ROUNDS=1 alternate s48a_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 ROUNDS=1 alternate s48a_prof --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s48b)  # session 48: how divergent the flip loop's exact passes are (ncu: threads per warp instruction, time)
          # on grid and sphere 10^6, spread (the default)
    for d in grid sphere; do
      NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels "s48b_$d" \
        'exact_after_fast|propose_spread' gdel-bench --dist $d --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    done
    ;;
  s48c)  # session 48: the exact proposals in lockstep (flip::for_non_ld_faces): gpu_gflip3d and gpu_gdel3d, oldnew
          # against s48a's gdel-bench (gdel-bench-old), then s48b's ncu on the grid with the new binary
    for t in gpu_gflip3d gpu_gdel3d; do
      [ -x "$tbin/$t" ] && step "$t" 200 "$tbin/$t"
    done
    oldnew s48c
    NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels s48c_grid \
      'exact_after_fast|propose_spread' gdel-bench --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s48d)  # session 48: the committed code (s48a's binary: spreading on) on every generator at 10^6, medians of 5,
          # three rounds, and uniform 10^7
    for r in 1 2 3; do
      bench "s48d_m6_$r" 90 --dist uniform,gaussian,ball,thin_shell,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 5
    done
    bench s48d_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s48e)  # session 48: the small-iteration threshold again with spreading on (GDEL_TEAM_MAX: 1 024 default), grid,
          # sphere and uniform 10^6, medians of 5, two rounds
    for r in 1 2; do
      for tm in 1024 2048 4096 8192; do
        GDEL_TEAM_MAX=$tm bench "s48e_t${tm}_$r" 60 --dist uniform,grid,sphere --n 1000000 \
          --methods gdel3d-cuda-dev --repeat 5
      done
    done
    ;;
  s49a)  # session 49: exact proposals a face per thread on integer input (GDEL_SPLIT_EXACT: 0 a tet per thread, 1
          # the large iterations split (the default), 2 the spread proposals too: removed after s49c, 2 is now as 1):
          # the GPU tests, then grid, sphere and uniform 10^6 with each, medians of 5, two rounds; profiles of grid
          # and sphere with each
    gpu_tests
    split_rounds s49a 0 1 2
    for v in 0 1 2; do
      GDEL_SPLIT_EXACT=$v GDEL_PROFILE=1 bench "s49a_prof${v}" 60 --dist grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 1
    done
    ;;
  s49b)  # session 49: s49a's variants again (GDEL_SPLIT_EXACT 0 / 1 / 2: grid, sphere, uniform 10^6, medians of 5,
          # three rounds), then ncu on the flip loop's exact passes (threads per warp instruction, time) with 0 and 2
    ROUNDS=3 split_rounds s49b 0 1 2
    for v in 0 2; do
      for d in grid sphere; do
        GDEL_SPLIT_EXACT=$v NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels \
          "s49b_${d}_split$v" 'exact_after_fast|propose_spread|split_scratch_free' gdel-bench --dist $d --n 1000000 \
          --methods gdel3d-cuda-dev --repeat 1 --no-verify
      done
    done
    ;;
  s49c)  # session 49: the split's pieces counted in the pass (no count launch) and the other apexes loaded only
          # for faces not locally Delaunay: the GPU tests, GDEL_SPLIT_EXACT 0 / 1 / 2 (three rounds), ncu on the
          # sphere and the grid with 1 and 2, then every generator at 10^6 (two rounds) and uniform 10^7, default
    gpu_tests
    ROUNDS=3 split_rounds s49c 0 1 2
    for v in 1 2; do
      GDEL_SPLIT_EXACT=$v NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels \
        "s49c_sphere_split$v" 'exact_after_fast|propose_spread|split_scratch_free' gdel-bench --dist sphere \
        --n 1000000 --methods gdel3d-cuda-dev --repeat 1 --no-verify
    done
    for r in 1 2; do
      bench "s49c_m6_$r" 90 --dist uniform,gaussian,ball,thin_shell,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 5
    done
    bench s49c_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s49d)  # session 49: the committed code (the split of the small iterations removed): the GPU tests, then
          # GDEL_SPLIT_EXACT 0 / default on uniform, grid and sphere 10^6, medians of 5, two rounds
    gpu_tests
    split_rounds s49d 0 1  # (1: the default, named s49d_default_ in the recorded run)
    ;;
  s49e)  # session 49: the split pieces with the small-integer stage first (GDEL_SMALL_STAGE=1, flip::SmallFirst)
          # against without: uniform, grid, sphere 10^6, medians of 5, three rounds; ncu on grid and sphere with it.
          # Run on a build with that code, which was not kept (bench/RESULTS.md, session 49): without it both
          # halves run the committed code
    for r in 1 2 3; do
      for v in 0 1; do
        GDEL_SMALL_STAGE=$v bench "s49e_small${v}_$r" 60 --dist uniform,grid,sphere --n 1000000 \
          --methods gdel3d-cuda-dev --repeat 5
      done
    done
    for d in grid sphere; do
      GDEL_SMALL_STAGE=1 NCU_METRICS=smsp__inst_executed.sum,smsp__thread_inst_executed.sum ncu_kernels \
        "s49e_${d}_small" 'split_scratch_free' gdel-bench --dist $d --n 1000000 --methods gdel3d-cuda-dev \
        --repeat 1 --no-verify
    done
    ;;
  s49f)  # session 49's review (par::knob_off for the default-off knobs): the GPU tests, then uniform, grid and
          # sphere 10^6 with the default, medians of 5
    gpu_tests
    bench s49f_m6 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ;;
  s50a)  # session 50 (not run yet: no device was lent): the CPU backend on the device host's 16 threads after
          # the cavity insertions stopped logging and the deferred points got parallel passes, against CGAL
          # sequential and parallel in the same process (session 27's s27g: 1.10-1.30 s against 0.78-0.85);
          # 16 threads' deferral counts in the rows' notes
    for r in 1 2; do
      bench "s50a_u$r" 150 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal-par,cgal --repeat 3
    done
    bench s50a_gs 200 --dist grid,sphere,thin_shell --n 1000000 --methods gdel3d-cpu,cgal-par --repeat 3
    ;;
  s52a)  # session 52: HEAD's GPU figures (GPU code unchanged since session 49): medians at 10^6 and 10^7, step
          # profiles of uniform 10^7 and sphere 10^6, the CPU backend on the host's 16 threads against CGAL
          # (s50a's uniform row), then every kernel of a uniform 10^7 run by ncu (time, L2 sectors)
    bench s52a_m6 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s52a_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s52a_prof7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s52a_profs 40 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    bench s52a_cpu 150 --dist uniform --n 1000000 --methods gdel3d-cpu,cgal-par,cgal --repeat 3
    NCU_TOP=40 NCU_METRICS=lts__t_sectors.sum ncu_kernels s52a_e7 . gdel-bench --dist uniform --n 10000000 \
      --methods gdel3d-cuda-dev --repeat 1 --no-verify
    ;;
  s52b|s52c)  # session 52: the next active set listed and sorted (default: in a small iteration's team and in large
          # iterations whose set is below 1/32 of the slots) against the pass over every slot
          # (GDEL_ACTIVE_SLOTS=1) and the team alone (GDEL_ACTIVE_LISTED_LARGE=0), one binary: gpu_gflip3d,
          # gpu_gdel3d, then alternating medians at 10^6 (uniform, grid, sphere) and 10^7, step profiles
    step gflip3d 200 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    for r in 1 2; do
      GDEL_ACTIVE_SLOTS=1 bench "s52b_slots$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_ACTIVE_LISTED_LARGE=0 bench "s52b_team$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s52b_both$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_ACTIVE_SLOTS=1 bench s52b_slots7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_ACTIVE_LISTED_LARGE=0 bench s52b_team7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    bench s52b_both7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 GDEL_ACTIVE_SLOTS=1 bench s52b_profslots 40 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s52b_profboth 40 --dist sphere,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_ACTIVE_SLOTS=1 bench s52b_profslots7 40 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s52b_profboth7 40 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    # s52c: then the tet sorts only after rounds that inserted at least 1/R of the points so far
    # (GDEL_REORDER_SHARE=R; 0: after every round, as before): uniform 10^7 and 10^6, grid, sphere
    if [ "$plan" = s52c ]; then
      for r in 1 2; do
        for v in 0 8 4; do
          GDEL_REORDER_SHARE=$v bench "s52c_share${v}_e7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
        done
      done
      for v in 0 8 4; do
        GDEL_REORDER_SHARE=$v bench "s52c_share${v}_m6" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev \
          --repeat 5
      done
      GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 GDEL_REORDER_SHARE=8 bench s52c_prof8 40 --dist uniform --n 10000000 \
        --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s54a)  # session 54: one face byte per face (the neighbour's face and the face flags, one array where there
          # were two) against session 53's binary (gdel-bench-old); and by their knobs on the new binary what
          # session 53's plan s53a was to measure (never run; folded in here): insertion in SoS order
          # (GDEL_SOS_ORDER_SWITCH=0: never) and the last flip loop from the tail's tets (GDEL_FINAL_ALL_TETS=1:
          # from every tet). The GPU tests, alternating medians at 10^6 (uniform, grid, sphere) and 10^7,
          # profiles, session 52's pending A/B (GDEL_ACTIVE_SLOTS, GDEL_REORDER_SHARE), then 10^8 for its peak
          # bytes per point
    step gflip3d 200 "$tbin/gpu_gflip3d"
    step gdel3d 200 "$tbin/gpu_gdel3d"
    step mesh 60 "$tbin/gpu_mesh"
    for r in 1 2; do
      bench "s54a_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench_old "s54a_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_SOS_ORDER_SWITCH=0 GDEL_FINAL_ALL_TETS=1 bench "s54a_s52$r" 60 --dist uniform,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_SOS_ORDER_SWITCH=0 bench s54a_noswitch 60 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_FINAL_ALL_TETS=1 bench s54a_alltets 60 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    for r in 1 2; do
      bench "s54a_new7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench_old "s54a_old7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    GDEL_FINAL_ALL_TETS=1 bench s54a_alltets7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s54a_profs 40 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s54a_prof7 40 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_ACTIVE_SLOTS=1 bench s54a_slots 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_ACTIVE_SLOTS=1 bench s54a_slots7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    for v in 8 4; do
      GDEL_REORDER_SHARE=$v bench "s54a_share${v}_e7" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev \
        --repeat 3
    done
    GDEL_PROFILE=1 bench s54a_e8 200 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s54b)  # session 54, second call: the tie count without flat tets' ties (skew lines no longer switch to SoS
          # order) and the Auto test's sphere inserted by centroids: the GPU tests (GDel3DGpu.SkewLines timed
          # there), then medians at 10^6 (uniform, grid, sphere) and 10^7; gdel-bench-old is s54a's binary
    gpu_tests
    alternate s54b --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ROUNDS=1 alternate s54b_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s55a)  # session 55: the binary with geom::interior_point (and session 54's face bytes and tie fix):
          # the GPU tests, new-vs-old medians (gdel-bench-old = s54a's binary) at 10^6 (uniform, grid,
          # sphere) and 10^7, then GDEL_REORDER_SHARE=8 against the default, two rounds
    gpu_tests
    alternate s55a --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ROUNDS=1 alternate s55a_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    for r in 1 2; do
      GDEL_REORDER_SHARE=8 bench "s55a_rs8_$r" 60 --dist uniform,grid,sphere --n 1000000 \
        --methods gdel3d-cuda-dev --repeat 5
      GDEL_REORDER_SHARE=8 bench "s55a_rs8_e7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s55a_def_e7_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    ;;
  s55b)  # session 55, second call: the gFlip3D test binary of the final source (interior_point's range
          # guard, the wedge without an interior double): the whole gpu_gflip3d
    step gpu_gflip3d 200 "$tbin/gpu_gflip3d"
    ;;
  s55c)  # session 55, third call: gpu_predicates with orient3d_centroid_sos against GMP on the device
    step gpu_predicates 200 "$tbin/gpu_predicates"
    ;;
  s56a)  # session 56: ∞'s kernel point as an exact centroid where no double lies in the first tet
          # (Geo::k_centroid): every GPU test (hostile sets with the one-ulp cube and planes
          # included), gpu_predicates, then new-vs-old (gdel-bench-old = s55a's binary) at 10^6
          # (uniform, grid, sphere) and 10^7: the usual path must not slow down
    gpu_tests
    step gpu_predicates 200 "$tbin/gpu_predicates"
    alternate s56a --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ROUNDS=1 alternate s56a_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s56b)  # session 56, second call: s56a measured the centroid's out-of-line call in Geo::orient_fast
          # +13 % on uniform 10^6 and 10^7; the fast form now answers undecided there (no call):
          # gpu_gflip3d, gpu_hostile, registers against s55a's binary, new-vs-old at 10^6 and 10^7
    step gpu_gflip3d 200 "$tbin/gpu_gflip3d"
    step gpu_hostile 200 "$tbin/gpu_hostile"
    res_usage gdel-bench-old gdel-bench
    alternate s56b --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    alternate s56b_e7 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s56c)  # session 56, third call: the GPU tests s56b did not run, on the final source (gpu_greg3d with
          # the two planes one ulp apart); a third round of new-vs-old at 10^6, and step profiles
          # of both on uniform 10^6 (s56b's new binary ran it 7-10 % faster: where?)
    for t in gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_mesh gpu_predicates; do step "$t" 200 "$tbin/$t"; done
    ROUNDS=1 alternate s56c --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_PROFILE=1 alternate s56c_prof --dist uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s56d)  # session 56, fourth call: scripts/stress-small.py through the CUDA gdel command (small sets
          # whose first tetrahedron holds no double, among other hostile ones), every result checked
    step stress 420 python3 scripts/stress-small.py --gdel "$bin/gdel" --device cuda --sets 2000 --seed 56 \
      --seconds 360 --keep "$out/stress"
    tail -12 /tmp/gpu-run-stress.log | tee -a "$out/summary.txt"
    ;;
  s56e)  # session 56, fifth call: uniform 10^8 with the centroid-capable Geo (peak bytes per point, verified)
    GDEL_PROFILE=1 bench s56e_e8 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s57a)  # session 57, first call (H200): HEAD's device code (s56b's gdel-bench) on the issue's device; 2*10^8 on one GPU
    bench s57a_e6 150 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s57a_e7 120 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    GDEL_PROFILE=1 bench s57a_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_FLIP_TRACE=1 bench s57a_2e8 240 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s57b)  # session 57: votes cast in the proposing pass, the DAG links' dense reset (knobs off = the old passes), 1.5*10^8 on an H100, GPU tests
    for r in 1 2; do
      bench_old "s57b_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse bench "s57b_e7_off$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s57b_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse bench "s57b_e6_off$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s57b_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse bench s57b_e7p_off 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s57b_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    bench s57b_15e7 150 --dist uniform --n 150000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s57c)  # session 57 (not run: no device lent): s57b with the accepted flags' pass back (old = s56b's binary), the tet sort's gather (GDEL_REORDER_GATHER=1), GPU tests
    for r in 1 2 3; do
      bench_old "s57c_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_GATHER=1 bench "s57c_e7_gather$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s57c_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2; do
      bench_old "s57c_e6_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s57c_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 bench s57c_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_old s57c_e7p_old 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_REORDER_GATHER=1 bench s57c_e7p_gather 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    step gpu_gflip3d 200 "$tbin/gpu_gflip3d"
    step gpu_gdel3d 200 "$tbin/gpu_gdel3d"
    step gpu_mesh 60 "$tbin/gpu_mesh"
    GDEL_REORDER_GATHER=1 GDEL_REORDER_EVERY=1 step gpu_gflip3d_gather 200 "$tbin/gpu_gflip3d"
    ;;
  s58a)  # session 58: plan s57c on HEAD's binaries, with the knobs for the old passes ("off": GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse) instead of an old binary; the tet sort's gather (GDEL_REORDER_GATHER=1)
    for r in 1 2 3; do
      GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse bench "s58a_e7_off$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_GATHER=1 bench "s58a_e7_gather$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s58a_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2; do
      GDEL_REORDER_GATHER=1 bench "s58a_e6_gather$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s58a_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 bench s58a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_VOTE_IN_PROPOSE=0 GDEL_DAG_RESET=sparse bench s58a_e7p_off 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_REORDER_GATHER=1 bench s58a_e7p_gather 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    step gpu_mesh 60 "$tbin/gpu_mesh"
    GDEL_REORDER_GATHER=1 GDEL_REORDER_EVERY=1 step gpu_gflip3d_gather 200 "$tbin/gpu_gflip3d"
    ;;
  s58b)  # session 58: every GPU test on HEAD's binaries
    all_gpu_tests
    ;;
  s58c)  # session 58: HEAD (the gather by default): gpu_gdel3d, uniform 10^7 and 10^6 against the scatter (GDEL_REORDER_GATHER=0) and session 52's GDEL_REORDER_SHARE=8, then 2*10^8 uniform (on an H200 the estimate, 96.7 GB, admits it)
    step gpu_gdel3d 200 "$tbin/gpu_gdel3d"
    for r in 1 2 3; do
      bench "s58c_e7_gather$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_GATHER=0 bench "s58c_e7_scatter$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_REORDER_SHARE=8 bench "s58c_e7_share8_$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2; do
      bench "s58c_e6_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_REORDER_SHARE=8 bench "s58c_e6_share8_$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    bench s58c_2e8 400 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s58d)  # session 58: uniform 2*10^8 on an H200 (refused at once on an H100 by the estimate), then uniform 10^7 for the H200's figure
    bench s58d_2e8 400 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    bench s58d_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s58e)  # session 58: gpu_gflip3d and gpu_mesh with the gather as the default (s58c ran gpu_gdel3d)
    step gpu_gflip3d 200 "$tbin/gpu_gflip3d"
    step gpu_mesh 60 "$tbin/gpu_mesh"
    ;;
  s59a)  # session 59: one 32-byte record a tet (vertices + neighbour tets): every GPU test, then uniform 10^8 (peak B/point) with GDEL_PROFILE
    all_gpu_tests
    GDEL_FLIP_TRACE=1 bench s59a_e6_trace 60 --dist uniform --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s59a_e8 250 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s59b)  # session 59: the records against the split arrays (gdel-bench-old: binaries of aba1c6d) in one call: uniform 10^7 x3, 10^6 uniform/grid/sphere x2, profiles
    for r in 1 2 3; do
      bench_old "s59b_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s59b_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2; do
      bench_old "s59b_e6_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s59b_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    GDEL_PROFILE=1 bench s59b_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_old s59b_e7p_old 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s60a)  # session 60: the split's whole records, one pass for the pulled stars' tets, the extract's fused pass (gdel-bench-old: HEAD 9d56081), and the study GDEL_SORT_AFTER_SPLIT=1 ("sas"): uniform 10^7 x3, 10^6 x2, profiles with the flip loop's series; uniform 2*10^8 where the card holds it (an H200)
    for r in 1 2 3; do
      bench_old "s60a_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s60a_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_SORT_AFTER_SPLIT=1 bench "s60a_e7_sas$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2; do
      bench_old "s60a_e6_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s60a_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_SORT_AFTER_SPLIT=1 bench "s60a_e6_sas$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    series="flip: propose,flip: records + write tets,flip: adjacency,flip: next active set,tet reordering,relocate: DAG walk,flip: vote,insert: scores,insert: split"
    GDEL_PROFILE=1 bench_old s60a_e7p_old 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=2 GDEL_PROFILE_SERIES="$series" bench s60a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_SORT_AFTER_SPLIT=1 GDEL_PROFILE=1 GDEL_FLIP_TRACE=2 GDEL_PROFILE_SERIES="$series" bench s60a_e7p_sas 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    for v in new sas; do
      grep -h "^profile series\|^gflip3d " "/tmp/gpu-run-s60a_e7p_$v.log" >"$out/series_e7_$v.txt"
    done
    if big_gpu; then
      bench s60a_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s60b)  # session 60: every GPU test on the new binaries, then gFlip3D's and gDel3D's under GDEL_SORT_AFTER_SPLIT=1
    all_gpu_tests
    GDEL_SORT_AFTER_SPLIT=1 step gpu_gdel3d_sas 200 "$tbin/gpu_gdel3d"
    GDEL_SORT_AFTER_SPLIT=1 step gpu_gflip3d_sas 200 "$tbin/gpu_gflip3d"
    ;;
  s60c)  # session 60: SlotSource::spread (a batch's claims at their users' ranks among the freed slots) against GDEL_CLAIM_SPREAD=0 ("top") and HEAD 9d56081 (old): uniform 10^7 x3, 10^6 x3, profiles (10^7 series; grid and sphere 10^6), every GPU test
    for r in 1 2 3; do
      bench_old "s60c_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s60c_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      GDEL_CLAIM_SPREAD=0 bench "s60c_e7_top$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    for r in 1 2 3; do
      bench_old "s60c_e6_old$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      bench "s60c_e6_new$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
      GDEL_CLAIM_SPREAD=0 bench "s60c_e6_top$r" 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    done
    series="flip: propose,flip: records + write tets,flip: adjacency"
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=2 GDEL_PROFILE_SERIES="$series" bench s60c_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    grep -h "^profile series\|^gflip3d " /tmp/gpu-run-s60c_e7p_new.log >"$out/series_e7_new.txt"
    GDEL_PROFILE=1 bench_old s60c_e6p_old 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s60c_e6p_new 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_CLAIM_SPREAD=0 GDEL_PROFILE=1 bench s60c_e6p_top 60 --dist grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    ;;
  s60d)  # session 60: the final binaries (s60a's changes without the study knob; no SlotSource::spread): every GPU test, uniform 10^7 x2 and 10^6 against HEAD 9d56081
    all_gpu_tests
    for r in 1 2; do
      bench_old "s60d_e7_old$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
      bench "s60d_e7_new$r" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    done
    bench_old s60d_e6_old 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    bench s60d_e6_new 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    ;;
  s61a)  # session 61: no face bytes (a neighbour's face found in its record, the faces' flags in the state byte) against HEAD faa27de (old): uniform 10^7 x3, 10^6 x2, profiles, uniform 10^8 (peak B/point), every GPU test
    old_new s61a 3 2
    GDEL_PROFILE=1 bench_old s61a_e7p_old 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s61a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench s61a_e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    ;;
  s61b|s61c)  # session 61: final binaries against HEAD faa27de (old) and s61a's binary (noclear: a relinked neighbour's flag left set); s61b: the flag cleared by an atomic AND on the state byte, s61c: the flags in the neighbour entries' sign bits (a relink clears them): uniform 10^7 x3, 10^6 x2, a profile, uniform 10^8, every GPU test
    bench_noclear() {
      local gb="$bin/gdel-bench-noclear"
      bench "$@"
    }
    old_new "$plan" 3 2 bench_noclear
    GDEL_PROFILE=1 bench "${plan}_e7p_new" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench "${plan}_e8" 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    ;;
  s61d)  # session 61: the final binaries on an H200 against HEAD faa27de (old): uniform 10^7 x3, 10^6 x1, uniform 2*10^8 where the card holds it
    old_new s61d 3 1
    if big_gpu; then
      bench s61d_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  # (s62a's GDEL_LAZY_APEX and s62b's GDEL_FAST_MIN_BLOCKS exist only in those calls'
  # binaries, not in the code as committed: bench/RESULTS.md, session 62)
  s62a)  # session 62: the apexes across internal faces loaded only for a face that is not locally Delaunay (lazy, the default now) against HEAD 4874eaa's device code (old: session 61's final binary) and GDEL_LAZY_APEX=0 (eager): uniform 10^7 x3, 10^6 x2, profiles, a flip trace, every GPU test
    bench_eager() {
      GDEL_LAZY_APEX=0 bench "$@"
    }
    old_new s62a 3 2 bench_eager
    GDEL_PROFILE=1 bench s62a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_LAZY_APEX=0 bench s62a_e7p_eager 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_FLIP_TRACE=2 bench s62a_e7t 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    for b in gdel-bench gdel-bench-old; do  # flip_iteration's kernels: registers and stack
      cuobjdump -res-usage "$bin/$b" 2>&1 | python3 -c '
import re, subprocess, sys
items = re.findall(r"Function ([^\s:]+):\s*\n\s*REG:(\d+) STACK:(\d+)", sys.stdin.read())
names = subprocess.run(["c++filt"], input="\n".join(i[0] for i in items), capture_output=True, text=True).stdout.split("\n")
for (_, r, s), n in zip(items, names):
    if "flip_iteration" in n:
        print(f"   {sys.argv[1]}: regs {r:>3} stack {s:>5}  {n[:60]} ... {n[-60:]}")
' "$b" | tee -a "$out/summary.txt"
    done
    all_gpu_tests
    ;;
  s62b)  # session 62: a tet's record loaded beside its state in the proposals, a neighbour's record beside its stamp in the adjacency pass (new), against s62a's binary with GDEL_LAZY_APEX=0 (prev: HEAD's device code and the clean-ups) and HEAD 4874eaa's device code (old); the fast passes (par::fast_then_exact) compiled for 4 or 5 resident blocks an SM (GDEL_FAST_MIN_BLOCKS: mb4, mb5): uniform 10^7 x3, 10^6 x1, profiles, the fast kernels' registers, every GPU test (default)
    bench_prev() {
      local gb="$bin/gdel-bench-prev"
      GDEL_LAZY_APEX=0 bench "$@"
    }
    bench_mb4() {
      GDEL_FAST_MIN_BLOCKS=4 bench "$@"
    }
    bench_mb5() {
      GDEL_FAST_MIN_BLOCKS=5 bench "$@"
    }
    old_new s62b 3 1 bench_prev bench_mb4 bench_mb5
    GDEL_PROFILE=1 bench_prev s62b_e7p_prev 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_FAST_MIN_BLOCKS=4 bench s62b_e6_mb4 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    GDEL_FAST_MIN_BLOCKS=5 bench s62b_e6_mb5 60 --dist uniform,grid,sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 5
    for v in 0 4 5; do
      GDEL_PROFILE=1 GDEL_FAST_MIN_BLOCKS=$v bench "s62b_e7p_mb$v" 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    done
    cuobjdump -res-usage "$bin/gdel-bench" 2>&1 | python3 -c '
import re, subprocess, sys
items = re.findall(r"Function ([^\s:]+):\s*\n\s*REG:(\d+) STACK:(\d+)", sys.stdin.read())
names = subprocess.run(["c++filt"], input="\n".join(i[0] for i in items), capture_output=True, text=True).stdout.split("\n")
for (_, r, s), n in zip(items, names):
    if "fast_then_exact_impl" in n and ("GFlip3D" in n or "flip_iteration" in n or "commit_flips" in n):
        kind = re.match(r"void gdel::par::detail::(\w+)(<\d+)?", n)
        label = kind.group(1) + (kind.group(2) or "") if kind else n[:40]
        print(f"   regs {r:>3} stack {s:>5}  {label}  ... {n[-90:]}")
' | tee -a "$out/summary.txt"
    all_gpu_tests
    ;;
  s62c)  # session 62: the final binaries (HEAD 4874eaa's device code with the clean-ups) against session 61's (old): every GPU test, uniform 10^7 x2, 10^6 x1; then ncu's speed-of-light, warp-state, memory and occupancy sections over three late large launches at 10^7 of the proposals' fast pass and of the flips' (records + tets) fast pass
    all_gpu_tests
    old_new s62c 2 1
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for k in flip_iteration commit_flips; do
      step "s62c_ncu_$k" 150 "$ncu" --clock-control none --kernel-name-base mangled \
        -k "regex:for_kernel.*fast_then_exact_impl.*$k" --launch-skip 150 --launch-count 3 \
        --section SpeedOfLight --section WarpStateStats --section MemoryWorkloadAnalysis --section Occupancy \
        "$bin/gdel-bench" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    done
    ;;
  s62d)  # session 62: the final binaries on an H200 against session 61's (old): uniform 10^7 x3, 10^6 x1, uniform 2*10^8 where the card holds it
    old_new s62d 3 1
    if big_gpu; then
      bench s62d_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s63a)  # session 63: the proposals' face loop over the faces to test (not the four with the others skipped) and a state byte only for a flip's new slot (new), against session 62's final binary (old): uniform 10^7 x3, 10^6 x2, profiles of both, every GPU test; on an H200 also uniform 2*10^8
    old_new s63a 3 2
    GDEL_PROFILE=1 bench s63a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_old s63a_e7p_old 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    # the proposals' fast pass (launch 151 at 10^7) under ncu: its instruction mix, and its
    # SASS with each instruction's executions (CSV, for counting where the issues go)
    ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
    for b in gdel-bench gdel-bench-old; do
      step "s63a_ncu_$b" 120 "$ncu" --clock-control none --kernel-name-base mangled \
        -k "regex:for_kernel.*fast_then_exact_impl.*flip_iteration" --launch-skip 150 --launch-count 1 \
        --section SpeedOfLight --section InstructionStats --section SourceCounters --section WarpStateStats \
        -o "$out/prop-$b" "$bin/$b" --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
      step "s63a_sass_$b" 60 bash -c "'$ncu' -i '$out/prop-$b.ncu-rep' --page source --print-source sass --csv > '$out/prop-sass-$b.csv'"
      step "s63a_details_$b" 60 "$ncu" -i "$out/prop-$b.ncu-rep" --page details
    done
    all_gpu_tests
    if big_gpu; then
      bench s63a_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s63b)  # session 63 (GDEL_ACTIVE_VERTEX exists only in this call's binary: a pair sort, ties in candidate order; the final knob is GDEL_ACTIVE_SPACE): a large iteration's next active set sorted by its tets' smallest vertex (GDEL_ACTIVE_VERTEX=1, vtx) against the default slot order, one binary: uniform 10^7 x3, 10^6 x2, profiles of both, gpu_gflip3d under the knob; on an H200 also uniform 2*10^8 (default)
    bench_vtx() {
      GDEL_ACTIVE_VERTEX=1 bench "$@"
    }
    ab s63b 3 2 bench bench_vtx
    GDEL_PROFILE=1 bench s63b_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_vtx s63b_e7p_vtx 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_ACTIVE_VERTEX=1 step gpu_gflip3d_vtx 200 "$tbin/gpu_gflip3d"
    if big_gpu; then
      bench s63b_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s63c)  # session 63's plan for the next session (its device time ran out before it ran): the next active set in space order past 2^23 slots (GDEL_ACTIVE_SPACE=auto, the intended default) against slot order (the default), one binary: uniform 10^7 x3, 10^6 x1, a profile and uniform 10^8 under auto, every GPU test (gpu_gflip3d's path test runs in both orders); on an H200 also uniform 2*10^8 under auto
    bench_auto() {
      GDEL_ACTIVE_SPACE=auto bench "$@"
    }
    ab s63c 3 1 bench bench_auto
    GDEL_PROFILE=1 bench_auto s63c_e7p_auto 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench_auto s63c_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    if big_gpu; then
      bench_auto s63c_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s64a)  # session 64: the space order's pair sort, now the default (auto), against slot order (GDEL_ACTIVE_SPACE=0, the same binary) and against session 63's 64-bit key sort under auto (gdel-bench-old: HEAD c481039's gdel-bench) and against keys of blocks of 256 points (GDEL_SPACE_SHIFT=8, two radix passes at 10^7) and the tet sort every second round (GDEL_REORDER_EVERY=2): uniform 10^7 x3, 10^6 x2, a profile and uniform 10^8 at the default, every GPU test; on an H200 also uniform 2*10^8
    bench_off() {
      GDEL_ACTIVE_SPACE=0 bench "$@"
    }
    bench_k64() {
      GDEL_ACTIVE_SPACE=auto bench_old "$@"
    }
    bench_sh8() {
      GDEL_SPACE_SHIFT=8 bench "$@"
    }
    bench_re2() {
      GDEL_REORDER_EVERY=2 bench "$@"
    }
    ab s64a 3 2 bench bench_off bench_k64 bench_sh8 bench_re2
    GDEL_PROFILE=1 bench s64a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench s64a_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    if big_gpu; then
      bench s64a_2e8 300 --dist uniform --n 200000000 --methods gdel3d-cuda-dev --repeat 1
    fi
    ;;
  s64b)  # session 64: the radix pair sorts of the next active set and of the tet sort hand over their alternate arrays instead of copying back (gdel-bench) against 4cf438d (gdel-bench-old): uniform 10^7 x3, 10^6 x2, a profile, uniform 10^8, every GPU test
    ab s64b 3 2 bench bench_old
    GDEL_PROFILE=1 bench s64b_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench s64b_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    ;;
  s65a)  # session 65: the next active set in stream order (the candidates' own order, no sort; the new default, GDEL_ACTIVE_SPACE unset) against session 64's default (GDEL_ACTIVE_SPACE=sort: sorted by vertex past 2^23 slots, slot order below) and stream order with the tet sort every second round (GDEL_REORDER_EVERY=2): uniform 10^7 x3, 10^6 x2, profiles, uniform 10^8, every GPU test
    bench_sort() {
      GDEL_ACTIVE_SPACE=sort bench "$@"
    }
    bench_re2() {
      GDEL_REORDER_EVERY=2 bench "$@"
    }
    ab s65a 3 2 bench bench_sort bench_re2
    GDEL_PROFILE=1 bench s65a_e7p_new 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_sort s65a_e7p_sort 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    bench s65a_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    all_gpu_tests
    ;;
  s65b)  # session 65: stream order (the default) against session 64's (GDEL_ACTIVE_SPACE=sort) and the tet sort every second round, uniform 10^7 x3; stream against sort at 10^6 x3 (the grid's ratio to uniform); uniform 10^8
    bench_sort() {
      GDEL_ACTIVE_SPACE=sort bench "$@"
    }
    bench_re2() {
      GDEL_REORDER_EVERY=2 bench "$@"
    }
    ab s65b 3 0 bench bench_sort bench_re2
    ab s65b 0 3 bench bench_sort
    bench s65b_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s65c)  # session 65: uniform 10^8 in stream order (the default) and in session 64's order (GDEL_ACTIVE_SPACE=sort), alternating, twice
    for r in 1 2; do
      bench "s65c_1e8_new$r" 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
      GDEL_ACTIVE_SPACE=sort bench "s65c_1e8_sort$r" 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    done
    ;;
  s65d)  # session 65: auto switches from stream to space order at 2^27 slots: uniform 10^8 (and 10^7 once) at the default
    bench s65d_1e8 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    bench s65d_e7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 3
    ;;
  s67a)  # session 67: the sparser tet sort (GDEL_REORDER_SHARE=$SHARE, default 4) against every round's at 10^6 x3 (uniform, grid, sphere: the ratios to uniform) and uniform 10^7 x2
    bench_share() {
      GDEL_REORDER_SHARE=${SHARE:-4} bench "$@"
    }
    ab s67a 0 3 bench bench_share
    ab s67a 2 0 bench bench_share
    ;;
  s66b | s67b)  # session 67 (session 66's s66b, never run as written, for a short call, its measurements first): uniform 10^8 auto against sort; uniform 10^7 x3 against GDEL_REORDER_SHARE=8, 4, three rounds; gpu_gflip3d and gpu_parallel (the changed code), then the other GPU tests; the 10^7 profile with the round trace; the switch at 2^26 at 10^8
    e8 s67b_1e8_auto1
    GDEL_ACTIVE_SPACE=sort e8 s67b_1e8_sort1
    for r in 1 2 3; do
      for sh in 0 8 4; do
        GDEL_REORDER_SHARE=$sh e7 "s67b_e7_share${sh}_$r"
      done
    done
    gpu_tests gpu_gflip3d gpu_parallel gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh gpu_predicates
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench s67b_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_STREAM_MAX_SLOTS=67108864 e8 s67b_1e8_sw26
    ;;
  s69a)  # session 69: the build with the insertion's scores through atomic_raise by default (the point padding and the gathered proposals dropped) against HEAD d5433b9's binary (gdel-bench-old) and against itself with GDEL_SCORE_RAISE=0, uniform 10^7 x3 and 10^6 x2; its step profile at 10^7; gpu_gflip3d's knob tests and gpu_parallel; uniform 10^8
    ab s69a 3 2 bench_old bench bench_noraise
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench s69a_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    step gpu_gflip3d_knobs 120 "$tbin/gpu_gflip3d" --gtest_filter='*ChangesNothing*:*LogFlush*'
    gpu_tests gpu_parallel
    e8 s69a_1e8
    ;;
  s69b)  # session 69, for session 70: the flip DAG's links stamped (GDEL_DAG_RESET=stamp: no zeroing of aux_key_ before a relocation, no reset after it) against the default, uniform 10^7 x3 and 10^6 x2; the step profiles of both at 10^7; gpu_gflip3d's knob tests (DagStampChangesNothing); uniform 10^8 with both; then every GPU test
    ab s69b 3 2 bench bench_stamp
    GDEL_PROFILE=1 bench s69b_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_DAG_RESET=stamp bench s69b_e7p_stamp 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    step gpu_gflip3d_knobs 150 "$tbin/gpu_gflip3d" --gtest_filter='*ChangesNothing*:*LogFlush*'
    e8 s69b_1e8
    GDEL_DAG_RESET=stamp e8 s69b_1e8_stamp
    all_gpu_tests
    ;;
  s70a)  # session 70: the build with the stamped DAG links by default against itself with them zeroed (GDEL_DAG_RESET=zero), and the flip log's cap at 5 (the default at 10^7), 10, 20, 40 million records, uniform 10^7 x3 alternating; the step profiles (with the trace) of 5 and 20 million; gpu_gflip3d's knob tests; every GPU test but gpu_gflip3d; uniform 10^8 at 50 (the default) and 100 million records; gpu_gflip3d; 10^6 x2 (default, zero); gpu_parallel, gpu_predicates. The steps in order of need: a smaller GDEL_CALL_BUDGET cuts the last ones (the whole plan ≈ 520 s; ≈ 260 s reaches the 10^8 runs)
    ab s70a 3 0 bench bench_zero bench_log10 bench_log20 bench_log40
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench s70a_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench_log20 s70a_e7p_log20 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    step gpu_gflip3d_knobs 150 "$tbin/gpu_gflip3d" --gtest_filter='*ChangesNothing*:*LogFlush*'
    gpu_tests gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh
    e8 s70a_1e8
    GDEL_FLIP_LOG_RECORDS=100000000 e8 s70a_1e8_log100
    gpu_tests gpu_gflip3d
    ab s70a 0 2 bench bench_zero
    gpu_tests gpu_parallel
    step gpu_predicates 60 "$tbin/gpu_predicates"
    ;;
  s71a)  # session 71: the team flip loop (GDEL_TEAM_LOOP=1) against the host's iterations (the default) at 10^6 (uniform, grid, sphere; x2) and uniform 10^7 (x3), alternating; the knob tests (TeamLoopChangesNothing, the small iterations' paths, the stamped links, the log's flushes); profiles with the flip trace of both at 10^7 and of sphere 10^6; every other GPU test; uniform 10^8 default and loop; the flip log's cap at 20 million records x2 (session 70's study). The steps in order of need (the whole plan ≈ 560 s; ≈ 330 s reaches the GPU tests)
    ab s71a 0 2 bench bench_loop
    ab s71a 3 0 bench bench_loop
    step gpu_gflip3d_knobs 200 "$tbin/gpu_gflip3d" --gtest_filter='*ChangesNothing*:*LogFlush*:*SmallIteration*'
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench s71a_e7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 GDEL_FLIP_TRACE=1 bench_loop s71a_e7p_loop 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s71a_e6p 60 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench_loop s71a_e6p_loop 60 --dist sphere --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    gpu_tests gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh
    e8 s71a_1e8
    GDEL_TEAM_LOOP=1 e8 s71a_1e8_loop
    ab s71a 2 0 bench_log20
    gpu_tests gpu_gflip3d gpu_parallel
    step gpu_predicates 60 "$tbin/gpu_predicates"
    ;;
  s72a)  # session 72: the build with the flip log's floor (2*10^7 records from 10^7 points up) against its old cap at 10^7 (5 million) and a cap of 4*10^7, uniform 10^7 x3 alternating; uniform 10^8 (the floor does not apply); a step profile at 10^7; 10^6 x2 (default, the team runs on every input, a log of 2*10^7 records); auto's runs; the GPU tests but gpu_gflip3d (plan s72b). In order of need (≈ 520 s)
    ab s72a 3 0 bench bench_log05 bench_log40
    e8 s72a_1e8
    GDEL_PROFILE=1 bench s72a_prof7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    ab s72a 0 2 bench bench_loop bench_log20
    GDEL_TEAM_LOOP=auto ab s72a_auto 0 1 bench
    gpu_tests gpu_gdel3d gpu_gstar4d gpu_greg3d gpu_hostile gpu_mesh gpu_parallel
    step gpu_predicates 60 "$tbin/gpu_predicates"
    ;;
  s72b)  # session 72: gpu_gflip3d in two steps, the knobs' tests first (≈ 360 s)
    step gpu_gflip3d_knobs 280 "$tbin/gpu_gflip3d" --gtest_filter='*ChangesNothing*:*LogFlush*'
    step gpu_gflip3d_rest 280 "$tbin/gpu_gflip3d" --gtest_filter='-*ChangesNothing*:*LogFlush*'
    ;;
  s72c)  # session 72: one device pool kept for the process (GDEL_DEVICE_POOL=keep) against a pool per call (the default), uniform 10^7 x3 and 10^6 x2 alternating; its step profile at 10^7 (two runs: the second finds its memory mapped); uniform 10^8 twice in one process with it; gpu_hostile (out of memory), gpu_gdel3d and gpu_parallel with it (≈ 200 s)
    ab s72c 3 2 bench bench_keep
    GDEL_DEVICE_POOL=keep GDEL_PROFILE=1 bench s72c_prof7k 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 2
    GDEL_DEVICE_POOL=keep bench s72c_e8k 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 2
    export GDEL_DEVICE_POOL=keep
    gpu_tests gpu_hostile gpu_gdel3d gpu_parallel
    unset GDEL_DEVICE_POOL
    ;;
  s73a)  # session 73: the memory precheck counting the pool's unused memory, with the kept pool (GDEL_DEVICE_POOL=keep): uniform 10^8 twice in one process (session 72: the second run refused); then default against keep, uniform 10^7 x3 and 10^6 x3; gpu_hostile with keep (from commit 6a8dd99 on it has KeptDeviceMemoryIsBoundedAndReleased, which sets the bound itself through gdel::keep_device_memory) (≈ 230 s)
    GDEL_DEVICE_POOL=keep bench s73a_e8k 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 2
    ab s73a 3 3 bench bench_keep
    GDEL_DEVICE_POOL=keep gpu_tests gpu_hostile
    ;;
  s74a)  # session 74 (binaries of HEAD from 6bb39a0 on, rebuilt: no build folder is kept between sessions): plan s73a's steps (uniform 10^8 twice with the kept pool; gpu_hostile with it, KeptDeviceMemoryIsBoundedAndReleased included), and session 73's study GDEL_POOL_PRIME=1 (the pool mapped to the estimate at once) beside the default and keep, uniform 10^7 x3 and 10^6 x2, with a profile of its first run at 10^7 (≈ 330 s)
    GDEL_DEVICE_POOL=keep bench s74a_e8k 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 2
    ab s74a 3 2 bench bench_keep bench_prime
    GDEL_POOL_PRIME=1 GDEL_PROFILE=1 bench s74a_prof7p 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_PROFILE=1 bench s74a_prof7 60 --dist uniform --n 10000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_DEVICE_POOL=keep gpu_tests gpu_hostile
    ;;
  s74b)  # session 73's second call: HostileGpu.KeptDeviceMemoryIsBoundedAndReleased read on the shared pool itself (gpu_hostile of HOSTILE_DIR, default build/s74b), alone, and after the tests before it with GDEL_DEVICE_POOL=keep; then the prime (GDEL_POOL_PRIME=1) against the default, uniform 10^7 x2 and 10^6 x4, and uniform 10^8 with it (≈ 200 s)
    hdir=${HOSTILE_DIR:-build/s74b}
    step s74b_kept 120 "$hdir/gpu_hostile" --gtest_filter='*KeptDevice*'
    GDEL_DEVICE_POOL=keep step s74b_kept_after 200 "$hdir/gpu_hostile" --gtest_filter='*Peers*:*SameArrays*:*TwentyMillion*:*OutOfDevice*:*MemoryEstimate*:*KeptDevice*:*PoolPrime*'
    ab s74b 2 4 bench bench_prime
    GDEL_POOL_PRIME=1 bench s74b_e8p 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  s75a)  # session 74's call, binaries of HEAD c4f1603 (the trim fixed; the pool reads in one helper): the kept test alone, then after the other hostile tests with GDEL_DEVICE_POOL=keep; step profiles of uniform and grid 10^6; uniform 10^8 twice with the kept pool (the precheck counting its memory); default, keep and prime at 10^7 x3 and 10^6 x3; gpu_hostile whole (228 s on the H100)
    step s75a_kept 120 "$tbin/gpu_hostile" --gtest_filter='*KeptDevice*'
    GDEL_DEVICE_POOL=keep step s75a_kept_after 200 "$tbin/gpu_hostile" --gtest_filter='*Peers*:*SameArrays*:*TwentyMillion*:*OutOfDevice*:*MemoryEstimate*:*KeptDevice*:*PoolPrime*'
    GDEL_PROFILE=1 bench s75a_prof6 60 --dist uniform,grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    GDEL_DEVICE_POOL=keep bench s75a_e8k 150 --dist uniform --n 100000000 --methods gdel3d-cuda-dev --repeat 2
    ab s75a 3 3 bench bench_keep bench_prime
    gpu_tests gpu_hostile
    ;;
  s76a)  # for session 75: gpu_gflip3d on session 74's binaries (build/s75x: the one GPU suite that did not run on them; its code unchanged since it last passed), then the grid's flip trace at 10^6 on the GPU (GDEL_FLIP_TRACE=1, its rounds' iterations against the CPU backend's) (≈ 230 s)
    gpu_tests gpu_gflip3d
    GDEL_FLIP_TRACE=1 bench s76a_gtrace 60 --dist grid --n 1000000 --methods gdel3d-cuda-dev --repeat 1
    ;;
  cmd)
    step cmd "${STEP_LIMIT:-540}" "$@"
    ;;
  *)
    echo "unknown plan $plan" >&2
    exit 1
    ;;
esac
# shellcheck disable=SC2034
: "$bin"
