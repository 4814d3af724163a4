// The largest eigenvalues of a symmetric pencil A q = mu K q with K the (positive definite) reduced
// stiffness: buckling (A = -K_G, mu = 1/lambda) and vibration of frames (msa) and of FEA links (fea)
// (A = M, mu = 1/omega^2). Spectra's
// Lanczos solver in regular-inverse mode (SymGEigsSolver<..., GEigsMode::RegularInverse>) on
// kinestat's sparse Cholesky of K; below 24 unknowns, Eigen's dense generalized solver.
//
// Why this form: the wanted eigenvalues (the smallest positive lambda, the lowest omega^2) are the
// largest mu, at the end of a spectrum that gathers at 0 (the stiff motions), where Lanczos converges
// fastest; K is already factorized by the static solve's checks, and no shift has to be guessed (a
// shift-invert on K - sigma K_G needs sigma below the unknown lambda_1 and an indefinite factor).
#pragma once

#include <utility>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::solver {

// The `count` largest mu (fewer when the system has fewer unknowns), descending, and their vectors
// as columns, K-orthonormal (q' K q = 1). `chol` was prepared with K (Factorize);
// Lanczos assumes its solves exact to round-off: a direct one (factors_on_one_process). Only the lower triangles of
// A and Kr are read (full symmetric matrices and the FEA's lower-triangle storage both work). kNotConverged when
// Lanczos does not converge, kInternal when it fails.
StatusOr<std::pair<VecX, MatX>> largest_generalized_eigenpairs(const SparseMatrix& A, const SparseMatrix& Kr,
                                                               const LinearSolver& chol, int count);

}  // namespace kinestat::solver
