// The PETSc backends (internal: made through solver/linear_solver_factory.hpp): MUMPS's distributed
// Cholesky (a SparseCholesky), and CG preconditioned by GAMG with the rigid-body near-null space (a
// LinearSolver of the iterative kind). Both assemble and solve through one PETSc KSP.
#pragma once

#include <memory>

#include "kinestat/solver/linear_solver.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

bool petsc_built();
// Only with petsc_built() (the factory checks it; without PETSc they return nullptr).
std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions& options);

}  // namespace kinestat::solver
