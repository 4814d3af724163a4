#include <dlfcn.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "kinestat/solver/blas_threads.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {
namespace {

int threads_of_this_process() {
  return static_cast<int>(
      std::distance(std::filesystem::directory_iterator("/proc/self/task"), std::filesystem::directory_iterator{}));
}

// The 7-point Laplacian of an n^3 grid, grounded at every node (diagonal 6.5): at n = 25 its
// supernodes are large enough for OpenBLAS to thread their products.
SparseMatrix grid_laplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int a = id(i, j, k);
        t.emplace_back(a, a, 6.5);
        if (i + 1 < n) t.emplace_back(a, id(i + 1, j, k), -1.0), t.emplace_back(id(i + 1, j, k), a, -1.0);
        if (j + 1 < n) t.emplace_back(a, id(i, j + 1, k), -1.0), t.emplace_back(id(i, j + 1, k), a, -1.0);
        if (k + 1 < n) t.emplace_back(a, id(i, j, k + 1), -1.0), t.emplace_back(id(i, j, k + 1), a, -1.0);
      }
  SparseMatrix A(n * n * n, n * n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Each test runs in its own process (gtest_discover_tests), so OpenBLAS's workers started at load
// are all there: releasing them ends exactly openblas_get_num_threads() - 1 threads, and a
// factorization afterwards starts them again and is still right.
TEST(BlasThreads, IdleOpenBlasThreadsEndAndComeBackForAFactorization) {
  using Count = int (*)();
  const auto num_threads = reinterpret_cast<Count>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto parallel = reinterpret_cast<Count>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
  if (!num_threads || !parallel || parallel() != 1 || num_threads() < 2)
    GTEST_SKIP() << "the BLAS is not OpenBLAS's pthreads build on more than one core";
  const int workers = num_threads() - 1;
  const int before = threads_of_this_process();
  ASSERT_TRUE(release_idle_blas_threads());
  EXPECT_EQ(threads_of_this_process(), before - workers);

  const SparseMatrix A = grid_laplacian(25);
  auto chol = make_sparse_cholesky();
  FactorizationReport rep;
  ASSERT_TRUE(chol->Factorize(A, &rep).ok());
  EXPECT_TRUE(rep.supernodal);
  EXPECT_EQ(threads_of_this_process(), before);
  const MatX B = MatX::Ones(A.rows(), 1);
  MatX X;
  ASSERT_TRUE(chol->Solve(B, &X).ok());
  EXPECT_LT((A * X - B).norm(), 1e-12 * B.norm());  // 2.3e-15 measured
}

}  // namespace
}  // namespace kinestat::solver
