#!/usr/bin/env bash
# Installs dependencies, builds the release preset and runs every test (unit, conformance,
# validation and OpenCL on the PoCL CPU device), then fuzzes the scene parser for 60 seconds.
# The OpenCL tests fail, not skip, when no OpenCL device is found.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release
ctest --preset release -j "$(nproc)" --timeout 900
bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
