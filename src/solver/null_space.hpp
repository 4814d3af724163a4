// Free motions of a singular (positive semi-definite) stiffness matrix: its near-null space.
// Used to explain a singular model in words instead of refusing it.
#pragma once

#include "core/status.hpp"
#include "core/types.hpp"
#include "solver/sparse_cholesky.hpp"

namespace kinestat::solver {

struct NullSpace {
  MatX modes;    // n x k, columns D-normalized (D = diag A), ascending ratio
  VecX ratios;   // Rayleigh ratios x'Ax / x'Dx: ~1e-16 for an exact mechanism, ~1 for a stiff mode
};

// The generalized eigenpairs A x = lambda D x with lambda below `threshold` (at least the lowest
// one is returned), found by subspace iteration with the shifted, positive definite A + sigma D and
// a Rayleigh-Ritz step. `block` is the number of vectors iterated (>= expected nullity + 2).
StatusOr<NullSpace> near_null_space(const SparseMatrix& A, int block, double threshold = 1e-10);

}  // namespace kinestat::solver
