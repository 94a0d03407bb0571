#!/usr/bin/env bash
# One command for the scaling benchmark (issue 6 item 2): builds bench_scaling in Release, runs it
# (lines/s on 1 and 2 threads, time against points per line and designs per batch, C++ memory per
# design), then bench/scaling/report.py fits the scaling, measures the Python-side memory of
# gecko.critical_line_batch and writes bench/results/scaling.{csv,json,md,png}. About 4-6 minutes
# on the shared 2-core machine.
#   bench/scaling/run.sh [--reps N] [--quick]
# Environment: BUILD_DIR (default build-bench), JOBS (default 2), PYTHON (default python3; needs
# numpy, matplotlib and an importable gecko: PYTHONPATH defaults to python/ of this checkout).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-bench}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGECKO_BUILD_BENCHMARKS=ON \
      -DGECKO_BUILD_TESTS=OFF -DGECKO_BUILD_PYTHON=OFF -DGECKO_INSTALL=OFF > /dev/null
cmake --build "$build" --target bench_scaling -j "${JOBS:-2}"
mkdir -p "$root/bench/results"
raw="$(mktemp)"
trap 'rm -f "$raw"' EXIT
"$build/bench/scaling/bench_scaling" "$@" | tee "$raw"
PYTHONPATH="${PYTHONPATH:-$root/python}" "${PYTHON:-python3}" "$root/bench/scaling/report.py" "$raw" "$root/bench/results"
echo "wrote $root/bench/results/scaling.{csv,json,md,png}"
