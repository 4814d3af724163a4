// kinestat.solver.library_versions() and petsc_versions() (solver/library_versions.hpp): the numerical
// libraries this process runs on, for a report next to the results.
#include "kinestat/solver/library_versions.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_library_versions(py::module_& solver) {
  solver.def(
      "library_versions",
      [] {
        const solver::LibraryVersions v = solver::library_versions();
        py::dict d;
        d["cholmod"] = v.cholmod;
        d["blas"] = v.blas;
        return d;
      },
      "{'cholmod': ..., 'blas': ...}: CHOLMOD's and the BLAS's versions as loaded into this process");
  solver.def("petsc_versions", &solver::petsc_versions,
             "PETSc's and SLEPc's versions and the module they were loaded from ('not built in' without them); "
             "loads that module");
}

}  // namespace kinestat::python
