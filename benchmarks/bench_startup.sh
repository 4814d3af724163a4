#!/usr/bin/env bash
# The cost of starting kinestat: N runs each of `kinestat --help`, a small map (the Orthoglide
# file at 50 mm, 125 postures) and the issue's loaded map of models/orthoglide_puu.yaml (68 921
# postures, 2 threads), for each program given, one after the other in the same run: user, system and
# wall seconds per run.
#   benchmarks/bench_startup.sh [-n N] KINESTAT [KINESTAT2 ...]
set -euo pipefail
cd "$(dirname "$0")/.."
n=20
if [[ ${1:-} == -n ]]; then n=$2; shift 2; fi
[[ $# -ge 1 ]] || { echo "usage: benchmarks/bench_startup.sh [-n N] KINESTAT [KINESTAT2 ...]" >&2; exit 2; }
per_run() {  # per_run LABEL RUNS COMMAND...: mean user, system and wall seconds of RUNS runs
  local label=$1 runs=$2
  shift 2
  local out
  out=$( { /usr/bin/time -f "%U %S %e" bash -c 'for ((i = 0; i < $0; ++i)); do "$@" >/dev/null 2>&1; done' \
           "$runs" "$@"; } 2>&1 | tail -n1)
  read -r u s e <<<"$out"
  awk -v l="$label" -v u="$u" -v s="$s" -v e="$e" -v n="$runs" \
    'BEGIN { printf "%-58s user %8.4f s  sys %8.4f s  wall %8.4f s\n", l, u / n, s / n, e / n }'
}
uptime
for bin in "$@"; do
  echo "$bin: $(ldd "$bin" | wc -l) shared libraries"
  per_run "  --help (x$n)" "$n" "$bin" --help
  per_run "  map orthoglide_puu.yaml --step 50 (x$n)" "$n" "$bin" map models/orthoglide_puu.yaml \
    --box -100:100,-100:100,-100:100 --step 50 --quiet
  per_run "  the issue's loaded map, --step 5, 2 threads (x3)" 3 "$bin" map models/orthoglide_puu.yaml \
    --box -100:100,-100:100,-100:100 --step 5 --wrench 0,0,-500,0,0,0 --threads 2 --quiet
done
