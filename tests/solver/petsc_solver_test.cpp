// The PETSc backends in one process (one MPI rank; tests/mpi/ runs them on two): the same solutions
// as a dense LDL^T, the CG tolerance met by the true residual, free motions refused; SLEPc's
// generalized eigenpairs on petsc-mumps against Spectra's on CHOLMOD.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "kinestat/solver/generalized_eigen.hpp"
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

// A chain of n springs and n masses, clamped at one end (1D, one dof per mass): stiffnesses and
// masses vary along it, so its eigenvalues are simple (a Jacobi pencil) and its vectors unique up
// to sign. Lower triangles, as the FEA stores K and M.
std::pair<SparseMatrix, SparseMatrix> spring_mass_chain(int n) {
  std::vector<Eigen::Triplet<double>> k, m;
  for (int i = 0; i < n; ++i) {
    const double ki = 1e3 * (1.0 + 0.5 * std::sin(0.7 * i)), kj = 1e3 * (1.0 + 0.5 * std::sin(0.7 * (i + 1)));
    k.emplace_back(i, i, ki + (i + 1 < n ? kj : 0.0));  // spring i to the left, spring i + 1 to the right
    if (i + 1 < n) k.emplace_back(i + 1, i, -kj);
    m.emplace_back(i, i, 2.0 + std::cos(1.3 * i));
  }
  SparseMatrix K(n, n), M(n, n);
  K.setFromTriplets(k.begin(), k.end());
  M.setFromTriplets(m.begin(), m.end());
  return {K, M};
}

// SLEPc (petsc-mumps, dispatched by largest_generalized_eigenpairs) against Spectra (cholmod): the
// same eigenvalues to 1e-10 relative and the same K-normalized vectors up to sign, K given whole
// (Factorize) and as two summands (FactorizeSum; on one rank A is then this rank's whole summand).
TEST(PetscSolver, SlepcEigenpairsMatchSpectras) {
  if (!backend_built(Backend::kPetscMumps)) GTEST_SKIP() << "PETSc (and SLEPc) not built in";
  const int n = 60, count = 6;  // above generalized_eigen.cpp's dense threshold: Lanczos vs Krylov-Schur
  const auto [K, M] = spring_mass_chain(n);
  auto cholmod = make_sparse_cholesky({.backend = Backend::kCholmod});
  ASSERT_TRUE(cholmod->Factorize(K, nullptr).ok());
  auto spectra = largest_generalized_eigenpairs(M, K, *cholmod, count);
  ASSERT_TRUE(spectra.ok()) << spectra.status().message();
  const SparseMatrix Kfull = K.selfadjointView<Eigen::Lower>();
  const SparseMatrix half = K.triangularView<Eigen::Lower>() * 0.5;  // two equal summands
  for (bool summed : {false, true}) {
    SCOPED_TRACE(summed ? "FactorizeSum" : "Factorize");
    auto mumps = make_sparse_cholesky({.backend = Backend::kPetscMumps});
    const std::vector<SparseMatrix> halves = {half, half};
    ASSERT_TRUE((summed ? mumps->FactorizeSum(halves, nullptr) : mumps->Factorize(K, nullptr)).ok());
    auto slepc = largest_generalized_eigenpairs(M, K, *mumps, count);
    ASSERT_TRUE(slepc.ok()) << slepc.status().message();
    const auto& [mu, Q] = *slepc;
    const auto& [mu_ref, Q_ref] = *spectra;
    ASSERT_EQ(mu.size(), count);
    ASSERT_EQ(Q.rows(), n);
    ASSERT_EQ(Q.cols(), count);
    std::cout << "SLEPc against Spectra, " << (summed ? "FactorizeSum" : "Factorize") << ": max |dmu| / mu "
              << ((mu - mu_ref).cwiseAbs().array() / mu_ref.array()).maxCoeff() << "\n";
    for (int k = 0; k < count; ++k) {
      EXPECT_NEAR(mu(k), mu_ref(k), 1e-10 * mu_ref(k)) << "eigenvalue " << k;
      if (k > 0) {
        EXPECT_LT(mu(k), mu(k - 1));  // descending
      }
      EXPECT_NEAR(Q.col(k).dot(Kfull * Q.col(k)), 1.0, 1e-12);  // K-normalized
      const double sign = Q.col(k).dot(Kfull * Q_ref.col(k)) < 0.0 ? -1.0 : 1.0;
      EXPECT_LT((sign * Q.col(k) - Q_ref.col(k)).norm(), 1e-7 * Q_ref.col(k).norm()) << "eigenvector " << k;
    }
  }
}

// A pencil of fewer unknowns than Krylov-Schur's default basis, all its eigenpairs asked for: the
// dense route's answer (generalized_eigen.cpp solves below 24 unknowns densely on cholmod).
TEST(PetscSolver, SlepcGivesEveryEigenpairOfASmallPencil) {
  if (!backend_built(Backend::kPetscMumps)) GTEST_SKIP() << "PETSc (and SLEPc) not built in";
  const int n = 8;
  const auto [K, M] = spring_mass_chain(n);
  auto cholmod = make_sparse_cholesky({.backend = Backend::kCholmod});
  auto mumps = make_sparse_cholesky({.backend = Backend::kPetscMumps});
  ASSERT_TRUE(cholmod->Factorize(K, nullptr).ok());
  ASSERT_TRUE(mumps->Factorize(K, nullptr).ok());
  auto dense = largest_generalized_eigenpairs(M, K, *cholmod, n);
  auto slepc = largest_generalized_eigenpairs(M, K, *mumps, n);
  ASSERT_TRUE(dense.ok()) << dense.status().message();
  ASSERT_TRUE(slepc.ok()) << slepc.status().message();
  ASSERT_EQ(slepc->first.size(), n);
  for (int k = 0; k < n; ++k) EXPECT_NEAR(slepc->first(k), dense->first(k), 1e-10 * dense->first(k)) << k;
}

TEST(PetscSolver, SlepcRefusesAPencilOfAnotherSize) {
  if (!backend_built(Backend::kPetscMumps)) GTEST_SKIP() << "PETSc (and SLEPc) not built in";
  const auto [K, M] = spring_mass_chain(40);
  auto mumps = make_sparse_cholesky({.backend = Backend::kPetscMumps});
  ASSERT_TRUE(mumps->Factorize(K, nullptr).ok());
  const SparseMatrix smaller = M.topLeftCorner(30, 30);
  auto eig = largest_generalized_eigenpairs(smaller, K, *mumps, 3);
  ASSERT_FALSE(eig.ok());
  EXPECT_EQ(eig.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(eig.status().message().find("A has 30 rows, K has 40"), std::string::npos) << eig.status().message();
}

}  // namespace
}  // namespace kinestat::solver
