// The loaded chains' Gaussian elimination (src/mechanisms/small_lu.hpp) against Eigen's full-pivoting
// LU on the same systems.
#include "mechanisms/small_lu.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace kinestat::mechanisms::fixed_vjm {
namespace {

// A random n x n matrix whose diagonal is zero (every step must exchange rows) and whose last rows
// and columns are a bordered system's (zero bottom-right block), as the Newton matrices are.
Eigen::MatrixXd newton_like(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return u(rng); });
  if (n > 1) A.diagonal().setZero();
  const int b = std::min(6, n / 2);
  A.bottomRightCorner(b, b).setZero();
  return A;
}

// Every size up to the capacity, each padding remainder included: the solution of A X = B for seven
// right-hand sides agrees with FullPivLU's to 1e-13 times the condition number (both backward stable:
// their errors are a few epsilon times it), and the last six rows first, then the others, from a
// combination of partly solved columns, give the combination's solution.
TEST(SmallLU, SolvesAsFullPivotingLU) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 1; n <= kSmallLUStride; ++n) {
    const Eigen::MatrixXd A = newton_like(n, rng);
    const Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(n, 7, [&] { return u(rng); });
    const Eigen::FullPivLU<Eigen::MatrixXd> reference(A);
    ASSERT_TRUE(reference.isInvertible()) << n;
    const Eigen::MatrixXd X = reference.solve(B);
    const double condition = A.norm() * reference.inverse().norm();
    SmallLU lu;
    lu.reset(n) = A;
    ASSERT_TRUE(lu.factor()) << n;
    PaddedColumns<7> x;
    x.reset(n) = B;
    lu.forward(x);
    const int first = std::max(0, n - 6);
    lu.backward(x, first, n);
    const Eigen::VectorXd dt = Eigen::VectorXd::LinSpaced(6, 1.0, -2.0);
    PaddedColumns<1> y;
    y.reset(n) = x.view().col(0) + x.view().rightCols<6>() * dt;
    lu.backward(x, 0, first);
    lu.backward(y, 0, first);
    const double tolerance = 1e-13 * condition * X.norm();
    EXPECT_LE((x.view() - X).norm(), tolerance) << n;
    EXPECT_LE((y.view() - (X.col(0) + X.rightCols<6>() * dt)).norm(), tolerance) << n;
  }
}

// A zero column (a free coordinate) and a non-finite entry are refused, not factored into numbers.
TEST(SmallLU, RefusesSingularAndNonFiniteMatrices) {
  std::mt19937 rng(11);
  for (int n : {3, 8, 23}) {
    Eigen::MatrixXd A = newton_like(n, rng);
    A.col(n / 2).setZero();
    SmallLU lu;
    lu.reset(n) = A;
    EXPECT_FALSE(lu.factor()) << n;
    A = newton_like(n, rng);
    A(n - 1, 0) = std::numeric_limits<double>::infinity();
    lu.reset(n) = A;
    EXPECT_FALSE(lu.factor()) << n;
  }
}

}  // namespace
}  // namespace kinestat::mechanisms::fixed_vjm
