#!/usr/bin/env bash
# Configures and builds a preset (default: release) after making sure the Debian packages are
# present. Used by validate.sh and test.sh; safe to run again (incremental).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/install-deps.sh
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"
