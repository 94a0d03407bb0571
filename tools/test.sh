#!/usr/bin/env bash
# Sets up (tools/setup.sh) and runs every test: the C++ tests (ctest) in a warnings-as-errors
# Release build, again under AddressSanitizer + UndefinedBehaviorSanitizer, a bounded fixed-seed
# fuzzing run (tools/fuzz.sh), then the Python tests (pytest) against the installed package, once
# with OPENBLAS_CORETYPE unset and once with OPENBLAS_CORETYPE=Haswell.
#   bash tools/test.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
# Each stage's header says how long the run has taken so far (CI's budget is 45 minutes).
stage() { echo "== $* [$(date -u +%T), ${SECONDS} s in]"; }

jobs=$(nproc 2>/dev/null || echo 2)
warn="-Wall -Wextra -Werror"
# The test executables are compiled in batches of five files (CMake's unity build), the seta tests
# in one (tests/CMakeLists.txt): every seta test file instantiates the same solver, so one batch
# costs about what one file does alone. Test files therefore keep their file-local names distinct.
unity="-DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=5"

stage "C++ tests (Release, $warn)"
cmake -S . -B build/ci-release -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="$warn" $unity >/dev/null
cmake --build build/ci-release -j "$jobs"
ctest --test-dir build/ci-release --output-on-failure -j "$jobs"

stage "C++ tests under ASan + UBSan"
san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# -O1 -g1: sanitizer builds compile twice as fast as -O2 -g and still report file:line.
cmake -S . -B build/ci-asan -G Ninja -DCMAKE_BUILD_TYPE= -DGECKO_INSTALL=OFF $unity \
      -DCMAKE_CXX_FLAGS="-O1 -g1 $warn $san" -DCMAKE_EXE_LINKER_FLAGS="$san" >/dev/null
cmake --build build/ci-asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/ci-asan --output-on-failure -j "$jobs"

stage "Fuzzing (bounded, fixed seed): elliptic kernels (libFuzzer) and the scene parser (atheris)"
bash tools/fuzz.sh

# Twice: with OPENBLAS_CORETYPE unset, and with the Haswell kernels that OpenBLAS selects (or is
# told to select) on some machines of CI's kind; BLAS rounding must not change a verdict.
stage "Python tests (OPENBLAS_CORETYPE unset)"
env -u OPENBLAS_CORETYPE .venv/bin/python -m pytest -q tests/python
stage "Python tests (OPENBLAS_CORETYPE=Haswell)"
OPENBLAS_CORETYPE=Haswell .venv/bin/python -m pytest -q tests/python
stage "Documentation (tools/docs.sh: warnings are errors, tutorials executed)"
bash tools/docs.sh
stage "done"
