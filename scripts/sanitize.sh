#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (docs/reliability.md).
# Builds with clang-16 in build-sanitize/ (its own folder: the Release build in build/ is untouched),
# with -fsanitize=address,undefined (five checks left out, below) -fno-sanitize-recover=undefined,
# and runs every ctest test there: any sanitizer report fails the test that triggered it, and this
# script. The same build carries the
# libFuzzer harnesses that scripts/fuzz.sh runs (KINESTAT_BUILD_FUZZERS); benchmarks and the mesh
# generator (meshes/make_meshes.cpp, which no test runs) are left out.
#   scripts/sanitize.sh             build and run the tests
#   scripts/sanitize.sh --build     build only (scripts/fuzz.sh)
# Called by scripts/test.sh, hence by CI.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(scripts/cpus.sh)
# -gline-tables-only: file and line in the reports at little build cost. -fno-sanitize=object-size:
# UBSan's object-size check doubles clang's compile time of the Eigen-heavy files (measured on
# src/core/stiffness_indices.cpp: 69 s with it, 35 s without, 37 s ASan alone), and AddressSanitizer
# already catches every access outside an object, which is what it checks. alignment, null, vptr and
# pointer-overflow are left out too: together they cost about a quarter of the build (tests/msa/
# frames_test.cpp: 21-25 s with them, 16-17 s without, 2026-11-26), and what they catch here another
# check catches first or they have little to check (a null access faults under ASan, a misaligned one
# only matters vectorized, and then faults; kinestat downcasts only with dynamic_cast; its pointer
# arithmetic is the standard containers' and Eigen's). PETSc is left out: Open MPI keeps allocations past
# MPI_Finalize that LeakSanitizer would report as ours; the PETSc backends are tested in the Release
# build (1 and 2 ranks).
flags="-fsanitize=address,undefined -fno-sanitize=object-size,alignment,null,vptr,pointer-overflow"
flags+=" -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-16 \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DKINESTAT_BUILD_BENCHMARKS=OFF -DKINESTAT_BUILD_PYTHON=OFF -DKINESTAT_USE_PETSC=OFF \
  -DKINESTAT_BUILD_FUZZERS=ON -DKINESTAT_BUILD_MESH_TOOL=OFF >/dev/null
cmake --build build-sanitize -j"$jobs"
if [ "${1:-}" = "--build" ]; then exit 0; fi
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/lsan.supp"  # third-party caches kept until exit
cd build-sanitize
ctest --output-on-failure -j"$jobs" --timeout 900
