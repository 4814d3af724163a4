// The numerical libraries the solver runs on, as loaded into this process: for `kinestat --version`
// and the solver reports (a factorization's speed depends on the BLAS behind CHOLMOD).
#pragma once

#include <string>

namespace kinestat::solver {

struct LibraryVersions {
  std::string cholmod;  // "CHOLMOD 3.0.14 (SuiteSparse)": the library's own version (run time)
  std::string blas;     // "OpenBLAS 0.3.21 ... (/usr/lib/.../libopenblasp-r0.3.21.so)", or the BLAS files mapped
};

LibraryVersions library_versions();

// "PETSc 3.18.4, SLEPc 3.18.2 (module PATH)", "not built in", or why their module does not load. It
// loads that module (src/solver/petsc_module.hpp); library_versions() never does.
std::string petsc_versions();

}  // namespace kinestat::solver
