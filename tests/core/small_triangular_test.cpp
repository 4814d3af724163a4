// lower_solve_in_place (core/small_triangular.hpp) against an independent route, Eigen's triangular
// solve, on the shapes the kernels use: a dense lower triangle, a block-diagonal one (the skipped
// zeros), entries above the diagonal that must not be read, fixed and dynamic sizes.
#include "kinestat/core/small_triangular.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "kinestat/core/types.hpp"

namespace kinestat {
namespace {

TEST(SmallTriangular, EqualsEigensTriangularSolve) {
  std::srand(11);
  for (int n = 1; n <= 14; ++n)
    for (int variant = 0; variant < 2; ++variant) {
      SCOPED_TRACE(testing::Message() << n << " rows, variant " << variant);
      // A well-conditioned lower triangle (diagonal 1.5..3.5, off-diagonal entries within 1: condition
      // numbers up to 5.7), junk above it; variant 1 block diagonal in blocks of 6 and 1 (a chain's
      // springs and an actuator).
      MatX L = MatX::Random(n, n);
      L.diagonal().array() += 2.5;
      if (variant == 1)
        for (int i = 0; i < n; ++i)
          for (int k = 0; k < i; ++k)
            if (i / 6 != k / 6 || i == 12) L(i, k) = 0.0;
      const MatX B = MatX::Random(n, 6);
      MatX X = B;
      lower_solve_in_place(L, X);
      const MatX want = L.triangularView<Eigen::Lower>().solve(B);
      // Entries of order 1: 1e-13 is ~500 eps (measured 2.2e-16 and 5.6e-16 at worst).
      EXPECT_LE((X - want).cwiseAbs().maxCoeff(), 1e-13);
      EXPECT_LE((MatX(L.triangularView<Eigen::Lower>()) * X - B).cwiseAbs().maxCoeff(), 1e-13);
    }
  // Fixed size, as the fixed-size kernels call it.
  Mat3 L3;
  L3 << 2, 99, 99, 1, 4, 99, -1, 3, 5;
  Vec3 b(1, 2, 3);
  lower_solve_in_place(L3, b);
  // By hand: x0 = 1/2, x1 = (2 - 1/2)/4 = 3/8, x2 = (3 + 1/2 - 9/8)/5 = 19/40.
  EXPECT_DOUBLE_EQ(b(0), 0.5);
  EXPECT_DOUBLE_EQ(b(1), 0.375);
  EXPECT_DOUBLE_EQ(b(2), 19.0 / 40.0);
}

}  // namespace
}  // namespace kinestat
