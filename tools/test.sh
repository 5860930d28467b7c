#!/usr/bin/env bash
# README command 2: set up, build and run the whole test suite with ctest, then check every scene
# under configs/ with `plyimpact check`. A failed build stops here (ctest would otherwise run stale
# binaries).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
