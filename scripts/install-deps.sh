#!/usr/bin/env bash
# Installs kinestat's build and test dependencies from Debian 12 packages, only those missing.
# Runs as root on CI; uses sudo otherwise.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  python3                  # scripts/check_layers.py (Debian's /usr/bin/python3)
  libeigen3-dev            # dense linear algebra
  libspectra-dev           # sparse symmetric eigensolver on Eigen (kinestat buckling: Lanczos on the Cholesky of K)
  libsuitesparse-dev       # CHOLMOD (sparse Cholesky), with METIS ordering
  libopenblas0-pthread     # optimized BLAS under CHOLMOD's supernodal factorization
  libcgal-dev              # Mesh_3 tetrahedral meshing
  libvtk9-dev              # VTK XML (.vtu/.pvd) output for ParaView
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libyaml-cpp-dev          # structure files
  libmuparser-dev          # expressions of named parameters in robot files (models/robots/)
  libcli11-dev             # command-line options
  nlohmann-json3-dev       # JSON results
  libfmt-dev               # formatting
  libtbb-dev               # threads (FEA assembly)
  libssl-dev               # OpenSSL's SHA-256: the FEA result cache's keys and checksums
  python3-dev pybind11-dev python3-pybind11  # the Python module kinestat (python/, docs/python.md)
  python3-numpy            # its arrays
  python3-pytest           # its tests (tests/python)
  python3-matplotlib       # the Python examples' pictures (examples/python)
  libplplot-dev            # PNG maps (kinestat map/design --png) ...
  plplot-driver-cairo      # ... through PLplot's pngcairo device
  clang-16 libclang-rt-16-dev libfuzzer-16-dev  # scripts/sanitize.sh, scripts/fuzz.sh: ASan, UBSan, libFuzzer
  clang-format-16 clang-tidy-16  # scripts/check_format.sh, scripts/tidy.sh: the formatting and lint gates
)

# Optional: the distributed backends petsc-mumps and petsc-cg (docs/fea.md, "Large meshes").
# Installed with --petsc (scripts/test.sh, so CI covers them); demo.sh does without.
if [ "${1:-}" = "--petsc" ]; then
  PACKAGES+=(libpetsc-real-dev)  # PETSc 3.18 with Open MPI (mpiexec), MUMPS and hypre
  PACKAGES+=(slepc-dev)          # SLEPc 3.18 (PETSc's): link modes on petsc-mumps (eigensolver on its factor)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all dependencies present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
