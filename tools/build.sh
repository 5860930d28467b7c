#!/usr/bin/env bash
# Installs what is missing (Debian 12), configures and builds plyimpact in ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
