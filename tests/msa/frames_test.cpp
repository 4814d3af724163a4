// Linear statics of beams and frames against closed-form solutions, reciprocity and equilibrium.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "beam_line.hpp"
#include "kinestat/core/frame.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "msa/assembly.hpp"
#include "msa/dof_map.hpp"

namespace kinestat::msa {
namespace {

// A straight beam from the origin along `dir` in `n` elements, clamped at node "0".
Structure cantilever(const Vec3& dir, double L, int n, const Section& sec,
                     BeamTheory th = BeamTheory::kEulerBernoulli) {
  Structure s = straight(L, n, sec, th, kSteel, false, dir);
  s.add_support({0, kAllDofs, Mat3::Identity()});
  return s;
}

LoadCase point_load(const std::string& name, int node, const Vec6& w) { return {name, {{node, w}}, {}}; }

TEST(Cantilever, TipDeflectionRotationAxialAndTorsion) {
  const Section sec = rectangle_section(0.02, 0.04);
  const double L = 0.8, P = 100.0, T = 5.0;
  Structure s = cantilever(Vec3::UnitX(), L, 4, sec);
  s.add_load_case(point_load("Fz", 4, (Vec6() << 0, 0, P, 0, 0, 0).finished()));
  s.add_load_case(point_load("Fx", 4, (Vec6() << P, 0, 0, 0, 0, 0).finished()));
  s.add_load_case(point_load("Mx", 4, (Vec6() << 0, 0, 0, T, 0, 0).finished()));
  s.add_load_case(point_load("Fy", 4, (Vec6() << 0, P, 0, 0, 0, 0).finished()));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const double E = kSteel.E, G = kSteel.G;
  const Vec6 tz = sol.cases[0].displacement[4];
  EXPECT_NEAR(tz(2), P * L * L * L / (3 * E * sec.Iy), 1e-10 * tz(2));
  EXPECT_NEAR(tz(4), -P * L * L / (2 * E * sec.Iy), 1e-10 * std::abs(tz(4)));
  EXPECT_NEAR(sol.cases[1].displacement[4](0), P * L / (E * sec.A), 1e-10 * P * L / (E * sec.A));
  EXPECT_NEAR(sol.cases[2].displacement[4](3), T * L / (G * sec.J), 1e-10 * T * L / (G * sec.J));
  EXPECT_NEAR(sol.cases[3].displacement[4](1), P * L * L * L / (3 * E * sec.Iz),
              1e-10 * P * L * L * L / (3 * E * sec.Iz));
  EXPECT_NEAR(sol.cases[3].displacement[4](5), P * L * L / (2 * E * sec.Iz), 1e-10 * P * L * L / (2 * E * sec.Iz));
  // Reaction at the clamp: -P and the moment P L.
  EXPECT_NEAR(sol.cases[0].reaction[0](2), -P, 1e-9 * P);
  EXPECT_NEAR(sol.cases[0].reaction[0](4), P * L, 1e-9 * P * L);
  for (const auto& c : sol.cases) {
    EXPECT_LT(c.equilibrium_error, 1e-12);
    EXPECT_LT(c.free_dof_residual, 1e-12);
  }
  // Element end forces in local axes: beam 0 carries shear P and moment P L at the clamp.
  const Vec12& f0 = sol.cases[0].beam_end_forces[0];
  EXPECT_NEAR(std::abs(f0(2)), P, 1e-9 * P);
  EXPECT_NEAR(std::abs(f0(4)), P * L, 1e-9 * P * L);
}

TEST(Cantilever, PureMomentCaseHasASmallEquilibriumError) {
  // A skew cantilever under a tip moment only: the clamp's reaction force is zero up to round-off,
  // so the error must compare the resultant with the moments, not the round-off forces with
  // themselves (which gave 1.0). The clamp's reaction moment is exactly minus the applied one.
  Structure s = cantilever(Vec3(1, 2, 3), 0.8, 5, rectangle_section(0.02, 0.04));
  const Vec3 M(0.3, -1.0, 2.0);
  s.add_load_case(point_load("M", 5, (Vec6() << 0, 0, 0, M).finished()));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const LoadCaseResult& c = sol.cases[0];
  EXPECT_LT((c.reaction[0].tail<3>() + M).norm(), 1e-9 * M.norm());
  EXPECT_LT(c.reaction[0].head<3>().norm(), 1e-9 * M.norm() / 0.8);
  EXPECT_LT(c.equilibrium_error, 1e-9);
}

TEST(Cantilever, SameAnswerInAnyDirection) {
  // A skew 3D cantilever with a load normal to it deflects by PL^3/3EI (circular section).
  const Section sec = circle_section(0.03);
  const Vec3 dir = Vec3(1, 2, 2).normalized();
  const Vec3 n = Vec3(2, -1, 0).normalized();  // normal to dir
  const double L = 1.2, P = 40.0;
  Structure s = cantilever(dir, L, 3, sec);
  s.add_load_case(point_load("P", 3, (Vec6() << P * n, Vec3::Zero()).finished()));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok());
  const Vec3 u = sol.cases[0].displacement[3].head<3>();
  EXPECT_NEAR(u.dot(n), P * L * L * L / (3 * kSteel.E * sec.Iy), 1e-9 * u.norm());
  EXPECT_NEAR(u.dot(dir), 0.0, 1e-9 * u.norm());
}

TEST(Cantilever, TimoshenkoShortBeamMatchesShearFormula) {
  const Section sec = rectangle_section(0.05, 0.05);
  const double L = 0.15, P = 1e4;
  for (auto th : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    Structure s = cantilever(Vec3::UnitX(), L, 5, sec, th);
    s.add_load_case(point_load("Fy", 5, (Vec6() << 0, P, 0, 0, 0, 0).finished()));
    const Solution sol = solve(s);
    ASSERT_TRUE(sol.status.ok());
    const double bend = P * L * L * L / (3 * kSteel.E * sec.Iz);
    const double shear = th == BeamTheory::kTimoshenko ? P * L / (kSteel.G * sec.Asy) : 0.0;
    EXPECT_NEAR(sol.cases[0].displacement[5](1), bend + shear, 1e-10 * (bend + shear));
  }
}

TEST(Frame, LShapedFrameOutOfPlaneLoad) {
  // Member a along x (clamped at the origin), member b along y from its end; tip load P along z:
  // delta = P a^3/3EI + P b^3/3EI + P b^2 a/GJ (bending of both, torsion of a by the arm b).
  const Section sec = circle_section(0.02);
  const double a = 0.6, b = 0.4, P = 30.0;
  Structure s;
  const int m = s.add_material(kSteel), c = s.add_section(sec);
  s.add_node("O", Vec3(0, 0, 0));
  s.add_node("K", Vec3(a, 0, 0));
  s.add_node("T", Vec3(a, b, 0));
  s.add_beam({"a", 0, 1, m, c});
  s.add_beam({"b", 1, 2, m, c});
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case(point_load("P", 2, (Vec6() << 0, 0, P, 0, 0, 0).finished()));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok());
  const double EI = kSteel.E * sec.Iy, GJ = kSteel.G * sec.J;
  const double expected = P * a * a * a / (3 * EI) + P * b * b * b / (3 * EI) + P * b * b * a / GJ;
  EXPECT_NEAR(sol.cases[0].displacement[2](2), expected, 1e-10 * expected);
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
}

TEST(Frame, SimplySupportedByReleasesEqualsPinnedSupports) {
  // Midspan load on a beam: PL^3/48EI, with (a) pinned supports, (b) clamps + end moment releases.
  const Section sec = circle_section(0.02);
  const double L = 1.0, P = 10.0;
  const double expected = P * L * L * L / (48 * kSteel.E * sec.Iz);
  for (int variant = 0; variant < 2; ++variant) {
    Structure s;
    const int m = s.add_material(kSteel), c = s.add_section(sec);
    s.add_node("A", Vec3(0, 0, 0));
    s.add_node("M", Vec3(L / 2, 0, 0));
    s.add_node("B", Vec3(L, 0, 0));
    Beam b1{"b1", 0, 1, m, c}, b2{"b2", 1, 2, m, c};
    if (variant == 0) {
      s.add_support({0, {true, true, true, true, false, false}, Mat3::Identity()});
      s.add_support({2, {false, true, true, false, false, false}, Mat3::Identity()});
    } else {
      b1.releases[4] = b1.releases[5] = true;    // moments free at A
      b2.releases[10] = b2.releases[11] = true;  // and at B
      // The releases disconnect the end rotations from the beam, so the support must hold them
      // (otherwise node B's ry, rz are free: the solver diagnoses exactly that).
      s.add_support({0, kAllDofs, Mat3::Identity()});
      s.add_support({2, {false, true, true, true, true, true}, Mat3::Identity()});
    }
    s.add_beam(b1);
    s.add_beam(b2);
    s.add_load_case(point_load("P", 1, (Vec6() << 0, -P, 0, 0, 0, 0).finished()));
    const Solution sol = solve(s);
    ASSERT_TRUE(sol.status.ok()) << variant << ": " << sol.status.message();
    EXPECT_NEAR(sol.cases[0].displacement[1](1), -expected, 1e-10 * expected) << variant;
    EXPECT_NEAR(sol.cases[0].reaction[0](1), P / 2, 1e-9 * P) << variant;
    if (variant == 1) {
      EXPECT_NEAR(sol.cases[0].beam_end_forces[0](5), 0.0, 1e-9);  // released moment
    }
  }
}

TEST(Frame, RigidOffsetTurnsLoadIntoTorsion) {
  // Cantilever along x with a rigid arm of length d along y at the tip; load F along z at the arm's
  // end: uz = F L^3/3EI + F d^2 L/GJ (the arm itself is rigid).
  const Section sec = circle_section(0.02);
  const double L = 0.5, d = 0.1, F = 20.0;
  Structure s = cantilever(Vec3::UnitX(), L, 2, sec);
  const int arm = s.add_node("arm", Vec3(L, d, 0));
  s.add_rigid_link({"offset", 2, arm, kAllDofs, Mat3::Identity()});
  s.add_load_case(point_load("F", arm, (Vec6() << 0, 0, F, 0, 0, 0).finished()));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const double expected = F * L * L * L / (3 * kSteel.E * sec.Iy) + F * d * d * L / (kSteel.G * sec.J);
  EXPECT_NEAR(sol.cases[0].displacement[arm](2), expected, 1e-10 * expected);
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
}

TEST(Frame, RigidJointComponentsActAsConstraints) {
  // A revolute joint with rigid translations and rigid rx, ry between the tip of a cantilever and a
  // second beam: loads along z pass through; rz is free, so the second beam needs its own support.
  const Section sec = circle_section(0.02);
  const double L = 0.5, P = 10.0;
  Structure s = cantilever(Vec3::UnitX(), L, 1, sec);
  const int j = s.add_node("j", Vec3(L, 0, 0));
  s.add_joint({"hinge", 1, j, Mat3::Identity(), (Vec6() << kRigid, kRigid, kRigid, kRigid, kRigid, 0).finished()});
  s.add_load_case(point_load("Pz", j, (Vec6() << 0, 0, P, 0, 0, 0).finished()));
  s.add_load_case(point_load("Mx", j, (Vec6() << 0, 0, 0, 1.0, 0, 0).finished()));
  const Solution sol = solve(s);
  // Node j has rz free and nothing resists it: a mechanism, and the diagnosis says so.
  ASSERT_EQ(sol.status.code(), StatusCode::kSingular);
  ASSERT_EQ(sol.singularity.modes.size(), 1u);
  const Vec6 m = sol.singularity.modes[0].node_motion[j];
  EXPECT_NEAR(std::abs(m(5)), m.norm(), 1e-9);  // only rz of node j moves
  // Add a rotational spring about z: now the tip carries the load exactly as the cantilever.
  Structure s2 = cantilever(Vec3::UnitX(), L, 1, sec);
  const int j2 = s2.add_node("j", Vec3(L, 0, 0));
  s2.add_joint({"hinge", 1, j2, Mat3::Identity(), (Vec6() << kRigid, kRigid, kRigid, kRigid, kRigid, 50.0).finished()});
  s2.add_load_case(point_load("Pz", j2, (Vec6() << 0, 0, P, 0, 0, 0).finished()));
  s2.add_load_case(point_load("Mz", j2, (Vec6() << 0, 0, 0, 0, 0, 1.0).finished()));
  const Solution sol2 = solve(s2);
  ASSERT_TRUE(sol2.status.ok()) << sol2.status.message();
  EXPECT_NEAR(sol2.cases[0].displacement[j2](2), P * L * L * L / (3 * kSteel.E * sec.Iy), 1e-10);
  // Mz on j: rotation = 1/k_spring + L/EI of the cantilever.
  EXPECT_NEAR(sol2.cases[1].displacement[j2](5), 1.0 / 50.0 + L / (kSteel.E * sec.Iz), 1e-12);
  // The joint transmits Pz through its rigid z component (constraint force read from equilibrium).
  EXPECT_NEAR(std::abs(sol2.cases[0].joint_forces[0](2)), P, 1e-9 * P);
}

TEST(Frame, CoupledJointIsItsMatrixInItsFrame) {
  // A node held to a fixed one by a joint whose 6x6 couples its components (a link's FEA spring), in a
  // turned frame: the node's displacement under W is (R6 K R6^T)^-1 W, here solved by Eigen's LDLT on
  // the 6x6, and the joint's force in its frame is K R6^T u = R6^T W.
  Mat6 A;
  A << 4, 1, 0, 0.5, 0, 0.2, 1, 5, 0.3, 0, 0.1, 0, 0, 0.3, 6, 0, 0, 0.4, 0.5, 0, 0, 3, 0.2, 0, 0, 0.1, 0, 0.2, 2, 0.3,
      0.2, 0, 0.4, 0, 0.3, 1;
  const Vec6 scale = (Vec6() << 1e7, 1e7, 1e7, 1e3, 1e3, 1e3).finished();  // N/m, N m/rad
  const Mat6 K = scale.cwiseSqrt().asDiagonal() * (A * A.transpose()) * scale.cwiseSqrt().asDiagonal();
  Mat6 coupling = K;
  coupling.diagonal().setZero();
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Structure s;
  const int g = s.add_node("g", Vec3(0.1, 0.2, 0.3)), t = s.add_node("t", Vec3(0.1, 0.2, 0.3));
  s.add_support({g, kAllDofs, Mat3::Identity()});
  s.add_joint({"link", g, t, R, K.diagonal(), coupling});
  const Vec6 W = (Vec6() << 100, -50, 80, 3, -2, 1).finished();
  s.add_load_case(point_load("W", t, W));
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const Mat6 R6 = rotation6(R);
  const Vec6 expected = (R6 * K * R6.transpose()).ldlt().solve(W);
  const Vec6& u = sol.cases[0].displacement[t];
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(u(i), expected(i), 1e-10 * expected.cwiseAbs().maxCoeff()) << i;
  const Vec6 force = R6.transpose() * W;
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(sol.cases[0].joint_forces[0](i), force(i), 1e-10 * W.norm()) << i;
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
}

TEST(Frame, SupportInRotatedFrameAndPrescribedDisplacement) {
  // A node held by an isotropic spring k to the ground and by a roller whose normal is the support's
  // local x axis at 30 degrees: a load along global x moves the node only along the roller.
  const double k = 1e5, F = 100.0, a = std::numbers::pi / 6;
  Structure s;
  s.add_node("g", Vec3(0, 0, 0));
  s.add_node("n", Vec3(0, 0, 0));
  s.add_joint({"spring", 0, 1, Mat3::Identity(), (Vec6() << k, k, k, k, k, k).finished()});
  s.add_support({0, kAllDofs, Mat3::Identity()});
  const Mat3 R = axis_angle(Vec3::UnitZ(), a);
  s.add_support({1, {true, false, false, false, false, false}, R});
  s.add_load_case(point_load("Fx", 1, (Vec6() << F, 0, 0, 0, 0, 0).finished()));
  LoadCase push{"push", {}, {{1, 0, 1e-3}}};
  s.add_load_case(push);
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const Vec3 u = sol.cases[0].displacement[1].head<3>();
  EXPECT_NEAR(u.dot(R.col(0)), 0.0, 1e-15);
  // Along the roller (local y): the load's component F sin(a) over k... F.(R y) = -F sin(a).
  EXPECT_NEAR(u.dot(R.col(1)), -F * std::sin(a) / k, 1e-12);
  // Prescribed 1 mm along local x: the support reacts with -k * 1 mm along local x (into the spring).
  const Vec3 u2 = sol.cases[1].displacement[1].head<3>();
  EXPECT_NEAR((u2 - 1e-3 * R.col(0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(sol.cases[1].reaction[1].head<3>().dot(R.col(0)), k * 1e-3, 1e-9);
  EXPECT_LT(sol.cases[1].equilibrium_error, 1e-12);
}

// A space frame (a small tower) used for the matrix-level properties below.
Structure tower() {
  Structure s;
  const int m = s.add_material(kSteel), c = s.add_section(tube_section(0.04, 0.003));
  const double h = 0.5, w = 0.4;
  int id = 0;
  for (int level = 0; level < 3; ++level)
    for (int corner = 0; corner < 4; ++corner)
      s.add_node(std::to_string(id++), Vec3(w * (corner == 1 || corner == 2), w * (corner >= 2), h * level));
  int b = 0;
  for (int level = 0; level < 3; ++level)
    for (int corner = 0; corner < 4; ++corner) {
      const int n = 4 * level + corner;
      if (level > 0) s.add_beam({fmt::format("v{}", b++), n - 4, n, m, c});
      if (level > 0) s.add_beam({fmt::format("h{}", b++), n, 4 * level + (corner + 1) % 4, m, c});
      if (level > 0 && corner == 0) s.add_beam({fmt::format("d{}", b++), n - 4, n + 1, m, c});
    }
  for (int n = 0; n < 4; ++n) s.add_support({n, kAllDofs, Mat3::Identity()});
  s.add_load_case(point_load("A", 8, (Vec6() << 100, 50, -30, 0, 0, 0).finished()));
  s.add_load_case(point_load("B", 10, (Vec6() << -20, 80, 10, 5, 0, 3).finished()));
  s.set_report_node(9);
  return s;
}

TEST(Frame, AssembledMatricesAreSymmetricAndRigidMotionIsFree) {
  const Structure s = tower();
  auto K = assemble_stiffness(s);
  ASSERT_TRUE(K.ok());
  const MatX Kd(*K);
  EXPECT_LT((Kd - Kd.transpose()).norm(), 1e-14 * Kd.norm());
  // The unsupported assembly has the six rigid-body motions as its null space.
  for (int k = 0; k < 6; ++k) {
    VecX u(s.num_dofs());
    for (size_t n = 0; n < s.nodes().size(); ++n)
      u.segment<6>(6 * n) = rigid_transfer(s.nodes()[n].position) * Vec6::Unit(k);
    EXPECT_LT((Kd * u).norm(), 1e-9 * Kd.norm() * u.norm()) << "rigid mode " << k;
  }
  auto map = build_dof_map(s);
  ASSERT_TRUE(map.ok());
  const MatX Kr = MatX(map->C.transpose() * *K * map->C);
  EXPECT_LT((Kr - Kr.transpose()).norm(), 1e-14 * Kr.norm());
  EXPECT_EQ(Kr.rows(), s.num_dofs() - 24);
}

TEST(Frame, MaxwellBettiReciprocityAndCartesianStiffness) {
  const Structure s = tower();
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  // Work of load case A on the displacements of B equals the work of B on those of A.
  const Vec6 fa = s.load_cases()[0].loads[0].wrench, fb = s.load_cases()[1].loads[0].wrench;
  const double wab = fa.dot(sol.cases[1].displacement[8]);
  const double wba = fb.dot(sol.cases[0].displacement[10]);
  EXPECT_NEAR(wab, wba, 1e-10 * std::abs(wab));
  for (const auto& c : sol.cases) EXPECT_LT(c.equilibrium_error, 1e-12);
  // The condensed 6x6 at node 9 is symmetric positive definite and inverts its compliance.
  ASSERT_TRUE(sol.cartesian && sol.cartesian->stiffness_defined);
  const Mat6& K = sol.cartesian->stiffness;
  EXPECT_LT((K - K.transpose()).norm(), 1e-9 * K.norm());
  EXPECT_LT((K * sol.cartesian->compliance - Mat6::Identity()).norm(), 1e-8);
  EXPECT_GT(sol.cartesian->indices->eigenvalues.minCoeff(), 0.0);
  // A unit load at node 9 moves node 9 by the compliance column (a second, independent route).
  Structure s2 = tower();
  s2.add_load_case(point_load("unit", 9, Vec6::Unit(1)));
  const Solution sol2 = solve(s2);
  EXPECT_LT((sol2.cases[2].displacement[9] - sol.cartesian->compliance.col(1)).norm(),
            1e-10 * sol.cartesian->compliance.col(1).norm());
}

TEST(Frame, PostureSweepReusesTheSymbolicAnalysis) {
  Workspace ws;
  for (double angle : {0.0, 0.3, 0.6, 0.9}) {
    Structure s;
    const int m = s.add_material(kSteel), c = s.add_section(circle_section(0.02));
    s.add_node("O", Vec3::Zero());
    s.add_node("A", Vec3(std::cos(angle), std::sin(angle), 0) * 0.5);
    s.add_node("B", Vec3(std::cos(angle), std::sin(angle), 0) * 0.5 + Vec3(0.3, 0, 0));
    s.add_beam({"1", 0, 1, m, c});
    s.add_beam({"2", 1, 2, m, c});
    s.add_support({0, kAllDofs, Mat3::Identity()});
    s.set_report_node(2);
    const Solution sol = solve(s, ws);
    ASSERT_TRUE(sol.status.ok());
  }
  EXPECT_EQ(ws.num_symbolic_analyses(), 1);
}

}  // namespace
}  // namespace kinestat::msa
