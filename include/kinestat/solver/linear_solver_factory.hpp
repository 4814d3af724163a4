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

// The MPI processes a distributed backend runs on (rank 0 of 1 without MPI).
struct ProcessGroup {
  int rank = 0;
  int size = 1;
};
// Starts PETSc (and MPI) once per process for the PETSc backends: call it first thing when the
// program may run under mpirun, so that every rank knows its rank before writing anything. The PETSc
// backends also start it themselves when needed. Ok without effect when PETSc is not built in.
StatusOr<ProcessGroup> start_parallel();
ProcessGroup process_group();  // {0, 1} until start_parallel
// Ends PETSc and MPI (no solver object may outlive it); also done at exit.
void finish_parallel();

// Sharing what rank 0 alone computed (e.g. the FEA mesh: rank 0 meshes, the others receive it).
// Collective: every rank of process_group() calls them, in the same order; without PETSc, before
// start_parallel or on one rank they do nothing. On return every rank holds rank 0's `values`
// (resized on the others).
Status broadcast_from_root(std::vector<double>& values);
Status broadcast_from_root(std::vector<int>& values);
// Every rank's outcome of a step that may fail on some ranks only (rank 0's meshing, a rank's own
// elements): returns to every rank the failure of the lowest failing rank (code and message), or Ok.
// Call it before the next collective step, so that a failure stops every rank instead of leaving the
// others waiting for the failed one. Returns `mine` without MPI.
Status agree_on_status(const Status& mine);

}  // namespace kinestat::solver
