#include "kinestat/solver/generalized_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <stdexcept>
#include <utility>

#include <Spectra/SymGEigsSolver.h>
#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "solver/petsc_solver.hpp"

namespace kinestat::solver {
namespace {

// The pencil is solved equilibrated: K' = D K D (unit diagonal) and A' = s D A D, with
// D = diag(K)^(-1/2) and s = 1 / max |A_ii| / K_ii, so that the largest |mu'| = |mu| s is at least 1
// (the Rayleigh quotient of a unit vector) and the vectors Spectra normalizes have entries of order 1.
// Spectra's tests are absolute: a residual vector with entries below 2.2e-16 is taken for 0 and the
// Krylov space restarted, a Ritz value below 3.7e-11 converges to an absolute tolerance; on the raw
// pencil a 20 um column (mu ~ 1e-14 s^2) or a density of 1e-6 kg/m^3 stopped on those at residuals of
// 0.3 to 0.9 (frequencies percents off), and a zero A made its tridiagonal solver fail on NaNs.
// q = D q' and mu = mu' / s; q' K' q' = q' K q, so the vectors stay K-orthonormal.
struct Scaling {
  VecX d;          // D's diagonal
  double s = 1.0;  // A's factor
};

// y = A' x = s D A D x (A symmetric, its lower triangle read).
struct Product {
  using Scalar = double;
  const SparseMatrix& A;
  const Scaling& scaling;
  Eigen::Index rows() const { return A.rows(); }
  Eigen::Index cols() const { return A.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    const VecX dx = scaling.d.cwiseProduct(Eigen::Map<const VecX>(x_in, A.cols()));
    Eigen::Map<VecX>(y_out, A.rows()).noalias() =
        scaling.s * scaling.d.cwiseProduct(A.selfadjointView<Eigen::Lower>() * dx);
  }
};

// B = K' = D K D (K reduced, positive definite; its lower triangle read): y = B x, and
// y = B^-1 x = D^-1 K^-1 D^-1 x through kinestat's sparse Cholesky of K (CHOLMOD, or the caller's
// backend), factorized once.
struct StiffnessInverse {
  using Scalar = double;
  const SparseMatrix& K;
  const LinearSolver& chol;
  const Scaling& scaling;
  Status* failure;  // where a failed solve's status is kept (Spectra sees an exception)
  Eigen::Index rows() const { return K.rows(); }
  Eigen::Index cols() const { return K.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    const VecX dx = scaling.d.cwiseProduct(Eigen::Map<const VecX>(x_in, K.cols()));
    Eigen::Map<VecX>(y_out, K.rows()).noalias() = scaling.d.cwiseProduct(K.selfadjointView<Eigen::Lower>() * dx);
  }
  void solve(const double* x_in, double* y_out) const {
    MatX X;
    if (Status st = chol.Solve(Eigen::Map<const VecX>(x_in, K.rows()).cwiseQuotient(scaling.d), &X); !st.ok()) {
      *failure = st;
      throw std::runtime_error(st.message());  // caught around compute() below
    }
    Eigen::Map<VecX>(y_out, K.rows()) = X.col(0).cwiseQuotient(scaling.d);
  }
};

// Below this many free dofs the pencil is solved densely (Eigen): Lanczos needs nev < ncv <= n and
// would build the full basis anyway.
constexpr int kDenseBelow = 24;

// Both Krylov routes (Spectra here, SLEPc on petsc-mumps) stop at this relative residual of each
// eigenpair, and give up after this many restarts.
constexpr EigenConvergence kConvergence{.tolerance = 1e-10, .max_restarts = 1000};

}  // namespace

StatusOr<std::pair<VecX, MatX>> largest_generalized_eigenpairs(const SparseMatrix& A, const SparseMatrix& Kr,
                                                               const LinearSolver& chol, int count) {
  // The one dispatch point: petsc-mumps solves on its own distributed K and factor (SLEPc).
  if (auto distributed = petsc_generalized_eigenpairs(A, chol, count, kConvergence)) return std::move(*distributed);
  if (chol.summing_ranks() > 1)  // A and Kr may be summands here; only petsc-mumps adds them up
    return Status::Invalid(
        fmt::format("generalized eigenpairs on {} MPI ranks need the petsc-mumps solver (SLEPc on its factor); "
                    "{} was given",
                    chol.summing_ranks(), chol.backend_description()));
  const int n = static_cast<int>(Kr.rows());
  if (n < kDenseBelow) {
    const MatX Ad = MatX(SparseMatrix(A.selfadjointView<Eigen::Lower>()));
    const MatX Kd = MatX(SparseMatrix(Kr.selfadjointView<Eigen::Lower>()));
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ges(Ad, Kd);
    if (ges.info() != Eigen::Success) return Status::Internal("the dense generalized eigensolver failed");
    const int m = std::min(count, n);
    return std::pair<VecX, MatX>{ges.eigenvalues().tail(m).reverse(),
                                 ges.eigenvectors().rightCols(m).rowwise().reverse()};
  }
  Scaling scaling;
  scaling.d = VecX(n);
  double largest_ratio = 0.0;  // max |A_ii| / K_ii: |mu| reaches it (the Rayleigh quotient of e_i)
  for (int i = 0; i < n; ++i) {
    const double kii = Kr.coeff(i, i);
    if (!(kii > 0.0) || !std::isfinite(kii))  // K is positive definite: a factorized K cannot have this
      return Status::Internal(fmt::format("generalized eigenpairs: K's diagonal entry {} is {:g}", i, kii));
    scaling.d(i) = 1.0 / std::sqrt(kii);
    largest_ratio = std::max(largest_ratio, std::abs(A.coeff(i, i)) / kii);
  }
  if (largest_ratio == 0.0) {
    // A semidefinite A (a mass) with a zero diagonal is zero; an indefinite one (-K_G) is scaled by
    // its largest entry against K's.
    double a = 0.0;
    for (int k = 0; k < A.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(A, k); it; ++it)
        a = std::max(a, std::abs(it.value()) * scaling.d(it.row()) * scaling.d(it.col()));
    largest_ratio = a;
  }
  // Below this the pencil's eigenvalues are lost to underflow in D A D (round-off far below any
  // model's: the callers refuse negligible masses and axial forces with their own messages first).
  constexpr double kNegligible = 1e-250;
  if (!(largest_ratio >= kNegligible) || !std::isfinite(largest_ratio))
    return Status::Invalid(
        fmt::format("generalized eigenpairs: the matrix A is {} against K (largest |A_ij| / sqrt(K_ii K_jj) = {:g}): "
                    "the pencil has no eigenvalue that can be computed",
                    largest_ratio == 0.0 ? "zero" : "negligible", largest_ratio));
  scaling.s = 1.0 / largest_ratio;
  Status solve_failure;
  Product op{A, scaling};
  StiffnessInverse bop{Kr, chol, scaling, &solve_failure};
  const int nev = std::min(count, n - 1);
  const int ncv = std::min(n, std::max(2 * nev + 1, 20));
  try {
    Spectra::SymGEigsSolver<Product, StiffnessInverse, Spectra::GEigsMode::RegularInverse> eig(op, bop, nev, ncv);
    eig.init();
    eig.compute(Spectra::SortRule::LargestAlge, kConvergence.max_restarts, kConvergence.tolerance);
    if (eig.info() != Spectra::CompInfo::Successful)
      return Status::NotConverged(
          fmt::format("the Lanczos eigensolver (Spectra) did not converge to {} eigenvalues in "
                      "{} restarts; ask for fewer modes",
                      nev, kConvergence.max_restarts));
    MatX Q = scaling.d.asDiagonal() * eig.eigenvectors();
    return std::pair<VecX, MatX>{eig.eigenvalues() / scaling.s, std::move(Q)};
  } catch (const std::bad_alloc&) {
    return Status::Internal("the Lanczos eigensolver (Spectra): out of memory");
  } catch (const std::exception& e) {
    if (!solve_failure.ok()) return solve_failure;  // the factor's own status (its code and message)
    // Spectra's own failures (a breakdown of its tridiagonal eigensolver on a degenerate pencil) are
    // the pencil's, not a bug: the caller adds what to check in its model.
    return Status::NotConverged(fmt::format(
        "the Lanczos eigensolver (Spectra) failed on this pencil ({}); no eigenvalue was computed", e.what()));
  }
}

}  // namespace kinestat::solver
