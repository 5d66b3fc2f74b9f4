#!/usr/bin/env bash
# The Python package on the GPU machine: builds gdel with the CUDA backend (sm_90 unless
# GDEL_CUDA_ARCH says otherwise) and runs pytest tests/python there, GPU tests included
# (torch/cupy CUDA arrays through the zero-copy path, tests/python/test_device_arrays.py).
#
#   device run: command "bash scripts/gpu-python.sh [pytest args...]"   (no carry needed)
#
# Should a cold build not leave time for the tests within one call's limit, run it in two
# calls on the same (warm) machine: `bash scripts/gpu-python.sh build`, then
# `bash scripts/gpu-python.sh test [pytest args...]`.
#
# The device image has no network: the venv sees the system's packages (torch, cupy,
# numpy, scipy, pytest, hypothesis, scikit-build-core, nanobind) through
# --system-site-packages, and pip builds with --no-index --no-deps --no-build-isolation.
# Only the extension is built (pyproject's build.targets: gdel._core and its stub, with
# the gdel library it links), in build/py-cuda-<wheel tag>, with one compile job per core.
# GDEL_GPU_PY_VENV (default build/gpu-py-venv), GDEL_GPU_PY_BUILD_DIR (default
# build/py-cuda-{wheel_tag}), PYTHON, GDEL_DEVICE_BENCH_N (points of the zero-copy timing
# test, default 10^6).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=all
case "${1:-}" in build|test) mode=$1; shift ;; esac

venv=${GDEL_GPU_PY_VENV:-build/gpu-py-venv}
python=${PYTHON:-python3}
export GDEL_CUDA=ON
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}
export CMAKE_ARGS="${CMAKE_ARGS:-} -DCMAKE_CUDA_ARCHITECTURES=${GDEL_CUDA_ARCH:-90}"
if [ -z "${CMAKE_CUDA_COMPILER:-}" ] && ! command -v nvcc >/dev/null && [ -x /usr/local/cuda/bin/nvcc ]; then
  export PATH=/usr/local/cuda/bin:$PATH
fi
# libgomp's busy-waiting hurts when pytest's CPU tests share cores with other work.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}

echo "== device"; nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader || true
echo "== tools"; "$python" --version; cmake --version | head -1; nvcc --version | tail -1

# A venv without its own pip (no ensurepip needed): the system's pip, run by the venv's
# python, installs into the venv; everything else comes from the system site-packages.
if [ ! -x "$venv/bin/python" ]; then
  echo "== python: creating $venv (--system-site-packages)"
  "$python" -m venv --without-pip --system-site-packages "$venv"
fi
py="$venv/bin/python"
"$py" - <<'EOF'
import importlib
for name in ("numpy", "torch", "cupy", "nanobind", "scikit_build_core", "pytest", "hypothesis", "scipy"):
    try:
        m = importlib.import_module(name)
        print(f"   {name} {getattr(m, '__version__', '?')}")
    except Exception as e:  # noqa: BLE001 - report and go on: the tests skip what is missing
        print(f"   {name}: not importable ({type(e).__name__}: {e})")
EOF
build_dir=${GDEL_GPU_PY_BUILD_DIR:-}
[ -n "$build_dir" ] || build_dir='build/py-cuda-{wheel_tag}'  # scikit-build-core fills in the tag

if [ "$mode" != test ]; then
echo "== python: pip install . (GDEL_CUDA=ON,$CMAKE_ARGS, $CMAKE_BUILD_PARALLEL_LEVEL jobs)"
start=$(date +%s)
log=build/gpu-python-build.log
mkdir -p build
if ! "$py" -m pip --disable-pip-version-check install --no-index --no-deps --no-build-isolation \
    -C build-dir="$build_dir" -v . >"$log" 2>&1; then
  grep -E -B2 -A12 'error|Error|FAILED' "$log" | head -150
  tail -30 "$log"
  exit 1
fi
echo "== python: installed in $(( $(date +%s) - start )) s (log: $log)"
fi
"$py" -c 'import gdel; print("   gdel", gdel.__version__, "built with CUDA:", gdel.built_with_cuda(), "device visible:", gdel.cuda_available())'
"$py" -c 'import gdel, sys; sys.exit(0 if gdel.built_with_cuda() else "gdel was built without CUDA")'
[ "$mode" = build ] && { echo "build done"; exit 0; }

# From the repository root, `import gdel` is the installed package (python/gdel is not on
# the path). -rsP: the reasons of skips, and the output of passing tests (the zero-copy
# tests print their host<->device byte counts and timings).
"$py" -m pytest -q -p no:cacheprovider -rsP tests/python "$@"
