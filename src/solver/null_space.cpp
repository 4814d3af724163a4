#include "kinestat/solver/null_space.hpp"

#include <algorithm>
#include <random>

#include <Eigen/Eigenvalues>

#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::solver {

VecX stiffness_scaling(const SparseMatrix& A) {
  VecX D = A.diagonal().cwiseAbs();
  const double dmax = D.size() ? D.maxCoeff() : 1.0;
  return D.cwiseMax(1e-12 * (dmax > 0 ? dmax : 1.0));
}

StatusOr<NullSpace> lowest_modes(const SparseMatrix& A, const SparseCholesky& factor, int block, int iterations) {
  const int n = static_cast<int>(A.rows());
  block = std::clamp(block, 1, n);
  const VecX D = stiffness_scaling(A);
  std::mt19937 rng(12345);  // fixed seed: diagnoses are reproducible
  std::normal_distribution<double> normal;
  MatX X(n, block);
  for (int j = 0; j < block; ++j)
    for (int i = 0; i < n; ++i) X(i, j) = normal(rng);
  const VecX Dsqrt = D.cwiseSqrt();
  for (int it = 0; it < iterations; ++it) {
    MatX Y;
    if (Status s = factor.Solve(D.asDiagonal() * X, &Y); !s.ok()) return s;
    Eigen::HouseholderQR<MatX> qr(Dsqrt.asDiagonal() * Y);  // D-orthonormalize
    X = Dsqrt.cwiseInverse().asDiagonal() * (qr.householderQ() * MatX::Identity(n, block));
  }
  // Rayleigh-Ritz on (A, D) in span(X).
  const MatX H = X.transpose() * (A * X);
  const MatX M = X.transpose() * D.asDiagonal() * X;
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ges(0.5 * (H + H.transpose()), 0.5 * (M + M.transpose()));
  return NullSpace{X * ges.eigenvectors(), ges.eigenvalues().cwiseMax(0.0)};
}

StatusOr<NullSpace> near_null_space(const SparseMatrix& A, int block, double threshold,
                                    const LinearSolverOptions& options) {
  const VecX D = stiffness_scaling(A);
  // The shift sits between round-off (~1e-16 relative) and real soft modes (>~1e-12), so
  // mechanisms converge much faster than real soft modes. If round-off still makes A + sigma D
  // indefinite, grow the shift.
  LinearSolverOptions shifted = options;
  shifted.singular_pivot_ratio = 0.0;
  auto chol = make_sparse_cholesky(shifted);
  Status st = Status::Internal("unreachable");
  for (double sigma : {1e-14, 1e-12, 1e-10}) {
    SparseMatrix S = A;
    for (int i = 0; i < S.rows(); ++i) S.coeffRef(i, i) += sigma * D(i);
    st = chol->Factorize(S, nullptr);
    if (st.ok()) break;
  }
  if (!st.ok()) return Status::Internal("could not factorize the shifted stiffness matrix: " + st.message());
  auto all = lowest_modes(A, *chol, block, 40);
  if (!all.ok()) return all.status();
  int k = 1;
  while (k < all->ratios.size() && all->ratios(k) < threshold) ++k;
  return NullSpace{all->modes.leftCols(k), all->ratios.head(k)};
}

}  // namespace kinestat::solver
