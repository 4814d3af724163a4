// Reactions at supported masters of rigid ties, against statics; an unbalanced solve fails; a node
// that nothing connects is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "beam_line.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

// A fixed, rigid link A->B (0.1 m along x), beam B->C (1 m along x), 1000 N down at C (issue 21):
// statics give the reaction force (0, 0, 1000) N at A and the moment -(C - A) x F = (0, -1100, 0) N m.
// `joint` ties B to A through a joint with rigid components in place of the rigid link.
Structure tied_cantilever(bool joint, const Vec3& pos_b = Vec3(0.1, 0, 0)) {
  Structure s;
  const int a = s.add_node("A", Vec3::Zero());
  const int b = s.add_node("B", pos_b);
  const int c = s.add_node("C", pos_b + Vec3(1.0, 0, 0));
  const int mat = s.add_material(kSteel), sec = s.add_section(rectangle_section(0.02, 0.04));
  if (joint) {
    // A and B coincide; rigid components tie B to A, the elastic one is assembled as a spring.
    Joint j;
    j.id = "J";
    j.node1 = a;
    j.node2 = b;
    j.stiffness = Vec6::Constant(kRigid);
    j.stiffness(5) = 1e4;  // an elastic component: it carries its force as a spring, not a tie
    s.add_joint(j);
  } else {
    s.add_rigid_link({.id = "AB", .master = a, .slave = b});
  }
  s.add_beam(make_beam("BC", b, c, mat, sec));
  s.add_support({a, kAllDofs, Mat3::Identity()});
  s.add_load_case({.name = "down", .loads = {{c, (Vec6() << 0, 0, -1000, 0, 0, 0).finished()}}});
  return s;
}

TEST(TieReactions, SupportedMasterOfARigidLinkCarriesTheWholeReaction) {
  const Solution sol = solve(tied_cantilever(false));
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const Vec6& r = sol.cases[0].reaction[0];
  const Vec6 expected = (Vec6() << 0, 0, 1000, 0, -1100, 0).finished();
  // Round-off of a 1e3 N, 1e3 N m answer: 1e-9 relative is ~1e4 times what it measures.
  EXPECT_LT((r - expected).norm(), 1e-9 * expected.norm()) << r.transpose();
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
}

TEST(TieReactions, SupportedMasterOfARigidJointCarriesTheWholeReaction) {
  // Coincident A and B (a joint), so the moment arm is the beam's 1 m: M = (0, -1000, 0) N m.
  const Solution sol = solve(tied_cantilever(true, Vec3::Zero()));
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const Vec6& r = sol.cases[0].reaction[0];
  const Vec6 expected = (Vec6() << 0, 0, 1000, 0, -1000, 0).finished();
  EXPECT_LT((r - expected).norm(), 1e-9 * expected.norm()) << r.transpose();
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
}

// Two cantilevers A1-B1 and A2-B2 whose tips and a node C are one rigid body: as a tree of ties (C and
// B2 slaves of B1) and as a loop (C slave of both B1 and B2: the second tie closes a loop, which
// build_dof_map eliminates as constraints after the tree). The same displacements and reactions to
// round-off (measured 4e-17 relative; bound 1e-9), and the loop's solve balances its loads.
Structure two_cantilevers(bool loop) {
  Structure s;
  const int a1 = s.add_node("A1", Vec3::Zero());
  const int a2 = s.add_node("A2", Vec3(0, 1, 0));
  const int b1 = s.add_node("B1", Vec3(1, 0, 0));
  const int b2 = s.add_node("B2", Vec3(1, 1, 0));
  const int c = s.add_node("C", Vec3(1.2, 0.5, 0.3));
  const int mat = s.add_material(kSteel), sec = s.add_section(rectangle_section(0.02, 0.04));
  s.add_beam(make_beam("A1B1", a1, b1, mat, sec));
  s.add_beam(make_beam("A2B2", a2, b2, mat, sec));
  s.add_rigid_link({.id = "B1C", .master = b1, .slave = c});
  if (loop)
    s.add_rigid_link({.id = "B2C", .master = b2, .slave = c});
  else
    s.add_rigid_link({.id = "B1B2", .master = b1, .slave = b2});
  s.add_support({a1, kAllDofs, Mat3::Identity()});
  s.add_support({a2, kAllDofs, Mat3::Identity()});
  s.add_load_case({.name = "load", .loads = {{c, (Vec6() << 100, -200, -1000, 50, 0, 30).finished()}}});
  return s;
}

TEST(TieReactions, ALoopOfTiesEqualsItsTree) {
  Structure tree_structure = two_cantilevers(false), loop_structure = two_cantilevers(true);
  // A second case: support A1 settles 1 mm and turns 1 mrad (prescribed), carried by the ties.
  for (Structure* s : {&tree_structure, &loop_structure})
    s->add_load_case({.name = "settle", .prescribed = {{0, 2, -1e-3}, {0, 3, 1e-3}}});
  const Solution tree = solve(tree_structure), loop = solve(loop_structure);
  ASSERT_TRUE(tree.status.ok()) << tree.status.message();
  ASSERT_TRUE(loop.status.ok()) << loop.status.message();
  double worst = 0.0;
  for (int c = 0; c < 2; ++c) {
    double scale_u = 0.0, scale_r = 0.0;
    for (int n = 0; n < 5; ++n) {
      scale_u = std::max(scale_u, tree.cases[c].displacement[n].norm());
      scale_r = std::max(scale_r, tree.cases[c].reaction[n].norm());
    }
    for (int n = 0; n < 5; ++n) {
      worst = std::max(worst, (loop.cases[c].displacement[n] - tree.cases[c].displacement[n]).norm() / scale_u);
      worst = std::max(worst, (loop.cases[c].reaction[n] - tree.cases[c].reaction[n]).norm() / scale_r);
    }
    EXPECT_LT(loop.cases[c].equilibrium_error, 1e-12);
  }
  EXPECT_LT(worst, 1e-9);
  std::printf("a loop of ties against its tree: %.1e relative\n", worst);
}

// A joint's rigid components carry what its slave carries, its own slaves' shares included: A joint
// A-B (coincident, rz elastic), B the master of a rigid link to D 1 m away, 1000 N down at D; the same
// joint with the load moved to B as its wrench (0, 0, -1000) N, (0, 1000, 0) N m. Equal joint forces
// (the constraint force on B was read off B alone, 0, before it took its slaves' shares).
TEST(TieReactions, AJointCarriesItsSlavesLoads) {
  const auto joint_force = [](bool at_d) {
    Structure s;
    const int a = s.add_node("A", Vec3::Zero());
    const int b = s.add_node("B", Vec3::Zero());
    const int d = s.add_node("D", Vec3(1, 0, 0));
    Joint j;
    j.id = "J";
    j.node1 = a;
    j.node2 = b;
    j.stiffness = Vec6::Constant(kRigid);
    j.stiffness(5) = 1e4;
    s.add_joint(j);
    s.add_rigid_link({.id = "BD", .master = b, .slave = d});
    s.add_support({a, kAllDofs, Mat3::Identity()});
    const Vec6 at_b = (Vec6() << 0, 0, -1000, 0, 1000, 0).finished();
    const Vec6 down = (Vec6() << 0, 0, -1000, 0, 0, 0).finished();
    s.add_load_case({.name = "load", .loads = {at_d ? NodalLoad{d, down} : NodalLoad{b, at_b}}});
    const Solution sol = solve(s);
    EXPECT_TRUE(sol.status.ok()) << sol.status.message();
    return sol.status.ok() ? sol.cases[0].joint_forces[0] : Vec6::Zero();
  };
  const Vec6 via_d = joint_force(true), at_b = joint_force(false);
  EXPECT_GT(at_b.norm(), 999.0);
  EXPECT_LT((via_d - at_b).norm(), 1e-9 * at_b.norm()) << via_d.transpose() << "\n" << at_b.transpose();
}

// A support's prescribed motion carries its tied nodes (it moved the support alone before): A fixed,
// rigid link A->B (0.1 m along x), beam B->C (1 m); A settles 10 mm down and turns 0.01 rad about
// y. The rest follows as a rigid body: u_z(x) = -0.01 - 0.01 x, r_y = 0.01, and no force.
TEST(TieReactions, APrescribedMotionCarriesTheTiedNodes) {
  Structure s = tied_cantilever(false);
  s.add_load_case({.name = "settle", .prescribed = {{0, 2, -0.01}, {0, 4, 0.01}}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const LoadCaseResult& r = sol.cases[1];
  for (int n = 0; n < 3; ++n) {
    const double x = s.nodes()[n].position.x();
    const Vec6 expected = (Vec6() << 0, 0, -0.01 - 0.01 * x, 0, 0.01, 0).finished();
    EXPECT_LT((r.displacement[n] - expected).norm(), 1e-12) << n << ": " << r.displacement[n].transpose();
  }
  EXPECT_LT(r.reaction[0].norm(), 1e-6);  // N, N m: round-off of a 1e8 N/m stiffness times 1e-14 m
}

TEST(TieReactions, AChainOfTiesCarriesTheReactionToTheSupportedEnd) {
  // A -> B -> D rigid chain (D slave of B, B slave of A), beam D -> C: reaction at A from statics.
  Structure s;
  const int a = s.add_node("A", Vec3::Zero());
  const int b = s.add_node("B", Vec3(0.1, 0, 0));
  const int d = s.add_node("D", Vec3(0.1, 0.2, 0));
  const int c = s.add_node("C", Vec3(1.1, 0.2, 0.3));
  s.add_rigid_link({.id = "AB", .master = a, .slave = b});
  s.add_rigid_link({.id = "BD", .master = b, .slave = d});
  const int mat = s.add_material(kSteel), sec = s.add_section(rectangle_section(0.02, 0.04));
  s.add_beam(make_beam("DC", d, c, mat, sec));
  s.add_support({a, kAllDofs, Mat3::Identity()});
  const Vec3 F(100, -200, -1000), M(5, 0, -7);
  s.add_load_case({.name = "skew", .loads = {{c, (Vec6() << F, M).finished()}}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  Vec6 expected;
  expected << -F, -M - s.nodes()[c].position.cross(F);
  const Vec6& r = sol.cases[0].reaction[a];
  EXPECT_LT((r - expected).norm(), 1e-9 * expected.norm()) << r.transpose();
}

TEST(TieReactions, ANodeThatNothingConnectsIsNamed) {
  Structure s = tied_cantilever(false);
  s.add_node("E", Vec3(5, 5, 5), "frame.yaml:9");
  const Solution sol = solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kInvalidInput);
  EXPECT_NE(sol.status.message().find("frame.yaml:9: node 'E' is connected to no beam, joint or rigid link"),
            std::string::npos)
      << sol.status.message();
  // Fully supported, an unconnected node is harmless.
  Structure t = tied_cantilever(false);
  t.add_support({t.add_node("E", Vec3(5, 5, 5)), kAllDofs, Mat3::Identity()});
  EXPECT_TRUE(solve(t).status.ok());
}

TEST(TieReactions, NodesAndALoadButNoElementIsNamedNotACholmodFailure) {
  Structure s;
  s.add_node("A", Vec3::Zero());
  s.add_node("B", Vec3(1, 0, 0), "frame.yaml:4");
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case({.name = "push", .loads = {{1, (Vec6() << 1, 0, 0, 0, 0, 0).finished()}}});
  const Solution sol = solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kInvalidInput);
  EXPECT_NE(sol.status.message().find("node 'B' is connected to no beam"), std::string::npos) << sol.status.message();
}

TEST(TieReactions, AnUnbalancedSolveIsAnErrorNotAResult) {
  // The check itself: with a bound below this case's round-off (a skew load gives a nonzero error,
  // printed on failure) the solve must fail, naming the case, and give no result.
  SolveOptions opt;
  opt.max_equilibrium_error = 1e-300;
  Structure s = tied_cantilever(false);
  s.add_load_case({.name = "moment", .loads = {{2, (Vec6() << 0, 3, -1000, 1, 2, 3).finished()}}});
  const Solution sol = solve(s, opt);
  ASSERT_EQ(sol.status.code(), StatusCode::kInternal) << solve(s).cases[1].equilibrium_error;
  EXPECT_NE(sol.status.message().find("loads and reactions do not balance"), std::string::npos) << sol.status.message();
}

}  // namespace
}  // namespace kinestat::msa
