// The one place that turns a backend choice into a solver object (as Ceres' LinearSolver::Create).
// Every solver object in kinestat is made here, from the caller's LinearSolverOptions. A new backend
// is one implementation file pair in src/solver/ (a SparseCholesky, or a LinearSolver of another
// kind), one enumerator of solver::Backend and its entries in this factory; the methods (MSA, FEA)
// do not change. The PETSc backends (src/solver/petsc/petsc_solver.cpp) are built when PETSc is found,
// into a module that the first request for one of them loads (src/solver/petsc_module.hpp).
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/solver/linear_solver.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

// A solver of any kind for options.backend, configured by `options`. A backend that is not built in
// gives an object whose Factorize fails with kInvalidInput saying so (check_backend_built's message).
std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options = {});

// A direct factorization for options.backend (cholmod, petsc-mumps): for callers that solve with
// one factor exactly and repeatedly. An iterative backend gives an object whose Factorize fails with
// kInvalidInput saying it is not a factorization; one not built in, with check_backend_built's.
std::unique_ptr<SparseCholesky> make_sparse_cholesky(const LinearSolverOptions& options = {});

// The backends built into this library, and their names for options and reports ("cholmod",
// "petsc-mumps", "petsc-cg"). backend_from_name knows every backend, built or not.
std::vector<Backend> available_backends();
bool backend_built(Backend backend);
const char* backend_name(Backend backend);
std::optional<Backend> backend_from_name(std::string_view name);
// Ok, or kInvalidInput naming the backend and why it is not built in (how to get it), or kInternal
// when it is built in but its module does not load (where it was looked for). For a PETSc backend
// it loads that module; so do backend_built and available_backends.
Status check_backend_built(Backend backend);

// Whether solver/generalized_eigen.hpp works on `backend`'s solver: a direct one, whose solves are
// exact to round-off as the Krylov eigensolvers assume (cholmod: Spectra; petsc-mumps: SLEPc, on any
// number of MPI ranks). Not an iterative one (petsc-cg): its solves carry CG's tolerance.
bool solves_generalized_eigenproblems(Backend backend);
// The relative residual the solutions of `options` are accurate to: 0 for a direct backend, the
// stopping tolerance for an iterative one (results of different tolerances are not interchangeable).
double solution_tolerance(const LinearSolverOptions& options);

}  // namespace kinestat::solver
