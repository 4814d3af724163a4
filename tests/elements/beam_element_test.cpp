#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kinestat/core/frame.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/joint_element.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {
namespace {

const Material kSteel{"steel", 2.1e11, 0.81e11};

// Rigid-body motions of the two end nodes of an element from p1 to p2.
MatX rigid_modes(const Vec3& p1, const Vec3& p2) {
  MatX M(12, 6);
  for (int k = 0; k < 6; ++k) {
    Vec6 ref = Vec6::Unit(k);
    M.col(k) << rigid_transfer(p1) * ref, rigid_transfer(p2) * ref;
  }
  return M;
}

TEST(BeamElement, SymmetricAndFreeOfRigidBodyForces) {
  const Section s = rectangle_section(0.02, 0.05);
  const Vec3 p1(0.1, -0.2, 0.3), p2(0.7, 0.4, -0.1);
  Mat3 axes;
  ASSERT_TRUE(element_axes(p1, p2, Vec3(0.3, 0.1, 1.0), axes));
  for (BeamTheory th : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    const Mat12 kl = beam_local_stiffness(kSteel, s, (p2 - p1).norm(), th);
    const Mat12 T = beam_transformation(axes);
    const Mat12 K = T.transpose() * kl * T;
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    // Rigid motions (translations and rotations about any point) produce no force.
    EXPECT_LT((K * rigid_modes(p1, p2)).norm(), 1e-9 * K.norm());
    // Exactly six zero eigenvalues, the other six positive.
    Eigen::SelfAdjointEigenSolver<Mat12> eig(K);
    EXPECT_LT(eig.eigenvalues()(5), 1e-9 * eig.eigenvalues()(11));
    EXPECT_GT(eig.eigenvalues()(6), 1e-9 * eig.eigenvalues()(11));
  }
}

TEST(BeamElement, CantileverFlexibilityByCondensation) {
  // Fix node 1; the inverse of the node-2 block is the cantilever compliance.
  const Section s = circle_section(0.01);
  const double L = 0.4;
  const Mat12 k = beam_local_stiffness(kSteel, s, L, BeamTheory::kEulerBernoulli);
  const Mat6 C = k.bottomRightCorner<6, 6>().inverse();
  const double E = kSteel.E, G = kSteel.G;
  EXPECT_NEAR(C(0, 0), L / (E * s.A), 1e-12 * C(0, 0));
  EXPECT_NEAR(C(1, 1), L * L * L / (3 * E * s.Iz), 1e-10 * C(1, 1));
  EXPECT_NEAR(C(2, 2), L * L * L / (3 * E * s.Iy), 1e-10 * C(2, 2));
  EXPECT_NEAR(C(3, 3), L / (G * s.J), 1e-10 * C(3, 3));
  EXPECT_NEAR(C(5, 5), L / (E * s.Iz), 1e-10 * C(5, 5));
  EXPECT_NEAR(C(1, 5), L * L / (2 * E * s.Iz), 1e-10 * C(1, 5));   // Fy -> +rz
  EXPECT_NEAR(C(2, 4), -L * L / (2 * E * s.Iy), 1e-10 * C(1, 5));  // Fz -> -ry
}

TEST(BeamElement, TimoshenkoAddsShearCompliance) {
  // A short beam (L/h = 2): shear adds L/(kGA) to the tip compliance.
  const Section s = rectangle_section(0.05, 0.05);
  const double L = 0.1;
  const Mat12 kt = beam_local_stiffness(kSteel, s, L, BeamTheory::kTimoshenko);
  const Mat12 ke = beam_local_stiffness(kSteel, s, L, BeamTheory::kEulerBernoulli);
  const double ct = kt.bottomRightCorner<6, 6>().inverse()(1, 1);
  const double ce = ke.bottomRightCorner<6, 6>().inverse()(1, 1);
  EXPECT_NEAR(ct, L * L * L / (3 * kSteel.E * s.Iz) + L / (kSteel.G * s.Asy), 1e-10 * ct);
  EXPECT_GT(ct / ce, 1.05);  // not negligible at this slenderness
}

TEST(BeamElement, ReleaseOfEndMomentGivesProppedStiffness) {
  // Pin at node 2 about local z: a cantilever end with rotation free has lateral stiffness 3EI/L^3
  // when node 1 is clamped, i.e. K*(uy2,uy2) = 3EI/L^3 and the released row is zero.
  const Section s = circle_section(0.02);
  const double L = 0.5;
  BeamReleases rel{};
  rel[11] = true;
  auto kc = condense_releases(beam_local_stiffness(kSteel, s, L, BeamTheory::kEulerBernoulli), rel);
  ASSERT_TRUE(kc.ok());
  EXPECT_NEAR((*kc)(7, 7), 3 * kSteel.E * s.Iz / (L * L * L), 1e-9 * (*kc)(7, 7));
  EXPECT_EQ(kc->row(11).norm(), 0.0);
  EXPECT_LT((*kc - kc->transpose()).norm(), 1e-12 * kc->norm());
  // Torsion released at both ends leaves the element free to twist: refused with a message.
  BeamReleases both{};
  both[3] = both[9] = true;
  auto bad = condense_releases(beam_local_stiffness(kSteel, s, L, BeamTheory::kEulerBernoulli), both);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("torsion"), std::string::npos);
}

// The released dofs' static shapes carry the other matrices too (condense_with_releases): a rigid
// translation moves no released rotation, so the condensed mass keeps the beam's mass rho A L along
// every axis, and the condensed K_G gives a rigid translation no force; the released rows are zero;
// with X = K it is condense_releases' matrix.
TEST(BeamElement, ReleasedShapesCondenseMassAndGeometricStiffness) {
  const Material steel{"steel", 2.1e11, 0.81e11, 7850.0};
  const Section s = circle_section(0.02);
  const double L = 0.5;
  BeamReleases rel{};
  rel[4] = rel[5] = rel[11] = true;
  const Mat12 K = beam_local_stiffness(steel, s, L, BeamTheory::kEulerBernoulli);
  const auto m = condense_with_releases(K, rel, beam_local_mass(steel, s, L, false));
  const auto g = condense_with_releases(K, rel, beam_local_geometric_stiffness(-800.0, L, 1e-4));
  const auto k = condense_with_releases(K, rel, K);
  const auto kc = condense_releases(K, rel);
  ASSERT_TRUE(m.ok() && g.ok() && k.ok() && kc.ok());
  for (int d = 0; d < 3; ++d) {
    Vec12 r = Vec12::Zero();
    r(d) = r(6 + d) = 1.0;
    EXPECT_NEAR(r.dot(*m * r), steel.density * s.A * L, 1e-12 * steel.density * s.A * L) << "axis " << d;
    EXPECT_LT((*g * r).norm(), 1e-12 * g->norm()) << "axis " << d;
  }
  for (int i : {4, 5, 11}) {
    EXPECT_EQ(m->row(i).norm(), 0.0);
    EXPECT_EQ(g->row(i).norm(), 0.0);
  }
  EXPECT_LT((*k - *kc).norm(), 1e-12 * kc->norm());
  EXPECT_LT((*m - m->transpose()).norm(), 1e-15 * m->norm());
}

TEST(Section, RectangleTorsionConstantAgainstTables) {
  // Roark/Timoshenko table: J = beta a b^3 with beta(a/b=1) = 0.1406, beta(2) = 0.229, beta(10) = 0.312.
  EXPECT_NEAR(rectangle_torsion_constant(1, 1), 0.1406, 2e-4);
  EXPECT_NEAR(rectangle_torsion_constant(1, 2) / 2.0, 0.2287, 2e-4);
  EXPECT_NEAR(rectangle_torsion_constant(10, 1) / 10.0, 0.3123, 2e-4);
  const Section c = circle_section(0.02);
  EXPECT_NEAR(c.J, std::numbers::pi * std::pow(0.02, 4) / 32, 1e-20);
}

TEST(JointElement, SpringInRotatedFrame) {
  const Mat3 R = axis_angle(Vec3(0, 0, 1), std::numbers::pi / 6);
  Vec6 k;
  k << 1e6, 2e6, 3e6, 10, 20, 0;
  const Mat12 K = joint_global_stiffness(R, k);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  // A relative displacement along the joint's local y meets stiffness ky exactly.
  Vec12 u = Vec12::Zero();
  u.segment<3>(6) = R.col(1) * 1e-3;
  const Vec12 f = K * u;
  EXPECT_NEAR(f.segment<3>(6).dot(R.col(1)), 2e6 * 1e-3, 1e-9);
  EXPECT_NEAR(f.segment<3>(6).dot(R.col(0)), 0.0, 1e-9);
  // Rotation about the joint's z axis is free (revolute).
  u.setZero();
  u.segment<3>(9) = R.col(2);
  EXPECT_NEAR((K * u).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace kinestat
