// The one place that turns a backend choice into a solver object (as Ceres' LinearSolver::Create).
// Every factorization in kinestat is made here, from the caller's SparseCholeskyOptions.
// A new backend is one implementation file pair in src/solver/, one enumerator of solver::Backend
// and one entry in this factory; the methods (MSA, FEA) do not change. The PETSc backends
// (src/solver/petsc_solver.cpp) are the second implementation, built when PETSc is found.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

// A solver object for options.backend, configured by `options` (ordering, pivot tolerance). A backend
// that is not built in gives an object whose Factorize fails with kInvalidInput saying so.
std::unique_ptr<SparseCholesky> make_sparse_cholesky(const SparseCholeskyOptions& options = {});

// The backends built into this library, and their names for options and reports ("cholmod",
// "petsc-mumps", "petsc-cg"). backend_from_name knows every backend, built or not.
std::vector<Backend> available_backends();
bool backend_built(Backend backend);
const char* backend_name(Backend backend);
std::optional<Backend> backend_from_name(std::string_view name);
// Ok, or kInvalidInput naming the backend and why it is not built in (how to get it).
Status check_backend_built(Backend backend);

}  // namespace kinestat::solver
