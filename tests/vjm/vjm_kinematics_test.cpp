// Chain kinematics of eq. (1): Jacobians (eq. 5) and the derivatives of J^T F (eq. 20) against
// central finite differences of the forward kinematics, and geometric facts of the joints.
#include <gtest/gtest.h>

#include "kinestat/vjm/chain.hpp"
#include "vjm_test_chains.hpp"

namespace kinestat::vjm {
namespace {

using test_chains::eq1_chain;

VecX test_theta(const Chain& c) {
  // Small but non-zero spring deflections, so the Jacobians are evaluated off the nominal point.
  VecX th(c.num_virtual());
  for (int i = 0; i < th.size(); ++i) th[i] = 1e-3 * std::sin(1.0 + i);
  return th;
}

// Numerical Jacobian: columns are (pose(x + h) - pose(x - h)) / 2h as twists.
MatX fd_jacobian(const Chain& c, const VecX& q, const VecX& th, bool wrt_q) {
  const double h = 1e-6;
  const int n = wrt_q ? c.num_passive() : c.num_virtual();
  MatX J(6, n);
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q, tp = th, tm = th;
    (wrt_q ? qp : tp)[j] += h;
    (wrt_q ? qm : tm)[j] -= h;
    J.col(j) = pose_difference(c.forward(qp, tp), c.forward(qm, tm)) / (2 * h);
  }
  return J;
}

TEST(VjmKinematics, JacobiansMatchFiniteDifferences) {
  for (bool sph : {false, true}) {
    const Chain c = eq1_chain(sph);
    ASSERT_TRUE(c.validate().ok());
    const VecX q = c.nominal_passive(), th = test_theta(c);
    const ChainJacobians J = jacobians(c, q, th);
    EXPECT_LT((J.Jq - fd_jacobian(c, q, th, true)).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((J.Jtheta - fd_jacobian(c, q, th, false)).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((J.pose.matrix() - c.forward(q, th).matrix()).norm(), 1e-15);
  }
}

TEST(VjmKinematics, HessiansMatchFiniteDifferencesOfJtF) {
  const Vec6 F = (Vec6() << 120.0, -80.0, 45.0, 3.0, -7.0, 2.5).finished();  // N and N m
  const Chain c = eq1_chain(false);
  const VecX q = c.nominal_passive(), th = test_theta(c);
  const ChainHessians H = hessians(c, q, th, F);
  const int n = c.num_passive(), m = c.num_virtual();
  const double h = 1e-6;
  // d(J^T F)/dx_j for x = (q, theta), by central differences of the analytic Jacobians.
  MatX Hfd(n + m, n + m);
  for (int j = 0; j < n + m; ++j) {
    VecX qp = q, qm = q, tp = th, tm = th;
    if (j < n) {
      qp[j] += h;
      qm[j] -= h;
    } else {
      tp[j - n] += h;
      tm[j - n] -= h;
    }
    const ChainJacobians Jp = jacobians(c, qp, tp), Jm = jacobians(c, qm, tm);
    VecX gp(n + m), gm(n + m);
    gp << Jp.Jq.transpose() * F, Jp.Jtheta.transpose() * F;
    gm << Jm.Jq.transpose() * F, Jm.Jtheta.transpose() * F;
    Hfd.col(j) = (gp - gm) / (2 * h);
  }
  const double tol = 1e-6 * Hfd.cwiseAbs().maxCoeff();
  EXPECT_LT((H.Hqq - Hfd.topLeftCorner(n, n)).cwiseAbs().maxCoeff(), tol);
  EXPECT_LT((H.Hqtheta - Hfd.topRightCorner(n, m)).cwiseAbs().maxCoeff(), tol);
  EXPECT_LT((H.Hthetaq - Hfd.bottomLeftCorner(m, n)).cwiseAbs().maxCoeff(), tol);
  EXPECT_LT((H.Hthetatheta - Hfd.bottomRightCorner(m, m)).cwiseAbs().maxCoeff(), tol);
}

TEST(VjmKinematics, HessianIsSymmetricForAPureForceOnly) {
  const Chain c = eq1_chain(false);
  const VecX q = c.nominal_passive(), th = test_theta(c);
  auto full = [&](const Vec6& F) {
    const ChainHessians H = hessians(c, q, th, F);
    MatX M(H.Hqq.rows() + H.Hthetaq.rows(), H.Hqq.cols() + H.Hqtheta.cols());
    M << H.Hqq, H.Hqtheta, H.Hthetaq, H.Hthetatheta;
    return M;
  };
  // A force: H is the Hessian of F . p(q, theta), symmetric.
  const MatX Hf = full((Vec6() << 120.0, -80.0, 45.0, 0, 0, 0).finished());
  EXPECT_LT((Hf - Hf.transpose()).cwiseAbs().maxCoeff(), 1e-12 * Hf.cwiseAbs().maxCoeff());
  // A moment: rotations about different axes do not commute, the linearization is not symmetric.
  const MatX Hm = full((Vec6() << 0, 0, 0, 3.0, -7.0, 2.5).finished());
  EXPECT_GT((Hm - Hm.transpose()).cwiseAbs().maxCoeff(), 1e-3 * Hm.cwiseAbs().maxCoeff());
}

TEST(VjmKinematics, ParallelogramCouplingKeepsTheOrientation) {
  // Eq. (22): R_y(q) T_x(L) R_y(-q) translates the end on a circle without rotating it.
  Chain c("parallelogram");
  const int q = c.add_passive(JointType::kRevolute, Vec3::UnitY(), 0.4, "bar rotation");
  c.add_translation(Vec3(0.3, 0, 0), "bar");
  c.add_coupled(JointType::kRevolute, Vec3::UnitY(), q, -1.0, "coupled -q");
  const VecX q0 = c.nominal_passive();
  const ChainJacobians J = jacobians(c, q0, VecX(0));
  EXPECT_LT(J.Jq.col(0).tail<3>().norm(), 1e-15);
  EXPECT_LT((J.pose.linear() - Mat3::Identity()).norm(), 1e-15);
  // The end moves on a circle of radius 0.3 about y: velocity 0.3 rad^-1 perpendicular to the bar.
  EXPECT_NEAR(J.Jq.col(0).head<3>().norm(), 0.3, 1e-15);
  EXPECT_NEAR(J.Jq.col(0).head<3>().dot(J.pose.translation()), 0.0, 1e-15);
  EXPECT_LT((J.Jq - fd_jacobian(c, q0, VecX(0), true)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(VjmKinematics, DisplaceAndPoseDifferenceAreInverse) {
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  T.translation() = Vec3(0.1, -0.2, 0.3);
  const Vec6 d = (Vec6() << 1e-3, 2e-3, -5e-4, 0.2, -0.1, 0.3).finished();
  EXPECT_LT((pose_difference(displace(T, d), T) - d).norm(), 1e-14);
}

TEST(VjmKinematics, ValidateNamesTheBadSpring) {
  Chain c("bad");
  Mat6 K = Mat6::Identity();
  K(0, 0) = -1.0;
  c.add_spring(K, "leg spring");
  const Status s = c.validate();
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find("leg spring"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("positive definite"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace kinestat::vjm
