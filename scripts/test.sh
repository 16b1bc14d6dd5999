#!/usr/bin/env bash
# Installs dependencies, builds the release preset, fuzzes the scene parser for 60 seconds
# (FUZZ_SECONDS to change), then runs every test: unit, conformance, validation and OpenCL on
# the PoCL CPU device. The OpenCL tests fail, not skip, when no OpenCL device is found.
# Last, the full validation suite (about 2.5 minutes on 2 cores); it exits 1 on any failed check.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release
bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
ctest --preset release -j "$(nproc)" --timeout 900
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
build/release/collide validate validation/suites/full.toml --out "$out/full" --jobs "$(nproc)"
