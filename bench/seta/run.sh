#!/usr/bin/env bash
# One command for the seta benchmark: builds bench_seta in Release, runs it, then times the scipy
# peer and the Python call on the same grid (bench/seta/peer_scipy.py). Writes
# bench/results/seta.csv and bench/results/seta.md.
#   bench/seta/run.sh [--reps N]
# Environment: BUILD_DIR (default build-bench), JOBS (default 2). The scipy peer is
# bench/seta/scipy_peer.py; nothing outside the repository is read.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-bench}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGECKO_BUILD_BENCHMARKS=ON \
      -DGECKO_BUILD_TESTS=OFF -DGECKO_BUILD_PYTHON=OFF -DGECKO_INSTALL=OFF > /dev/null
cmake --build "$build" --target bench_seta -j "${JOBS:-2}"
mkdir -p "$root/bench/results"
"$build/bench/seta/bench_seta" --out "$root/bench/results" "$@"
python3 "$root/bench/seta/peer_scipy.py"
