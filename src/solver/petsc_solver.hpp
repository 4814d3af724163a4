// The PETSc backends (internal: made through solver/linear_solver_factory.hpp; in the module of
// solver/petsc_module.hpp, src/solver/petsc/petsc_solver.cpp): MUMPS's distributed
// Cholesky (a SparseCholesky), and CG preconditioned by GAMG with the rigid-body near-null space (a
// LinearSolver of the iterative kind). Both assemble and solve through one PETSc KSP; SLEPc solves
// the generalized eigenproblem on the MUMPS one.
#pragma once

#include <memory>
#include <optional>
#include <utility>

#include "kinestat/solver/linear_solver.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

// Ok when the PETSc backends can be used (built in, and their module loads: it is loaded here), else
// why not: kInvalidInput when PETSc was not built in, kInternal when the module does not load.
Status petsc_available();
// Only after petsc_available() is Ok (the factory checks it; else they return nullptr).
std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions& options);

// When a Krylov eigensolver stops: each eigenpair's relative residual, and the restarts it may take.
struct EigenConvergence {
  double tolerance = 0.0;
  int max_restarts = 0;
};

// solver/generalized_eigen.hpp's eigenpairs when `solver` is the petsc-mumps backend (made by
// make_petsc_mumps, factorized with K): SLEPc on its distributed K and MUMPS factor, `A` assembled
// as K was (FactorizeSum: this rank's summand; Factorize: the whole A). Collective. nullopt for
// any other solver (and before the module is loaded, or without PETSc), which the caller solves itself.
std::optional<StatusOr<std::pair<VecX, MatX>>> petsc_generalized_eigenpairs(const SparseMatrix& A,
                                                                            const LinearSolver& solver, int count,
                                                                            const EigenConvergence& convergence);

}  // namespace kinestat::solver
