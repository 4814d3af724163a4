// Singular structures are diagnosed in words (which nodes and dofs move freely, and how), never solved
// into garbage.
#include <gtest/gtest.h>

#include <algorithm>

#include "beam_line.hpp"
#include "kinestat/msa/singularity.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

// Cantilever O-A (0.5 m along x, clamped at O), a joint A-A' with `joint` stiffness (global frame),
// and a beam A'-B hanging from it; a unit load along z at B.
Structure hinged_chain(const Vec3& b, const Vec6& joint) {
  Structure s;
  const int m = s.add_material(kSteel), c = s.add_section(circle_section(0.02));
  s.add_node("O", Vec3(0, 0, 0));
  s.add_node("A", Vec3(0.5, 0, 0));
  s.add_node("A'", Vec3(0.5, 0, 0));
  s.add_node("B", b);
  s.add_beam(make_beam("OA", 0, 1, m, c));
  s.add_beam(make_beam("AB", 2, 3, m, c));
  s.add_joint({"joint", 1, 2, Mat3::Identity(), joint});
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case({"Fz", {{3, Vec6::Unit(2)}}, {}});
  return s;
}

// The six rigid-body motions of `nodes` in the canonical basis about point c: mode k < 3 translates
// every node along axis k, mode 3 + k rotates them about axis k through c.
void expect_canonical_rigid_modes(const Structure& s, const std::vector<FreeMotion>& modes, size_t first,
                                  const std::vector<int>& nodes, const Vec3& c) {
  ASSERT_GE(modes.size(), first + 6);
  for (int k = 0; k < 6; ++k) {
    const FreeMotion& fm = modes[first + k];
    EXPECT_LT(fm.rayleigh_ratio, 1e-12) << k;
    const Vec3 e = Vec3::Unit(k % 3);
    for (int n = 0; n < static_cast<int>(s.nodes().size()); ++n) {
      Vec6 expected = Vec6::Zero();
      if (std::find(nodes.begin(), nodes.end(), n) != nodes.end()) {
        if (k < 3)
          expected.head<3>() = e;
        else
          expected << e.cross(s.nodes()[n].position - c), e;
      }
      EXPECT_LT((fm.node_motion[n] - expected).norm(), 1e-12) << "mode " << k << " node " << n;
    }
  }
}

TEST(Singularity, UnsupportedFrameHasSixRigidBodyMotions) {
  Structure s;
  const int m = s.add_material(kSteel), c = s.add_section(circle_section(0.02));
  s.add_node("a", Vec3(0, 0, 0));
  s.add_node("b", Vec3(1, 0, 0));
  s.add_node("c", Vec3(1, 1, 0));
  s.add_beam(make_beam("ab", 0, 1, m, c));
  s.add_beam(make_beam("bc", 1, 2, m, c));
  s.add_load_case({"F", {{2, Vec6::Unit(0)}}, {}});
  const Solution sol = solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kSingular);
  EXPECT_TRUE(sol.cases.empty());  // no numbers from a singular matrix
  const std::string& msg = sol.status.message();
  EXPECT_NE(msg.find("The model has no supports: it moves as a rigid body (3 translations, 3 rotations)"),
            std::string::npos)
      << msg;
  // Exactly the six motions, in the canonical basis about the centroid (2/3, 1/3, 0) m, in words.
  EXPECT_EQ(sol.singularity.modes.size(), 6u);
  expect_canonical_rigid_modes(s, sol.singularity.modes, 0, {0, 1, 2}, Vec3(2.0 / 3, 1.0 / 3, 0));
  EXPECT_NE(msg.find("free motion 1 (rigid body"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the whole model translates along +x"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the whole model rotates about +z through (0.666667, 0.333333, 0) m"), std::string::npos) << msg;
}

TEST(Singularity, PartCutLooseIsNamedWithItsRigidBodyMotions) {
  // The joint A-A' has no stiffness at all: A'-B is not connected to the clamped cantilever O-A.
  const Structure s = hinged_chain(Vec3(0.5, 0.4, 0), Vec6::Zero());
  const Solution sol = solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kSingular);
  const std::string& msg = sol.status.message();
  EXPECT_NE(msg.find("Nodes {'A'', 'B'} are not connected to any support: they move as a rigid body"),
            std::string::npos)
      << msg;
  EXPECT_EQ(msg.find("no supports"), std::string::npos) << msg;
  EXPECT_EQ(sol.singularity.modes.size(), 6u);
  expect_canonical_rigid_modes(s, sol.singularity.modes, 0, {2, 3}, Vec3(0.5, 0.2, 0));
  EXPECT_NE(msg.find("nodes {'A'', 'B'} rotate about +x through (0.5, 0.2, 0) m"), std::string::npos) << msg;

  // A loose part next to a mechanism: its six motions first, then the hinge's three swings (found
  // in the rest of the near-null space), in which the loose beam C-D does not move.
  Structure s2 = hinged_chain(Vec3(0.5, 0.4, 0), (Vec6() << 1e10, 1e10, 1e10, 0, 0, 0).finished());
  const int cd_c = s2.add_node("C", Vec3(0, 1, 1)), cd_d = s2.add_node("D", Vec3(0, 2, 1));
  s2.add_beam(make_beam("CD", cd_c, cd_d, 0, 0));
  const Solution sol2 = solve(s2);
  ASSERT_EQ(sol2.status.code(), StatusCode::kSingular);
  ASSERT_EQ(sol2.singularity.modes.size(), 9u) << sol2.status.message();
  expect_canonical_rigid_modes(s2, sol2.singularity.modes, 0, {cd_c, cd_d}, Vec3(0, 1.5, 1));
  for (size_t k = 6; k < 9; ++k) {
    const FreeMotion& fm = sol2.singularity.modes[k];
    EXPECT_LT(fm.rayleigh_ratio, 1e-12);
    EXPECT_LT(fm.node_motion[cd_c].norm() + fm.node_motion[cd_d].norm(), 1e-9);
    EXPECT_GT(fm.node_motion[3].norm(), 0.1);  // B swings
    EXPECT_LT(fm.node_motion[0].norm(), 1e-9);
  }
  EXPECT_NE(sol2.status.message().find("Nodes {'C', 'D'} are not connected to any support"), std::string::npos);
}

TEST(Singularity, ReleasedChainSwingsAboutItsHinge) {
  // Cantilever O-A, then a spherical joint at A (all rotations released) and a beam A'-B hanging
  // free: A'-B can rotate about A in all three directions, including about its own axis.
  const Structure s = hinged_chain(Vec3(0.5, 0.4, 0), (Vec6() << 1e10, 1e10, 1e10, 0, 0, 0).finished());
  const Solution sol = solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kSingular);
  ASSERT_EQ(sol.singularity.modes.size(), 3u);
  for (const auto& fm : sol.singularity.modes) {
    // Nodes O and A do not take part in any free motion.
    EXPECT_LT(fm.node_motion[0].norm(), 1e-6);
    EXPECT_LT(fm.node_motion[1].head<3>().norm(), 1e-6);
    // A' rotates without translating: the hinge holds it.
    EXPECT_LT(fm.node_motion[2].head<3>().norm(), 1e-6);
  }
  EXPECT_NE(sol.status.message().find("node 'B'"), std::string::npos) << sol.status.message();
  // Holding B along z stops the rotation about x; the spin about A'B's own axis (y) and the swing
  // about z (B moving along x) stay free.
  Structure s2 = s;
  s2.add_support({3, {false, false, true, false, false, false}, Mat3::Identity()});
  const Solution sol2 = solve(s2);
  ASSERT_EQ(sol2.status.code(), StatusCode::kSingular);
  ASSERT_EQ(sol2.singularity.modes.size(), 2u);
  for (const auto& fm : sol2.singularity.modes) {
    EXPECT_LT(std::abs(fm.node_motion[3](2)), 1e-9);  // B no longer moves along z
    EXPECT_LT(std::abs(fm.node_motion[2](3)), 1e-9);  // nor does A'B rotate about x
  }
}

TEST(Singularity, RegularizedAnswerIsMarked) {
  // Hinge about z: B can swing in the x-y plane.
  const Structure s = hinged_chain(Vec3(1.0, 0, 0), (Vec6() << 1e10, 1e10, 1e10, 1e10, 1e10, 0).finished());
  SolveOptions opt;
  opt.regularize = true;
  const Solution sol = solve(s, opt);
  EXPECT_EQ(sol.status.code(), StatusCode::kSingular);
  EXPECT_TRUE(sol.regularized);
  EXPECT_NE(sol.status.message().find("REGULARIZED"), std::string::npos);
  ASSERT_EQ(sol.cases.size(), 1u);
  // Along z nothing is free: two cantilevers in series (L = 0.5 each) joined by the hinge's springs
  // (1e10 N/m along z, 1e10 N m/rad about y): uz(B) = F (2L)^3/3EI + F/kt + F L^2/kr.
  // The regularization (1e-10 x diag K) perturbs every dof by ~1e-10 x (stiffest/softest term), here
  // a few 1e-4: the answer is marked as regularized for that reason.
  const double EI = kSteel.E * circle_section(0.02).Iy;
  const double exact = 1.0 / (3 * EI) + 1.0 / 1e10 + 0.25 / 1e10;
  EXPECT_NEAR(sol.cases[0].displacement[3](2), exact, 1e-3 * exact);
  ASSERT_EQ(sol.singularity.modes.size(), 1u);
  const Vec6 mb = sol.singularity.modes[0].node_motion[3];
  EXPECT_NEAR(std::abs(mb(1)), mb.head<3>().norm(), 1e-9);  // B moves along y only
  EXPECT_NE(sol.singularity.modes[0].description.find("node 'B' translates along +y"), std::string::npos)
      << sol.singularity.modes[0].description;
}

TEST(Singularity, DescribesMotionInWords) {
  Vec6 m;
  m << 0, 1, 0, 0, 0, 0;
  EXPECT_EQ(describe_node_motion(m, 1.0), "translates along +y (1)");
  m << 0, 0, 0, 0, 0, -2;
  EXPECT_EQ(describe_node_motion(m, 1.0), "rotates about -z (2 rad)");
}

}  // namespace
}  // namespace kinestat::msa
