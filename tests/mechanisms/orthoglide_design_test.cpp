// Orthoglide design strategies (Pashkevich, Wenger, Chablat 2005, sections 3.2-6): Q-axis, critical
// points Q, R, S against SVD at the same point and against a numerical search over the whole
// workspace, the printed numbers of sections 5.2 and 6, Table 4 and the prototype.
//
// Tolerances follow the printed precision: half a unit of the last printed digit (4 decimals in
// sections 5.2 and 6, 3 in Table 4, 0.1 mm for the prototype), plus 1e-9 for floating point.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "kinestat/mechanisms/orthoglide_design.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr double kDigits4 = 0.5e-4 + 1e-9;
constexpr double kDigits3 = 0.5e-3 + 1e-9;
constexpr double kDigits2 = 0.5e-2 + 1e-9;
const OrthoglideGeometry kUnit{1.0};
constexpr double kInf = std::numeric_limits<double>::infinity();

// Root of f on [a, b] (f(a), f(b) of opposite signs) by bisection.
double bisect(const std::function<double(double)>& f, double a, double b) {
  const bool fa_positive = f(a) > 0.0;
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b);
    ((f(m) > 0.0) == fa_positive ? a : b) = m;
  }
  return 0.5 * (a + b);
}

Vec3 svd_singular_values_at(const Vec3& p) {
  const Vec3 rho = *inverse_kinematics(kUnit, p);
  return velocity_transmission(*inverse_jacobian(p, rho)).singular_values;
}

TEST(OrthoglideDesign, QAxisTable1) {
  // Table 1: P1 (chi = 1), O (0), P2 (-1/2), P3 (-1).
  struct Row {
    double chi, p, rho;
  };
  for (const Row& r :
       {Row{1.0, -std::sqrt(1.0 / 3), 0.0}, Row{0.0, 0.0, 1.0}, Row{-0.5, std::sqrt(1.0 / 6), std::sqrt(1.5)},
        Row{-1.0, std::sqrt(1.0 / 3), std::sqrt(4.0 / 3)}}) {
    EXPECT_NEAR(unit_q_axis_position(r.chi), r.p, 1e-15);
    EXPECT_NEAR(unit_q_axis_joint(r.chi), r.rho, 1e-15);
  }
  for (double chi : {-0.45, -0.2, 0.0, 0.3, 0.6, 0.95}) {
    const double p = unit_q_axis_position(chi), rho = unit_q_axis_joint(chi);
    EXPECT_NEAR(unit_q_axis_chi_from_position(p), chi, 1e-14);
    EXPECT_NEAR(unit_q_axis_chi_from_joint(rho), chi, 1e-14);
    EXPECT_NEAR((*inverse_kinematics(kUnit, Vec3::Constant(p)) - Vec3::Constant(rho)).norm(), 0.0, 1e-15);
  }
  EXPECT_NEAR(unit_q_axis_chi_from_joint(std::sqrt(0.5)), 0.25, 1e-15);  // where the printed form is 0/0
}

TEST(OrthoglideDesign, QAxisLimitsSection6AndEq36) {
  // Section 6, J-Space0 / C-Space0 for mu = 0.5.
  const UnitQAxisLimits q = unit_q_axis_limits(0.5);
  EXPECT_NEAR(q.rho_minus, 0.4082, kDigits4);
  EXPECT_NEAR(q.rho_plus, 1.1785, kDigits4);
  EXPECT_NEAR(q.rho_plus - q.rho_minus, 0.7703, kDigits4);
  EXPECT_NEAR(q.p_minus, -0.4082, kDigits4);
  EXPECT_NEAR(q.p_plus, 0.2357, kDigits4);
  EXPECT_NEAR(q.p_plus - q.p_minus, 0.6440, kDigits4);
  // Eq. (36a) and the Q- bounds of eq. (38) (the Q-axis alone) are closed forms of eq. (16).
  for (double mu : {0.2, 0.35, 0.5, 0.54, 0.7, 0.9}) {
    const UnitQAxisLimits l = unit_q_axis_limits(mu);
    EXPECT_NEAR(l.rho_plus, (3 - mu) / std::sqrt(2 * mu * mu - 4 * mu + 6), 1e-14);
    EXPECT_NEAR(l.rho_minus,
                std::max((3 * mu - 1) / std::sqrt(6 * mu * mu - 4 * mu + 2), mu / std::sqrt(2 * mu * mu - 4 * mu + 3)),
                1e-14);
    // The segment Q+Q- reaches the upper bound 1/mu (at Q+, and at Q- too when mu <= 1/2); the
    // lower bound mu only for mu >= 1/2, below which 1/mu binds Q- first (eq. 16).
    const TransmissionRange r = unit_cube_range(l.p_minus, l.p_plus);
    EXPECT_NEAR(r.max, 1 / mu, 1e-12);
    if (mu >= 0.5)
      EXPECT_NEAR(r.min, mu, 1e-13);
    else
      EXPECT_GT(r.min, mu + 0.01);
  }
}

TEST(OrthoglideDesign, CriticalPointClosedFormsMatchSvd) {
  for (double rho : {0.1, 0.3, 0.4472, 0.7, 0.95, 1.05, 1.15, 1.2}) {
    for (CriticalPoint c : {CriticalPoint::kQ, CriticalPoint::kR, CriticalPoint::kS}) {
      const Vec3 p = unit_critical_point_position(c, rho);
      const Vec3 joints = *inverse_kinematics(kUnit, p);
      // The point lies on the face rho_x = rho of the joint box (and rho_y = rho for Q and R).
      EXPECT_NEAR(joints.x(), rho, 1e-14) << to_string(c);
      const double r1 = c == CriticalPoint::kR   ? std::pow(rho * rho * (2 - rho * rho), 0.25)  // eq. (20)
                        : c == CriticalPoint::kS ? std::sqrt(rho * (2 - rho))                   // eq. (24)
                                                 : rho;
      EXPECT_NEAR(joints.z(), r1, 1e-14) << to_string(c);
      EXPECT_NEAR((unit_critical_point_singular_values(c, rho) - svd_singular_values_at(p)).norm(), 0.0, 1e-12)
          << to_string(c) << " rho = " << rho;
    }
  }
}

TEST(OrthoglideDesign, Section52ClosedFormsAndBoundaries) {
  using C = CriticalPoint;
  auto sigma_max = [](C c, double r) { return unit_critical_point_singular_values(c, r)[0]; };
  auto sigma_min = [](C c, double r) { return unit_critical_point_singular_values(c, r)[2]; };
  // Eq. (31) (Q- and Q+ branch) and eq. (33) (R- branch).
  for (double r : {0.5, 0.7, 0.9}) {
    EXPECT_NEAR(1 / sigma_max(C::kQ, r), 1.0 / 3 + 2 * r / (3 * std::sqrt(3 - 2 * r * r)), 1e-13);
    EXPECT_NEAR(1 / sigma_min(C::kR, r), 0.5 + std::sqrt(2 - r * r) / (2 * r), 1e-12);
  }
  for (double r : {1.05, 1.15, 1.2})
    EXPECT_NEAR(1 / sigma_max(C::kQ, r), 2.0 / 3 + std::sqrt(3 - 2 * r * r) / (3 * r), 1e-13);
  // Boundaries of the mu_min areas in Fig. 9a: S- | R- at rho_SR, R- | Q- at rho_RQ.
  const double rho_sr = bisect([&](double r) { return sigma_max(C::kS, r) - sigma_max(C::kR, r); }, 0.01, 0.2);
  const double rho_rq = bisect([&](double r) { return sigma_max(C::kR, r) - sigma_max(C::kQ, r); }, 0.15, 0.6);
  EXPECT_NEAR(rho_sr, 0.1093, kDigits4);
  EXPECT_NEAR(1 / sigma_max(C::kS, rho_sr), 0.3232, kDigits4);
  EXPECT_NEAR(rho_rq, 0.2240, kDigits4);
  EXPECT_NEAR(1 / sigma_max(C::kQ, rho_rq), 0.4210, kDigits4);
  // mu*: the Q- and R- bounds of eq. (36b) meet.
  const double mu_star =
      bisect([](double m) { return (3 * m - 1) / std::sqrt(6 * m * m - 4 * m + 2) - m / std::sqrt(m * m - 2 * m + 2); },
             0.4, 0.7);
  EXPECT_NEAR(mu_star, 0.5387, kDigits4);
  EXPECT_NEAR(unit_joint_space_rho_min(mu_star), 0.4892, kDigits4);
  EXPECT_NEAR(unit_q_axis_limits(mu_star).rho_plus, 1.1700, kDigits4);
  // Section 5.3: strategy 1 raises rho_max past sqrt(3/2) (singular W_rho) for mu below
  // 1 - sqrt(sqrt(1.5) - 1) ~ 0.53.
  const double mu_sing = bisect([](double m) { return 1 + unit_q_axis_limits(m).p_plus - std::sqrt(1.5); }, 0.3, 0.9);
  EXPECT_NEAR(mu_sing, 1 - std::sqrt(std::sqrt(1.5) - 1), 1e-12);
  EXPECT_NEAR(mu_sing, 0.53, kDigits2);
}

TEST(OrthoglideDesign, CriticalPointsMatchNumericalSearch) {
  // Joint-limit pairs with rho_min >= 0.25: the Q- area of Fig. 9a (and Q+ near (1, 1)) and both
  // areas of Fig. 9b. The critical points Q, R, S give the exact extremes over W_rho.
  struct Case {
    double rho_min, rho_max;
  };
  for (const Case& c : {Case{0.30, 1.20}, Case{0.60, 1.10}, Case{0.95, 1.20}, Case{0.90, 1.02}, Case{0.40, 1.05}}) {
    const TransmissionRange formula = unit_joint_space_range(c.rho_min, c.rho_max);
    const WorkspaceSearch search = search_joint_space(kUnit, c.rho_min, c.rho_max, kInf, 41);
    ASSERT_FALSE(search.singular);
    EXPECT_NEAR(search.range.min, formula.min, 1e-6 * formula.min) << c.rho_min << " " << c.rho_max;
    EXPECT_NEAR(search.range.max, formula.max, 1e-6 * formula.max) << c.rho_min << " " << c.rho_max;
  }
}

TEST(OrthoglideDesign, MinimumBelowRhoQuarterIsNotAtACriticalPoint) {
  // Section 5.2 claims that mu_min over W_rho is attained at S- (rho_min < rho_SR = 0.1093), R-
  // (up to rho_RQ = 0.2240) or Q-. The numerical search finds lower factors for rho_min below about
  // 0.24: on the edge with two joints at rho_min, but with the third joint well below its value at
  // R- (eq. 20) -- the extreme along that edge is not at the symmetric point p_z = 0. (At
  // rho_min = 0.05 it lies on the face near, not at, S-.) So the printed rho_SR, rho_RQ,
  // mu(rho_SR) = 0.3232 and mu(rho_RQ) = 0.4210 are where the critical-point formulas switch, not
  // the true global factors: e.g. at rho_RQ the true mu_min is about 0.4175. mu_max is unaffected.
  for (double rho_min : {0.05, 0.15, 0.2, 0.224}) {
    const TransmissionRange formula = unit_joint_space_range(rho_min, 1.1);
    const WorkspaceSearch search = search_joint_space(kUnit, rho_min, 1.1, kInf, 41);
    EXPECT_LT(search.range.min, formula.min - 2e-4) << rho_min;
    EXPECT_GT(search.range.min, 0.99 * formula.min) << rho_min;
    EXPECT_NEAR(search.range.max, formula.max, 1e-6 * formula.max) << rho_min;
    // Witness, recomputed independently of the search: the reported joints lie in the box and give
    // the reported factor.
    const Vec3 rho = search.rho_at_min;
    EXPECT_GE(rho.minCoeff(), rho_min - 1e-15);
    EXPECT_LE(rho.maxCoeff(), 1.1 + 1e-15);
    const Vec3 p = *direct_kinematics(kUnit, rho, -1);
    EXPECT_NEAR(velocity_transmission(*inverse_jacobian(p, rho)).mu_min, search.range.min, 1e-12);
    if (rho_min > 0.1) {  // the edge: two joints at rho_min, the third short of R-'s rho_1
      std::array<double, 3> r{rho.x(), rho.y(), rho.z()};
      std::sort(r.begin(), r.end());
      EXPECT_NEAR(r[1], rho_min, 1e-12);
      EXPECT_LT(r[2], std::pow(rho_min * rho_min * (2 - rho_min * rho_min), 0.25) - 0.02);
    }
  }
  EXPECT_NEAR(unit_joint_space_range(0.2240, 1.1).min, 0.4210, kDigits4);  // the formula, as printed
  EXPECT_LT(search_joint_space(kUnit, 0.2240, 1.1, kInf, 41).range.min, 0.4210 - 0.003);
}

TEST(OrthoglideDesign, CubeRangeMatchesNumericalSearch) {
  // Proposition 1: over a cube with vertices on the Q-axis the extremes are at those vertices.
  for (double mu : {0.3, 0.5, 0.7}) {
    const UnitQAxisLimits q = unit_q_axis_limits(mu);
    for (double p_max : {q.p_plus, q.rho_plus - 1.0}) {
      const WorkspaceSearch search = search_cube(kUnit, q.p_minus, p_max, 41);
      const TransmissionRange formula = unit_cube_range(q.p_minus, p_max);
      ASSERT_FALSE(search.singular);
      EXPECT_NEAR(search.range.min, formula.min, 1e-9);
      EXPECT_NEAR(search.range.max, formula.max, 1e-9);
    }
  }
}

TEST(OrthoglideDesign, Table4AndSection6) {
  const OrthoglideDesign d1 = *design_orthoglide(1, 0.5, 1.0);
  const OrthoglideDesign d2 = *design_orthoglide(2, 0.5, 1.0);
  const OrthoglideDesign d3 = *design_orthoglide(3, 0.5, 1.0);
  // Section 6 (unit manipulator): J-Space1, C-Space2, J-Space3, C-Space3.
  EXPECT_NEAR(d1.rho_max / d1.link_length, 1.2357, kDigits4);
  EXPECT_NEAR((d1.rho_max - d1.rho_min) / d1.link_length, 0.8275, kDigits4);
  EXPECT_NEAR(d2.p_max / d2.link_length, 0.1785, kDigits4);
  EXPECT_NEAR((d2.p_max - d2.p_min) / d2.link_length, 0.5868, kDigits4);
  EXPECT_NEAR(d3.rho_min / d3.link_length, 0.4472, kDigits4);
  EXPECT_NEAR((d3.rho_max - d3.rho_min) / d3.link_length, 0.7313, kDigits4);
  EXPECT_NEAR(d3.p_min / d3.link_length, -0.3884, kDigits4);
  EXPECT_NEAR((d3.p_max - d3.p_min) / d3.link_length, 0.5669, kDigits4);
  // Table 4 (c = 1). The text calls the scale "eta = c / delta rho"; the numbers are c / delta p.
  struct Row {
    const OrthoglideDesign& d;
    double L, rho_min, rho_max, drho, c_drho, cube_lo, cube_hi, joint_lo, joint_hi;
  };
  for (const Row& r : {Row{d1, 1.553, 0.634, 1.919, 1.285, 0.7782, 0.500, 2.000, 0.500, kInf},
                       Row{d2, 1.704, 0.696, 2.009, 1.313, 0.7618, 0.500, 2.000, 0.500, 2.158},
                       Row{d3, 1.764, 0.789, 2.079, 1.290, 0.7752, 0.518, 1.869, 0.518, 2.000}}) {
    SCOPED_TRACE(r.d.strategy);
    EXPECT_NEAR(r.d.link_length, r.L, kDigits3);
    EXPECT_NEAR(r.d.rho_min, r.rho_min, kDigits3);
    EXPECT_NEAR(r.d.rho_max, r.rho_max, kDigits3);
    EXPECT_NEAR(r.d.rho_max - r.d.rho_min, r.drho, kDigits3);
    EXPECT_NEAR(1.0 / (r.d.rho_max - r.d.rho_min), r.c_drho, kDigits4);
    EXPECT_NEAR(r.d.cube.min, r.cube_lo, kDigits3);
    EXPECT_NEAR(r.d.cube.max, r.cube_hi, kDigits3);
    EXPECT_NEAR(r.d.joint_space.min, r.joint_lo, kDigits3);
    if (std::isinf(r.joint_hi))
      EXPECT_TRUE(r.d.joint_space.singular());  // "singularity": rho_max > sqrt(1.5)
    else
      EXPECT_NEAR(r.d.joint_space.max, r.joint_hi, kDigits3);
  }
}

TEST(OrthoglideDesign, PrototypeSection6) {
  // 200 mm cube, mu in [0.5, 2]: L = 310.6 / 340.9 / 352.8 mm; strategy 1 joint limits 126.8 and
  // 383.8 mm, software limit sum(rho) <= 3 rho(Q+) = 1098.1 mm.
  const double tol = 0.05e-3 + 1e-12;
  const double L[3] = {310.6e-3, 340.9e-3, 352.8e-3};
  for (int s = 1; s <= 3; ++s) EXPECT_NEAR(design_orthoglide(s, 0.5, 0.2)->link_length, L[s - 1], tol);
  const OrthoglideDesign d = *design_orthoglide(1, 0.5, 0.2);
  EXPECT_NEAR(d.rho_min, 126.8e-3, tol);
  EXPECT_NEAR(d.rho_max, 383.8e-3, tol);
  EXPECT_NEAR(d.joint_sum_limit, 1098.1e-3, tol);
  EXPECT_NEAR(d.p_max - d.p_min, 0.2, 1e-15);
  // Strategies 2 and 3 need no software limit (rho_max < sqrt(1.5) L).
  EXPECT_TRUE(std::isinf(design_orthoglide(2, 0.5, 0.2)->joint_sum_limit));
}

TEST(OrthoglideDesign, SoftwareLimitRestoresJSpace0Factors) {
  // Section 6: with rho_max = 1.2357 > sqrt(1.5) the joint box reaches the parallel singularity; the
  // software limit sum(rho) <= 3 rho(Q+) removes it and "restores the original transmission
  // factors [0.50, 2.16]". The numerical search confirms both statements.
  const OrthoglideDesign d = *design_orthoglide(1, 0.5, 0.2);
  const OrthoglideGeometry g{d.link_length};
  EXPECT_TRUE(search_joint_space(g, d.rho_min, d.rho_max, kInf, 41).singular);
  const WorkspaceSearch limited = search_joint_space(g, d.rho_min, d.rho_max, d.joint_sum_limit, 41);
  EXPECT_FALSE(limited.singular);
  const TransmissionRange j0 = unit_joint_space_range(d.rho_min / d.link_length, d.rho_q_plus / d.link_length);
  EXPECT_NEAR(j0.min, 0.50, kDigits2);
  EXPECT_NEAR(j0.max, 2.16, kDigits2);
  EXPECT_NEAR(limited.range.min, j0.min, 1e-6);
  EXPECT_NEAR(limited.range.max, j0.max, 1e-6);
}

TEST(OrthoglideDesign, StrategiesMeetSpecificationNumerically) {
  for (double mu : {0.3, 0.45, 0.5, 0.6, 0.8}) {
    for (int s = 1; s <= 3; ++s) {
      SCOPED_TRACE(testing::Message() << "mu = " << mu << ", strategy " << s);
      const OrthoglideDesign d = *design_orthoglide(s, mu, 0.2);
      const OrthoglideDesignCheck check = check_design(d, 31);
      // Every strategy meets [mu, 1/mu] on its cube, and the critical points give the exact extremes.
      EXPECT_NEAR(check.cube.range.min, d.cube.min, 1e-9);
      EXPECT_NEAR(check.cube.range.max, d.cube.max, 1e-9);
      EXPECT_GE(check.cube.range.min, mu - 1e-12);
      EXPECT_LE(check.cube.range.max, 1 / mu + 1e-12);
      // The cube fits the joint limits (and touches rho_max along an axis: Propositions 1, 2).
      const OrthoglideGeometry g{d.link_length};
      EXPECT_NEAR(inverse_kinematics(g, Vec3(d.p_max, 0, 0))->x(), d.rho_max, 1e-12);
      EXPECT_NEAR(inverse_kinematics(g, Vec3::Constant(d.p_min))->x(), d.rho_min, 1e-12);
      EXPECT_FALSE(check.joint_space.singular);  // with the software limit where one is set
      if (std::isinf(d.joint_sum_limit)) {
        // Exact where the critical points hold (rho_min >= 0.25 L, see the test above).
        if (d.rho_min >= 0.25 * d.link_length) {
          EXPECT_NEAR(check.joint_space.range.min, d.joint_space.min, 1e-6);
        }
        EXPECT_LE(check.joint_space.range.min, d.joint_space.min + 1e-12);
        EXPECT_NEAR(check.joint_space.range.max, d.joint_space.max, 1e-6 * d.joint_space.max);
      }
      if (s == 3) {  // the whole joint-bounded workspace meets the specification, tightly
        EXPECT_GE(check.joint_space.range.min, mu - 1e-9);
        EXPECT_LE(check.joint_space.range.max, 1 / mu + 1e-9);
        EXPECT_NEAR(check.joint_space.range.max, 1 / mu, 1e-9);
      }
    }
  }
}

TEST(OrthoglideDesign, InvalidSpecificationsAreRejected) {
  for (double mu : {0.0, 1.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_EQ(design_orthoglide(1, mu, 0.2).status().code(), StatusCode::kInvalidInput) << mu;
  for (double c : {0.0, -0.2, kInf})
    EXPECT_EQ(design_orthoglide(1, 0.5, c).status().code(), StatusCode::kInvalidInput) << c;
  EXPECT_EQ(design_orthoglide(4, 0.5, 0.2).status().code(), StatusCode::kInvalidInput);
}

TEST(OrthoglideDesign, DexterousVolumesTable2) {
  // Second route: star-shaped volumes about the isotropic point, as the paper computed them (rays in
  // all directions with a dichotomic search for the end of each segment meeting the constraint):
  // V = (1/3) int r(e)^3 de.
  auto inside = [](const Vec3& p, int which) {
    if (p.squaredNorm() >= 1.0) return false;
    const Vec3 rho = *inverse_kinematics(kUnit, p);
    if (direct_kinematics_branch(p, rho) != -1) return false;
    const VelocityTransmission v = velocity_transmission(*inverse_jacobian(p, rho));
    return which == 0 || (which != 3 && v.mu_min >= 1.0 / 3 && (which == 1 || v.mu_max <= 3)) ||
           (which == 3 && v.mu_max <= 3);
  };
  const int n_dir = 1500;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  double r3[4] = {0, 0, 0, 0};  // W0, lower, two-sided, upper
  for (int i = 0; i < n_dir; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n_dir, r = std::sqrt(1.0 - z * z);
    const Vec3 e(r * std::cos(golden * i), r * std::sin(golden * i), z);
    for (int w = 0; w < 4; ++w) {
      double lo = 0.0;
      while (lo + 0.02 < 1.0 && inside((lo + 0.02) * e, w)) lo += 0.02;
      double hi = lo + 0.02;
      for (int k = 0; k < 30; ++k) (inside(0.5 * (lo + hi) * e, w) ? lo : hi) = 0.5 * (lo + hi);
      r3[w] += lo * lo * lo;
    }
  }
  const DexterousVolumes v = unit_dexterous_volumes(1.0 / 3, 3.0, 80);
  EXPECT_NEAR(v.singularity_free_of_sphere, r3[0] / n_dir, 0.005);
  EXPECT_NEAR(v.lower_of_w0, r3[1] / r3[0], 0.01);
  EXPECT_NEAR(v.two_sided_of_w0, r3[2] / r3[0], 0.01);
  EXPECT_NEAR(v.upper_of_w0, r3[3] / r3[0], 0.01);
  // Table 2 prints 0.84 / 0.67 / 0.72 V0 and Fig. 3 gives V0 = 97.2 % of the sphere. The lower
  // bounding fraction is reproduced; the others are not: both routes give V0 ~ 95.0 % of the sphere,
  // two-sided ~ 0.684 and upper ~ 0.733 V0 (a 2.3 % smaller V0 would bring these two into line, but
  // then not the lower one). See docs/orthoglide.md.
  EXPECT_NEAR(v.lower_of_w0, 0.84, kDigits2);
  EXPECT_LT(v.singularity_free_of_sphere, 0.972 - 0.01);
  EXPECT_GT(v.two_sided_of_w0, 0.67 + kDigits2);
  EXPECT_GT(v.upper_of_w0, 0.72 + kDigits2);
}

// mu_min at unit joints rho (+inf where no regular assembly exists).
double unit_mu_min(const Vec3& rho) {
  auto p = direct_kinematics(kUnit, rho, -1);
  if (!p.ok()) return kInf;
  auto Jinv = inverse_jacobian(*p, rho);
  return Jinv.ok() ? velocity_transmission(*Jinv).mu_min : kInf;
}

// The smallest mu_min on the face rho_x = r of the box [r, 1]^3 with max(rho_y, rho_z) >= t0 (t0 = r:
// the whole face): a 81 x 81 scan, then a compass search (step halved down to 1e-12) from the best
// point. Independent of search_joint_space and of the edge the library follows.
double face_minimum(double r, double t0) {
  const int n = 81;
  Eigen::Vector2d best(r, 1.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d yz(r + (1 - r) * i / (n - 1), r + (1 - r) * j / (n - 1));
      if (yz.maxCoeff() >= t0 && unit_mu_min(Vec3(r, yz.x(), yz.y())) < unit_mu_min(Vec3(r, best.x(), best.y())))
        best = yz;
    }
  double f = unit_mu_min(Vec3(r, best.x(), best.y()));
  for (double h = (1 - r) / (n - 1); h > 1e-12;) {
    bool moved = false;
    for (const Eigen::Vector2d& d :
         {Eigen::Vector2d(h, 0), Eigen::Vector2d(-h, 0), Eigen::Vector2d(0, h), Eigen::Vector2d(0, -h)}) {
      const Eigen::Vector2d yz = (best + d).cwiseMax(r).cwiseMin(1.0);
      if (yz.maxCoeff() < t0) continue;
      const double g = unit_mu_min(Vec3(r, yz.x(), yz.y()));
      if (g < f) {
        f = g;
        best = yz;
        moved = true;
      }
    }
    if (!moved) h /= 2;
  }
  return f;
}

TEST(OrthoglideDesign, MinimumSwitchPointsOfSection52) {
  const MinimumSwitchPoints m = unit_minimum_switch_points();
  // Where the paper's critical-point formulas switch (as printed).
  EXPECT_NEAR(m.rho_sr, 0.1093, kDigits4);
  EXPECT_NEAR(m.mu_sr, 0.3232, kDigits4);
  EXPECT_NEAR(m.rho_rq, 0.2240, kDigits4);
  EXPECT_NEAR(m.mu_rq, 0.4210, kDigits4);
  // The true minimum at those rho_min (a face point near S-, an edge point short of R-) is lower.
  for (const auto& [r, formula, search] :
       {std::tuple{m.rho_sr, m.mu_sr, m.search_mu_at_rho_sr}, std::tuple{m.rho_rq, m.mu_rq, m.search_mu_at_rho_rq}}) {
    EXPECT_NEAR(search, face_minimum(r, r), 1e-7) << r;
    EXPECT_LT(search, formula - 2e-3) << r;
  }
  // The true switch to Q-: where the face's minimum away from the vertex Q- = (r, r, r) rises above
  // Q-'s factor, by bisection on the face scan.
  double lo = 0.23, hi = 0.26;  // 24 halvings: 2e-9
  for (int k = 0; k < 24; ++k) {
    const double r = 0.5 * (lo + hi);
    (face_minimum(r, r + 0.1) < unit_mu_min(Vec3::Constant(r)) ? lo : hi) = r;
  }
  const double rho_q = 0.5 * (lo + hi);
  EXPECT_NEAR(m.rho_q, rho_q, 1e-6);
  EXPECT_NEAR(m.mu_q, unit_mu_min(Vec3::Constant(rho_q)), 1e-6);
  EXPECT_GT(m.rho_q, m.rho_rq + 0.01);  // the paper's rho_RQ = 0.2240 is not where Q- takes over
  // And the whole-box search agrees: the minimum is below Q-'s just before the switch, Q-'s just after.
  const double before = m.rho_q - 2e-3, after = m.rho_q + 2e-3;
  EXPECT_LT(search_joint_space(kUnit, before, 1.0, kInf, 41).range.min, unit_mu_min(Vec3::Constant(before)) - 1e-5);
  EXPECT_NEAR(search_joint_space(kUnit, after, 1.0, kInf, 41).range.min, unit_mu_min(Vec3::Constant(after)), 1e-12);
}

TEST(OrthoglideDesign, JointBoxKeptBySoftwareLimitAgainstMonteCarlo) {
  // Closed form (a corner simplex cut from the joint box) against the share of uniform random joint
  // points under the limit, with its binomial error bar. mu = 0.3 cuts more than the stroke's corner.
  for (double mu : {0.5, 0.3}) {
    const OrthoglideDesign d = *design_orthoglide(1, mu, 0.2);
    ASSERT_TRUE(std::isfinite(d.joint_sum_limit));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(d.rho_min, d.rho_max);
    const int N = 400000;
    int kept = 0;
    for (int i = 0; i < N; ++i) kept += u(rng) + u(rng) + u(rng) <= d.joint_sum_limit;
    const double share = static_cast<double>(kept) / N, sigma = std::sqrt(share * (1 - share) / N);
    EXPECT_NEAR(d.joint_box_kept, share, 4 * sigma + 1e-12) << mu << " sigma " << sigma;
    EXPECT_LT(d.joint_box_kept, 1.0);
  }
  EXPECT_EQ(design_orthoglide(2, 0.5, 0.2)->joint_box_kept, 1.0);  // no software limit
}

TEST(OrthoglideDesign, EncoderOffsetsOfSection6) {
  // The prototype (strategy 1, 200 mm, mu = 0.5) with every slider 5 or 10 mm further out than
  // commanded. The paper: cube factors [0.50, 2.42] and [0.50, 3.42]. Independent route: a plain
  // 31^3 grid over the commanded cube, postures by the direct kinematics.
  const OrthoglideDesign d = *design_orthoglide(1, 0.5, 0.2);
  const OrthoglideGeometry g{d.link_length};
  const OrthoglideDesignCheck check = check_design(d, 41, {0.0, 5e-3, 10e-3});
  ASSERT_EQ(check.encoder_offsets.size(), 3u);
  EXPECT_NEAR(check.encoder_offsets[0].cube.range.min, 0.5, 1e-9);  // no offset: the design's cube
  EXPECT_NEAR(check.encoder_offsets[0].cube.range.max, 2.0, 1e-9);
  for (const EncoderOffsetEffect& e : check.encoder_offsets) {
    const int n = 31;
    TransmissionRange grid{kInf, 0.0};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vec3 p = Vec3::Constant(d.p_min) + Vec3(i, j, k) * ((d.p_max - d.p_min) / (n - 1));
          const Vec3 rho = *inverse_kinematics(g, p) + Vec3::Constant(e.offset);
          const VelocityTransmission v = velocity_transmission(*inverse_jacobian(*direct_kinematics(g, rho, -1), rho));
          grid.min = std::min(grid.min, v.mu_min);
          grid.max = std::max(grid.max, v.mu_max);
        }
    EXPECT_FALSE(e.cube.singular);
    EXPECT_LE(e.cube.range.min, grid.min + 1e-12) << e.offset;  // the search refines what the grid finds
    EXPECT_GE(e.cube.range.max, grid.max - 1e-12) << e.offset;
    EXPECT_NEAR(e.cube.range.min, grid.min, 1e-3) << e.offset;
    EXPECT_NEAR(e.cube.range.max, grid.max, 1e-3) << e.offset;
  }
  // The paper's upper bounds to the printed digits; the lower bound rises a little instead of staying
  // at the printed 0.50 (docs/orthoglide.md).
  EXPECT_NEAR(check.encoder_offsets[1].cube.range.max, 2.42, kDigits2);
  EXPECT_NEAR(check.encoder_offsets[2].cube.range.max, 3.42, kDigits2);
  EXPECT_NEAR(check.encoder_offsets[1].cube.range.min, 0.507, kDigits3);
  EXPECT_NEAR(check.encoder_offsets[2].cube.range.min, 0.515, kDigits3);
}

TEST(OrthoglideDesign, DexterousVolumesAgainstMonteCarlo) {
  // The grid count the design command prints (n = 80) against uniform random points in [-1, 1]^3,
  // each fraction with its binomial error bar; the grid's own error is a few 1e-3 (the cells cut by
  // the boundary).
  const DexterousVolumes v = unit_dexterous_volumes(1.0 / 3, 3.0, 80);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  long sphere = 0, w0 = 0, counts[3] = {0, 0, 0};
  for (int i = 0; i < 300000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (p.squaredNorm() >= 1.0) continue;
    ++sphere;
    const Vec3 rho = *inverse_kinematics(kUnit, p);
    if (direct_kinematics_branch(p, rho) != -1) continue;
    ++w0;
    const VelocityTransmission t = velocity_transmission(*inverse_jacobian(p, rho));
    counts[0] += t.mu_min >= 1.0 / 3;
    counts[1] += t.mu_min >= 1.0 / 3 && t.mu_max <= 3.0;
    counts[2] += t.mu_max <= 3.0;
  }
  auto expect_fraction = [](double grid, long hits, long total, const char* what) {
    const double f = static_cast<double>(hits) / total, sigma = std::sqrt(f * (1 - f) / total);
    EXPECT_NEAR(grid, f, 4 * sigma + 3e-3) << what << ": Monte Carlo " << f << " +- " << sigma;
  };
  expect_fraction(v.singularity_free_of_sphere, w0, sphere, "V0 / sphere");
  expect_fraction(v.lower_of_w0, counts[0], w0, "lower");
  expect_fraction(v.two_sided_of_w0, counts[1], w0, "two-sided");
  expect_fraction(v.upper_of_w0, counts[2], w0, "upper");
  // Fig. 3's 97.2 % is not reproduced: ~95.0 % (DexterousVolumesTable2, docs/orthoglide.md).
  EXPECT_NEAR(v.singularity_free_of_sphere, 0.950, 0.003);
}

}  // namespace
}  // namespace kinestat::mechanisms
