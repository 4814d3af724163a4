#!/usr/bin/env bash
# Proves the installable package: installs build/ into a temporary prefix, checks that the prefix
# holds the headers, the layer libraries, the kinestat executable, the CMake package files and (when
# built) the PETSc module and the Python package, which it imports from there (both load that
# module from the prefix); then
# configures, builds and runs tests/install/consumer (find_package(kinestat), kinestat::kinestat)
# against that prefix alone. Called by scripts/test.sh after ctest; run it after a build.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install build --prefix "$prefix" >/dev/null
missing=0
for f in include/kinestat/msa/static_analysis.hpp include/kinestat/core/cartesian_stiffness.hpp \
         include/kinestat/solver/linear_solver_factory.hpp bin/kinestat; do
  [[ -e "$prefix/$f" ]] || { echo "check_install: $f is not installed" >&2; missing=1; }
done
config=$(find "$prefix" -name kinestatConfig.cmake -path '*/cmake/kinestat/*' | head -n1)
[[ -n "$config" ]] || { echo "check_install: kinestatConfig.cmake is not installed" >&2; exit 1; }
package=$(dirname "$config")             # PREFIX/LIBDIR/cmake/kinestat
libdir=$(dirname "$(dirname "$package")")
for f in kinestatConfigVersion.cmake kinestatTargets.cmake; do
  [[ -e "$package/$f" ]] || { echo "check_install: $f is not installed" >&2; missing=1; }
done
for layer in core elements solver msa vjm fea mechanisms io cli; do
  [[ -e "$libdir/libkinestat_$layer.a" ]] || { echo "check_install: libkinestat_$layer.a is not installed" >&2; missing=1; }
done
# The package refers to nothing in the source or build tree.
if grep -rl "$root" "$package" >/dev/null; then
  echo "check_install: the installed CMake files name the source tree ($root):" >&2
  grep -rl "$root" "$package" >&2
  missing=1
fi
# Internal headers stay private.
if [[ -e "$prefix/include/kinestat/msa/dof_map.hpp" || -d "$prefix/include/msa" ]]; then
  echo "check_install: an internal header was installed" >&2; missing=1
fi
[[ $missing == 0 ]] || exit 1

"$prefix/bin/kinestat" --help >/dev/null
# The PETSc module, when it was built: installed, and found there (not in the build tree) by the
# installed program, which --version shows, and by the installed Python module below.
petsc_module=
if [[ -e build/src/solver/petsc/libkinestat_petsc.so ]]; then
  petsc_module="$libdir/kinestat/libkinestat_petsc.so"
  [[ -e "$petsc_module" ]] || { echo "check_install: $petsc_module is not installed" >&2; exit 1; }
  "$prefix/bin/kinestat" --version | grep -qF "(module $petsc_module)" ||
    { echo "check_install: the installed kinestat does not load $petsc_module:" >&2; "$prefix/bin/kinestat" --version >&2; exit 1; }
fi
# The Python package, when it was built: found under the prefix by setting one path, as
# docs/python.md says, and imported from there (not from the build tree).
if compgen -G "build/python/kinestat/_kinestat*.so" >/dev/null; then
  site=$(find "$prefix" -type d -name kinestat -path '*-packages/kinestat' | head -n1)
  [[ -n "$site" ]] || { echo "check_install: the Python package kinestat is not installed" >&2; exit 1; }
  (cd "$work" && PYTHONPATH="$(dirname "$site")" /usr/bin/python3 -c "
import kinestat, sys
assert kinestat.__file__.startswith(sys.argv[1]), kinestat.__file__
assert kinestat.mechanisms.compute_workspace_map and kinestat.fea.compute_link_stiffness
module = sys.argv[2]
assert not module or kinestat.solver.petsc_versions().endswith('(module %s)' % module), kinestat.solver.petsc_versions()
" "$prefix" "$petsc_module") || { echo "check_install: the installed Python package does not import, or does not load its PETSc module" >&2; exit 1; }
fi
cmake -S "$root/tests/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer" -j"$(scripts/cpus.sh)" >/dev/null
"$work/consumer/cantilever"
echo "check_install: the installed package builds and runs an outside project"
