#include "mechanisms/fixed_size_vjm.hpp"

#include "kinestat/core/frame.hpp"

namespace kinestat::mechanisms::fixed_vjm {

Mat6 rotate6(const Mat6& G, const Mat3& R) {
  Mat6 out;
  out.topLeftCorner<3, 3>() = R * G.topLeftCorner<3, 3>() * R.transpose();
  out.topRightCorner<3, 3>() = R * G.topRightCorner<3, 3>() * R.transpose();
  out.bottomLeftCorner<3, 3>() = out.topRightCorner<3, 3>().transpose();
  out.bottomRightCorner<3, 3>() = R * G.bottomRightCorner<3, 3>() * R.transpose();
  return out;
}

Mat6 transfer_compliance(const Mat6& G, const Vec3& r) {
  // Blocks of J G J^T with J = [I, M; 0, I], M = -[r]x: the rotation part is unchanged.
  const Mat3 M = -skew(r);
  const Mat3 top_right = G.topRightCorner<3, 3>() + M * G.bottomRightCorner<3, 3>();
  Mat6 out;
  out.topLeftCorner<3, 3>() = G.topLeftCorner<3, 3>() + M * G.bottomLeftCorner<3, 3>() + top_right * M.transpose();
  out.topRightCorner<3, 3>() = top_right;
  out.bottomLeftCorner<3, 3>() = top_right.transpose();
  out.bottomRightCorner<3, 3>() = G.bottomRightCorner<3, 3>();
  return out;
}

bool regular_inverse(const Mat6& Kt, double tolerance, Mat6& C) {
  // A FullPivLU that finds a lower rank would "invert" with the free variables set to zero: finite.
  const Eigen::FullPivLU<Mat6> lu(Kt);
  if (!lu.isInvertible()) return false;
  C = lu.inverse();
  if (1.0 / C.norm() > tolerance * Kt.norm()) return true;
  const Vec6 sv = Eigen::JacobiSVD<Mat6>(Kt).singularValues();
  return sv[5] > tolerance * sv[0];
}

void set_platform_result(const Mat6& K, const Vec6& w, const Vec6& load, PostureResult& r) {
  const Vec6 wi = w.cwiseInverse();
  const Mat6 Kt = wi.asDiagonal() * K * wi.asDiagonal();
  const Eigen::LLT<Mat6> llt(Kt);
  r.status = PostureStatus::kSingular;
  if (llt.info() != Eigen::Success) return;
  const Vec6 pivots = llt.matrixLLT().diagonal().cwiseAbs2();
  if (!(pivots.cwiseQuotient(Kt.diagonal()).minCoeff() >= kPivotRatioTolerance)) return;
  r.status = PostureStatus::kOk;
  set_stiffness(r, K, wi.asDiagonal() * spd_inverse<6>(llt) * wi.asDiagonal());
  r.deflection = r.compliance * load;
}

}  // namespace kinestat::mechanisms::fixed_vjm
