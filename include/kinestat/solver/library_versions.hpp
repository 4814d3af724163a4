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

}  // namespace kinestat::solver
