#include "solver/null_space.hpp"

#include <algorithm>
#include <random>

#include <Eigen/Eigenvalues>

namespace kinestat::solver {

StatusOr<NullSpace> near_null_space(const SparseMatrix& A, int block, double threshold) {
  const int n = static_cast<int>(A.rows());
  block = std::clamp(block, 1, n);
  // D = diag(A), floored so that dofs with no stiffness at all still get a (tiny) positive shift.
  VecX D = A.diagonal().cwiseAbs();
  const double dmax = D.size() ? D.maxCoeff() : 1.0;
  for (int i = 0; i < n; ++i) D(i) = std::max(D(i), 1e-12 * (dmax > 0 ? dmax : 1.0));

  // The shift sits between round-off (~1e-16 relative) and the weakest real stiffness we still
  // accept (the 1e-12 pivot tolerance), so mechanisms converge ~10x per iteration faster than
  // real soft modes. If round-off still makes A + sigma D indefinite, grow the shift.
  auto chol = SparseCholesky::Create({.singular_pivot_ratio = 0.0});
  Status st = Status::Internal("unreachable");
  for (double sigma : {1e-13, 1e-11, 1e-9}) {
    SparseMatrix S = A;
    for (int i = 0; i < n; ++i) S.coeffRef(i, i) += sigma * D(i);
    st = chol->Factorize(S, nullptr);
    if (st.ok()) break;
  }
  if (!st.ok()) return Status::Internal("could not factorize the shifted stiffness matrix: " + st.message());

  std::mt19937 rng(12345);  // fixed seed: diagnoses are reproducible
  std::normal_distribution<double> normal;
  MatX X(n, block);
  for (int j = 0; j < block; ++j)
    for (int i = 0; i < n; ++i) X(i, j) = normal(rng);
  const auto Dsqrt = D.cwiseSqrt();
  for (int it = 0; it < 40; ++it) {
    MatX Y;
    if (Status s = chol->Solve(D.asDiagonal() * X, &Y); !s.ok()) return s;
    // D-orthonormalize: QR of D^(1/2) Y.
    Eigen::HouseholderQR<MatX> qr(Dsqrt.asDiagonal() * Y);
    X = Dsqrt.cwiseInverse().asDiagonal() * (qr.householderQ() * MatX::Identity(n, block));
  }
  // Rayleigh-Ritz on (A, D) in span(X).
  const MatX H = X.transpose() * (A * X);
  const MatX M = X.transpose() * D.asDiagonal() * X;
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ges(0.5 * (H + H.transpose()), 0.5 * (M + M.transpose()));
  const VecX lambda = ges.eigenvalues();
  const MatX V = X * ges.eigenvectors();
  int k = 1;
  while (k < block && lambda(k) < threshold) ++k;
  NullSpace ns;
  ns.modes = V.leftCols(k);
  ns.ratios = lambda.head(k).cwiseMax(0.0);
  return ns;
}

}  // namespace kinestat::solver
