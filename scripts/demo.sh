#!/usr/bin/env bash
# Installs what is missing, builds Release, solves the bundled default model (the 5R five-bar of
# Gonçalves et al. 2010 at a non-singular posture) and writes VTK + JSON results into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --target kinestat
mkdir -p out
./build/src/cli/kinestat solve models/five_bar.yaml --vtk out --json out/five_bar.json
echo
echo "Results written to $(pwd)/out:"
ls -1 out | sed 's/^/  out\//'
echo "Open out/five_bar.pvd in ParaView (Warp By Vector on 'displacement' shows the deformed shape)."
