#include "vjm/bordered_system.hpp"

#include <algorithm>

namespace kinestat::vjm {

Vec6 twist_scale(double length_scale) {
  Vec6 w;
  w << Vec3::Constant(1.0 / length_scale), Vec3::Ones();
  return w;
}

Vec6 unscaled_direction(const Vec6& scaled, double length_scale) {
  const Vec6 t = scaled.cwiseQuotient(twist_scale(length_scale));
  return t / t.norm();
}

ToolSpaceSplit split_tool_space(const MatX& Jq, const MatX& Jtheta, const Vec6& w, double tol) {
  MatX J(6, Jq.cols() + Jtheta.cols());
  J << w.asDiagonal() * Jq, w.asDiagonal() * Jtheta;
  for (int j = 0; j < J.cols(); ++j)
    if (J.col(j).norm() > 0) J.col(j).normalize();
  ToolSpaceSplit s;
  if (J.cols() == 0) return s;
  Eigen::JacobiSVD<MatX> svd(J, Eigen::ComputeFullU);
  const VecX& sv = svd.singularValues();
  while (s.rank < sv.size() && sv[s.rank] > tol * std::max(1.0, sv[0])) ++s.rank;
  s.U = svd.matrixU();
  return s;
}

Mat6 spring_compliance(const MatX& Jtheta, const MatX& Ktheta) {
  if (Jtheta.cols() == 0) return Mat6::Zero();
  // K_theta is symmetric positive definite (Chain::validate), so LLT applies; no inverse is formed.
  const Eigen::LLT<MatX> llt(Ktheta);
  const Mat6 S = Jtheta * llt.solve(Jtheta.transpose());
  return 0.5 * (S + S.transpose());
}

BorderedSystem factor_bordered_system(const MatX& Jq, const Mat6& S, double L, double tol) {
  BorderedSystem B;
  B.S = S;
  const Vec6 w = twist_scale(L);
  const int n = static_cast<int>(Jq.cols());

  // SVD of the scaled J_q with unit columns (a prismatic and a revolute column become comparable);
  // the column scaling D is undone for the self-motions and the pseudo-inverse.
  MatX Jn = w.asDiagonal() * Jq;
  VecX D = VecX::Ones(n);
  for (int j = 0; j < n; ++j) {
    const double c = Jn.col(j).norm();
    if (c > 0) {
      D[j] = 1.0 / c;
      Jn.col(j) /= c;
    }
  }
  int r = 0;
  Eigen::Matrix<double, 6, 6> U = Mat6::Identity();
  B.Jq_pinv = MatX::Zero(n, 6);
  if (n > 0) {
    Eigen::JacobiSVD<MatX> svd(Jn, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const VecX& sv = svd.singularValues();
    while (r < sv.size() && sv[r] > tol * std::max(1.0, sv[0])) ++r;
    U = svd.matrixU();
    const MatX& V = svd.matrixV();
    // Pseudo-inverse of the unscaled J_q: D V_r Sigma_r^-1 U_r^T W.
    for (int k = 0; k < r; ++k)
      B.Jq_pinv += D.asDiagonal() * V.col(k) * (U.col(k).transpose() * w.asDiagonal()) / sv[k];
    for (int k = r; k < n; ++k) {
      const VecX dq = D.asDiagonal() * V.col(k);
      B.self_motions.push_back(dq / dq.norm());
    }
  }

  // Wrenches the passive joints transmit: N = U(:, r:6). Scaled S~ = W S W.
  const MatX N = U.rightCols(6 - r);
  if (N.cols() == 0) return B;  // the passive joints give every direction for free: K = 0
  const Mat6 St = w.asDiagonal() * S * w.asDiagonal();
  const MatX C = N.transpose() * St * N;
  Eigen::SelfAdjointEigenSolver<MatX> eig(C);
  const VecX& lambda = eig.eigenvalues();  // ascending
  const double lmax = std::max(lambda.maxCoeff(), 0.0);
  Mat6 Kt = Mat6::Zero();
  for (int k = 0; k < lambda.size(); ++k) {
    const Vec6 dir = N * eig.eigenvectors().col(k);
    if (!(lambda[k] > tol * lmax)) {
      B.rigid_directions.push_back(unscaled_direction(dir, L));
      continue;
    }
    Kt += dir * dir.transpose() / lambda[k];
  }
  // Back to SI: K = W K~ W.
  B.K = w.asDiagonal() * Kt * w.asDiagonal();
  B.K = 0.5 * (B.K + B.K.transpose());
  return B;
}

void BorderedSystem::solve(const Vec6& dt, Vec6* F, VecX* dq) const {
  *F = K * dt;
  *dq = Jq_pinv * (dt - S * *F);
}

}  // namespace kinestat::vjm
