#!/usr/bin/env bash
# Sets up (tools/setup.sh) and runs the main job: the reference two-level seta's exact critical
# line of adhesion with the Kendall and Rivlin peel lines, as PNG + CSV in out/demo/.
#   bash tools/demo.sh [extra `gecko run` options, e.g. --svg]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
.venv/bin/gecko run examples/demo_reference_critical_line.toml --out out/demo "$@"
echo "demo: wrote $(ls out/demo | tr '\n' ' ')"
