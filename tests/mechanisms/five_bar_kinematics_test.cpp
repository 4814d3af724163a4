// Kinematics of the 5R five-bar (Gonçalves et al. 2010, eq. (14)-(27)): checked against the
// paper's closed forms written out literally, round trips, the closure equations and finite
// differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kinestat/core/units.hpp"
#include "kinestat/mechanisms/five_bar.hpp"

namespace kinestat::mechanisms {
namespace {

using std::numbers::pi;
using units::kDeg;

// Angle difference modulo 2 pi, in [0, pi].
double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * pi)); }

// Eq. (15)-(16): both distal links have length r2.
void expect_closed(const FiveBarParams& p, const FiveBarPosture& q) {
  EXPECT_NEAR((q.P - q.B1).norm(), p.r2, 1e-12);
  EXPECT_NEAR((q.P - q.B2).norm(), p.r2, 1e-12);
  EXPECT_NEAR((q.B1 - q.A1).norm(), p.r1, 1e-12);
  EXPECT_NEAR((q.B2 - q.A2).norm(), p.r1, 1e-12);
}

// Eq. (17)-(19) as printed: theta_i = 2 atan(z_i), z_i = (-b_i +- sqrt(b_i^2 - 4 a_i c_i)) / (2 a_i).
double paper_ik_angle(const FiveBarParams& p, const Vec2& P, int leg, int sign) {
  const double u = leg == 1 ? P.x() + p.r3 : P.x() - p.r3;
  const double base = p.r1 * p.r1 + P.y() * P.y() + u * u - p.r2 * p.r2;
  const double a = base + 2.0 * u * p.r1, b = -4.0 * P.y() * p.r1, c = base - 2.0 * u * p.r1;
  return 2.0 * std::atan((-b + sign * std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a));
}

TEST(FiveBarKinematics, FourWorkingModesAreTheRootsOfEq18) {
  const FiveBarParams p;
  // Generic points (a_i != 0) of the workspace, above and below the base.
  for (const Vec2& P : {Vec2(0.03, 0.12), Vec2(-0.05, 0.08), Vec2(0.06, -0.05)}) {
    auto sols = inverse_kinematics(p, P);
    ASSERT_TRUE(sols.ok()) << sols.status().message();
    const std::array<const char*, 4> labels = {"++", "+-", "-+", "--"};
    for (int i = 0; i < 4; ++i) {
      const FiveBarPosture& q = (*sols)[i];
      EXPECT_EQ(to_string(q.working_mode), labels[i]);
      EXPECT_LT(angle_gap(q.theta1, paper_ik_angle(p, P, 1, q.working_mode.sign1)), 1e-12) << labels[i];
      EXPECT_LT(angle_gap(q.theta2, paper_ik_angle(p, P, 2, q.working_mode.sign2)), 1e-12) << labels[i];
      EXPECT_TRUE(q.P.isApprox(P));
      expect_closed(p, q);
    }
    // The two roots of each leg differ (P is not on a serial singularity).
    EXPECT_GT(angle_gap((*sols)[0].theta1, (*sols)[2].theta1), 1e-3);
    EXPECT_GT(angle_gap((*sols)[0].theta2, (*sols)[1].theta2), 1e-3);
  }
}

TEST(FiveBarKinematics, WorkingModeWhereEq18DividesByZero) {
  // a_1 = (x + r3 + r1)^2 + y^2 - r2^2 = 0: z_1 is infinite in eq. (18), theta_1 = 180 deg.
  // (With r3 = r1 = r2 such a P is out of reach of leg 2, so r3 is halved.)
  FiveBarParams p;
  p.r3 = 0.05;
  const Vec2 P = Vec2(-p.r3 - p.r1, 0.0) + p.r2 * Vec2(std::cos(1.0), std::sin(1.0));
  auto q = inverse_kinematics(p, P, WorkingMode{1, 1});
  auto q_minus = inverse_kinematics(p, P, WorkingMode{-1, 1});
  ASSERT_TRUE(q.ok() && q_minus.ok());
  const double other = std::min(angle_gap(q->theta1, pi), angle_gap(q_minus->theta1, pi));
  EXPECT_LT(other, 1e-12);  // one of the two roots is theta1 = pi
  expect_closed(p, *q);
  expect_closed(p, *q_minus);
}

TEST(FiveBarKinematics, DirectKinematicsMatchesEq22To27) {
  const FiveBarParams p;
  for (const auto& [t1, t2] : {std::pair{80.0, 100.0}, {60.0, 114.0}, {68.0, 89.0}, {120.0, 150.0}, {-60.0, -100.0}}) {
    const double c1 = std::cos(t1 * kDeg), s1 = std::sin(t1 * kDeg), c2 = std::cos(t2 * kDeg), s2 = std::sin(t2 * kDeg);
    const double den = 2.0 * p.r3 + p.r1 * c2 - p.r1 * c1;
    const double e = p.r1 * (s1 - s2) / den, f = p.r1 * p.r3 * (c2 + c1) / den;
    const double d = 1.0 + e * e;
    const double g = 2.0 * (e * f - e * p.r1 * c1 + e * p.r3 - p.r1 * s1);
    const double h =
        f * f - 2.0 * f * (p.r1 * c1 - p.r3) - 2.0 * p.r1 * p.r3 * c1 + p.r3 * p.r3 + p.r1 * p.r1 - p.r2 * p.r2;
    const double y_hi = (-g + std::sqrt(g * g - 4.0 * d * h)) / (2.0 * d);
    const double y_lo = (-g - std::sqrt(g * g - 4.0 * d * h)) / (2.0 * d);
    auto both = direct_kinematics(p, t1 * kDeg, t2 * kDeg);
    ASSERT_TRUE(both.ok()) << both.status().message();
    // x_B1 < x_B2 at these postures, so "up" is the larger y.
    const FiveBarPosture& up = (*both)[0];
    const FiveBarPosture& down = (*both)[1];
    EXPECT_EQ(up.assembly, Assembly::kUp);
    EXPECT_EQ(down.assembly, Assembly::kDown);
    EXPECT_NEAR(up.P.y(), y_hi, 1e-12);
    EXPECT_NEAR(up.P.x(), e * y_hi + f, 1e-12);
    EXPECT_NEAR(down.P.y(), y_lo, 1e-12);
    EXPECT_NEAR(down.P.x(), e * y_lo + f, 1e-12);
    expect_closed(p, up);
    expect_closed(p, down);
  }
}

TEST(FiveBarKinematics, DirectKinematicsWhereEq23DenominatorVanishes) {
  // r1 = r2 = 0.2, r3 = 0.1: 2 r3 + r1 cos t2 - r1 cos t1 = 0 at t1 = 0, t2 = 90 deg. Then
  // B1 = (0.1, 0), B2 = (0.1, 0.2): B1B2 is vertical and P = (0.1 -+ sqrt(0.03), 0.1).
  FiveBarParams p;
  p.r1 = 0.2;
  p.r2 = 0.2;
  auto both = direct_kinematics(p, 0.0, 90.0 * kDeg);
  ASSERT_TRUE(both.ok()) << both.status().message();
  EXPECT_NEAR((*both)[0].P.x(), 0.1 - std::sqrt(0.03), 1e-14);  // up: left of B1 -> B2 (+y)
  EXPECT_NEAR((*both)[0].P.y(), 0.1, 1e-14);
  EXPECT_NEAR((*both)[1].P.x(), 0.1 + std::sqrt(0.03), 1e-14);
  EXPECT_NEAR((*both)[1].P.y(), 0.1, 1e-14);
  // Each assembly mode is continuous across the vanishing denominator.
  for (int mode = 0; mode < 2; ++mode) {
    const Assembly a = mode == 0 ? Assembly::kUp : Assembly::kDown;
    auto before = direct_kinematics(p, 0.0, 90.0 * kDeg - 1e-7, a);
    auto after = direct_kinematics(p, 0.0, 90.0 * kDeg + 1e-7, a);
    ASSERT_TRUE(before.ok() && after.ok());
    EXPECT_LT((before->P - (*both)[mode].P).norm(), 1e-6);
    EXPECT_LT((after->P - (*both)[mode].P).norm(), 1e-6);
  }
}

TEST(FiveBarKinematics, RoundTripsOverAGrid) {
  const FiveBarParams p;
  int checked = 0;
  for (int i = -17; i <= 18; ++i) {
    for (int j = -17; j <= 18; ++j) {
      auto both = direct_kinematics(p, (10.0 * i + 3.0) * kDeg, (10.0 * j + 7.0) * kDeg);
      if (!both.ok()) continue;
      for (const FiveBarPosture& q : *both) {
        // Far enough from the singularities that the square roots lose no accuracy.
        const FiveBarJacobians J = five_bar_jacobians(q);
        if (J.parallel_measure < 1e-3 || J.serial_measure < 1e-3) continue;
        auto back = inverse_kinematics(p, q.P, q.working_mode);
        ASSERT_TRUE(back.ok()) << back.status().message();
        EXPECT_LT(angle_gap(back->theta1, q.theta1), 1e-10);
        EXPECT_LT(angle_gap(back->theta2, q.theta2), 1e-10);
        EXPECT_EQ(back->assembly, q.assembly);
        auto again = direct_kinematics(p, back->theta1, back->theta2, back->assembly);
        ASSERT_TRUE(again.ok());
        EXPECT_LT((again->P - q.P).norm(), 1e-12);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 500);  // the grid really covers the workspace
}

TEST(FiveBarKinematics, UnreachableInputsAreReported) {
  const FiveBarParams p;
  auto far = inverse_kinematics(p, Vec2(0.5, 0.5));
  ASSERT_FALSE(far.ok());
  EXPECT_EQ(far.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(far.status().message().find("P = (0.5, 0.5)"), std::string::npos) << far.status().message();
  EXPECT_NE(far.status().message().find("leg 1"), std::string::npos);

  // P = A1 with r1 = r2: theta1 is undetermined.
  auto at_base = inverse_kinematics(p, Vec2(-0.1, 0.0));
  ASSERT_FALSE(at_base.ok());
  EXPECT_EQ(at_base.status().code(), StatusCode::kInvalidInput);

  // Arms pointing apart: |B1B2| = 0.4 m > 2 r2 = 0.2 m.
  auto apart = direct_kinematics(p, pi, 0.0);
  ASSERT_FALSE(apart.ok());
  EXPECT_EQ(apart.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(apart.status().message().find("theta1 = 180 deg"), std::string::npos) << apart.status().message();

  // B1 = B2 = O: the platform can turn about them.
  auto folded = direct_kinematics(p, 0.0, pi);
  ASSERT_FALSE(folded.ok());
  EXPECT_EQ(folded.status().code(), StatusCode::kInvalidInput);

  FiveBarParams bad = p;
  bad.r2 = -0.1;
  auto s = direct_kinematics(bad, 1.0, 2.0);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("r2"), std::string::npos);
}

TEST(FiveBarKinematics, JacobiansMatchFiniteDifferences) {
  const FiveBarParams p;
  for (const auto& [t1, t2, a] : {std::tuple{80.0, 100.0, Assembly::kUp},
                                  {60.0, 114.0, Assembly::kUp},
                                  {64.0, 75.0, Assembly::kDown},
                                  {30.0, 100.0, Assembly::kUp}}) {
    auto q = direct_kinematics(p, t1 * kDeg, t2 * kDeg, a);
    ASSERT_TRUE(q.ok());
    const FiveBarJacobians J = five_bar_jacobians(*q);
    const double step = 1e-6;
    Mat2 dP;  // column j: dP/dtheta_j by central differences of the direct kinematics
    for (int j = 0; j < 2; ++j) {
      const double d1 = j == 0 ? step : 0.0, d2 = j == 1 ? step : 0.0;
      auto plus = direct_kinematics(p, q->theta1 + d1, q->theta2 + d2, a);
      auto minus = direct_kinematics(p, q->theta1 - d1, q->theta2 - d2, a);
      ASSERT_TRUE(plus.ok() && minus.ok());
      dP.col(j) = (plus->P - minus->P) / (2.0 * step);
    }
    // A dP/dtheta = B, scale ~ r^2 = 1e-2.
    EXPECT_LT((J.A * dP - J.B).norm(), 1e-9) << t1 << ", " << t2;
  }
}

TEST(FiveBarKinematics, EqualInputAnglesAreParallelSingular) {
  // r1 = r2 = r3: theta1 = theta2 puts B1, P, B2 on one horizontal line (|B1B2| = 2 r3 = 2 r2);
  // these are the postures of Table 1, rows 1-6.
  const FiveBarParams p;
  for (double t : {0.0, 10.0, 30.0, 60.0, 80.0, 90.0}) {
    auto q = direct_kinematics(p, t * kDeg, t * kDeg, Assembly::kUp);
    ASSERT_TRUE(q.ok()) << q.status().message();
    const FiveBarJacobians J = five_bar_jacobians(*q);
    EXPECT_TRUE(J.parallel_singular()) << t << " deg: " << J.parallel_measure;
    // At 0 deg A1, B1, P, B2, A2 all lie on the x axis: serial singular as well (Table 1 row 1).
    EXPECT_EQ(J.serial_singular(), t == 0.0) << t;
    // With the actuators locked, P is free along the normal of the aligned links: y.
    Eigen::JacobiSVD<Mat2> svd(J.A, Eigen::ComputeFullV);
    EXPECT_LT(svd.singularValues()(1), 1e-6 * svd.singularValues()(0));
    EXPECT_NEAR(std::abs(svd.matrixV()(1, 1)), 1.0, 1e-6);
  }
  // One degree apart the measure is far from zero: the classification is not a tolerance artefact.
  auto near = direct_kinematics(p, 89.0 * kDeg, 91.0 * kDeg, Assembly::kUp);
  ASSERT_TRUE(near.ok());
  EXPECT_GT(five_bar_jacobians(*near).parallel_measure, 0.3);  // 2 h |B1B2| / (2 r2^2), h = 0.0186 m
}

TEST(FiveBarKinematics, StretchedLegIsSerialSingular) {
  const FiveBarParams p;
  const Vec2 P = Vec2(-p.r3, 0.0) + (p.r1 + p.r2) * Vec2(std::cos(pi / 4), std::sin(pi / 4));
  auto q = inverse_kinematics(p, P, WorkingMode{1, 1});
  ASSERT_TRUE(q.ok()) << q.status().message();
  const FiveBarJacobians J = five_bar_jacobians(*q);
  EXPECT_TRUE(J.serial_singular()) << J.serial_measure;
  EXPECT_FALSE(J.parallel_singular());
  EXPECT_LT(std::abs(J.B(0, 0)), 1e-8 * p.r1 * p.r2);
  EXPECT_GT(std::abs(J.B(1, 1)), 1e-3 * p.r1 * p.r2);
  // Both roots of leg 1 coincide at the boundary.
  auto other = inverse_kinematics(p, P, WorkingMode{-1, 1});
  ASSERT_TRUE(other.ok());
  EXPECT_LT(angle_gap(q->theta1, other->theta1), 1e-6);
}

TEST(FiveBarModes, NamesRoundTrip) {
  for (const WorkingMode m : {WorkingMode{1, 1}, WorkingMode{1, -1}, WorkingMode{-1, 1}, WorkingMode{-1, -1}})
    EXPECT_EQ(working_mode_from_name(to_string(m)), m);
  for (const Assembly a : {Assembly::kUp, Assembly::kDown}) EXPECT_EQ(assembly_from_name(to_string(a)), a);
  for (const char* bad : {"", "+", "+x", "+++", "0+"}) EXPECT_FALSE(working_mode_from_name(bad)) << bad;
  EXPECT_FALSE(assembly_from_name("Up"));
}

}  // namespace
}  // namespace kinestat::mechanisms
