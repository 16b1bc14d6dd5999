#!/usr/bin/env bash
# The main job: install dependencies, build, run the default validation suite on every
# backend and render its accuracy report.
#   bash scripts/validate.sh [SUITE] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
suite="${1:-validation/suites/default.toml}"
out="${2:-results/$(basename "$suite" .toml)}"
bash scripts/build.sh release
# A refused suite stops here (its exit status 1 is that of failed checks too), before the report
# below could draw an earlier run's results left in $out as if they were this run's.
build/release/collide validate "$suite" --plan > /dev/null
status=0
build/release/collide validate "$suite" --out "$out" --jobs "$(nproc)" || status=$?
build/release/collide report "$out"
echo "report: $out/report/index.html (summary: $out/report/summary.md)"
exit $status
