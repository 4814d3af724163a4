// Unloaded VJM stiffness (eq. 9-10), link springs from beams, aggregation and singular postures,
// each against beam theory, a rigid-body transfer, the literal eq. (9) or a penalty limit.
#include <gtest/gtest.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "vjm/bordered_system.hpp"
#include "vjm_test_chains.hpp"

namespace kinestat::vjm {
namespace {

using test_chains::eq1_chain;
using test_chains::pendulum;
using test_chains::steel;

double rel_diff(const Mat6& A, const Mat6& B) { return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff(); }
double asym(const Mat6& A) { return (A - A.transpose()).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff(); }

TEST(VjmStiffness, CantileverSpringGivesTheBeamFormulas) {
  // Tip compliance of a clamped Euler-Bernoulli beam: L/EA, L^3/3EI, L/EI, L^2/2EI, L/GJ.
  const Material m = steel();
  const Section s = rectangle_section(0.02, 0.03);
  const double L = 0.4;
  Chain c("cantilever");
  c.add_translation(Vec3(L, 0, 0), "beam");
  c.add_spring(cantilever_spring(m, s, L, BeamTheory::kEulerBernoulli), "beam spring");
  StatusOr<CartesianStiffness> k = unloaded_stiffness(c);
  ASSERT_TRUE(k.ok()) << k.status().message();
  ASSERT_TRUE(k->status.ok()) << k->status.message();
  ASSERT_TRUE(k->compliance_defined);
  const Mat6& C = k->compliance;
  EXPECT_NEAR(C(0, 0), L / (m.E * s.A), 1e-9 * C(0, 0));
  EXPECT_NEAR(C(1, 1), L * L * L / (3 * m.E * s.Iz), 1e-9 * C(1, 1));
  EXPECT_NEAR(C(2, 2), L * L * L / (3 * m.E * s.Iy), 1e-9 * C(2, 2));
  EXPECT_NEAR(C(3, 3), L / (m.G * s.J), 1e-9 * C(3, 3));
  EXPECT_NEAR(C(5, 5), L / (m.E * s.Iz), 1e-9 * C(5, 5));
  EXPECT_NEAR(C(1, 5), L * L / (2 * m.E * s.Iz), 1e-9 * C(1, 5));
  EXPECT_NEAR(C(2, 4), -L * L / (2 * m.E * s.Iy), 1e-9 * C(2, 2));
  EXPECT_LT(asym(k->stiffness), 1e-12);
  EXPECT_LT(asym(k->compliance), 1e-12);
}

TEST(VjmStiffness, SpringAtTheBaseIsTransferredRigidly) {
  // A spring at the base seen from a tool at offset r: C_tool = A C A^T, A = rigid_transfer(r).
  const Mat6 Ks = cantilever_spring(steel(), circle_section(0.015), 0.2, BeamTheory::kTimoshenko);
  const Vec3 r(0.3, -0.1, 0.2);
  Chain c("offset");
  c.add_spring(Ks, "base spring");
  c.add_translation(r, "arm");
  StatusOr<CartesianStiffness> k = unloaded_stiffness(c);
  ASSERT_TRUE(k.ok() && k->compliance_defined);
  const Mat6 A = rigid_transfer(r);
  EXPECT_LT(rel_diff(k->compliance, A * Ks.inverse() * A.transpose()), 1e-10);
}

TEST(VjmStiffness, TwoBeamLinkEqualsOneLongBeam) {
  // Section 4.2: a link as a serial chain of beams. Two collinear Euler-Bernoulli segments of
  // lengths a, b are exactly one cantilever of length a + b.
  const Material m = steel();
  const Section s = tube_section(0.03, 0.003);
  const double a = 0.12, b = 0.18;
  Chain link("two beams");
  link.add_rotation(Vec3::UnitZ(), 0.6, "link direction");  // end frame rotated: checks the frame change
  link.add_translation(Vec3(a, 0, 0), "segment 1");
  link.add_spring(cantilever_spring(m, s, a, BeamTheory::kEulerBernoulli), "segment 1");
  link.add_translation(Vec3(b, 0, 0), "segment 2");
  link.add_spring(cantilever_spring(m, s, b, BeamTheory::kEulerBernoulli), "segment 2");
  StatusOr<Mat6> K = serial_link_spring(link);
  ASSERT_TRUE(K.ok()) << K.status().message();
  EXPECT_LT(rel_diff(*K, cantilever_spring(m, s, a + b, BeamTheory::kEulerBernoulli)), 1e-9);
  EXPECT_LT(asym(*K), 1e-12);
}

TEST(VjmStiffness, EliminationEqualsLiteralEq9AtARegularPosture) {
  // Eq. (10): K is the 6x6 block of the inverse of the bordered matrix of eq. (9). At a regular
  // posture that matrix is invertible and a full-pivot LU gives K independently.
  const Chain c = eq1_chain(false);
  const ChainJacobians J = jacobians(c, c.nominal_passive(), VecX::Zero(c.num_virtual()));
  const Mat6 S = spring_compliance(J.Jtheta, c.spring_stiffness());
  const int n = c.num_passive();
  MatX B = MatX::Zero(6 + n, 6 + n);
  B << S, J.Jq, J.Jq.transpose(), MatX::Zero(n, n);
  const Eigen::FullPivLU<MatX> lu(B);
  ASSERT_TRUE(lu.isInvertible());
  MatX rhs = MatX::Zero(6 + n, 6);
  rhs.topRows(6).setIdentity();
  const Mat6 K_literal = lu.solve(rhs).topRows(6);
  StatusOr<CartesianStiffness> k = unloaded_stiffness(c);
  ASSERT_TRUE(k.ok());
  EXPECT_LT(rel_diff(k->stiffness, K_literal), 1e-9);
  EXPECT_LT(asym(k->stiffness), 1e-12);
  // Four independent passive joints: four free tool directions, K has rank 2.
  EXPECT_EQ(k->free_directions.size(), 4u);
  EXPECT_TRUE(k->status.ok());
  for (const Vec6& d : k->free_directions) EXPECT_LT((k->stiffness * d).norm(), 1e-9 * k->stiffness.norm());
}

TEST(VjmStiffness, PendulumUnloadedHasClosedFormAndNamesRigidDirections) {
  const double k = 200.0, ka = 1e5, l = 0.5;
  StatusOr<CartesianStiffness> K = unloaded_stiffness(pendulum(k, ka, l));
  ASSERT_TRUE(K.ok());
  Mat6 expected = Mat6::Zero();
  expected(0, 0) = ka;           // axial spring
  expected(1, 1) = k / (l * l);  // base spring through the lever l (tip rotation is free)
  EXPECT_LT(rel_diff(K->stiffness, expected), 1e-12);
  // Nothing moves the tip along z or rotates it about x, y: three rigid directions, reported.
  EXPECT_EQ(K->status.code(), StatusCode::kSingular);
  EXPECT_EQ(K->rigid_directions.size(), 3u);
  EXPECT_NE(K->status.message().find("rigid"), std::string::npos);
  EXPECT_NE(K->status.message().find("translation along +z"), std::string::npos) << K->status.message();
  ASSERT_EQ(K->free_directions.size(), 1u);
  EXPECT_NEAR(std::abs(K->free_directions[0][5]), 1.0, 1e-12);  // rotation about z
}

// Stretched planar 3R passive arm on a 6-dof base spring: at q = 0 the three passive columns span
// only (y, rz), so eq. (9) is singular (a first-order self-motion). The stiffness that exists is the
// limit of the regular problem where the passive joints get vanishing springs eps.
TEST(VjmStiffness, SingularPassivePostureEqualsPenaltyLimit) {
  Mat6 Kb = cantilever_spring(steel(), circle_section(0.03), 0.1, BeamTheory::kEulerBernoulli);
  Chain c("3R");
  c.add_spring(Kb, "base spring");
  for (int i = 0; i < 3; ++i) {
    c.add_passive(JointType::kRevolute, Vec3::UnitZ(), 0.0, "pin");
    c.add_translation(Vec3(0.1 + 0.05 * i, 0, 0), "bar");
  }
  StatusOr<CartesianStiffness> K = unloaded_stiffness(c);
  ASSERT_TRUE(K.ok());
  EXPECT_NE(K->note.find("1 self-motion"), std::string::npos) << K->note;
  EXPECT_TRUE(K->status.ok()) << K->status.message();  // a self-motion alone does not change K

  // Penalty route: passive joints as springs eps (N m/rad), C_eps = J K_all^-1 J^T, K_eps = C_eps^-1.
  const ChainJacobians J = jacobians(c, c.nominal_passive(), VecX::Zero(6));
  const double eps = 1e-4;
  const Mat6 C = J.Jtheta * Kb.inverse() * J.Jtheta.transpose() + J.Jq * J.Jq.transpose() / eps;
  const Mat6 Keps = C.inverse();
  EXPECT_LT(rel_diff(K->stiffness, Keps), 1e-5);
  EXPECT_GT(K->stiffness(0, 0), 0.0);  // axial stiffness survives: x is not free at this posture
}

TEST(VjmStiffness, PlatformAggregationSumsRotatedChains) {
  // Three elastic legs meeting at the origin (no passive joints): K = sum R6 K_leg R6^T.
  const Mat6 Kleg = cantilever_spring(steel(), circle_section(0.01), 0.25, BeamTheory::kEulerBernoulli);
  std::vector<Chain> legs;
  Mat6 expected = Mat6::Zero();
  for (int i = 0; i < 3; ++i) {
    const Vec3 dir(std::cos(2.1 * i), std::sin(2.1 * i), 0.5);
    Chain c("leg " + std::to_string(i));
    const Mat3 R = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), -dir).toRotationMatrix();
    c.add_translation(0.25 * dir.normalized(), "base");
    c.add_rotation(Eigen::AngleAxisd(R).axis(), Eigen::AngleAxisd(R).angle(), "leg axis");
    c.add_translation(Vec3(0.25, 0, 0), "leg");
    c.add_spring(Kleg, "leg spring");
    legs.push_back(c);
    expected += rotation6(R) * Kleg * rotation6(R).transpose();
  }
  StatusOr<CartesianStiffness> K = platform_unloaded_stiffness(legs);
  ASSERT_TRUE(K.ok()) << K.status().message();
  EXPECT_TRUE(K->status.ok());
  EXPECT_LT(rel_diff(K->stiffness, expected), 1e-10);
  EXPECT_LT(rel_diff(K->compliance * K->stiffness, Mat6::Identity()), 1e-10);
  EXPECT_LT(asym(K->stiffness), 1e-12);
}

TEST(VjmStiffness, PlatformWithAFreeRotationIsDiagnosed) {
  // Three orthogonal actuated prismatic chains with S joints at the tool: translations are held
  // by the actuator springs (k each), rotations are free: a singular platform.
  std::vector<Chain> chains;
  const double k = 1e6;
  for (int i = 0; i < 3; ++i) {
    Chain c("axis " + std::to_string(i));
    c.add_translation(-0.5 * Vec3::Unit(i), "base");
    c.add_actuator(JointType::kPrismatic, Vec3::Unit(i), 0.3, k, "actuator");
    // Passive slides along the other two axes and a spherical joint: only the actuator direction resists.
    c.add_passive(JointType::kPrismatic, Vec3::Unit((i + 1) % 3), 0.0, "slide 1");
    c.add_passive(JointType::kPrismatic, Vec3::Unit((i + 2) % 3), 0.0, "slide 2");
    c.add_translation(0.2 * Vec3::Unit(i), "leg");
    c.add_spherical(Vec3::Zero(), "S");
    chains.push_back(c);
  }
  StatusOr<CartesianStiffness> K = platform_unloaded_stiffness(chains);
  ASSERT_TRUE(K.ok()) << K.status().message();
  Mat6 expected = Mat6::Zero();
  expected.topLeftCorner<3, 3>() = k * Mat3::Identity();
  EXPECT_LT(rel_diff(K->stiffness, expected), 1e-12);
  EXPECT_EQ(K->status.code(), StatusCode::kSingular);
  EXPECT_FALSE(K->compliance_defined);
  EXPECT_EQ(K->free_directions.size(), 3u);
  EXPECT_NE(K->status.message().find("rotation about"), std::string::npos) << K->status.message();
}

TEST(VjmStiffness, UnassembledPlatformIsRejectedByName) {
  std::vector<Chain> chains = {pendulum(1, 1, 0.5), pendulum(1, 1, 0.6)};
  const Status s = platform_unloaded_stiffness(chains).status();
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find("not assembled"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace kinestat::vjm
