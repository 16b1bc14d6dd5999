#!/usr/bin/env bash
# Installs dependencies, builds the release preset, fuzzes the scene parser for 60 seconds
# (FUZZ_SECONDS to change), then runs every test: unit, conformance, validation and OpenCL on
# the PoCL CPU device. The OpenCL tests fail, not skip, when no OpenCL device is found.
# Then the full validation suite (442 cases, about a minute on 2 idle cores); it exits 1 on any failed check.
# Last, the README's main job as its reader sees it: the default suite (about a minute on 2
# cores), its report, and the report's first screen in headless Chromium
# (tests/report/test_browser.py; ctest runs that test on the small report-test suite, whose
# table is shorter than the default suite's: the default suite's once ended below the screen).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release
bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
ctest --preset release -j "$(nproc)" --timeout 900
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
build/release/collide validate validation/suites/full.toml --out "$out/full" --jobs "$(nproc)"
build/release/collide validate validation/suites/default.toml --out "$out/default" --jobs "$(nproc)"
build/release/collide report "$out/default"
python="$(sed -n 's/^_\{0,1\}Python3_EXECUTABLE:[A-Z]*=//p' build/release/CMakeCache.txt | head -n 1)"  # ctest's interpreter (FindPython3 caches it as _Python3_EXECUTABLE)
"${python:-python3}" tests/report/test_browser.py "$out/default"
