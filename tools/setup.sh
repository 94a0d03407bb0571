#!/usr/bin/env bash
# Installs everything gecko's build, tests and benchmarks need, on a fresh Debian/Ubuntu machine,
# then builds and installs the Python package into ./.venv. Idempotent: a second run is quick.
#   bash tools/setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."

apt_packages=(g++ cmake ninja-build python3 python3-venv python3-dev
              libeigen3-dev catch2 libgsl-dev libboost-dev libbenchmark-dev
              clang libclang-rt-14-dev)   # clang + libFuzzer: tools/fuzz.sh
missing=()
for p in "${apt_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

python=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
  "$python" -m venv .venv
fi
.venv/bin/python -m pip install -q --upgrade pip
.venv/bin/python -m pip install -q numpy scipy mpmath pytest matplotlib \
    pandas pyarrow "dask[distributed]" atheris   # sweeps ([sweep], [dask] extras) and the scene-parser fuzzer
# The package itself, built in an isolated environment exactly as a user's `pip install .`
# (scikit-build-core + pybind11 + cmeel-eigen come from PyPI as build requirements).
.venv/bin/python -m pip install -q .
.venv/bin/python -c "import gecko; print('setup: gecko', gecko.__version__, 'installed in .venv')"
