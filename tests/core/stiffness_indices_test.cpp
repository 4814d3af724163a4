#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

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
  EXPECT_DOUBLE_EQ(ix.norm_1, 4.0);                   // column 2: |-4|
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

// cartesian_indices equals stiffness_indices on the common fields, and its block eigenvalues are
// those of the 3x3 blocks: on stiffness-like matrices (mixed units, 1e7 N/m next to 1e2 N m/rad),
// indefinite and slightly unsymmetric ones, and a singular one.
TEST(CartesianIndices, EqualsStiffnessIndicesOnTheCommonFields) {
  std::srand(3);
  std::vector<Mat6> cases;
  for (int k = 0; k < 20; ++k) {
    const Mat6 A = Mat6::Random();
    Vec6 scale;
    scale << Vec3::Constant(std::pow(10.0, 3 + k % 5)), Vec3::Constant(std::pow(10.0, k % 3));
    Mat6 K = scale.cwiseSqrt().asDiagonal() * (A * A.transpose() + 0.1 * Mat6::Identity()) *
             scale.cwiseSqrt().asDiagonal();
    if (k % 4 == 1) K -= 2.0 * K.trace() / 6 * Vec6::Unit(k % 6) * Vec6::Unit(k % 6).transpose();  // indefinite
    if (k % 4 == 2) K(0, 5) *= 1.001;                                                           // unsymmetric
    cases.push_back(K);
  }
  Mat6 singular = Mat6::Zero();
  singular.diagonal() << 1e6, 2e6, 0.0, 10.0, 20.0, 30.0;
  cases.push_back(singular);
  const auto rel = [](double a, double b) { return a == b ? 0.0 : std::abs(a - b) / std::max(std::abs(a), std::abs(b)); };
  for (const Mat6& K : cases) {
    const CartesianIndices c = cartesian_indices(K);
    const StiffnessIndices s = stiffness_indices(MatX(K));
    for (const auto& [a, b] : {std::pair{c.trace, s.trace}, {c.norm_1, s.norm_1}, {c.norm_2, s.norm_2},
                               {c.norm_frobenius, s.norm_frobenius}, {c.norm_inf, s.norm_inf},
                               {c.max_abs_entry, s.max_abs_entry}, {c.symmetry_error, s.symmetry_error}})
      EXPECT_LE(rel(a, b), 1e-13) << K;
    EXPECT_EQ(c.det_sign, s.det_sign);
    if (s.det_sign != 0) {
      EXPECT_NEAR(c.log10_abs_det, s.log10_abs_det, 1e-13);
    }
    if (std::isfinite(s.condition_number)) {
      EXPECT_LE(rel(c.condition_number, s.condition_number), 1e-10) << K;
    }
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(c.eigenvalues(i), s.eigenvalues(i), 1e-13 * s.norm_2);
    const Mat6 Ks = 0.5 * (K + K.transpose());
    const VecX t = stiffness_indices(MatX(Ks.topLeftCorner<3, 3>())).eigenvalues;
    const VecX r = stiffness_indices(MatX(Ks.bottomRightCorner<3, 3>())).eigenvalues;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(c.translational_eigenvalues(i), t(i), 1e-13 * t.cwiseAbs().maxCoeff());
      EXPECT_NEAR(c.rotational_eigenvalues(i), r(i), 1e-13 * r.cwiseAbs().maxCoeff());
    }
  }
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
