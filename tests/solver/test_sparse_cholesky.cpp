#include <gtest/gtest.h>

#include "kinestat/solver/null_space.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {
namespace {

// 1D chain of n springs k between n+1 nodes; node 0 grounded by a spring kg (kg = 0: free).
SparseMatrix spring_chain(int n, double k, double kg) {
  std::vector<Eigen::Triplet<double>> t;
  for (int e = 0; e < n; ++e) {
    t.emplace_back(e, e, k);
    t.emplace_back(e + 1, e + 1, k);
    t.emplace_back(e, e + 1, -k);
    t.emplace_back(e + 1, e, -k);
  }
  t.emplace_back(0, 0, kg);
  SparseMatrix A(n + 1, n + 1);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(SparseCholesky, SolvesAgainstDenseAndReusesSymbolicAnalysis) {
  auto chol = SparseCholesky::Create();
  const SparseMatrix A = spring_chain(50, 1e3, 1e3);
  FactorizationReport rep;
  ASSERT_TRUE(chol->Factorize(A, &rep).ok());
  EXPECT_FALSE(rep.reused_symbolic);
  MatX B = MatX::Random(51, 3), X;
  ASSERT_TRUE(chol->Solve(B, &X).ok());
  const MatX Xd = MatX(A).ldlt().solve(B);
  EXPECT_LT((X - Xd).norm(), 1e-10 * Xd.norm());
  // Same pattern, new values: no new analysis.
  ASSERT_TRUE(chol->Factorize(2.0 * A, &rep).ok());
  EXPECT_TRUE(rep.reused_symbolic);
  EXPECT_EQ(chol->num_symbolic_analyses(), 1);
  ASSERT_TRUE(chol->Solve(B, &X).ok());
  EXPECT_LT((2.0 * X - Xd).norm(), 1e-10 * Xd.norm());
  // A different pattern: analysed again.
  ASSERT_TRUE(chol->Factorize(spring_chain(60, 1e3, 1e3), &rep).ok());
  EXPECT_EQ(chol->num_symbolic_analyses(), 2);
}

TEST(SparseCholesky, UngroundedChainIsSingularAndSaysWhere) {
  // Without the ground spring the chain can translate freely: exactly one zero pivot.
  auto chol = SparseCholesky::Create({.ordering = Ordering::kNatural});
  FactorizationReport rep;
  const Status st = chol->Factorize(spring_chain(10, 1e3, 0.0), &rep);
  EXPECT_EQ(st.code(), StatusCode::kSingular);
  EXPECT_TRUE(rep.singular());
  // Natural order: the last column is the dependent one (sum of rows is zero).
  const int where = rep.failed_column >= 0 ? rep.failed_column : rep.weak_columns.front();
  EXPECT_EQ(where, 10);
  MatX X;
  EXPECT_FALSE(chol->Solve(MatX::Ones(11, 1), &X).ok());  // no garbage from a singular factor
}

TEST(SparseCholesky, StiffSpringsAreNotMistakenForMechanisms) {
  // Springs 1e9 times stiffer than their neighbours (as joint springs next to slender beams).
  std::vector<Eigen::Triplet<double>> t;
  const double k[3] = {2e11, 200.0, 2e11};
  for (int e = 0; e < 3; ++e) {
    t.emplace_back(e, e, k[e]);
    t.emplace_back(e + 1, e + 1, k[e]);
    t.emplace_back(e, e + 1, -k[e]);
    t.emplace_back(e + 1, e, -k[e]);
  }
  t.emplace_back(0, 0, 2e11);
  SparseMatrix A(4, 4);
  A.setFromTriplets(t.begin(), t.end());
  for (Ordering o : {Ordering::kNatural, Ordering::kAmd}) {
    auto chol = SparseCholesky::Create({.ordering = o});
    FactorizationReport rep;
    EXPECT_TRUE(chol->Factorize(A, &rep).ok());
    EXPECT_GT(rep.min_pivot_ratio, 1e-11);
  }
}

TEST(NullSpace, FindsTheRigidTranslationOfAFreeChain) {
  auto ns = near_null_space(spring_chain(20, 1e3, 0.0), 3, 1e-13);
  ASSERT_TRUE(ns.ok());
  ASSERT_EQ(ns->modes.cols(), 1);
  EXPECT_LT(ns->ratios(0), 1e-12);
  const VecX m = ns->modes.col(0) / ns->modes(0, 0);
  EXPECT_LT((m - VecX::Ones(21)).norm(), 1e-8);  // all nodes translate together
}

}  // namespace
}  // namespace kinestat::solver
