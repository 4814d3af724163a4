// The largest eigenvalues of a symmetric pencil A q = mu K q with K the (positive definite) reduced
// stiffness: buckling (A = -K_G, mu = 1/lambda) and vibration of frames (msa) and of FEA links (fea)
// (A = M, mu = 1/omega^2). On one process's factor (cholmod): Spectra's Lanczos solver in
// regular-inverse mode (SymGEigsSolver<..., GEigsMode::RegularInverse>) on kinestat's sparse
// Cholesky of K; below 24 unknowns, Eigen's dense generalized solver. On petsc-mumps (any number of
// MPI ranks): SLEPc's Krylov-Schur with a shift of 0 (the same operator K^-1 A) on the backend's
// distributed K, solving with its MUMPS factor (docs/fea.md, "Large meshes").
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
// as columns, K-orthonormal (q' K q = 1). `chol` was prepared with K (Factorize or FactorizeSum);
// the Krylov iterations assume its solves exact to round-off: a direct one
// (solves_generalized_eigenproblems). Only the lower triangles of A and Kr are read (full symmetric
// matrices and the FEA's lower-triangle storage both work). On petsc-mumps the call is collective,
// A is given as K was (after FactorizeSum on summing_ranks() > 1: this rank's summand of A), Kr is
// not read (the backend holds K), and every rank gets all the eigenpairs. kNotConverged when the
// iteration does not converge or fails on the pencil (Spectra's message: a degenerate pencil is the
// caller's input, never a bug), the factor's own status when a solve with it fails, kInternal when
// memory runs out.
StatusOr<std::pair<VecX, MatX>> largest_generalized_eigenpairs(const SparseMatrix& A, const SparseMatrix& Kr,
                                                               const LinearSolver& chol, int count);

}  // namespace kinestat::solver
