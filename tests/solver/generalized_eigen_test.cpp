// largest_generalized_eigenpairs (solver/generalized_eigen.hpp) on the Lanczos path against a closed
// form, at any scale of A, and its refusal of a zero A.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "kinestat/solver/generalized_eigen.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::solver {
namespace {

// n equal masses m on n equal springs k, fixed at one end, free at the other (lower triangles):
// omega_j^2 = (4 k / m) sin^2((2j - 1) pi / (2 (2n + 1))), j = 1..n.
void fixed_free_chain(int n, double k, double m, SparseMatrix* K, SparseMatrix* M) {
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int i = 0; i < n; ++i) {
    kt.emplace_back(i, i, i + 1 < n ? 2 * k : k);
    if (i + 1 < n) kt.emplace_back(i + 1, i, -k);
    mt.emplace_back(i, i, m);
  }
  *K = SparseMatrix(n, n);
  *M = SparseMatrix(n, n);
  K->setFromTriplets(kt.begin(), kt.end());
  M->setFromTriplets(mt.begin(), mt.end());
}

// mu = 1/omega^2 of the chain scales as m: from m = 1 kg (mu_1 = 1.5 s^2) to 1e-20 and 1e-200 kg.
// Spectra's tests are absolute (a vector below 2.2e-16 is 0, Ritz values below 3.7e-11 converge to an
// absolute tolerance); the pencil is solved equilibrated, so every scale converges alike. Before, the
// 1e-20 chain's mu were up to 89 % wrong and the 1e-200 one failed in Spectra ("TridiagEigen").
// Measured: the largest relative error 4e-14 at every scale; asserted 1e-10, the eigensolver's
// tolerance.
TEST(GeneralizedEigen, LanczosGivesTheClosedFormAtAnyScaleOfA) {
  const int n = 60, count = 5;  // above the dense path's 24 unknowns
  const double k = 1e3;
  for (double m : {1.0, 1e-20, 1e-200}) {
    SparseMatrix K, M;
    fixed_free_chain(n, k, m, &K, &M);
    auto chol = make_sparse_cholesky();
    ASSERT_TRUE(chol->Factorize(SparseMatrix(K.selfadjointView<Eigen::Lower>()), nullptr).ok());
    auto eig = largest_generalized_eigenpairs(M, K, *chol, count);
    ASSERT_TRUE(eig.ok()) << "m = " << m << ": " << eig.status().message();
    const auto& [mu, Q] = *eig;
    ASSERT_EQ(mu.size(), count);
    double worst = 0.0;
    for (int j = 0; j < count; ++j) {
      const double s = std::sin((2 * j + 1) * std::numbers::pi / (2.0 * (2 * n + 1)));
      const double exact = m / (4 * k * s * s);
      worst = std::max(worst, std::abs(mu(j) / exact - 1.0));
      EXPECT_NEAR(mu(j), exact, 1e-10 * exact) << "m = " << m << ", mode " << j + 1;
      // K-normalized vectors: q' K q = 1.
      const SparseMatrix Kfull = K.selfadjointView<Eigen::Lower>();
      EXPECT_NEAR(Q.col(j).dot(Kfull * Q.col(j)), 1.0, 1e-10) << "m = " << m;
    }
    std::printf("m = %g kg: largest relative error of mu %.1e\n", m, worst);
  }
}

// A zero A has no eigenvalue to compute: kInvalidInput, not Spectra's failure on NaNs.
TEST(GeneralizedEigen, AZeroAIsRefused) {
  SparseMatrix K, M;
  fixed_free_chain(40, 1e3, 1.0, &K, &M);
  auto chol = make_sparse_cholesky();
  ASSERT_TRUE(chol->Factorize(SparseMatrix(K.selfadjointView<Eigen::Lower>()), nullptr).ok());
  const SparseMatrix zero(40, 40);
  auto eig = largest_generalized_eigenpairs(zero, K, *chol, 3);
  ASSERT_FALSE(eig.ok());
  EXPECT_EQ(eig.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(eig.status().message().find("the matrix A is zero"), std::string::npos) << eig.status().message();
}

}  // namespace
}  // namespace kinestat::solver
