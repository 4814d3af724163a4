// householder_qr (core/small_qr.hpp) against an independent route, Eigen's HouseholderQR of the
// same block: the same reflections, so the same R, Q and count to round-off; and against the
// definition: Q orthogonal, Q R = A, the rest of both matrices untouched.
#include "kinestat/core/small_qr.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>

namespace kinestat {
namespace {

using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

// Every block shape the kernels use (cols <= rows <= 6), random entries, and columns already along
// their axis (no reflection) and zero (R(k, k) = 0).
TEST(SmallQr, EqualsEigensHouseholderQrOnEveryShape) {
  std::srand(7);
  for (int rows = 1; rows <= 6; ++rows)
    for (int cols = 1; cols <= rows; ++cols)
      for (int variant = 0; variant < 3; ++variant) {
        SCOPED_TRACE(testing::Message() << rows << " x " << cols << ", variant " << variant);
        Mat6 A = Mat6::Zero();
        A.topLeftCorner(rows, cols) = Block::Random(rows, cols);
        if (variant == 1) A.col(0).segment(1, 5).setZero();  // along e_0: no reflection
        if (variant == 2) A.col(cols - 1).setZero();         // a zero column
        const Block block = A.topLeftCorner(rows, cols);
        Mat6 R = A, Q;
        const int count = householder_qr(R, rows, cols, Q);

        const Eigen::HouseholderQR<Block> eigen(block);
        int eigen_count = 0;
        for (Eigen::Index k = 0; k < eigen.hCoeffs().size(); ++k) eigen_count += eigen.hCoeffs()(k) != 0.0;
        EXPECT_EQ(count, eigen_count);
        const Block eigen_R = eigen.matrixQR().triangularView<Eigen::Upper>();
        const Block eigen_Q = eigen.householderQ();
        // Entries of order 1: 1e-14 is about 50 eps, the round-off of a 6-term reflection.
        EXPECT_LE((R.topLeftCorner(rows, cols) - eigen_R).cwiseAbs().maxCoeff(), 1e-14);
        EXPECT_LE((Q.topLeftCorner(rows, rows) - eigen_Q).cwiseAbs().maxCoeff(), 1e-14);

        EXPECT_LE((Q.transpose() * Q - Mat6::Identity()).cwiseAbs().maxCoeff(), 1e-14);
        EXPECT_LE((Q * R - A).cwiseAbs().maxCoeff(), 1e-14);
        EXPECT_EQ(R.bottomRows(6 - rows).cwiseAbs().sum() + R.rightCols(6 - cols).cwiseAbs().sum(), 0.0);
        EXPECT_EQ((Q.bottomRightCorner(6 - rows, 6 - rows) - Mat6::Identity().topLeftCorner(6 - rows, 6 - rows))
                          .cwiseAbs()
                          .sum() +
                      Q.topRightCorner(rows, 6 - rows).cwiseAbs().sum(),
                  0.0);
        for (int k = 0; k < cols; ++k) {  // R upper triangular: zeros below its diagonal
          EXPECT_EQ(R.col(k).segment(k + 1, 5 - k).cwiseAbs().sum(), 0.0);
        }
        if (variant == 2) {
          EXPECT_EQ(R(cols - 1, cols - 1), 0.0);
        }
      }
}

}  // namespace
}  // namespace kinestat
