#include "mechanisms/fixed_chain.hpp"

#include <algorithm>
#include <cmath>

#include "kinestat/vjm/chain.hpp"
#include "mechanisms/fixed_size_vjm.hpp"

namespace kinestat::mechanisms::fixed_vjm {

namespace {

using BorderedMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoordinates + 6,
                                     kMaxCoordinates + 6>;
using BorderedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxCoordinates + 6, 1>;

// vjm::pose_difference and vjm::displace.
Vec6 pose_difference(const Pose& to, const Pose& from) {
  Vec6 d;
  d.head<3>() = to.p - from.p;
  const Eigen::AngleAxisd aa(Mat3(to.R * from.R.transpose()));
  d.tail<3>() = aa.angle() * aa.axis();
  return d;
}

Pose displace(const Pose& T, const Vec6& d) {
  Pose out = T;
  out.p += d.head<3>();
  const double angle = d.tail<3>().norm();
  if (angle > 0) out.R = Eigen::AngleAxisd(angle, d.tail<3>() / angle).toRotationMatrix() * T.R;
  return out;
}

// A moving factor's unit twist (spatial form: linear part = velocity of the point at the origin),
// scaled by its coefficient, and the coordinate that drives it.
struct Twist {
  Vec3 v, w;
  int slot;
};

}  // namespace

void FixedChain::clear() {
  size_ = n_ = m_ = 0;
  K_.setZero();
}

void FixedChain::add_transform(const Mat3& R, const Vec3& p) {
  Factor& f = f_[size_++];
  f = Factor{};
  f.R = R;
  f.p = p;
}

void FixedChain::add_motion(Kind kind, const Vec3& axis, double offset, bool passive, int index, double coefficient) {
  Factor& f = f_[size_++];
  f = Factor{};
  f.kind = kind;
  f.axis = axis;
  f.offset = offset;
  f.passive = passive;
  f.index = index;
  f.coefficient = coefficient;
}

void FixedChain::add_prismatic_actuator(const Vec3& axis, double value, double stiffness) {
  K_(m_, m_) = stiffness;
  add_motion(Kind::kPrismatic, axis, value, false, m_++, 1.0);
}

void FixedChain::add_spring(const Mat6& K) {
  K_.block<6, 6>(m_, m_) = K;
  for (int i = 0; i < 6; ++i)
    add_motion(i < 3 ? Kind::kPrismatic : Kind::kRevolute, Vec3::Unit(i % 3), 0.0, false, m_++, 1.0);
}

int FixedChain::add_passive(const Vec3& axis, double nominal) {
  q0_[n_] = nominal;
  add_motion(Kind::kRevolute, axis, 0.0, true, n_, 1.0);
  return n_++;
}

void FixedChain::add_coupled(const Vec3& axis, int index, double coefficient) {
  add_motion(Kind::kRevolute, axis, 0.0, true, index, coefficient);
}

CoordinateVector FixedChain::nominal() const {
  CoordinateVector x = CoordinateVector::Zero(n_ + m_);
  for (int i = 0; i < n_; ++i) x[i] = q0_[i];
  return x;
}

double FixedChain::length_scale() const {
  double L = 0.0;
  for (int k = 0; k < size_; ++k) {
    const Factor& f = f_[k];
    if (f.kind == Kind::kConstant) L += f.p.norm();
    if (f.kind == Kind::kPrismatic) L += std::abs(f.offset);
  }
  return L > 0.0 ? L : 1.0;
}

Pose FixedChain::kinematics(const CoordinateVector& x, ChainJacobian& J, const Vec6* F, CoordinateMatrix* H) const {
  // vjm's walk: the twists of the moving factors in product order, then the tool pose.
  std::array<Twist, kMaxFactors> tw;
  int nt = 0;
  Pose T;
  for (int k = 0; k < size_; ++k) {
    const Factor& f = f_[k];
    if (f.kind == Kind::kConstant) {
      T.p += T.R * f.p;
      T.R = T.R * f.R;
      continue;
    }
    double value = f.offset;
    if (f.index >= 0) {
      const int slot = f.passive ? f.index : n_ + f.index;
      value += f.coefficient * x[slot];
      const Vec3 a = T.R * f.axis;
      const double c = f.coefficient;
      tw[nt++] = f.kind == Kind::kRevolute ? Twist{c * T.p.cross(a), c * a, slot} : Twist{c * a, Vec3::Zero(), slot};
    }
    if (f.kind == Kind::kRevolute)
      T.R = T.R * Eigen::AngleAxisd(value, f.axis).toRotationMatrix();
    else
      T.p += T.R * (value * f.axis);
  }
  const Vec3& p = T.p;
  J.setZero(6, n_ + m_);
  for (int a = 0; a < nt; ++a) {
    J.col(tw[a].slot).head<3>() += tw[a].v + tw[a].w.cross(p);  // velocity of the tool point
    J.col(tw[a].slot).tail<3>() += tw[a].w;
  }
  if (F && H) {
    H->setZero(n_ + m_, n_ + m_);
    vjm::for_each_hessian_term(tw.data(), nt, p, *F,
                               [&](int b, int a, double value) { (*H)(tw[b].slot, tw[a].slot) += value; });
  }
  return T;
}

// Eq. (11) by Newton-Raphson from s, with vjm::chain_equilibrium's residuals, scaling, tolerance and
// backtracking; s is the converged state on return (true) or unspecified (false).
bool LoadedPlatform::solve_chain(int i, const Pose& target, FixedChainState& s) const {
  const FixedChain& c = chains[i];
  const int n = c.num_passive(), m = c.num_virtual(), N = n + m + 6;
  const Vec6 w = twist_scale(c.length_scale());
  struct Linearization {
    ChainJacobian J;
    Vec6 r;
    CoordinateVector g;  // (J_q^T F, J_theta^T F - K_theta theta)
    double kin = 0, stat = 0;
    double merit() const { return kin + stat; }
  };
  const auto linearize = [&](const CoordinateVector& x, const Vec6& F, Linearization& l) {
    const Pose T = c.kinematics(x, l.J, nullptr, nullptr);
    l.r = pose_difference(target, T);
    l.kin = l.r.cwiseProduct(w).norm();
    l.g = l.J.transpose() * F;
    const CoordinateVector Kt = c.spring_stiffness() * x.tail(m);
    const double jtf = l.g.tail(m).norm();
    l.g.tail(m) -= Kt;
    const double num = l.g.norm(), den = l.g.head(n).norm() + jtf + Kt.norm();
    l.stat = num > 0 ? num / den : 0.0;
  };
  const auto done = [&](const Linearization& l) {
    return l.kin <= equilibrium_tolerance && l.stat <= equilibrium_tolerance;
  };
  Linearization lin, trial;
  linearize(s.x, s.wrench, lin);
  ChainJacobian J;
  CoordinateMatrix H;
  BorderedMatrix A(N, N);
  BorderedVector b(N);
  // At least one step: under a prescribed wrench the outer iteration moves the target by less than
  // the tolerance near convergence, and a chain left where it was would stall it.
  for (int it = 0; it == 0 || !done(lin); ++it) {
    if (it >= max_iterations) return false;
    c.kinematics(s.x, J, &s.wrench, &H);
    // Rows: kinematics (scaled by W), J_q^T F, J_theta^T F - K_theta theta; unknowns (dq, dtheta, W^-1 dF).
    A.setZero();
    A.topLeftCorner(6, n + m) = w.asDiagonal() * lin.J;
    A.bottomLeftCorner(n + m, n + m) = H;
    A.block(6 + n, n, m, m) -= c.spring_stiffness();
    A.bottomRightCorner(n + m, 6) = lin.J.transpose() * w.asDiagonal();
    b << lin.r.cwiseProduct(w), -lin.g;
    const BorderedVector d = Eigen::PartialPivLU<BorderedMatrix>(A).solve(b);
    if (!d.allFinite()) return false;
    double step = 1.0;
    for (int k = 0; k < 20; ++k, step *= 0.5) {
      const CoordinateVector x = s.x + step * d.head(n + m);
      const Vec6 F = s.wrench + step * d.tail<6>().cwiseProduct(w);
      linearize(x, F, trial);
      if (trial.merit() < lin.merit() || k == 19) {
        s.x = x;
        s.wrench = F;
        std::swap(lin, trial);
        break;
      }
    }
  }
  return true;
}

// Eq. (21) at a regular posture, as vjm::loaded_stiffness computes it (no rigid direction, so its
// complement basis is the identity): K = W X W with X the 6x6 top-left block of A^-1.
bool LoadedPlatform::loaded_stiffness(int i, const FixedChainState& s, Mat6& K) const {
  const FixedChain& c = chains[i];
  const int n = c.num_passive(), m = c.num_virtual();
  const Vec6 w = twist_scale(c.length_scale());
  ChainJacobian J;
  CoordinateMatrix H;
  c.kinematics(s.x, J, &s.wrench, &H);
  const CoordinateMatrix Ath = c.spring_stiffness() - H.bottomRightCorner(m, m);
  const Eigen::FullPivLU<CoordinateMatrix> lu(Ath);
  if (!lu.isInvertible()) return false;  // the springs buckle under this load
  const ChainJacobian Jw = w.asDiagonal() * J;
  const auto Jq = Jw.leftCols(n);
  const auto Jth = Jw.rightCols(m);
  const CoordinateMatrix kJt = lu.solve(Jth.transpose());
  const CoordinateMatrix kH = lu.solve(H.bottomLeftCorner(m, n));
  BorderedMatrix A(6 + n, 6 + n);
  A.topLeftCorner<6, 6>() = Jth * kJt;
  A.topRightCorner(6, n) = Jq + Jth * kH;
  A.bottomLeftCorner(n, 6) = Jq.transpose() + H.topRightCorner(n, m) * kJt;
  A.bottomRightCorner(n, n) = H.topLeftCorner(n, n) + H.topRightCorner(n, m) * kH;
  BorderedMatrix rhs = BorderedMatrix::Zero(6 + n, 6);
  rhs.topRows<6>().setIdentity();
  const Eigen::FullPivLU<BorderedMatrix> alu(A);
  if (!alu.isInvertible()) return false;
  const BorderedMatrix X = alu.solve(rhs);
  K = w.asDiagonal() * X.topRows<6>() * w.asDiagonal();
  return true;
}

bool LoadedPlatform::platform_stiffness(Mat6& K) const {
  K.setZero();
  for (int i = 0; i < num_chains; ++i) {
    Mat6 Ki;
    if (!loaded_stiffness(i, states_[i], Ki)) return false;
    K += Ki;
  }
  return true;
}

void LoadedPlatform::evaluate(const Vec6* displacement, const Vec6* wrench, PostureResult& r) {
  length_scale_ = 0.0;
  ChainJacobian J;
  for (int i = 0; i < num_chains; ++i) {
    states_[i].x = chains[i].nominal();
    states_[i].wrench.setZero();
    nominal_[i] = chains[i].kinematics(states_[i].x, J);
    length_scale_ = std::max(length_scale_, chains[i].length_scale());
  }
  const Vec6 w = twist_scale(length_scale_);
  // Every chain at the platform displaced by d, from its current state.
  const auto solve_chains = [&](const Vec6& d) {
    for (int i = 0; i < num_chains; ++i)
      if (!solve_chain(i, displace(nominal_[i], d), states_[i])) return false;
    return true;
  };
  r.status = PostureStatus::kFailed;
  Vec6 d = Vec6::Zero();
  Mat6 K;
  if (displacement) {
    d = *displacement;
    if (!solve_chains(d)) return;
  } else {
    // vjm::platform_equilibrium_under_wrench: Newton on the platform pose with the loaded stiffness
    // as dF/dt, from the unloaded platform (the chains' nominal state is their equilibrium at d = 0).
    const double ref = wrench->cwiseQuotient(w).norm();
    for (int it = 0;; ++it) {
      if (!platform_stiffness(K)) return;
      Vec6 total = Vec6::Zero();
      for (int i = 0; i < num_chains; ++i) total += states_[i].wrench;
      const Vec6 R = (*wrench - total).cwiseQuotient(w);
      const double res = ref > 0 ? R.norm() / ref : R.norm();
      if (res <= 100 * equilibrium_tolerance) break;
      if (it >= max_iterations) return;
      const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
      const Eigen::FullPivLU<Mat6> lu(Kt);
      if (!lu.isInvertible()) return;  // a free direction: the wrench cannot be resisted
      const Vec6 dt = lu.solve(R).cwiseQuotient(w);
      d = pose_difference(displace(displace(nominal_[0], d), dt), nominal_[0]);
      if (!solve_chains(d)) return;
    }
  }
  r.status = PostureStatus::kSingular;
  if (!platform_stiffness(K)) return;
  // vjm's aggregate: a singular value of the scaled K below rank_tolerance of the largest is a free
  // direction (the compliance is undefined).
  const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
  const Vec6 sv = Eigen::JacobiSVD<Mat6>(Kt).singularValues();
  if (!(sv[5] > rank_tolerance * sv[0])) return;
  r.status = PostureStatus::kOk;
  r.stiffness = K;
  r.compliance = w.cwiseInverse().asDiagonal() * Eigen::FullPivLU<Mat6>(Kt).inverse() * w.cwiseInverse().asDiagonal();
  r.indices = cartesian_indices(K);
  r.deflection = d;
}

}  // namespace kinestat::mechanisms::fixed_vjm
