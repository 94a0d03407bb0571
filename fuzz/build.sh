#!/usr/bin/env bash
# Builds the libFuzzer targets of gecko's elliptic kernels with clang++ (never part of the default
# gcc/CMake build). Output: build/fuzz/<target> (or $1).
#   bash fuzz/build.sh [outdir]
#   FUZZ_CXXFLAGS=-DGECKO_FUZZ_STRICT bash fuzz/build.sh build/fuzz-strict   # no known-finding filters
# CXX (default clang++) must support -fsanitize=fuzzer (Debian/Ubuntu: clang + libclang-rt-XX-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/fuzz}
cxx=${CXX_FUZZ:-clang++}
mkdir -p "$out"
flags=(-std=c++17 -O1 -g -fno-omit-frame-pointer
       -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
       -Wall -Wextra -Werror
       -I include -I /usr/include/eigen3)
# shellcheck disable=SC2206  # FUZZ_CXXFLAGS is a list of flags
flags+=(${FUZZ_CXXFLAGS:-})
pids=()
for t in fuzz_carlson fuzz_legendre; do
  # two compilations in parallel (CI has 2 cores); each is one header-only translation unit
  "$cxx" "${flags[@]}" "fuzz/$t.cpp" -o "$out/$t" &
  pids+=($!)
done
status=0
for p in "${pids[@]}"; do wait "$p" || status=1; done
exit $status
