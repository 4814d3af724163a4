// Orthoglide kinematics (Pashkevich, Wenger, Chablat 2005, eq. 1-8, 13): checked against the
// constraint equations (1), finite differences, the Q-axis closed forms and a brute-force search over
// directions of motion.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "kinestat/mechanisms/orthoglide_kinematics.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr double kL = 0.3106;  // m, the prototype's link length (section 6)
const OrthoglideGeometry kProto{kL};

// Residuals of eq. (1): |p - rho_i e_i|^2 - L^2.
Vec3 constraint_residual(const Vec3& p, const Vec3& rho, double L) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    Vec3 bar = p;
    bar[i] -= rho[i];
    r[i] = bar.squaredNorm() - L * L;
  }
  return r;
}

// Points of the singularity-free working mode: inside the sphere of radius 0.9 L, direct-kinematics
// branch m = -1 (section 2.3) and away from the flat singularity.
std::vector<Vec3> working_points(int count) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-0.9 * kL, 0.9 * kL);
  std::vector<Vec3> pts;
  while (static_cast<int>(pts.size()) < count) {
    const Vec3 p(u(gen), u(gen), u(gen));
    if (p.norm() > 0.9 * kL) continue;
    const Vec3 rho = *inverse_kinematics(kProto, p);
    if (p.cwiseQuotient(rho).sum() - 1.0 > -0.05) continue;
    pts.push_back(p);
  }
  return pts;
}

TEST(OrthoglideKinematics, ZeroPostureIsIsotropic) {
  // Section 2.1: p0 = 0 <-> rho0 = (L, L, L); section 3.1: J0 = I.
  const Vec3 rho = *inverse_kinematics(kProto, Vec3::Zero());
  EXPECT_NEAR((rho - Vec3::Constant(kL)).norm(), 0.0, 1e-15);
  const Mat3 Jinv = *inverse_jacobian(Vec3::Zero(), rho);
  EXPECT_NEAR((Jinv - Mat3::Identity()).norm(), 0.0, 1e-15);
  const VelocityTransmission v = velocity_transmission(Jinv);
  EXPECT_NEAR(v.mu_min, 1.0, 1e-14);
  EXPECT_NEAR(v.mu_max, 1.0, 1e-14);
  EXPECT_NEAR(v.manipulability, 1.0, 1e-14);
  EXPECT_NEAR(v.condition_number, 1.0, 1e-14);
}

TEST(OrthoglideKinematics, InverseKinematicsAllSignsSatisfyConstraints) {
  const Vec3 p(0.05, -0.08, 0.11);
  for (int code = 0; code < 8; ++code) {
    const OrthoglideSigns s{code & 1 ? -1 : 1, code & 2 ? -1 : 1, code & 4 ? -1 : 1};
    const auto rho = inverse_kinematics(kProto, p, s);
    ASSERT_TRUE(rho.ok());
    EXPECT_LT(constraint_residual(p, *rho, kL).cwiseAbs().maxCoeff(), 1e-15);
    for (int i = 0; i < 3; ++i) EXPECT_EQ((*rho)[i] - p[i] > 0.0 ? 1 : -1, s[i]);  // s_i = sign(rho_i - p_i)
  }
}

TEST(OrthoglideKinematics, InverseDirectRoundTripBothBranches) {
  for (const Vec3& p : working_points(200)) {
    const Vec3 rho = *inverse_kinematics(kProto, p);
    const auto both = direct_kinematics(kProto, rho);
    ASSERT_TRUE(both.ok());
    EXPECT_LT(((*both)[0] - p).norm(), 1e-13) << p.transpose();  // the working branch m = -1 returns p
    EXPECT_EQ(direct_kinematics_branch((*both)[0], rho), -1);
    // The other assembly also closes every chain, on the far side of the slider plane (m = +1).
    EXPECT_LT(constraint_residual((*both)[1], rho, kL).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_EQ(direct_kinematics_branch((*both)[1], rho), 1);
    EXPECT_LT(((*direct_kinematics(kProto, rho, 1)) - (*both)[1]).norm(), 1e-15);
  }
}

TEST(OrthoglideKinematics, ZeroPostureSecondAssemblyFromQuadratic) {
  // At rho = (L, L, L) the quadratic (eq. 4, divided by B) is 3 t^2 / L^2 + t - L^2 / 4 = 0 with
  // roots t = -L^2/2 (p = 0) and t = L^2/6, i.e. p = (2/3) L (1, 1, 1).
  const auto both = *direct_kinematics(kProto, Vec3::Constant(kL));
  EXPECT_NEAR(both[0].norm(), 0.0, 1e-15);
  EXPECT_NEAR((both[1] - Vec3::Constant(2.0 * kL / 3.0)).norm(), 0.0, 1e-15);
}

TEST(OrthoglideKinematics, InvalidInputsAreReported) {
  // Outside the cylinder of chain x (p_y^2 + p_z^2 > L^2).
  EXPECT_EQ(inverse_kinematics(kProto, Vec3(0.0, 0.3, 0.1)).status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(inverse_kinematics(kProto, Vec3::Zero(), {1, 0, 1}).status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(inverse_kinematics(OrthoglideGeometry{-1.0}, Vec3::Zero()).status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(direct_kinematics(kProto, Vec3(0.0, kL, kL)).status().code(), StatusCode::kInvalidInput);  // eq. (2)
  // On the Q-axis rho(chi) peaks at sqrt(3/2) L (section 3.2): (1.3 L, 1.3 L, 1.3 L) has no assembly.
  EXPECT_EQ(direct_kinematics(kProto, Vec3::Constant(1.3 * kL)).status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(direct_kinematics(kProto, Vec3::Constant(kL), 0).status().code(), StatusCode::kInvalidInput);
}

TEST(OrthoglideKinematics, InverseJacobianMatchesFiniteDifferences) {
  const double h = 1e-6 * kL;
  for (const Vec3& p : working_points(50)) {
    const Vec3 rho = *inverse_kinematics(kProto, p);
    const Mat3 Jinv = *inverse_jacobian(p, rho);
    Mat3 fd;
    for (int j = 0; j < 3; ++j) {
      const Vec3 dp = Vec3::Unit(j) * h;
      fd.col(j) = (*inverse_kinematics(kProto, p + dp) - *inverse_kinematics(kProto, p - dp)) / (2.0 * h);
    }
    EXPECT_LT((Jinv - fd).norm(), 1e-6 * Jinv.norm()) << p.transpose();
    // And J = dp/drho by differencing the direct kinematics is its inverse.
    Mat3 J;
    for (int j = 0; j < 3; ++j) {
      const Vec3 dr = Vec3::Unit(j) * h;
      J.col(j) = (*direct_kinematics(kProto, rho + dr, -1) - *direct_kinematics(kProto, rho - dr, -1)) / (2.0 * h);
    }
    EXPECT_LT((J * Jinv - Mat3::Identity()).norm(), 1e-6) << p.transpose();
  }
}

TEST(OrthoglideKinematics, ClosedFormDeterminantMatchesNumeric) {
  for (const Vec3& p : working_points(100)) {
    const Vec3 rho = *inverse_kinematics(kProto, p);
    const double det6 = *inverse_jacobian_determinant(p, rho);
    const Mat3 Jinv = *inverse_jacobian(p, rho);
    EXPECT_NEAR(det6, Jinv.determinant(), 1e-12 * std::abs(det6));
    // Manipulability (section 4.1) is the product of the singular values = |det J^-1|.
    EXPECT_NEAR(velocity_transmission(Jinv).manipulability, std::abs(det6), 1e-12 * std::abs(det6));
    EXPECT_GT(det6, 0.0);  // the working mode never crosses a singularity
  }
}

TEST(OrthoglideKinematics, QAxisClosedForms) {
  // Section 3.2, eq. (7), (8), (13): on the bisector J^-1 = [1 chi chi; chi 1 chi; chi chi 1] with
  // chi = -p / sqrt(L^2 - 2 p^2), eigenvalues 1 + 2 chi and 1 - chi (twice).
  for (double pn : {-0.5, -0.3, -0.1, 0.05, 0.2, 0.35}) {
    const Vec3 p = Vec3::Constant(pn * kL);
    const Vec3 rho = *inverse_kinematics(kProto, p);
    const Mat3 Jinv = *inverse_jacobian(p, rho);
    const double chi = -pn / std::sqrt(1.0 - 2.0 * pn * pn);
    Mat3 expected = Mat3::Constant(chi);
    expected.diagonal().setOnes();
    EXPECT_LT((Jinv - expected).norm(), 1e-14);
    EXPECT_LT((Jinv - Jinv.transpose()).norm(), 1e-14);  // symmetric on the Q-axis
    const VelocityTransmission v = velocity_transmission(Jinv);
    EXPECT_NEAR(v.manipulability, (1 - chi) * (1 - chi) * std::abs(1 + 2 * chi), 1e-13);  // eq. (8)
    const double cond = chi > 0 ? 1 + 3 * chi / (1 - chi) : 1 - 3 * chi / (1 + 2 * chi);  // eq. (13)
    EXPECT_NEAR(v.condition_number, cond, 1e-12);
    EXPECT_NEAR(v.mu_min, 1.0 / std::max(std::abs(1 + 2 * chi), std::abs(1 - chi)), 1e-13);
    EXPECT_NEAR(v.mu_max, 1.0 / std::min(std::abs(1 + 2 * chi), std::abs(1 - chi)), 1e-13);
  }
}

TEST(OrthoglideKinematics, TransmissionFactorsBoundEveryDirection) {
  // lambda(e) = ||J^-1 e||^-1 over unit directions e (section 4.3) spans [mu_min, mu_max]:
  // brute force over a Fibonacci sphere of directions.
  const int n = 20000;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (const Vec3& p : working_points(5)) {
    const Vec3 rho = *inverse_kinematics(kProto, p);
    const Mat3 Jinv = *inverse_jacobian(p, rho);
    double lo = 1e300, hi = 0.0;
    for (int i = 0; i < n; ++i) {
      const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
      const Vec3 e(r * std::cos(golden * i), r * std::sin(golden * i), z);
      const double lambda = 1.0 / (Jinv * e).norm();
      lo = std::min(lo, lambda);
      hi = std::max(hi, lambda);
    }
    const VelocityTransmission v = velocity_transmission(Jinv);
    EXPECT_LE(v.mu_min, lo + 1e-12);
    EXPECT_GE(v.mu_max, hi - 1e-12);
    EXPECT_NEAR(v.mu_min, lo, 2e-3 * lo);  // the direction grid is ~0.03 rad apart
    EXPECT_NEAR(v.mu_max, hi, 2e-3 * hi);
  }
}

TEST(OrthoglideKinematics, SingularitiesAreDetected) {
  // Parallel singularity P2 of Table 1: p = L / sqrt(6) (1, 1, 1), rho = sqrt(3/2) L: the two
  // assemblies merge (B^2 = 4AC) and det J^-1 = 0, so the largest transmission factor is unbounded.
  const Vec3 p2 = Vec3::Constant(kL / std::sqrt(6.0));
  const Vec3 rho2 = *inverse_kinematics(kProto, p2);
  EXPECT_NEAR(rho2.x(), std::sqrt(1.5) * kL, 1e-15);
  EXPECT_NEAR(*inverse_jacobian_determinant(p2, rho2), 0.0, 1e-12);
  const auto both = direct_kinematics(kProto, rho2 * (1.0 - 1e-12));
  ASSERT_TRUE(both.ok());
  EXPECT_LT(((*both)[0] - (*both)[1]).norm(), 1e-5 * kL);
  EXPECT_GT(velocity_transmission(*inverse_jacobian(p2, rho2)).mu_max, 1e12);
  // Serial singularity: p_y^2 + p_z^2 = L^2 puts bar x orthogonal to its slider (rho_x = p_x).
  const Vec3 ps(0.3 * kL, 0.6 * kL, 0.8 * kL);
  const Vec3 rhos(ps.x(), ps.y() + std::sqrt(kL * kL - ps.x() * ps.x() - ps.z() * ps.z()),
                  ps.z() + std::sqrt(kL * kL - ps.x() * ps.x() - ps.y() * ps.y()));
  EXPECT_EQ(inverse_jacobian(ps, rhos).status().code(), StatusCode::kSingular);
  EXPECT_EQ(inverse_jacobian_determinant(ps, rhos).status().code(), StatusCode::kSingular);
}

}  // namespace
}  // namespace kinestat::mechanisms
