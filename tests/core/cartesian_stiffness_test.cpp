// kinestat::CartesianStiffness, the one 6x6 result of MSA, VJM and FEA: built from a compliance,
// lost directions, and the report every method prints.
#include <gtest/gtest.h>

#include "kinestat/core/cartesian_stiffness.hpp"

namespace kinestat {
namespace {

// A symmetric positive definite compliance with SI-like scales (m/N ~1e-6, rad/(N m) ~1e-4).
Mat6 sample_compliance() {
  Mat6 A = Mat6::Random();
  const Vec6 scale = (Vec6() << 1e-3, 1e-3, 1e-3, 1e-2, 1e-2, 1e-2).finished();
  return scale.asDiagonal() * (A * A.transpose() + Mat6::Identity()) * scale.asDiagonal();
}

TEST(CartesianStiffness, FromARegularComplianceTheStiffnessIsItsInverse) {
  const Mat6 C = sample_compliance();
  const CartesianStiffness c = cartesian_from_compliance(C, Vec3(1, 2, 3), "global axes");
  EXPECT_TRUE(c.stiffness_defined);
  EXPECT_TRUE(c.compliance_defined);
  EXPECT_TRUE(c.rigid_directions.empty());
  EXPECT_TRUE(c.free_directions.empty());
  EXPECT_LT((c.stiffness * C - Mat6::Identity()).norm(), 1e-10);
  EXPECT_LT((c.stiffness - c.stiffness.transpose()).norm(), 1e-14 * c.stiffness.norm());
  ASSERT_TRUE(c.indices.has_value());
  EXPECT_NEAR(c.indices->trace, c.stiffness.trace(), 1e-12 * c.stiffness.trace());
  EXPECT_EQ(c.point, Vec3(1, 2, 3));
  EXPECT_TRUE(c.status.ok());
}

TEST(CartesianStiffness, ASupportedDofIsARigidDirectionAndLeavesTheStiffnessUndefined) {
  Mat6 C = sample_compliance();
  C.row(1).setZero();  // uy held: no motion along y under any wrench
  C.col(1).setZero();
  const CartesianStiffness c = cartesian_from_compliance(C, Vec3::Zero(), "global axes");
  EXPECT_FALSE(c.stiffness_defined);
  EXPECT_TRUE(c.compliance_defined);
  ASSERT_EQ(c.rigid_directions.size(), 1u);
  EXPECT_NEAR(std::abs(c.rigid_directions[0](1)), 1.0, 1e-12);
  EXPECT_FALSE(c.indices.has_value());
  EXPECT_FALSE(c.note.empty());
  const std::string report = cartesian_stiffness_report(c, "node 'B'");
  EXPECT_NE(report.find("LOST (rigid, infinite stiffness): translation along "), std::string::npos) << report;
  EXPECT_EQ(report.find("stiffness K ["), std::string::npos) << report;  // no numbers for an infinite stiffness
  EXPECT_NE(report.find("compliance C = K^-1 [m/N"), std::string::npos) << report;
}

TEST(CartesianStiffness, ReportNamesPointFrameUnitsIndicesAndFreeDirections) {
  CartesianStiffness c = cartesian_from_compliance(sample_compliance(), Vec3(0.25, 0, -0.5), "link axes");
  std::string report = cartesian_stiffness_report(c, "tool");
  EXPECT_EQ(report.rfind("tool: point (0.25, 0, -0.5) m, link axes", 0), 0u) << report;
  EXPECT_NE(report.find(CartesianStiffness::kStiffnessUnits), std::string::npos);
  EXPECT_NE(report.find(CartesianStiffness::kComplianceUnits), std::string::npos);
  EXPECT_NE(report.find("condition number"), std::string::npos);
  EXPECT_EQ(report.find("LOST"), std::string::npos);
  // A VJM platform with a free motion: no compliance, the direction in words, the status.
  c.compliance_defined = false;
  c.free_directions = {(Vec6() << 0, 0, 0, 0, 0, 1).finished()};
  c.status = Status::Singular("the platform has zero stiffness along a rotation");
  report = cartesian_stiffness_report(c, "tool");
  EXPECT_EQ(report.find("compliance C"), std::string::npos);
  EXPECT_NE(report.find("LOST (free, zero stiffness): rotation about +z through the point"), std::string::npos);
  EXPECT_NE(report.find("STATUS: the platform has zero stiffness"), std::string::npos);
}

TEST(CartesianStiffness, TwistsInWords) {
  EXPECT_EQ(describe_twist((Vec6() << 2, 0, 0, 0, 0, 0).finished()), "translation along +x");
  EXPECT_EQ(describe_twist((Vec6() << 0, 0, 0, 0, -1, 0).finished()), "rotation about -y through the point");
  // Rotation about z with the point moving along y at 0.5 m/rad: a screw (the axis is 0.5 m away).
  EXPECT_EQ(describe_twist((Vec6() << 0, 0.5, 0, 0, 0, 1).finished()),
            "screw motion: rotation about +z with point translation 0.5 m/rad along +y");
}

}  // namespace
}  // namespace kinestat
