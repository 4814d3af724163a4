// The PETSc backends of SparseCholesky (internal: made through solver/linear_solver_factory.hpp):
// MUMPS's distributed Cholesky, and CG preconditioned by GAMG with the rigid-body near-null space.
#pragma once

#include <memory>

#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

bool petsc_built();
// Without PETSc: an object whose Factorize and Solve fail with check_backend_built's message.
std::unique_ptr<SparseCholesky> make_petsc_solver(const SparseCholeskyOptions& options);

}  // namespace kinestat::solver
