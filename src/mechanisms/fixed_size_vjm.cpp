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

bool parallelogram_stiffness(const Mat6& bar, double length, double width, double c, double s, Mat6& K) {
  Mat3 Ry;
  Ry << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  const Vec3 t = length * Ry.col(0), y = Vec3::UnitY();
  const Mat6 G = rotate6(bar, Ry);
  K.setZero();
  for (double side : {0.5, -0.5}) {
    const Vec3 o2 = side * width * Vec3::UnitZ() + t;  // the distal pin
    Eigen::Matrix<double, 6, 4> N;
    N << line_force(Ry.col(0), o2, t), line_force(y, o2, t), couple(Vec3::UnitX()), couple(Vec3::UnitZ());
    Mat6 Kb;
    if (!chain_stiffness<4>(N, transfer_compliance(G, t - o2), Kb)) return false;
    K += Kb;
  }
  Vec6 u;
  u << Ry.col(2), Vec3::Zero();
  K += K.topLeftCorner<3, 3>().trace() * u * u.transpose();
  // At q = +-90 deg the bars lie on one line and nothing holds the plate's turn about y (its
  // stiffness goes as cos^2 q): a pivot of the length-scaled K (twist_scale(length)) below
  // kPivotRatioTolerance of its largest diagonal entry, as the kernels' singularity test.
  const Vec6 w = twist_scale(length);
  const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
  const Eigen::LLT<Mat6> llt(Kt);
  if (llt.info() != Eigen::Success) return false;
  const double floor = kPivotRatioTolerance * Kt.diagonal().maxCoeff();
  for (int i = 0; i < 6; ++i)
    if (!(std::pow(llt.matrixLLT()(i, i), 2) > floor)) return false;
  return true;
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
