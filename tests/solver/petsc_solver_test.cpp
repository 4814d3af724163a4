// The PETSc backends in one process (one MPI rank; tests/mpi/ runs them on two): the same solutions
// as a dense LDL^T, the CG tolerance met by the true residual, free motions refused.
#include <gtest/gtest.h>

#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::solver {
namespace {

// n + 1 nodes in a row, 3 dofs each (x, y, z), each direction a chain of springs k (y and z 10 and
// 100 times stiffer, so the three decouple but differ), node 0 grounded by kg in every direction.
SparseMatrix spring_chain_3d(int n, double k, double kg) {
  std::vector<Eigen::Triplet<double>> t;
  for (int d = 0; d < 3; ++d) {
    const double kd = k * std::pow(10.0, d);
    for (int e = 0; e < n; ++e) {
      const int a = 3 * e + d, b = 3 * (e + 1) + d;
      t.emplace_back(a, a, kd);
      t.emplace_back(b, b, kd);
      t.emplace_back(b, a, -kd);
      t.emplace_back(a, b, -kd);
    }
    t.emplace_back(d, d, kg);
  }
  SparseMatrix A(3 * (n + 1), 3 * (n + 1));
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// The three translations of the chain (its null space without the ground spring).
MatX translations(int n) {
  MatX T = MatX::Zero(3 * (n + 1), 3);
  for (int i = 0; i <= n; ++i) T.block<3, 3>(3 * i, 0).setIdentity();
  return T;
}

TEST(PetscSolver, NotBuiltInSaysSo) {
  if (backend_built(Backend::kPetscCg)) GTEST_SKIP() << "PETSc is built in";
  auto solver = make_linear_solver({.backend = Backend::kPetscCg});
  FactorizationReport rep;
  const Status s = solver->Factorize(spring_chain_3d(5, 1.0, 1.0), &rep);
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find("libpetsc-real-dev"), std::string::npos);
}

TEST(PetscSolver, BothModesMatchADenseSolve) {
  if (!backend_built(Backend::kPetscCg)) GTEST_SKIP() << "PETSc not built in";
  const int n = 40;
  const SparseMatrix A = spring_chain_3d(n, 1e3, 1e3);
  const SparseMatrix lower = A.triangularView<Eigen::Lower>();  // the backends read the lower triangle
  const MatX B = MatX::Random(A.rows(), 6);
  const MatX Xd = MatX(A).ldlt().solve(B);
  for (Backend b : {Backend::kPetscMumps, Backend::kPetscCg}) {
    SCOPED_TRACE(backend_name(b));
    auto solver = make_linear_solver(
        {.backend = b, .relative_tolerance = 1e-12, .near_null_space = [&] { return translations(n); }});
    FactorizationReport rep;
    ASSERT_TRUE(solver->Factorize(lower, &rep).ok());
    EXPECT_EQ(rep.n, A.rows());
    MatX X;
    SolveReport solve;
    ASSERT_TRUE(solver->Solve(B, &X, &solve).ok());
    // cond(A) ~ 1e6 here, so 1e-12 residuals give ~1e-6 relative error at worst; we see far less.
    EXPECT_LT((X - Xd).norm(), 1e-7 * Xd.norm());
    ASSERT_EQ(solve.relative_residual.size(), 6u);
    for (int k = 0; k < 6; ++k) {
      // The true residual, recomputed here from the solution.
      const double residual = (B.col(k) - A * X.col(k)).norm() / B.col(k).norm();
      EXPECT_NEAR(solve.relative_residual[k], residual, 1e-3 * residual + 1e-15);
      if (b == Backend::kPetscCg) {
        EXPECT_GT(solve.iterations[k], 0);
        EXPECT_LT(residual, 10 * 1e-12);  // CG stops on its recursive residual; the true one is close
      } else {
        EXPECT_EQ(solve.iterations[k], 0);
        EXPECT_LT(residual, 1e-11);  // backward stable: ~cond(A) eps at worst, 1e-10 here
      }
    }
  }
}

TEST(PetscSolver, MumpsRefusesAFreeMotion) {
  if (!backend_built(Backend::kPetscMumps)) GTEST_SKIP() << "PETSc not built in";
  auto solver = make_sparse_cholesky({.backend = Backend::kPetscMumps});
  FactorizationReport rep;
  const Status s = solver->Factorize(spring_chain_3d(10, 1e3, 0.0), &rep);  // ungrounded: 3 translations
  EXPECT_EQ(s.code(), StatusCode::kSingular) << s.message();
  MatX X;
  EXPECT_FALSE(solver->Solve(MatX::Ones(33, 1), &X).ok());  // no numbers from a singular matrix
}

}  // namespace
}  // namespace kinestat::solver
