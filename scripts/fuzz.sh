#!/usr/bin/env bash
# Builds the scene-parser fuzzer with clang (libFuzzer + ASan + UBSan) and runs it for
# SECONDS (default 60) starting from the scene library as corpus. Exits non-zero on any crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
bash scripts/install-deps.sh
cmake -S . -B build/fuzz -DCOLLIDE_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ > build-fuzz-configure.log 2>&1 \
  || { cat build-fuzz-configure.log; exit 1; }
rm -f build-fuzz-configure.log
cmake --build build/fuzz --target fuzz_scene_parser -j "$(nproc)"
corpus=build/fuzz/corpus
mkdir -p "$corpus"
find data/scenes -name '*.toml' -exec cp {} "$corpus/" \;
build/fuzz/tests/fuzz/fuzz_scene_parser -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix=build/fuzz/ "$corpus"
echo "fuzz: no crash in ${seconds} s"
