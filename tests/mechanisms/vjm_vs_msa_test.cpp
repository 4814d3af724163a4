// Cross-check of two methods: a 3D frame of beams and an elastic joint, clamped at one end, as an
// MSA structure and as a VJM chain of cantilever springs (each beam's 12x12 condensed onto its free
// end) and rigid links. For beams and linear springs the serial VJM model is exact, so the two
// Cartesian stiffness matrices at the free end must agree to round-off.
#include <gtest/gtest.h>

#include <utility>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/link_spring.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat {
namespace {

// Rigid transform that takes the current frame (axes `from`, columns in global) to `to` (same origin).
vjm::Transform reorient(const Mat3& from, const Mat3& to) {
  vjm::Transform T = vjm::Transform::Identity();
  T.linear() = from.transpose() * to;
  return T;
}

void cross_check(BeamTheory theory) {
  const Material steel = Material::from_E_nu("steel", 2.1e11, 0.3);
  const Vec3 p0(0, 0, 0), p1(0.4, 0.05, -0.1), p2(0.45, 0.35, 0.2);
  Mat3 joint_frame = axis_angle(Vec3(1, -2, 0.5), 0.7);
  Vec6 joint_k;
  joint_k << 2e7, 5e7, 8e7, 3e4, 6e4, 9e4;  // N/m, N m/rad in the joint frame

  msa::Structure s;
  const int n0 = s.add_node("base", p0), n1 = s.add_node("elbow", p1), n1b = s.add_node("elbow'", p1),
            n2 = s.add_node("tip", p2);
  const int mat = s.add_material(steel);
  Section sec1 = circle_section(0.02);
  sec1.id = "round";
  Section sec2 = rectangle_section(0.02, 0.03);
  sec2.id = "flat";
  const int s1 = s.add_section(sec1), s2 = s.add_section(sec2);
  msa::Beam b1{.id = "upper", .node1 = n0, .node2 = n1, .material = mat, .section = s1, .theory = theory};
  msa::Beam b2{.id = "lower",
               .node1 = n1b,
               .node2 = n2,
               .material = mat,
               .section = s2,
               .orientation = Vec3(0.3, 0.2, 1.0),
               .theory = theory};
  s.add_beam(b1);
  s.add_beam(b2);
  s.add_joint({.id = "elbow joint", .node1 = n1, .node2 = n1b, .frame = joint_frame, .stiffness = joint_k});
  s.add_support({.node = n0});
  msa::Workspace ws;
  StatusOr<CartesianStiffness> K_msa = msa::cartesian_stiffness(s, ws, n2);
  ASSERT_TRUE(K_msa.ok()) << K_msa.status().message();
  ASSERT_TRUE(K_msa->stiffness_defined) << K_msa->note;

  const Mat3 a1 = s.beam_axes(s.beams()[0]), a2 = s.beam_axes(s.beams()[1]);
  vjm::Chain c("frame");
  vjm::Transform base = vjm::Transform::Identity();
  base.linear() = a1;
  base.translation() = p0;
  c.add_transform(base, "base, upper beam axes");
  c.add_translation(Vec3((p1 - p0).norm(), 0, 0), "upper beam");
  c.add_spring(vjm::cantilever_spring(steel, sec1, (p1 - p0).norm(), theory), "upper beam");
  c.add_transform(reorient(a1, joint_frame), "joint frame");
  c.add_spring(joint_k.asDiagonal().toDenseMatrix(), "elbow joint");
  c.add_transform(reorient(joint_frame, a2), "lower beam axes");
  c.add_translation(Vec3((p2 - p1).norm(), 0, 0), "lower beam");
  c.add_spring(vjm::cantilever_spring(steel, sec2, (p2 - p1).norm(), theory), "lower beam");
  StatusOr<CartesianStiffness> K_vjm = vjm::unloaded_stiffness(c);
  ASSERT_TRUE(K_vjm.ok()) << K_vjm.status().message();
  ASSERT_TRUE(K_vjm->compliance_defined) << K_vjm->status.message();
  EXPECT_LT((c.nominal_pose().translation() - p2).norm(), 1e-15);

  // Relative to each matrix's largest entry; the compliance has entries from 1e-9 to 1e-4.
  const Mat6& Km = K_msa->stiffness;
  EXPECT_LT((K_vjm->stiffness - Km).cwiseAbs().maxCoeff() / Km.cwiseAbs().maxCoeff(), 1e-9);
  const Mat6& Cm = K_msa->compliance;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_NEAR(K_vjm->compliance(i, j), Cm(i, j), 1e-9 * std::sqrt(Cm(i, i) * Cm(j, j))) << i << "," << j;
}

TEST(VjmVsMsa, BeamFrameWithElasticJointEulerBernoulli) { cross_check(BeamTheory::kEulerBernoulli); }
TEST(VjmVsMsa, BeamFrameWithElasticJointTimoshenko) { cross_check(BeamTheory::kTimoshenko); }

// Released joints: the five-bar (two chains closed at P through passive revolutes) by the VJM and
// by MSA on the same inputs (mechanisms/five_bar_vjm.hpp vs make_five_bar_structure). Both models are
// exact for beams and linear springs; the 2e11 N/m joint springs next to ~1e4 N/m of link stiffness
// cost ~7 of the 16 digits, so they agree to ~1e-8 (measured: 3e-9 to 2e-8), asserted at 1e-6.
TEST(VjmVsMsa, FiveBarWithReleasedJointsAtTable1Postures) {
  const mechanisms::FiveBarParams p;
  constexpr double deg = units::kDeg;
  msa::Workspace ws;
  for (const auto& [t1, t2] : {std::pair{64.0, 75.0}, {89.0, 91.0}, {60.0, 114.0}, {70.0, 100.0}}) {
    const auto q = mechanisms::direct_kinematics(p, t1 * deg, t2 * deg, mechanisms::Assembly::kUp);
    ASSERT_TRUE(q.ok());
    const auto kv = vjm::platform_unloaded_stiffness(mechanisms::five_bar_vjm_chains(p, *q));
    ASSERT_TRUE(kv.ok()) << kv.status().message();
    const auto km =
        msa::cartesian_stiffness(mechanisms::make_five_bar_structure(p, *q), ws, mechanisms::kFiveBarPlatformNode);
    ASSERT_TRUE(km.ok() && km->stiffness_defined);
    const double scale = km->stiffness.cwiseAbs().maxCoeff();
    EXPECT_LT((kv->stiffness - km->stiffness).cwiseAbs().maxCoeff(), 1e-6 * scale) << t1 << ", " << t2;
  }
  EXPECT_EQ(ws.num_symbolic_analyses(), 1);
}

// At theta1 = theta2 (a parallel singularity) both methods lose the platform's motion along y.
TEST(VjmVsMsa, FiveBarSingularPostureLosesTheSameDirection) {
  const mechanisms::FiveBarParams p;
  constexpr double deg = units::kDeg;
  const auto q = mechanisms::direct_kinematics(p, 30 * deg, 30 * deg, mechanisms::Assembly::kUp);
  ASSERT_TRUE(q.ok());
  const auto kv = vjm::platform_unloaded_stiffness(mechanisms::five_bar_vjm_chains(p, *q));
  ASSERT_TRUE(kv.ok());
  ASSERT_EQ(kv->free_directions.size(), 1u) << kv->status.message();
  const Vec6& d = kv->free_directions[0];
  EXPECT_NEAR(std::abs(d(1)), d.head<3>().norm(), 1e-6);  // translation of P along y
  msa::Workspace ws;
  const auto km =
      msa::cartesian_stiffness(mechanisms::make_five_bar_structure(p, *q), ws, mechanisms::kFiveBarPlatformNode);
  EXPECT_EQ(km.status().code(), StatusCode::kSingular);
}

}  // namespace
}  // namespace kinestat
