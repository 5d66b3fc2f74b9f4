#!/usr/bin/env bash
# The Python package's tests: builds and installs gdel with pip into a virtual
# environment under build/ and runs pytest on tests/python.
#
#   scripts/test-python.sh [pytest args...]
#
# Re-runs are fast: the venv is kept, and scikit-build-core's build folder
# (build/py-<wheel tag>, pyproject.toml) makes the rebuild incremental.
# Environment: GDEL_CUDA=ON|OFF|AUTO (default here OFF: the CUDA backend is
# compile-checked by scripts/test.sh and has no GPU to run on in CI; set AUTO or ON
# to build it into the package), GDEL_PY_VENV (default build/py-venv), PYTHON.
set -euo pipefail
cd "$(dirname "$0")/.."

venv=${GDEL_PY_VENV:-build/py-venv}
python=${PYTHON:-python3}
export GDEL_CUDA=${GDEL_CUDA:-OFF}
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
# libgomp's default busy-waiting collapses when the cores are shared with other
# jobs (measured here: 1000 points in 1.2 s instead of 0.03 s); tests want passive.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}

# A Debian system Python needs python3-venv and python3-dev (headers) for this.
if ! "$python" -c 'import ensurepip, sysconfig, os, sys; sys.exit(not os.path.exists(os.path.join(sysconfig.get_paths()["include"], "Python.h")))' 2>/dev/null; then
  echo "== python: installing python3-venv python3-dev"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq python3-venv python3-dev >/dev/null
fi
if [ ! -x "$venv/bin/python" ]; then
  echo "== python: creating $venv"
  "$python" -m venv "$venv"
fi
py="$venv/bin/python"

# The build requirements live in the venv and pip builds without isolation: the
# nanobind path then stays the same between runs and CMake rebuilds only what changed
# (an isolated build recompiles nanobind every time).
pip=("$py" -m pip --disable-pip-version-check)
"${pip[@]}" install --quiet "scikit-build-core>=0.10" "nanobind>=2.0"
echo "== python: pip install .[test] (GDEL_CUDA=$GDEL_CUDA)"
start=$(date +%s)
"${pip[@]}" install --quiet --no-build-isolation ".[test]"
echo "== python: installed in $(( $(date +%s) - start )) s"

# `import gdel` is the installed package: the sources live in python/gdel, which is
# not on the path, so the tests exercise exactly what pip installed.
"$py" -m pytest -q -p no:cacheprovider tests/python "$@"
