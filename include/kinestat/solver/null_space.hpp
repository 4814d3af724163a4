// Free motions of a singular (positive semi-definite) stiffness matrix: its near-null space.
// Used to explain a singular model in words instead of refusing it, and to catch mechanisms whose
// null pivot, spoiled by round-off, passed the pivot check.
#pragma once

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

struct NullSpace {
  MatX modes;   // n x k, columns D-normalized (D = diag A), ascending ratio
  VecX ratios;  // Rayleigh ratios x'Ax / x'Dx: ~1e-16 for an exact mechanism, ~1 for a stiff mode
};

// The `block` lowest generalized eigenpairs A x = lambda D x, by subspace iteration with a
// factorization of A (or of a slightly shifted A) and a Rayleigh-Ritz step. All are returned.
StatusOr<NullSpace> lowest_modes(const SparseMatrix& A, const SparseCholesky& factor, int block, int iterations);

// The modes with lambda below `threshold` (at least the lowest one), from the shifted, positive
// definite A + sigma D, which exists also when A is singular. `block` >= expected nullity + 2.
// The shifted matrix is factorized with the caller's `options` (backend, ordering); its pivot
// check is off (the shift, not the check, makes the matrix regular).
StatusOr<NullSpace> near_null_space(const SparseMatrix& A, int block, double threshold,
                                    const LinearSolverOptions& options);

// D = diag(A), floored at 1e-12 max|diag| so that dofs with no stiffness at all still count.
VecX stiffness_scaling(const SparseMatrix& A);

}  // namespace kinestat::solver
