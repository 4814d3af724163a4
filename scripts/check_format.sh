#!/usr/bin/env bash
# Fails when a C++ file differs from `clang-format-16` with the project's .clang-format (scripts/test.sh
# runs it; CONTRIBUTING.md). `scripts/check_format.sh --fix` formats them in place.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format-16 -i "${files[@]}"
  exit 0
fi
if ! clang-format-16 --dry-run --Werror "${files[@]}" 2> /tmp/kinestat_format.$$; then
  grep -E "^[^ ].*error:" /tmp/kinestat_format.$$ | sed 's/: error:.*//' | sort -u | head -20 >&2
  rm -f /tmp/kinestat_format.$$
  echo "check_format: the files above are not formatted; run scripts/check_format.sh --fix" >&2
  exit 1
fi
rm -f /tmp/kinestat_format.$$
echo "check_format: ${#files[@]} files formatted"
