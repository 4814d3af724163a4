#!/usr/bin/env bash
# Runs each libFuzzer harness (fuzz/, built with ASan and UBSan by scripts/sanitize.sh in
# build-sanitize/) for SECONDS (default 60), as many side by side as there are CPUs, from seed
# corpora made of the bundled models, meshes and test inputs (docs/reliability.md). A crash, a sanitizer report, an
# allocation above 1 GB, more than 2 GB of memory or an input running 30 s stops the run with the
# input saved under build-sanitize/fuzz/artifacts/NAME/: fix the code, then keep the input as a
# regression under tests/fuzz/NAME/ (ctest replays that folder in every build).
#   scripts/fuzz.sh [SECONDS]      CI runs scripts/fuzz.sh 10 from scripts/test.sh
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
scripts/sanitize.sh --build >/dev/null
root=build-sanitize/fuzz
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/lsan.supp"  # third-party caches kept until exit

# Seeds: what each reader reads in the repository. The surface and option harnesses take a first
# byte choosing the format or the parser (see their sources): the bundled meshes get byte 0 (OFF).
seed() {
  local name=$1 corpus=$root/corpus/$1
  mkdir -p "$corpus" "$root/artifacts/$name"
  cp -n tests/fuzz/"$name"/* "$corpus"/ 2>/dev/null || true
  case $name in
    *_yaml) cp -n models/*.yaml models/robots/*.yaml tests/io/data/*.yaml "$corpus"/ ;;
    surface_mesh)
      for m in meshes/*.off; do
        [ -e "$corpus/mesh_$(basename "$m")" ] || { printf '\0'; cat "$m"; } > "$corpus/mesh_$(basename "$m")"
      done ;;
  esac
}

# One harness: its report lines are printed when it ends (harnesses run side by side, one per CPU).
run() {
  local name=$1 log=$root/$1.log
  if ! build-sanitize/fuzz/fuzz_"$name" "$root/corpus/$name" -max_total_time="$seconds" -timeout=30 \
      -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 \
      -artifact_prefix="$root/artifacts/$name/" >"$log" 2>&1; then
    echo "fuzz: $name FAILED; the input is in $root/artifacts/$name/, the report in $log:"
    tail -40 "$log"
    return 1
  fi
  # The last status line: runs, coverage (edges) and features, corpus size, executions per second.
  grep -a -E "^#[0-9]+[[:space:]]+DONE" "$log" | tail -1 | sed "s/^/fuzz: $name: /"
}

jobs=$(scripts/cpus.sh)
status=0
pids=()
for name in structure_yaml vjm_yaml identification_yaml surface_mesh option_parsers frame3dd robot_yaml; do
  seed "$name"
  echo "fuzz: $name for ${seconds} s"
  run "$name" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status
