// kinestat.solver: the options and the report of the linear solvers (solver/linear_solver.hpp). The
// solvers themselves are reached through msa.solve and fea.link_stiffness; SciPy sparse matrices are
// not a dependency, so LinearSolver, SparseCholesky and the null-space routines are not bound.
#include "kinestat/solver/linear_solver.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_solver(py::module_& m) {
  using solver::FactorizationReport;
  using solver::LinearSolverOptions;
  py::enum_<solver::Ordering>(m, "Ordering")
      .value("AUTO", solver::Ordering::kAuto)
      .value("AMD", solver::Ordering::kAmd)
      .value("METIS", solver::Ordering::kMetis)
      .value("NATURAL", solver::Ordering::kNatural);

  py::enum_<solver::Backend>(m, "Backend", "CHOLMOD, or PETSc over MPI (MUMPS, CG + GAMG) when built in")
      .value("CHOLMOD", solver::Backend::kCholmod)
      .value("PETSC_MUMPS", solver::Backend::kPetscMumps)
      .value("PETSC_CG", solver::Backend::kPetscCg);

  py::class_<LinearSolverOptions>(m, "LinearSolverOptions")
      .def(py::init<>())
      .def_readwrite("backend", &LinearSolverOptions::backend)
      .def_readwrite("relative_tolerance", &LinearSolverOptions::relative_tolerance,
                     "PETSC_CG: stop at ||b - Ax|| <= tol ||b|| per right-hand side (default 1e-10)")
      .def_readwrite("max_iterations", &LinearSolverOptions::max_iterations)
      .def_readwrite("ordering", &LinearSolverOptions::ordering)
      .def_readwrite("singular_pivot_ratio", &LinearSolverOptions::singular_pivot_ratio,
                     "a pivot below this fraction of its diagonal entry is a free motion (default 1e-12)");

  py::class_<FactorizationReport>(m, "FactorizationReport",
                                  "What a factorization did and found; columns in the caller's numbering.")
      .def_readonly("n", &FactorizationReport::n)
      .def_readonly("nnz_matrix", &FactorizationReport::nnz_matrix)
      .def_readonly("nnz_factor", &FactorizationReport::nnz_factor)
      .def_readonly("flops", &FactorizationReport::flops)
      .def_readonly("reused_symbolic", &FactorizationReport::reused_symbolic,
                    "the sparsity pattern matched the previous call (no new symbolic analysis)")
      .def_readonly("supernodal", &FactorizationReport::supernodal)
      .def_readonly("ordering", &FactorizationReport::ordering)
      .def_readonly("analyze_seconds", &FactorizationReport::analyze_seconds)
      .def_readonly("factor_seconds", &FactorizationReport::factor_seconds)
      .def_readonly("failed_column", &FactorizationReport::failed_column)
      .def_readonly("weak_columns", &FactorizationReport::weak_columns)
      .def_readonly("min_pivot_ratio", &FactorizationReport::min_pivot_ratio)
      .def_readonly("min_pivot_column", &FactorizationReport::min_pivot_column)
      .def_property_readonly("singular", &FactorizationReport::singular);
}

}  // namespace kinestat::python
