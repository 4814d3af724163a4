#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/stiffness_indices.hpp"

namespace kinestat {
namespace {

TEST(StiffnessIndices, DiagonalMatrixByHand) {
  MatX K = Vec3(1.0, -4.0, 2.0).asDiagonal();
  K(0, 2) = 0.5;
  K(2, 0) = 0.5;
  const auto ix = stiffness_indices(K);
  EXPECT_DOUBLE_EQ(ix.trace, -1.0);
  EXPECT_DOUBLE_EQ(ix.norm_1, 4.0);  // column 2: |-4|
  EXPECT_DOUBLE_EQ(ix.norm_inf, 4.0);
  EXPECT_DOUBLE_EQ(ix.max_abs_entry, 4.0);
  EXPECT_NEAR(ix.norm_frobenius, std::sqrt(1 + 16 + 4 + 0.5), 1e-14);
  // det = -4 * (1*2 - 0.25) = -7
  EXPECT_EQ(ix.det_sign, -1);
  EXPECT_NEAR(ix.determinant, -7.0, 1e-12);
  EXPECT_NEAR(ix.log10_abs_det, std::log10(7.0), 1e-14);
  // eigenvalues: -4 and (3 +- sqrt(1 + 1))/2
  EXPECT_NEAR(ix.eigenvalues(0), -4.0, 1e-14);
  EXPECT_NEAR(ix.eigenvalues(1), (3 - std::sqrt(2.0)) / 2, 1e-14);
  EXPECT_NEAR(ix.norm_2, 4.0, 1e-14);
  EXPECT_NEAR(ix.condition_number, 4.0 / ((3 - std::sqrt(2.0)) / 2), 1e-12);
  EXPECT_EQ(ix.symmetry_error, 0.0);
}

TEST(StiffnessIndices, InvariantsUnderRotation) {
  Mat6 K = Mat6::Zero();
  K.diagonal() << 1e7, 2e7, 3e7, 1e3, 2e3, 5e3;
  const Mat6 R = rotation6(axis_angle(Vec3(1, 2, 3), 0.7));
  const auto a = stiffness_indices(MatX(K));
  const auto b = stiffness_indices(MatX(R * K * R.transpose()));
  EXPECT_NEAR(b.trace / a.trace, 1.0, 1e-14);
  EXPECT_NEAR(b.norm_2 / a.norm_2, 1.0, 1e-14);
  EXPECT_NEAR(b.norm_frobenius / a.norm_frobenius, 1.0, 1e-14);
  EXPECT_NEAR(b.log10_abs_det, a.log10_abs_det, 1e-12);
  EXPECT_NEAR(b.condition_number / a.condition_number, 1.0, 1e-9);
  // The entry-wise norms are not invariant: the rotation mixes entries.
  EXPECT_GT(std::abs(b.norm_inf - a.norm_inf) / a.norm_inf, 1e-3);
}

TEST(StiffnessIndices, HugeDeterminantKeptInLog) {
  MatX K = MatX::Identity(40, 40) * 1e11;
  const auto ix = stiffness_indices(K);
  EXPECT_NEAR(ix.log10_abs_det, 440.0, 1e-9);
  EXPECT_TRUE(std::isinf(ix.determinant));
  EXPECT_EQ(ix.det_sign, 1);
}

// The 6x6 path: the block eigenvalues are the 3x3 blocks' whatever the coupling, and the 6x6 indices
// are those of eq. (7)-(13) by hand. K = diag(R Dt R', R Dr R') plus a coupling block C that leaves the
// blocks alone; with C = 0 the 6x6's eigenvalues are Dt and Dr, its determinant their product.
TEST(CartesianIndices, BlockEigenvaluesAndIndicesByHand) {
  const Mat3 R = axis_angle(Vec3(1, 2, 3).normalized(), 0.7);
  const Vec3 dt(1e7, 2e7, 3e7), dr(1e3, 2e3, 5e3);  // N/m, N m/rad
  Mat6 K = Mat6::Zero();
  K.topLeftCorner<3, 3>() = R * dt.asDiagonal() * R.transpose();
  K.bottomRightCorner<3, 3>() = R * dr.asDiagonal() * R.transpose();
  const CartesianIndices a = cartesian_indices(K);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.translational_eigenvalues(i), dt(i), 1e-14 * dt(2));  // round-off of a 3x3 eigensolve
    EXPECT_NEAR(a.rotational_eigenvalues(i), dr(i), 1e-14 * dr(2));
    EXPECT_NEAR(a.eigenvalues(i), dr(i), 1e-9 * dr(2));  // round-off eps ‖K‖ ~ 1e-8, 500x below
    EXPECT_NEAR(a.eigenvalues(i + 3), dt(i), 1e-14 * dt(2));
  }
  EXPECT_NEAR(a.trace, dt.sum() + dr.sum(), 1e-14 * dt.sum());
  EXPECT_EQ(a.det_sign, 1);
  EXPECT_NEAR(a.log10_abs_det, std::log10(dt.prod() * dr.prod()), 1e-13);
  EXPECT_NEAR(a.determinant / (dt.prod() * dr.prod()), 1.0, 1e-12);
  EXPECT_NEAR(a.condition_number, 3e7 / 1e3, 1e-8 * 3e4);

  Mat6 coupled = K;
  coupled.topRightCorner<3, 3>() = 1e4 * R;  // m N/m: the same blocks, another 6x6
  coupled.bottomLeftCorner<3, 3>() = 1e4 * R.transpose();
  const CartesianIndices b = cartesian_indices(coupled);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(b.translational_eigenvalues(i), dt(i), 1e-14 * dt(2));
    EXPECT_NEAR(b.rotational_eigenvalues(i), dr(i), 1e-14 * dr(2));
  }
  EXPECT_GT(std::abs(b.eigenvalues(0) - dr(0)), 1.0);  // the coupling moves the 6x6's spectrum
  EXPECT_LT(b.symmetry_error, 1e-15);                  // R D R' is symmetric to round-off: 8e-17 measured
}

TEST(Frame, ElementAxesAreRightHandedAndContainOrientation) {
  Mat3 axes;
  ASSERT_TRUE(element_axes(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 1), axes));
  EXPECT_NEAR((axes.transpose() * axes - Mat3::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-15);
  EXPECT_NEAR(axes.col(1).dot(Vec3(0, 0, 1)), 1.0, 1e-15);  // orientation lies in local x-y
  EXPECT_FALSE(element_axes(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), axes));
  EXPECT_FALSE(element_axes(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), axes));
  // Default orientation of an in-plane element gives local z = global z.
  ASSERT_TRUE(element_axes(Vec3(0, 0, 0), Vec3(1, 2, 0), default_orientation(Vec3(1, 2, 0)), axes));
  EXPECT_NEAR((axes.col(2) - Vec3::UnitZ()).norm(), 0.0, 1e-15);
}

TEST(Frame, RigidTransferMovesAPointWithTheBody) {
  // A rotation theta about z of a body moves a point at offset (1,0,0) by theta along +y.
  Vec6 ref = Vec6::Zero();
  ref(5) = 1e-3;
  const Vec6 moved = rigid_transfer(Vec3(1, 0, 0)) * ref;
  EXPECT_NEAR(moved(1), 1e-3, 1e-18);
  EXPECT_NEAR(moved(0), 0.0, 1e-18);
  EXPECT_NEAR(moved(5), 1e-3, 1e-18);
}

}  // namespace
}  // namespace kinestat
