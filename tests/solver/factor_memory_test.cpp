// The memory estimate made after the symbolic analysis, the refusal it allows before the numeric
// factorization allocates anything, and the factorization's threads.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <fstream>
#include <string>

#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::solver {
namespace {

// 7-point Laplacian on an m^3 grid plus the identity: SPD, with the fill of a 3D mesh (supernodal).
SparseMatrix grid_laplacian(int m) {
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        t.emplace_back(id(i, j, k), id(i, j, k), 7.0);
        if (i + 1 < m) t.emplace_back(id(i + 1, j, k), id(i, j, k), -1.0);
        if (j + 1 < m) t.emplace_back(id(i, j + 1, k), id(i, j, k), -1.0);
        if (k + 1 < m) t.emplace_back(id(i, j, k + 1), id(i, j, k), -1.0);
      }
  SparseMatrix A(m * m * m, m * m * m);
  A.setFromTriplets(t.begin(), t.end());  // lower triangle only: all the factorization reads
  return A;
}

// The estimate covers the factor's values (8 bytes per entry of L) and stays within a small factor
// of it and of CHOLMOD's own count of its peak memory (an independent route: its allocator's tally).
TEST(FactorMemory, EstimateBoundsTheFactorAndMatchesCholmodsPeak) {
  const SparseMatrix A = grid_laplacian(24);  // 13 824 unknowns
  auto chol = make_sparse_cholesky();
  FactorizationReport r;
  ASSERT_TRUE(chol->Factorize(A, &r).ok());
  ASSERT_TRUE(r.supernodal);
  const double values = 8.0 * static_cast<double>(r.nnz_factor);
  EXPECT_GT(r.factor_bytes, values);
  EXPECT_LT(r.factor_bytes, 2.5 * values);        // indices and the supernodes' padding: 1.94 here
  EXPECT_GT(r.memory_available_bytes, 0.0);       // read from /proc/meminfo
  EXPECT_GT(r.factor_bytes, 0.9 * r.peak_bytes);  // 1.05 here
  EXPECT_LT(r.factor_bytes, 1.25 * r.peak_bytes);
}

TEST(FactorMemory, RefusedBeforeTheNumericFactorizationWhenItDoesNotFit) {
  const SparseMatrix A = grid_laplacian(16);
  FactorizationReport fits;
  ASSERT_TRUE(make_sparse_cholesky()->Factorize(A, &fits).ok());

  LinearSolverOptions o;
  o.memory_limit_bytes = 0.5 * fits.factor_bytes;  // injected: the estimate does not fit
  std::vector<std::string> stages;
  o.progress = [&stages](const std::string& s) { stages.push_back(s); };
  auto chol = make_sparse_cholesky(o);
  FactorizationReport r;
  const Status s = chol->Factorize(A, &r);
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_TRUE(r.refused_for_memory());
  EXPECT_DOUBLE_EQ(r.factor_bytes, fits.factor_bytes);
  EXPECT_EQ(r.factor_seconds, 0.0);  // no numeric factorization ran
  EXPECT_TRUE(stages.empty());       // nor was it announced
  EXPECT_NE(s.message().find("GB"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("--solver petsc"), std::string::npos) << s.message();
  MatX X;
  EXPECT_FALSE(chol->Solve(MatX::Ones(A.rows(), 1), &X).ok());

  // With room, the same options factorize and announce the flops and memory first.
  o.memory_limit_bytes = 2.0 * fits.factor_bytes;
  auto roomy = make_sparse_cholesky(o);
  ASSERT_TRUE(roomy->Factorize(A, &r).ok());
  ASSERT_EQ(stages.size(), 1u);
  EXPECT_NE(stages[0].find("Gflop"), std::string::npos) << stages[0];
}

int thread_count() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
  return -1;
}

// CHOLMOD's OpenMP regions run on the calling thread (cholmod_cholesky.cpp): a supernodal
// factorization starts no OpenMP team (its workers would stay alive afterwards), and the OpenMP
// setting of the program around it is given back.
TEST(FactorThreads, CholmodStartsNoOpenMpTeamAndRestoresTheSetting) {
  auto* get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  if (get == nullptr) GTEST_SKIP() << "CHOLMOD is built without OpenMP here";
  const int levels = get();
  const int threads = thread_count();
  FactorizationReport r;
  ASSERT_TRUE(make_sparse_cholesky()->Factorize(grid_laplacian(24), &r).ok());
  ASSERT_TRUE(r.supernodal);
  EXPECT_EQ(thread_count(), threads);
  EXPECT_EQ(get(), levels);
}

}  // namespace
}  // namespace kinestat::solver
