#!/usr/bin/env bash
# The per-spatula cost of simulate_spatulae before (main) and after (this tree) spatula
# populations, in one run: builds bench_population.cpp against each header with the Release
# flags, runs the two builds alternately (ROUNDS rounds, so a noisy interval hits both alike) and
# writes bench/results/friction_population.{md,csv} with the medians over the rounds.
#
#   bench/friction/population_cost.sh [--reps N]     environment: BASE, ROUNDS (5), CXX
# BASE defaults to 7f3d0a6^, the last commit before populations (main now has them).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
base="${BASE:-7f3d0a6^}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/main/gecko/friction"
git -C "$root" show "$base:include/gecko/friction/spatula_simulation.hpp" \
  > "$work/main/gecko/friction/spatula_simulation.hpp"
flags=(-O3 -DNDEBUG -std=c++17 -Wall -Wextra -Werror -I"$root/bench" -isystem /usr/include/eigen3)
cxx="${CXX:-c++}"
"$cxx" "${flags[@]}" -I"$work/main" -I"$root/include" "$root/bench/friction/bench_population.cpp" \
  -o "$work/bench_main"
"$cxx" "${flags[@]}" -DGECKO_BENCH_POPULATION -I"$root/include" \
  "$root/bench/friction/bench_population.cpp" -o "$work/bench_tree"
for r in $(seq 1 "${ROUNDS:-5}"); do  # the order alternates too: neither build always goes first
  first=main second=tree
  if (( r % 2 == 0 )); then first=tree second=main; fi
  "$work/bench_$first" "$@" | sed "s/^/$first $r /" >> "$work/lines"
  "$work/bench_$second" "$@" | sed "s/^/$second $r /" >> "$work/lines"
done
python3 - "$work/lines" "$root/bench/results" "$(git -C "$root" rev-parse --short "$base")" \
  "$(git -C "$root" rev-parse --short HEAD)" "${flags[*]}" <<'PY'
import statistics, sys
from collections import defaultdict
lines, out, base, head, flags = sys.argv[1:]
ns, info = defaultdict(list), {}
for ln in open(lines):
    build, _, case, t, cycles, mean = ln.split()
    ns[(build, case)].append(float(t))
    info[(build, case)] = (int(cycles), mean)
cases = list(dict.fromkeys(c for _, c in ns))
rows = []
for c in cases:
    m = statistics.median(ns[("main", c)]) if ("main", c) in ns else None
    t = statistics.median(ns[("tree", c)])
    same = ("main", c) in info and info[("main", c)] == info[("tree", c)]
    rows.append((c, m, t, info[("tree", c)][0], same))
with open(f"{out}/friction_population.csv", "w") as f:
    f.write("case,main_ns_per_spatula_cycle,tree_ns_per_spatula_cycle,spatula_cycles,same_result\n")
    for c, m, t, n, same in rows:
        f.write(f"{c},{'' if m is None else f'{m:.4f}'},{t:.4f},{n},{int(same)}\n")
with open(f"{out}/friction_population.md", "w") as f:
    f.write(f"simulate_spatulae, CPU time per simulated spatula cycle (1000 spatulae x 100 cycles, FIG6 "
            f"viscoelastic, V = 100 um/s, t_off = 0.1 ms), median of {len(ns[('tree', cases[0])])} "
            f"alternating rounds of the two builds (each round the median of its repetitions).\n"
            f"main = {base} (before populations), tree = {head}. Flags: {flags}\n\n")
    f.write("| case | main (ns / spatula cycle) | tree (ns / spatula cycle) | tree / main | same result |\n")
    f.write("|---|---|---|---|---|\n")
    for c, m, t, n, same in rows:
        ratio = "" if m is None else f"{t / m:.3f}"
        f.write(f"| {c} | {'' if m is None else f'{m:.2f}'} | {t:.2f} | {ratio} | "
                f"{'yes' if same else ('n/a' if m is None else 'NO')} |\n")
print(open(f"{out}/friction_population.md").read())
PY
