// Fixed-size pieces of the virtual joint method for the posture kernels (five_bar_kernel.cpp,
// orthoglide_kernel.cpp): no heap allocation, no rank-revealing decompositions. They compute what
// vjm::platform_unloaded_stiffness computes (Pashkevich et al. 2009, eq. 9-10 and section 3.3) for
// chains whose springs are all regular, with the same twist scaling (vjm/bordered_system.hpp).
#pragma once

#include <cmath>

#include <Eigen/Dense>

#include "kinestat/core/small_triangular.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"

namespace kinestat::mechanisms::fixed_vjm {

// diag(R, R) G diag(R, R)^T: a 6x6 (ux uy uz rx ry rz) given in the axes R, in R's parent axes.
Mat6 rotate6(const Mat6& G, const Mat3& R);

// J G J^T with J = [I, -[r]x; 0, I]: the compliance G of a spring about point o seen at the tool
// point o + r (the spring's 6 columns of J_theta, eq. 5, are J diag(R, R)), i.e. its term of
// S = J_theta K_theta^-1 J_theta^T (eq. 9).
Mat6 transfer_compliance(const Mat6& G, const Vec3& r);

// Wrench (force f along the line through point o, about the tool point t): (f, (o - t) x f).
inline Vec6 line_force(const Vec3& f, const Vec3& o, const Vec3& t) {
  Vec6 w;
  w << f, (o - t).cross(f);
  return w;
}
// Pure moment m: (0, m).
inline Vec6 couple(const Vec3& m) {
  Vec6 w;
  w << Vec3::Zero(), m;
  return w;
}

// The spring between a parallelogram's plates (the Pa joint of eq. 22) at bar angle q (c = cos q,
// s = sin q): two bars of length L, `width` apart along z, pinned about y at both plates, each of
// compliance `bar` in its own axes (x along the bar, y the pins' axis) as a cantilever. In the plates'
// axes (x: the bars at q = 0, y: the pins, z = x cross y), about the distal plate's centre L R_y(q) e_x:
// each bar transmits forces along itself and y and moments about x and z through its distal pin,
// and the two add; along the plates' free translation u = R_y(q) e_z it adds k0 u u^T, k0 the
// trace of the translational block (the passive q takes that motion, so k0 does not matter). This
// is what mechanisms::parallelogram_spring derives by the VJM of the two bars. False where K is
// singular (a pivot of the length-scaled K below kPivotRatioTolerance of its largest diagonal entry):
// at q = +-90 deg the bars lie on one line and the plate turns freely about y.
bool parallelogram_stiffness(const Mat6& bar, double length, double width, double c, double s, Mat6& K);

// Twist scaling of vjm::twist_scale: W = diag(I/L, I).
inline Vec6 twist_scale(double length_scale) {
  Vec6 w;
  w << Vec3::Constant(1.0 / length_scale), Vec3::Ones();
  return w;
}

// L^-1 B for the lower triangle L of `factor` (e.g. LLT::matrixLLT()), core/small_triangular.hpp.
template <int N, int M>
Eigen::Matrix<double, N, M> lower_solve(const Eigen::Matrix<double, N, N>& factor, Eigen::Matrix<double, N, M> B) {
  lower_solve_in_place(factor, B);
  return B;
}

// The inverse L^-T L^-1 of a symmetric positive definite matrix from its Cholesky factorization:
// symmetric by construction.
template <int N>
Eigen::Matrix<double, N, N> spd_inverse(const Eigen::LLT<Eigen::Matrix<double, N, N>>& llt) {
  const Eigen::Matrix<double, N, N> Li = lower_solve<N, N>(llt.matrixLLT(), Eigen::Matrix<double, N, N>::Identity());
  return Li.transpose() * Li;
}

// Eq. (10) as vjm's bordered system solves it, K = N (N^T S N)^-1 N^T with N a basis of the wrenches
// the passive joints transmit (null(J_q^T), the reciprocal screws of the passive joints). vjm finds
// N by an SVD of the length-scaled J_q; K does not depend on the basis (N -> N G for any regular G,
// the scaling W included), so each kernel writes its chain's transmitted wrenches in closed form.
// False when N^T S N is not positive definite (a rigid direction, which a chain with a 6-dof spring
// cannot have).
template <int NF>
bool chain_stiffness(const Eigen::Matrix<double, 6, NF>& N, const Mat6& S, Mat6& K) {
  const Eigen::Matrix<double, NF, NF> C = N.transpose() * S * N;
  const Eigen::LLT<Eigen::Matrix<double, NF, NF>> llt(C);
  if (llt.info() != Eigen::Success) return false;
  // N C^-1 N^T = Y^T Y with Y = L^-1 N^T: symmetric by construction.
  const Eigen::Matrix<double, NF, 6> Y = lower_solve<NF, 6>(llt.matrixLLT(), N.transpose());
  K = Y.transpose() * Y;
  return true;
}

// Singularity test of the platform stiffness K (SI) in the scaled twists of W: the smallest pivot
// ratio d_i / K~_ii of the Cholesky factorization of K~ = W^-1 K W^-1. A free motion of the
// platform leaves a pivot at round-off level (~1e-16); vjm's aggregate calls a direction free
// below 1e-10 of the largest singular value of K~, and this ratio is never below that one
// (d_i >= lambda_min), so the kernels use the same 1e-10.
inline constexpr double kPivotRatioTolerance = 1e-10;

// vjm's aggregate's rank test on a loaded platform stiffness Kt (scaled twists, not necessarily
// symmetric): false where a singular value is at or below `tolerance` of the largest (a free
// direction) or the LU's pivots find a rank below 6, else true with C = Kt^-1. sigma_min >=
// 1 / |Kt^-1|_F and sigma_max <= |Kt|_F certify most matrices without the SVD, which decides the
// others (a ratio within a factor 6 of the tolerance).
bool regular_inverse(const Mat6& Kt, double tolerance, Mat6& C);

// Fills `r` from a platform stiffness K: kOk with the stiffness, the compliance (K^-1), the indices
// and `deflection = C load` when K passes the pivot test above, else kSingular with no values.
void set_platform_result(const Mat6& K, const Vec6& w, const Vec6& load, PostureResult& r);

}  // namespace kinestat::mechanisms::fixed_vjm
