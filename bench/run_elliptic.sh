#!/usr/bin/env bash
# One command for the elliptic benchmark: builds bench_elliptic in Release and runs it, writing
# bench/results/elliptic.csv and bench/results/elliptic.md (the README table is copied from .md).
#
#   bench/run_elliptic.sh [extra bench_elliptic arguments, e.g. --reps 21]
#
# Environment: BUILD_DIR (default build-bench, under the repository root), JOBS (default 2).
# The input/reference data are committed; regenerate with  python3 bench/elliptic/gen_inputs.py
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build-bench}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGECKO_BUILD_BENCHMARKS=ON \
      -DGECKO_BUILD_TESTS=OFF -DGECKO_BUILD_PYTHON=OFF -DGECKO_INSTALL=OFF > /dev/null
cmake --build "$build" --target bench_elliptic -j "${JOBS:-2}"
mkdir -p "$root/bench/results"
"$build/bench/elliptic/bench_elliptic" --data "$root/bench/elliptic/data" --out "$root/bench/results" "$@"
