#!/usr/bin/env bash
# Configures and builds kinestat (Release) in build/. Extra arguments are passed to `cmake --build`
# (e.g. `--target kinestat`). Used by demo.sh and test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
"$(dirname "$0")/install-deps.sh"
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs" "$@"
