// Loaded mode: equilibrium (eq. 11-15, Newton fallback) and loaded stiffness (eq. 19-21), against
// the closed form of a loaded pendulum, finite differences of the equilibrium, and first-order
// linear statics for small wrenches.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "vjm_test_chains.hpp"

namespace kinestat::vjm {
namespace {

using test_chains::eq1_chain;
using test_chains::pendulum;
using test_chains::steel;

constexpr double kK = 200.0, kKa = 1e5, kL = 0.5;  // N m/rad, N/m, m

// Force on the pendulum tip held at (X, Y): L = |(X, Y)|, phi = atan2(Y, X). Statics by hand: the
// axial spring carries ka (L - l) along the link, the base spring k phi = L F_t.
Vec3 pendulum_force(double X, double Y) {
  const double L = std::hypot(X, Y), phi = std::atan2(Y, X);
  const Vec3 er(std::cos(phi), std::sin(phi), 0), et(-std::sin(phi), std::cos(phi), 0);
  return kKa * (L - kL) * er + kK * phi / L * et;
}

TEST(VjmLoaded, PendulumUnderAxialLoadHasClosedFormStiffness) {
  // Tip pulled (d > 0) or pushed (d < 0) along the link: F = ka d, and the tangential stiffness is
  // k / L^2 +- F / L with L = l + d (energy of the spring pair, second derivative in y).
  for (double d : {2e-3, -2e-3}) {
    const Chain c = pendulum(kK, kKa, kL);
    StatusOr<ChainState> s = chain_equilibrium(c, (Vec6() << d, 0, 0, 0, 0, 0).finished());
    ASSERT_TRUE(s.ok()) << s.status().message();
    const double F = kKa * d, L = kL + d;
    EXPECT_NEAR(s->wrench[0], F, 1e-9 * std::abs(F));
    EXPECT_LT(s->wrench.tail<5>().norm(), 1e-9 * std::abs(F));
    StatusOr<CartesianStiffness> K = loaded_stiffness(c, *s);
    ASSERT_TRUE(K.ok()) << K.status().message();
    EXPECT_NEAR(K->stiffness(1, 1), kK / (L * L) + F / L, 1e-9 * kK / (L * L));
    EXPECT_NEAR(K->stiffness(0, 0), kKa, 1e-9 * kKa);
    EXPECT_NEAR(K->stiffness(0, 1), 0.0, 1e-9 * kKa);
    EXPECT_EQ(K->rigid_directions.size(), 3u);
    // The paper's iteration suffices at this load.
    EXPECT_EQ(s->report.newton_iterations, 0);
    EXPECT_TRUE(s->report.converged);
  }
}

TEST(VjmLoaded, NewtonTakesOverBeyondTheBucklingLoad) {
  // Two-link column: base spring k1, link l, spring k2, link l, axial spring ka, pin at the tip; the
  // tip held at (X, Y) leaves one internal mode (the middle joint moving sideways) whose stiffness
  // (k1 + 4 k2) / l^2 competes with the load's -2P / l: critical load P = (k1 + 4 k2) / (2 l) = 2000 N.
  // At P ~ 4000 N, eq. (15), which ignores the load's geometric stiffness, is repelled from the
  // equilibrium (contraction factor ~ 2); the full Newton-Raphson finds it.
  const double k1 = 200, k2 = 200, l = 0.25, ka = 1e6;
  Chain c("column");
  c.add_actuator(JointType::kRevolute, Vec3::UnitZ(), 0.0, k1, "base spring");
  c.add_translation(Vec3(l, 0, 0), "link 1");
  c.add_actuator(JointType::kRevolute, Vec3::UnitZ(), 0.0, k2, "middle spring");
  c.add_translation(Vec3(l, 0, 0), "link 2");
  c.add_actuator(JointType::kPrismatic, Vec3::UnitX(), 0.0, ka, "axial spring");
  c.add_passive(JointType::kRevolute, Vec3::UnitZ(), 0.0, "tip pin");
  StatusOr<ChainState> s = chain_equilibrium(c, (Vec6() << -4e-3, 1e-3, 0, 0, 0, 0).finished());
  ASSERT_TRUE(s.ok()) << s.status().message();
  EXPECT_GT(s->report.newton_iterations, 0) << s->report.summary();
  EXPECT_GT(s->report.fixed_point_iterations, 0) << s->report.summary();
  // Hand statics at the solved configuration: spring torques balance the moment of the tip force
  // about each spring's axis, the axial spring the force along link 2.
  const double phi1 = s->theta[0], phi2 = s->theta[1], ext = s->theta[2];
  const Vec3 joint2 = l * Vec3(std::cos(phi1), std::sin(phi1), 0);
  const Vec3 e2(std::cos(phi1 + phi2), std::sin(phi1 + phi2), 0);
  const Vec3 tip = joint2 + (l + ext) * e2, F = s->wrench.head<3>();
  EXPECT_NEAR(tip.cross(F).z(), k1 * phi1, 1e-9 * F.norm() * l);
  EXPECT_NEAR((tip - joint2).cross(F).z(), k2 * phi2, 1e-9 * F.norm() * l);
  EXPECT_NEAR(F.dot(e2), ka * ext, 1e-9 * F.norm());
  EXPECT_GT(F.norm(), 3000.0);  // really beyond the critical load
}

// Central finite differences of the loaded equilibrium: column j of dF/dt.
Mat6 fd_stiffness(const std::vector<Chain>& chains, const Vec6& dt0) {
  const double h = 1e-6;  // m and rad
  Mat6 K;
  for (int j = 0; j < 6; ++j) {
    Vec6 e = Vec6::Zero();
    e[j] = h;
    // A step of the tool twist composed with dt0 (as the stiffness defines it), not dt0 + e.
    const Transform T0 = chains[0].nominal_pose();
    const Transform Td = displace(T0, dt0);
    StatusOr<PlatformState> p = platform_equilibrium(chains, pose_difference(displace(Td, e), T0));
    StatusOr<PlatformState> m = platform_equilibrium(chains, pose_difference(displace(Td, -e), T0));
    EXPECT_TRUE(p.ok() && m.ok());
    K.col(j) = (p->wrench - m->wrench) / (2 * h);
  }
  return K;
}

// Max entry error after scaling translations by the chain length (K~ = W^-1 K W^-1), relative
// to the largest scaled entry: makes N/m, N and N m/rad entries comparable.
double scaled_error(const Mat6& A, const Mat6& B, double L) {
  Vec6 s;
  s << L, L, L, 1, 1, 1;
  const Mat6 D = s.asDiagonal() * (A - B) * s.asDiagonal(), R = s.asDiagonal() * B * s.asDiagonal();
  return D.cwiseAbs().maxCoeff() / R.cwiseAbs().maxCoeff();
}

TEST(VjmLoaded, LoadedStiffnessEqualsFiniteDifferenceOfEquilibrium) {
  // Eq.-(1) chains at a loaded pose that includes a rotation. With U joints at both leg ends the
  // chain carries a moment, so K^F is asymmetric and eq. (21) must still be dF/dt exactly; with an
  // S joint at the tool point it carries a pure force and K^F is symmetric.
  const Vec6 dt0 = (Vec6() << 1.5e-4, -1e-4, 2e-4, 2e-4, -1e-4, 3e-4).finished();
  for (bool sph : {false, true}) {
    const std::vector<Chain> one = {eq1_chain(sph)};
    const double L = one[0].length_scale();
    StatusOr<PlatformState> s = platform_equilibrium(one, dt0);
    ASSERT_TRUE(s.ok()) << s.status().message();
    StatusOr<CartesianStiffness> K = platform_loaded_stiffness(one, *s);
    ASSERT_TRUE(K.ok()) << K.status().message();
    const Mat6 Kfd = fd_stiffness(one, dt0);
    EXPECT_LT(scaled_error(K->stiffness, Kfd, L), 1e-6) << "spherical end: " << sph << "\n"
                                                        << K->stiffness << "\n\n"
                                                        << Kfd;
    // The load changes the stiffness by much more than the tolerance (the test can fail).
    StatusOr<CartesianStiffness> K0 = platform_unloaded_stiffness(one);
    EXPECT_GT(scaled_error(K->stiffness, K0->stiffness, L), 1e-4);
    const double asym = scaled_error(K->stiffness, K->stiffness.transpose(), L);
    if (sph) {
      EXPECT_LT(s->wrench.tail<3>().norm(), 1e-9 * s->wrench.head<3>().norm() * L);
      EXPECT_LT(asym, 1e-10);
    } else {
      EXPECT_GT(std::abs(s->wrench.tail<3>().norm()), 1e-3 * s->wrench.head<3>().norm() * L);
      EXPECT_GT(asym, 1e-6);
    }
  }
}

TEST(VjmLoaded, LoadedAtZeroLoadEqualsUnloaded) {
  // Eq. (21) with F = 0 reduces to eq. (9); the two are computed by different eliminations.
  const Chain c = eq1_chain(false);
  StatusOr<ChainState> s = chain_equilibrium(c, Vec6::Zero());
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->report.fixed_point_iterations + s->report.newton_iterations, 0);
  StatusOr<CartesianStiffness> K = loaded_stiffness(c, *s), K0 = unloaded_stiffness(c);
  ASSERT_TRUE(K.ok() && K0.ok());
  EXPECT_LT(scaled_error(K->stiffness, K0->stiffness, c.length_scale()), 1e-10);
}

TEST(VjmLoaded, PendulumUnderAPrescribedWrenchSatisfiesHandStatics) {
  // Fz acts along a rigid direction: a reaction, no motion. The in-plane force deflects the
  // pendulum; the solved tip position must satisfy the hand-derived statics exactly.
  const std::vector<Chain> c = {pendulum(kK, kKa, kL)};
  const Vec6 W = (Vec6() << 300.0, 50.0, 20.0, 0, 0, 0).finished();
  StatusOr<PlatformState> s = platform_equilibrium_under_wrench(c, W);
  ASSERT_TRUE(s.ok()) << s.status().message();
  EXPECT_TRUE(s->report.converged);
  const Vec6 d = s->displacement;
  EXPECT_NEAR(d[2], 0.0, 1e-15);
  EXPECT_GT(std::abs(d[1]), 1e-2);  // a large deflection (phi ~ L F_y / (k - ...)), not a linear one
  const Vec3 F = pendulum_force(kL + d[0], d[1]);
  EXPECT_LT((F - W.head<3>() + Vec3(0, 0, W[2])).norm(), 1e-9 * W.norm()) << F.transpose();
}

// Pendulum at angle phi0: base spring k about z, link l, axial spring ka along the link (ka = +inf:
// a rigid link, no spring), pin about z at the tip (the tool point).
Chain swung_pendulum(double k, double l, double phi0, double ka) {
  Chain c("pendulum");
  c.add_actuator(JointType::kRevolute, Vec3::UnitZ(), phi0, k, "base spring");
  c.add_translation(Vec3(l, 0, 0), "link");
  c.add_actuator(JointType::kPrismatic, Vec3::UnitX(), 0.0, ka, "axial spring");
  c.add_passive(JointType::kRevolute, Vec3::UnitZ(), 0.0, "tip pin");
  return c;
}

TEST(VjmLoaded, ReactionAlongARigidLinkEntersTheLoadedStiffness) {
  // A force F along an exactly rigid link is a reaction: nothing deflects, but the pulled (pushed)
  // link stiffens (softens) the tangential motion: K_tt = k / l^2 + F / l (the tip force's work on
  // the swinging link). The same chain with a very stiff axial spring (ka = 1e12 N/m) is its limit.
  // The link at phi0 = 0.4 rad makes the rigid direction non-axial.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const double phi0 : {0.0, 0.4}) {
    for (const double F : {100.0, -100.0}) {
      SCOPED_TRACE(testing::Message() << "phi0 = " << phi0 << ", F = " << F);
      const Vec3 er(std::cos(phi0), std::sin(phi0), 0), et(-std::sin(phi0), std::cos(phi0), 0);
      const Vec6 W = (Vec6() << F * er, 0, 0, 0).finished();
      const double Ktt = kK / (kL * kL) + F / kL;
      const Vec6 t = (Vec6() << et, 0, 0, 0).finished();
      for (const double ka : {kInf, 1e12}) {
        const std::vector<Chain> c = {swung_pendulum(kK, kL, phi0, ka)};
        StatusOr<PlatformState> s = platform_equilibrium_under_wrench(c, W);
        ASSERT_TRUE(s.ok()) << "ka = " << ka << ": " << s.status().message();
        // The chain carries the whole wrench, reaction included (J^T F = K theta still holds); the
        // stiff spring's pose is known to ~eps, i.e. its force to ~eps ka l.
        const double tol = std::isinf(ka) ? 1e-12 : 1e-6;
        EXPECT_LT((s->chains[0].wrench - W).norm(), tol * W.norm());
        EXPECT_LT(std::abs(s->displacement.head<3>().dot(et)), tol * kL);  // no swing
        StatusOr<CartesianStiffness> K = platform_loaded_stiffness(c, *s);
        ASSERT_TRUE(K.ok()) << K.status().message();
        EXPECT_NEAR(t.dot(K->stiffness * t), Ktt, (std::isinf(ka) ? 1e-9 : 1e-6) * Ktt) << "ka = " << ka;
      }
      // The unloaded value differs by far more than the tolerance (the test can fail).
      EXPECT_GT(std::abs(Ktt - kK / (kL * kL)), 0.1 * Ktt);
    }
  }
}

TEST(VjmLoaded, WrenchOnAFreeDirectionIsRefused) {
  const std::vector<Chain> c = {pendulum(kK, kKa, kL)};
  const StatusOr<PlatformState> s = platform_equilibrium_under_wrench(c, (Vec6() << 0, 0, 0, 0, 0, 1.0).finished());
  EXPECT_EQ(s.status().code(), StatusCode::kSingular);
  EXPECT_NE(s.status().message().find("rotation about +z"), std::string::npos) << s.status().message();
}

// Three legs of length 0.25 m with spring Kleg at their far ends, meeting at a point.
std::vector<Chain> three_legs(const Mat6& Kleg) {
  std::vector<Chain> legs;
  for (int i = 0; i < 3; ++i) {
    const Vec3 dir = Vec3(std::cos(2.1 * i), std::sin(2.1 * i), 0.5).normalized();
    const Mat3 R = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), -dir).toRotationMatrix();
    Chain c("leg " + std::to_string(i));
    c.add_translation(0.25 * dir, "base");
    c.add_transform(Transform(R), "leg axis");
    c.add_translation(Vec3(0.25, 0, 0), "leg");
    c.add_spring(Kleg, "leg spring");
    legs.push_back(c);
  }
  return legs;
}

TEST(VjmLoaded, SmallWrenchGivesLinearCompliance) {
  // Three elastic legs meeting at a point: for a small wrench the displacement is C W to first order
  // (relative error of the order of the strain, ~1e-6 here).
  const std::vector<Chain> legs =
      three_legs(cantilever_spring(steel(), circle_section(0.01), 0.25, BeamTheory::kEulerBernoulli));
  const Vec6 W = (Vec6() << 10.0, -5.0, 8.0, 0.2, 0.1, -0.3).finished();
  StatusOr<PlatformState> s = platform_equilibrium_under_wrench(legs, W);
  ASSERT_TRUE(s.ok()) << s.status().message();
  StatusOr<CartesianStiffness> K0 = platform_unloaded_stiffness(legs);
  const Vec6 lin = K0->compliance * W;
  EXPECT_LT((s->displacement - lin).norm(), 1e-4 * lin.norm());
  EXPECT_GT((s->displacement - lin).norm(), 0.0);
  EXPECT_LT((s->wrench - W).norm(), 1e-10 * W.norm());
}

TEST(VjmLoaded, VeryStiffSpringsConvergeUnderAWrench) {
  // Springs of 1e9 in mm-N units (1e12 N/m, 1e6 N m/rad): a leg's wrench is K times a pose known to
  // ~eps, so the wrench residual cannot go below ~eps K l ~ 1e-5 N, whatever the load; a fixed
  // tolerance (1e-10 of the load) is out of reach. And a chain whose tool is displaced by ~1e-10 m
  // must not count a 1e-12 m pose error (1 N here) as converged.
  Vec6 k;
  k << 1e12, 1e12, 1e12, 1e6, 1e6, 1e6;
  const std::vector<Chain> legs = three_legs(k.asDiagonal());
  for (const double scale : {100.0, 2000.0}) {
    const Vec6 W = scale * (Vec6() << 1.0, -0.5, 0.8, 0.02, 0.01, -0.03).finished();
    StatusOr<PlatformState> s = platform_equilibrium_under_wrench(legs, W);
    ASSERT_TRUE(s.ok()) << s.status().message();
    EXPECT_TRUE(s->report.converged);
    // Displacements ~1e-10 m and rotations ~1e-5 rad: linear statics holds to ~1e-6.
    StatusOr<CartesianStiffness> K0 = platform_unloaded_stiffness(legs);
    const Vec6 lin = K0->compliance * W;
    EXPECT_LT((s->displacement - lin).norm(), 1e-5 * lin.norm()) << s->displacement.transpose() << "\n"
                                                                 << lin.transpose();
    Vec6 sum = Vec6::Zero();
    for (const ChainState& c : s->chains) sum += c.wrench;
    EXPECT_LT((sum - W).norm(), 1e-5 * W.norm()) << s->report.summary() << "\n"
                                                 << sum.transpose() << "\n"
                                                 << s->displacement.transpose();
  }
}

}  // namespace
}  // namespace kinestat::vjm
