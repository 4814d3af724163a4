#!/usr/bin/env bash
# clang-tidy (Debian's clang-tidy-16) with the checks of .clang-tidy on the lower layers (core,
# elements, solver: every other layer stands on them), warnings as errors. Needs build/ configured
# (compile_commands.json). scripts/test.sh runs it; `scripts/tidy.sh FILE...` checks those files.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files 'src/core/*.cpp' 'src/elements/*.cpp' 'src/solver/*.cpp')
fi
jobs=$(scripts/cpus.sh)
printf '%s\n' "${files[@]}" | xargs -P "$jobs" -n 1 clang-tidy-16 -p build --quiet 2>/dev/null
echo "tidy: ${#files[@]} files clean"
