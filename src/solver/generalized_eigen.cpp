#include "kinestat/solver/generalized_eigen.hpp"

#include <algorithm>
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

// Spectra's matrix operations (the interface of its SparseSymMatProd and SparseRegularInverse).
// y = A x (A symmetric, its lower triangle read).
struct Product {
  using Scalar = double;
  const SparseMatrix& A;
  Eigen::Index rows() const { return A.rows(); }
  Eigen::Index cols() const { return A.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<VecX>(y_out, A.rows()).noalias() =
        A.selfadjointView<Eigen::Lower>() * Eigen::Map<const VecX>(x_in, A.cols());
  }
};

// B = K (reduced, positive definite; its lower triangle read): y = B x, and y = B^-1 x through kinestat's sparse
// Cholesky (CHOLMOD, or the caller's backend), factorized once.
struct StiffnessInverse {
  using Scalar = double;
  const SparseMatrix& K;
  const LinearSolver& chol;
  Status* failure;  // where a failed solve's status is kept (Spectra sees an exception)
  Eigen::Index rows() const { return K.rows(); }
  Eigen::Index cols() const { return K.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<VecX>(y_out, K.rows()).noalias() =
        K.selfadjointView<Eigen::Lower>() * Eigen::Map<const VecX>(x_in, K.cols());
  }
  void solve(const double* x_in, double* y_out) const {
    MatX X;
    if (Status st = chol.Solve(Eigen::Map<const VecX>(x_in, K.rows()), &X); !st.ok()) {
      *failure = st;
      throw std::runtime_error(st.message());  // caught around compute() below
    }
    Eigen::Map<VecX>(y_out, K.rows()) = X.col(0);
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
  Status solve_failure;
  Product op{A};
  StiffnessInverse bop{Kr, chol, &solve_failure};
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
    return std::pair<VecX, MatX>{eig.eigenvalues(), eig.eigenvectors()};
  } catch (const std::bad_alloc&) {
    return Status::Internal("the Lanczos eigensolver (Spectra): out of memory");
  } catch (const std::exception& e) {
    if (!solve_failure.ok()) return solve_failure;  // the factor's own status (its code and message)
    // Spectra's own failures (a breakdown of its tridiagonal eigensolver on a degenerate pencil, a zero
    // A) are the pencil's, not a bug: the caller adds what to check in its model.
    return Status::NotConverged(fmt::format(
        "the Lanczos eigensolver (Spectra) failed on this pencil ({}); no eigenvalue was computed", e.what()));
  }
}

}  // namespace kinestat::solver
