#!/usr/bin/env bash
# One command for the friction benchmarks: builds bench_friction_beam and bench_friction_sliding
# in Release, runs them, and runs the Python-level benchmark (needs `import gecko` to work);
# results go to bench/results/friction_*.{md,csv}.
#
#   bench/friction/run.sh [--reps N]
# Environment: BUILD_DIR (default build-bench-friction), JOBS (default 2), PYTHON (python3).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-bench-friction}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGECKO_BUILD_BENCHMARKS=ON \
      -DGECKO_BUILD_TESTS=OFF -DGECKO_BUILD_PYTHON=OFF -DGECKO_INSTALL=OFF > /dev/null
cmake --build "$build" --target bench_friction_beam bench_friction_sliding -j "${JOBS:-2}"
mkdir -p "$root/bench/results"
"$build/bench/friction/bench_friction_beam" --out "$root/bench/results" "$@"
"$build/bench/friction/bench_friction_sliding" --out "$root/bench/results" "$@"
"${PYTHON:-python3}" "$root/bench/friction/bench_steady_sliding.py" --out "$root/bench/results" "$@"
"${PYTHON:-python3}" "$root/bench/friction/bench_fit.py" --out "$root/bench/results"
