#!/usr/bin/env bash
# Configures and builds kinestat (Release) in build/. Extra arguments are passed to `cmake --build`
# (e.g. `--target kinestat`). Used by demo.sh and test.sh. KINESTAT_PETSC=1 also installs PETSc
# (the optional distributed backends; test.sh sets it); KINESTAT_WERROR=1 makes our warnings errors.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${KINESTAT_PETSC:-0}" = 1 ]; then
  "$(dirname "$0")/install-deps.sh" --petsc
else
  "$(dirname "$0")/install-deps.sh"
fi
jobs=$(scripts/cpus.sh)
# KINESTAT_WERROR=1 (scripts/test.sh): a warning in kinestat's own code fails the build.
# KINESTAT_TEST_LAYERS="solver;fea;..." (scripts/test.sh sets four): only those layers' test programs.
# compile_commands.json: scripts/tidy.sh reads it.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DKINESTAT_WERROR="${KINESTAT_WERROR:-0}" \
  -DKINESTAT_TEST_LAYERS="${KINESTAT_TEST_LAYERS:-all}" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
cmake --build build -j"$jobs" "$@"
