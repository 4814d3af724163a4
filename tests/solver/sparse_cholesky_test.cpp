#include <gtest/gtest.h>

#include "kinestat/solver/linear_solver_factory.hpp"
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
  auto chol = make_sparse_cholesky();
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
  auto chol = make_sparse_cholesky({.ordering = Ordering::kNatural});
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
    auto chol = make_sparse_cholesky({.ordering = o});
    FactorizationReport rep;
    EXPECT_TRUE(chol->Factorize(A, &rep).ok());
    EXPECT_GT(rep.min_pivot_ratio, 1e-11);
  }
}

// The factory makes the backend the options name, configured by them, and knows its names.
// A lower-triangle-only matrix (what the assemblies store) is read in place, a full one through a
// copy of its lower half: the same solution, and the dense solver's.
TEST(SparseCholesky, LowerTriangleInPlaceAndFullMatrixGiveTheSameSolution) {
  const SparseMatrix full = spring_chain(40, 1e3, 1e3);
  const SparseMatrix lower = [&] {
    SparseMatrix l = full.triangularView<Eigen::Lower>();
    l.makeCompressed();
    return l;
  }();
  const MatX B = MatX::Random(full.rows(), 2);
  const MatX expected = MatX(full).llt().solve(B);
  for (const SparseMatrix* A : {&full, &lower}) {
    auto chol = make_sparse_cholesky();
    FactorizationReport r;
    ASSERT_TRUE(chol->Factorize(*A, &r).ok());
    EXPECT_EQ(r.nnz_matrix, lower.nonZeros());
    MatX X;
    ASSERT_TRUE(chol->Solve(B, &X).ok());
    EXPECT_LT((X - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(LinearSolverFactory, MakesTheNamedBackendWithTheCallersOptions) {
  for (Backend b : available_backends()) EXPECT_EQ(backend_from_name(backend_name(b)), b);
  EXPECT_EQ(backend_from_name("cholmod"), Backend::kCholmod);
  EXPECT_FALSE(backend_from_name("petsc-typo").has_value());
  auto chol = make_sparse_cholesky({.backend = Backend::kCholmod, .ordering = Ordering::kNatural});
  ASSERT_NE(chol, nullptr);
  EXPECT_NE(chol->backend_description().find("CHOLMOD"), std::string::npos);
  FactorizationReport rep;
  ASSERT_TRUE(chol->Factorize(spring_chain(30, 1e3, 1e3), &rep).ok());
  EXPECT_EQ(rep.ordering, "natural");  // the caller's ordering reached the backend
}

// CG + multigrid is a LinearSolver, not a Cholesky: make_sparse_cholesky refuses it at Factorize
// (after saying it is not built in, without PETSc); the direct solve reports no iterations; the
// factory's answers for the methods (no backend branch there) follow the kind.
TEST(LinearSolverFactory, TheIterativeBackendIsNoCholesky) {
  FactorizationReport rep;
  const Status s = make_sparse_cholesky({.backend = Backend::kPetscCg})->Factorize(spring_chain(5, 1.0, 1.0), &rep);
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find(backend_built(Backend::kPetscCg) ? "not a Cholesky" : "not built"), std::string::npos)
      << s.message();
  auto direct = make_linear_solver();
  ASSERT_TRUE(direct->Factorize(spring_chain(5, 1.0, 1.0), &rep).ok());
  MatX X;
  SolveReport solve;
  ASSERT_TRUE(direct->Solve(MatX::Ones(6, 2), &X, &solve).ok());
  EXPECT_EQ(solve.iterations, std::vector<int>({0, 0}));
  EXPECT_EQ(solve.relative_tolerance, 0.0);
  // The generalized eigensolver needs exact solves: both direct backends, not CG.
  EXPECT_TRUE(solves_generalized_eigenproblems(Backend::kCholmod));
  EXPECT_TRUE(solves_generalized_eigenproblems(Backend::kPetscMumps));
  EXPECT_FALSE(solves_generalized_eigenproblems(Backend::kPetscCg));
  EXPECT_EQ(solution_tolerance({.backend = Backend::kCholmod, .relative_tolerance = 1e-6}), 0.0);
  EXPECT_EQ(solution_tolerance({.backend = Backend::kPetscCg, .relative_tolerance = 1e-6}), 1e-6);
}

TEST(NullSpace, FindsTheRigidTranslationOfAFreeChain) {
  auto ns = near_null_space(spring_chain(20, 1e3, 0.0), 3, 1e-13, {.ordering = Ordering::kNatural});
  ASSERT_TRUE(ns.ok());
  ASSERT_EQ(ns->modes.cols(), 1);
  EXPECT_LT(ns->ratios(0), 1e-12);
  const VecX m = ns->modes.col(0) / ns->modes(0, 0);
  EXPECT_LT((m - VecX::Ones(21)).norm(), 1e-8);  // all nodes translate together
}

}  // namespace
}  // namespace kinestat::solver
