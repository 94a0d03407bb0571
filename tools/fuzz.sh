#!/usr/bin/env bash
# Bounded, fixed-seed fuzzing for CI (fuzz/README.md): builds the libFuzzer targets of the
# elliptic kernels with clang++ (-fsanitize=fuzzer,address,undefined -O1 -g), runs each for a
# fixed number of inputs from a fixed seed, then the atheris target of the scene parser.
# Exits non-zero on any finding (crash, sanitizer report, failed property, timeout, leak).
#   bash tools/fuzz.sh                    # CI: about 2-3 min on 2 cores (capped at 4)
#   FUZZ_SCALE=10 bash tools/fuzz.sh      # ten times as many inputs
#   PYTHON=python3 PYTHONPATH=python bash tools/fuzz.sh   # development checkout, no .venv
# Longer campaigns (corpus kept between runs, several jobs): see fuzz/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."

python=${PYTHON:-.venv/bin/python}
scale=${FUZZ_SCALE:-1}
out=build/fuzz
work=$(mktemp -d "${TMPDIR:-/tmp}/gecko-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$out/artifacts"

echo "== fuzz: building the libFuzzer targets (clang++)"
bash fuzz/build.sh "$out"

# -runs fixes the work (with -seed=1 the inputs tried are the same on every run);
# -max_total_time only caps a pathologically slow machine.
common=(-seed=1 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -max_total_time=$((120 * scale)))
declare -A runs=([fuzz_carlson]=$((1000000 * scale)) [fuzz_legendre]=$((2000000 * scale)))

status=0
run_native() {
  local t=$1
  mkdir -p "$work/$t"
  # the working corpus starts from the committed seeds; new units stay in $work
  if "$out/$t" "${common[@]}" -runs="${runs[$t]}" -artifact_prefix="$out/artifacts/$t-" \
       "$work/$t" "fuzz/corpus/$t" > "$work/$t.log" 2>&1; then
    echo "-- $t: ok ($(grep -E '^stat::number_of_executed_units' "$work/$t.log" | awk '{print $2}') inputs," \
         "$(grep -oE 'cov: [0-9]+' "$work/$t.log" | tail -1) edges, ${SECONDS}s since start)"
    grep -E '^fuzz_(carlson|legendre):' "$work/$t.log" || true
  else
    echo "-- $t: FINDING (reproduce: $out/$t <crash file>; GECKO_FUZZ_TRACE=1 prints the arguments)"
    grep -E 'gecko fuzz finding|runtime error|ERROR: AddressSanitizer|ERROR: libFuzzer|SUMMARY|Test unit written|Base64' \
      "$work/$t.log" | head -20
    return 1
  fi
}

echo "== fuzz: elliptic kernels (two targets in parallel)"
run_native fuzz_carlson & p1=$!
run_native fuzz_legendre & p2=$!
wait $p1 || status=1
wait $p2 || status=1

echo "== fuzz: scene parser (atheris, $python)"
if ! "$python" -c "import atheris, gecko.scene" 2>/dev/null; then
  echo "-- fuzz_scene: $python cannot import atheris and gecko.scene (pip install atheris;"
  echo "   for a development checkout: PYTHON=python3 PYTHONPATH=python bash tools/fuzz.sh)"
  exit 1
fi
mkdir -p "$work/scene"
if "$python" fuzz/fuzz_scene.py -seed=1 -runs=$((10000 * scale)) -timeout=20 -rss_limit_mb=3072 \
     -max_total_time=$((90 * scale)) -print_final_stats=1 -artifact_prefix="$out/artifacts/scene-" \
     "$work/scene" fuzz/corpus/scene > "$work/scene.log" 2>&1; then
  echo "-- fuzz_scene: ok ($(grep -E '^stat::number_of_executed_units' "$work/scene.log" | awk '{print $2}') inputs," \
       "${SECONDS}s since start)"
  grep -E '^fuzz_scene:' "$work/scene.log" || true
else
  echo "-- fuzz_scene: FINDING (reproduce: $python fuzz/fuzz_scene.py <crash file>)"
  grep -vE '^#[0-9]+|^INFO|^\s*"' "$work/scene.log" | tail -40
  status=1
fi

if [ $status -ne 0 ]; then
  echo "== fuzz: findings; inputs saved under $out/artifacts/"
fi
exit $status
