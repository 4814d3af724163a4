#!/usr/bin/env bash
# kinestat's FEA link solve against CalculiX (ccx) on the same mesh: bench_fea's quadratic-tet bar
# at n = 6 and 9 (88k / 296k dofs), clamped at x = 0, rigid end face, six unit loads.
# Usage: scripts/bench_calculix.sh [build-dir] [n ...]   (defaults: build-calculix, 6 9)
# Prints, per size: kinestat assembly / analyse+factor / six solves (bench_fea), ccx wall time and
# peak memory (/usr/bin/time -v), ccx's solver, and both codes' axial tip compliance ux/Fx (m/N).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-calculix}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(6 9)

if ! command -v ccx > /dev/null || [ ! -x /usr/bin/time ]; then
  sudo=$([ "$(id -u)" -eq 0 ] || echo sudo)
  $sudo apt-get update -qq && $sudo apt-get install -y -qq calculix-ccx time
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DKINESTAT_BUILD_BENCHMARKS=ON > /dev/null
cmake --build "$build" --target export_calculix bench_fea -j2 > /dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=2  # ccx's SPOOLES threads; kinestat's BLAS uses both cores too
rows=()
for n in "${sizes[@]}"; do
  mkdir -p "$work/$n"
  # kinestat: one process per size (bench_fea's peak memory is per process).
  json=$("$build/benchmarks/bench_fea" --benchmark_filter="Assembly/$n\$|FactorizeAndSolve/$n/" \
    --benchmark_format=json 2> /dev/null)
  ks=$(python3 -c '
import json, sys
b = {x["name"].split("/")[0]: x for x in json.load(sys.stdin)["benchmarks"]}
a, f = b["BM_Assembly"], b["BM_FactorizeAndSolve"]
print(int(f["dofs"]), a["real_time"] / 1e3, f["analyze_s"] + f["factor_s"], f["six_solves_s"], f["peak_rss_MB"])' <<< "$json")
  read -r dofs k_asm k_fact k_solve k_mem <<< "$ks"
  k_ux=$("$build/benchmarks/export_calculix" -n "$n" --solve "$work/$n/bar.inp" |
    sed -n 's/.*compliance diagonal[^:]*: \([^ ]*\).*/\1/p')
  # ccx: six *STEP blocks, each assembled and factored anew.
  (cd "$work/$n" && /usr/bin/time -v ccx -i bar > ccx.log 2> time.log)
  wall=$(sed -n 's/.*Elapsed (wall clock).*: //p' "$work/$n/time.log")
  c_mem=$(awk '/Maximum resident/ {printf "%.0f", $NF / 1024}' "$work/$n/time.log")
  solver=$(grep -o -m1 'using the [a-z ]* solver' "$work/$n/ccx.log" || echo unknown)
  # First printed displacement of step 1 (unit Fx): ux of the reference node.
  c_ux=$(awk '/displacements/ {found = 1; next} found && NF == 4 {print $2; exit}' "$work/$n/bar.dat")
  rows+=("$(printf '%s|%.2f|%.2f|%.2f|%.0f|%s|%s|%s|%s|%s' "$dofs" "$k_asm" "$k_fact" "$k_solve" "$k_mem" \
    "$wall" "$c_mem" "${solver#using the }" "$k_ux" "$c_ux")")
done
echo "| dofs | kinestat assembly (s) | analyse+factor (s) | six solves (s) | peak (MB) | ccx wall (m:ss, 6 steps) | ccx peak (MB) | ccx solver | ux/Fx kinestat (m/N) | ux/Fx ccx (m/N) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for r in "${rows[@]}"; do echo "| ${r//|/ | } |"; done
