#include "mechanisms/fixed_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinestat/vjm/chain.hpp"
#include "mechanisms/fixed_size_vjm.hpp"
#include "mechanisms/small_lu.hpp"

namespace kinestat::mechanisms::fixed_vjm {

namespace {

// A chord step is kept while it divides the largest residual (in units of its tolerance) by this at
// least, and not below kFloor of the tolerances, the round-off floor (relative residuals of 1e-15).
constexpr double kChordContraction = 0.1, kFloor = 1e-3;
// Where more chord steps than this would be needed at the last one's rate, a Newton step instead.
constexpr double kChordsPerNewton = 3;

using BorderedMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoordinates + 6, kMaxCoordinates + 6>;
static_assert(kMaxCoordinates + 6 <= kSmallLUStride);

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

}  // namespace

void FixedChain::clear() {
  K_.topLeftCorner(m_, m_).setZero();  // the rest is zero already: the springs fill only this corner
  size_ = n_ = m_ = 0;
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
  for (int k = 0; k < 3; ++k)
    if (axis == Vec3::Unit(k)) f.unit_axis = k;
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

bool FixedChain::assign(const vjm::Chain& chain) {
  clear();
  if (static_cast<int>(chain.factors().size()) > kMaxFactors || chain.num_coordinates() > kMaxCoordinates) return false;
  for (const vjm::Factor& f : chain.factors()) {
    if (!f.is_motion) {
      add_transform(f.transform.linear(), f.transform.translation());
      continue;
    }
    const Kind kind = f.type == vjm::JointType::kRevolute ? Kind::kRevolute : Kind::kPrismatic;
    const bool passive = f.variable && f.variable->kind == vjm::VariableKind::kPassive;
    add_motion(kind, f.axis, f.offset, passive, f.variable ? f.variable->index : -1,
               f.variable ? f.variable->coefficient : 1.0);
  }
  n_ = chain.num_passive();
  m_ = chain.num_virtual();
  for (int i = 0; i < n_; ++i) q0_[i] = chain.nominal_passive(i);
  for (const vjm::Spring& sp : chain.springs()) {
    const auto size = sp.stiffness.rows();
    K_.block(sp.first, sp.first, size, size) = sp.stiffness;
  }
  return true;
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

void FixedChain::walk(const CoordinateVector& x, ChainWalk& w, ChainJacobian& J) const {
  // vjm's walk: the twists of the moving factors in product order, then the tool pose.
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
      w.tw[nt++] = f.kind == Kind::kRevolute ? ChainWalk::Twist{c * T.p.cross(a), c * a, slot}
                                             : ChainWalk::Twist{c * a, Vec3::Zero(), slot};
    }
    if (f.kind == Kind::kRevolute && f.unit_axis >= 0) {
      // About a coordinate axis k, only the columns i, j of T.R turn: 12 flops for the 27 of a product.
      const int i = (f.unit_axis + 1) % 3, j = (f.unit_axis + 2) % 3;
      const double c = std::cos(value), s = std::sin(value);
      const Vec3 ri = T.R.col(i), rj = T.R.col(j);
      T.R.col(i) = c * ri + s * rj;
      T.R.col(j) = c * rj - s * ri;
    } else if (f.kind == Kind::kRevolute) {
      T.R = T.R * Eigen::AngleAxisd(value, f.axis).toRotationMatrix();
    } else
      T.p += T.R * (value * f.axis);
  }
  w.count = nt;
  w.T = T;
  const Vec3& p = T.p;
  J.setZero(6, n_ + m_);
  for (int a = 0; a < nt; ++a) {
    w.u[a] = w.tw[a].v + w.tw[a].w.cross(p);  // velocity of the tool point
    J.col(w.tw[a].slot).head<3>() += w.u[a];
    J.col(w.tw[a].slot).tail<3>() += w.tw[a].w;
  }
}

void FixedChain::hessian(const ChainWalk& w, const Vec6& F, CoordinateMatrix& H) const {
  H.setZero(n_ + m_, n_ + m_);
  vjm::for_each_hessian_term(w.tw.data(), w.count, w.T.p, F,
                             [&](int b, int a, double value) { H(w.tw[b].slot, w.tw[a].slot) += value; });
}

Pose FixedChain::kinematics(const CoordinateVector& x, ChainJacobian& J, const Vec6* F, CoordinateMatrix* H) const {
  ChainWalk w;
  walk(x, w, J);
  if (F && H) hessian(w, *F, *H);
  return w.T;
}

namespace {

// A chain's residuals of eq. (11) at (x, F) for a target pose, with the walk and the Jacobian, and H
// where a Newton step or the loaded stiffness needs it (a chord step needs only the residuals): one
// walk of the chain per iterate.
struct Linearization {
  ChainWalk walk;
  ChainJacobian J;
  CoordinateMatrix H;  // FixedChain::hessian from walk, where a Newton step needs it
  Vec6 r;              // target - f(x) as a twist
  CoordinateVector g;  // (J_q^T F, J_theta^T F - K_theta theta)
  double kin = 0, stat = 0;
  double merit() const { return kin + stat; }
};

// vjm::chain_equilibrium's residuals and scaling (w: the chain's twist scale).
void linearize(const FixedChain& c, const Pose& target, const Vec6& w, const CoordinateVector& x, const Vec6& F,
               Linearization& l) {
  const int n = c.num_passive(), m = c.num_virtual();
  c.walk(x, l.walk, l.J);
  l.r = pose_difference(target, l.walk.T);
  l.kin = l.r.cwiseProduct(w).norm();
  l.g = l.J.transpose() * F;
  const CoordinateVector Kt = c.spring_stiffness() * x.tail(m);
  const double jtf = l.g.tail(m).norm();
  l.g.tail(m) -= Kt;
  const double num = l.g.norm(), den = l.g.head(n).norm() + jtf + Kt.norm();
  l.stat = num > 0 ? num / den : 0.0;
}

// The Newton matrix of eq. (11) at l, into lu to factor. Rows: kinematics (scaled by W), J_q^T F,
// J_theta^T F - K_theta theta; unknowns (dq, dtheta, W^-1 dF).
void newton_matrix(const FixedChain& c, const Vec6& w, const Linearization& l, SmallLU& lu) {
  const int n = c.num_passive(), m = c.num_virtual();
  SmallLU::View A = lu.reset(n + m + 6);
  A.topLeftCorner(6, n + m) = w.asDiagonal() * l.J;
  A.bottomLeftCorner(n + m, n + m) = l.H;
  A.block(6 + n, n, m, m) -= c.spring_stiffness();
  A.bottomRightCorner(n + m, 6) = l.J.transpose() * w.asDiagonal();
}

// A chain's right-hand sides, the residual (column 0) and the target's six unit moves (columns 1-6),
// as condense() leaves them: L^-1 P of them, then the last six pivots of U^-1 (SmallLU::backward).
using Forward = PaddedColumns<7>;

// A Newton step's condensation of chain c at l (its H included): the Newton matrix factored into lu;
// x as above, whose last six rows are the wrench rows of the solutions: the wrench step (column 0)
// and the chain's dF/dt, K (eq. 21 as the Schur complement of the Newton matrix). False at a zero
// pivot or a value not finite.
bool condense(const FixedChain& c, const Vec6& w, const Linearization& l, SmallLU& lu, Forward& x, Vec6& wrench_step,
              Mat6& K) {
  newton_matrix(c, w, l, lu);
  if (!lu.factor()) return false;
  const int N = lu.rows();
  Forward::View X = x.reset(N);
  X.col(0) << l.r.cwiseProduct(w), -l.g;
  X.topRightCorner<6, 6>() = w.asDiagonal();  // the target moved by a unit twist
  lu.forward(x);
  lu.backward(x, N - 6, N);
  const auto last = X.bottomRows<6>();
  if (!last.allFinite()) return false;
  wrench_step = last.col(0);
  K = w.asDiagonal() * last.rightCols<6>();
  return true;
}

}  // namespace

// Eq. (11) by Newton-Raphson from s, with vjm::chain_equilibrium's residuals, scaling, tolerance and
// backtracking; s is the converged state on return (true) or unspecified (false). After a Newton step a
// step may be a chord step (the residuals solved with that step's factors), kept where it divides the
// merit by kChordContraction at least, as in coupled_equilibrium; elsewhere a Newton step. Once within
// the tolerances, chord steps go on to the round-off floor (the first that no longer contracts is
// dropped), where the loaded stiffness is evaluated, as in coupled_equilibrium. The Hessian at the
// solution, which that stiffness needs, is computed once at the end.
bool LoadedPlatform::solve_chain(int i, const Pose& target, FixedChainState& s, int& steps) const {
  const FixedChain& c = chains[i];
  const int n = c.num_passive(), m = c.num_virtual(), N = n + m + 6;
  const Vec6 w = twist_scale(c.length_scale());
  const auto within = [&](const Linearization& l, double share) {
    return l.kin <= share * equilibrium_tolerance && l.stat <= share * equilibrium_tolerance;
  };
  const auto done = [&](const Linearization& l) { return within(l, 1.0); };
  Linearization lin, trial;
  s.linearized = s.condensed = false;
  linearize(c, target, w, s.x, s.wrench, lin);
  SmallLU A;
  PaddedColumns<1> b;
  PaddedColumns<1>::View d = b.reset(N);  // the step
  bool factored = false;
  const auto take = [&](double step) {
    linearize(c, target, w, s.x + step * d.head(n + m), s.wrench + step * d.tail<6>().cwiseProduct(w), trial);
  };
  const auto accept = [&](double step) {
    s.x += step * d.head(n + m);
    s.wrench += step * d.tail<6>().cwiseProduct(w);
    std::swap(lin, trial);
  };
  // The step of the factors in A from the state in lin.
  const auto solve = [&] {
    d << lin.r.cwiseProduct(w), -lin.g;
    A.forward(b);
    A.backward(b);
    return d.allFinite();
  };
  // At least one step: under a prescribed wrench the outer iteration moves the target by less than
  // the tolerance near convergence, and a chain left where it was would stall it.
  bool floor = false;
  for (int it = 0; it == 0 || !done(lin) || (factored && !floor && !within(lin, kFloor)); ++it) {
    if (it >= max_iterations) return false;
    if (factored) {
      if (solve()) {
        take(1.0);
        if (trial.merit() < kChordContraction * lin.merit()) {
          accept(1.0);
          continue;
        }
      }
      if (done(lin)) {
        floor = true;
        continue;
      }
    }
    ++steps;
    c.hessian(lin.walk, s.wrench, lin.H);
    newton_matrix(c, w, lin, A);
    if (!A.factor()) return false;
    factored = true;
    if (!solve()) return false;
    double step = 1.0;
    for (int k = 0; k < 20; ++k, step *= 0.5) {
      take(step);
      // Backtracking is for steps from afar: a step taken from a state that already meets the
      // tolerances (the first step of a warm or nested re-solve) is kept, since at the round-off floor
      // the merit need not decrease and 20 halvings would each walk the chain for nothing.
      if (trial.merit() < lin.merit() || done(lin) || k == 19) {
        accept(step);
        break;
      }
    }
  }
  // The chain's loaded stiffness at the solution, as a Newton step there condenses it (a factorization,
  // counted as coupled_equilibrium counts its last one).
  ++steps;
  c.hessian(lin.walk, s.wrench, lin.H);
  Forward x;
  Vec6 wrench_step;
  if (!condense(c, w, lin, A, x, wrench_step, s.K)) return false;
  s.J = lin.J;
  s.H = lin.H;
  s.linearized = s.condensed = true;
  return true;
}

// Under a wrench: Newton on all the equations at once, every chain's eq. (11) and the platform's
// balance sum F_i = W_ext, unknowns every chain's (dx_i, dF_i) and the platform's twist dt. Each
// chain's Newton system is solved for its own residual and for the six unit moves of its target,
// which condenses it to F_i + dF_i0 + K_i dt (K_i: the chain's dF/dt, eq. 21 by the Schur complement
// of the same matrix); the 6x6 sum gives dt. The nested iteration (equilibrium(), the reference's)
// re-solves every chain to 1e-12 at each platform step; this converges in a few steps for all the
// unknowns together. From rest (F = 0, so H = 0) its first step is the linear response K0^-1 W_ext.
//
// A round whose residuals are not yet within the tolerances may be a chord step: the residuals (a
// walk of each chain, no Hessian) solved with the factors, the K_i and the 6x6 of the last Newton
// step, as long as each such round divides the largest residual by kChordContraction at least (the
// factors of the first step from a neighbour's equilibrium are those of the solution to a few 1e-3,
// so that a chord step gains about as many digits as a Newton step, for a fifth of its price) and
// would reach the floor in kChordsPerNewton more at the last one's rate; elsewhere a Newton step at
// the current state. Once every chain and the platform meet the nested iteration's tolerances and
// chord steps no longer contract (the round-off floor), one more Newton step, whose Schur
// complements give K, the loaded platform stiffness at that state (eq. 21), and whose J and H are
// kept in the chains' states (a step from the floor, which would move the state by round-off, is
// not taken). False after 8 Newton steps without converging, or with `monotone` (the start from
// rest) after a Newton step that did not reduce the residuals (left to the nested iteration, which
// backtracks). `steps` counts the Newton steps (one per chain), not the chord steps.
bool LoadedPlatform::coupled_equilibrium(const Vec6& wrench, Vec6& d, Mat6& K, int& steps, bool monotone) {
  constexpr int kMaxNewtonSteps = 8, kMaxChordSteps = 8;
  const Vec6 w = twist_scale(length_scale_);
  const double ref = wrench.cwiseQuotient(w).norm();
  std::array<Linearization, kMaxChains> lin;
  std::array<Vec6, kMaxChains> wc;
  for (int i = 0; i < num_chains; ++i) wc[i] = twist_scale(chains[i].length_scale());
  std::array<SmallLU, kMaxChains> lu;
  // Per chain, the residual and the target's six unit moves as condense() leaves them: the unit moves'
  // full solutions are never formed, only their last six rows (the chain's dF/dt, into Ksum) and, once
  // dt is known, the one solution of column 0 plus the moves times dt.
  std::array<Forward, kMaxChains> sols;
  std::array<Vec6, kMaxChains> wrench_step;
  PaddedColumns<1> b;
  Mat6 Ksum = Mat6::Zero();
  Eigen::FullPivLU<Mat6> platform_lu;
  bool factored = false, after_newton = false;
  int newton_steps = 0, chord_steps = 0;
  double last_merit = std::numeric_limits<double>::infinity();
  for (;;) {
    // The largest residual in units of its tolerance: each chain's kinematic and static ones, the
    // platform's relative wrench residual (tolerance 100 times the chains').
    double merit = 0.0;
    Vec6 total = Vec6::Zero();
    for (int i = 0; i < num_chains; ++i) {
      FixedChainState& s = states_[i];
      linearize(chains[i], displace(nominal_[i], d), wc[i], s.x, s.wrench, lin[i]);
      merit = std::max({merit, lin[i].kin, lin[i].stat});
      total += s.wrench;
    }
    const Vec6 R = (wrench - total).cwiseQuotient(w);
    merit = std::max(merit, (ref > 0 ? R.norm() / ref : R.norm()) / 100) / equilibrium_tolerance;
    if (!(merit == merit)) return false;  // NaN
    const bool converged = merit <= 1.0;
    if (monotone && after_newton && !converged && merit >= last_merit) return false;
    // A chord step while they contract and would reach the floor within kChordsPerNewton more at
    // the last one's rate (a chord step costs a fifth to a quarter of a Newton step; the first after a
    // Newton step is always tried): from rest, whose first factors lack the load's terms, chords
    // contract slowly, and a Newton step is taken instead (on the 41^3 map of
    // models/orthoglide_puu.yaml under 500 N of docs/maps.md: 4 % more Newton steps, 25 % fewer
    // chord steps). Such a Newton step counts as a chord step against the limits, since it replaces
    // several. Converged, the last step is a Newton step from the state at which they stop
    // contracting or are within kFloor of the tolerances (the round-off floor: 1e-15 relative
    // residuals), so that K is that state's: at a posture of condition number 1e7 a state within
    // the tolerances but not at the floor moves K's smallest eigenvalue by 1e-6
    // (tests/mechanisms/posture_kernels_test.cpp).
    const bool contracting =
        factored && merit < kChordContraction * last_merit && chord_steps < kMaxChordSteps && merit > kFloor;
    const bool slow =
        contracting && !after_newton && std::log(merit / kFloor) > kChordsPerNewton * std::log(last_merit / merit);
    const bool chord = contracting && !slow;
    const bool last = converged && !chord;
    last_merit = merit;
    after_newton = !chord;
    if (chord) {
      ++chord_steps;
      for (int i = 0; i < num_chains; ++i) {
        const int N = lu[i].rows();
        PaddedColumns<1>::View r = b.reset(N);
        r << lin[i].r.cwiseProduct(wc[i]), -lin[i].g;
        lu[i].forward(b);
        lu[i].backward(b, N - 6, N);
        sols[i].view().col(0) = r;
        wrench_step[i] = r.tail<6>();
        if (!wrench_step[i].allFinite()) return false;
      }
    } else {
      if (slow)
        ++chord_steps;
      else if (!last && newton_steps++ >= kMaxNewtonSteps)
        return false;
      // Condensed platform system: sum K_i dt = W_ext - sum (F_i + dF_i0), in the platform's scaling.
      Ksum.setZero();
      for (int i = 0; i < num_chains; ++i) {
        FixedChainState& s = states_[i];
        chains[i].hessian(lin[i].walk, s.wrench, lin[i].H);
        if (!condense(chains[i], wc[i], lin[i], lu[i], sols[i], wrench_step[i], s.K)) return false;
        Ksum += s.K;
      }
      platform_lu.compute(w.cwiseInverse().asDiagonal() * Ksum * w.cwiseInverse().asDiagonal());
      if (!platform_lu.isInvertible()) return false;
      factored = true;
      steps += num_chains;  // newton_iterations counts the factorizations
    }
    // At the floor the step would move the state by round-off; elsewhere (chord steps stopped
    // contracting within the tolerances) it takes the deflection there.
    if (last && merit <= kFloor) break;
    Vec6 F0 = Vec6::Zero();
    for (int i = 0; i < num_chains; ++i) F0 += states_[i].wrench + wrench_step[i].cwiseProduct(wc[i]);
    const Vec6 dt = platform_lu.solve((wrench - F0).cwiseQuotient(w)).cwiseQuotient(w);
    if (!dt.allFinite()) return false;
    for (int i = 0; i < num_chains; ++i) {
      FixedChainState& s = states_[i];
      const int N = lu[i].rows();
      PaddedColumns<1>::View step = b.reset(N);
      step = sols[i].view().col(0);
      step.noalias() += sols[i].view().rightCols<6>() * dt;
      lu[i].backward(b, 0, N - 6);
      if (!step.allFinite()) return false;
      s.x += step.head(N - 6);
      s.wrench += step.tail<6>().cwiseProduct(wc[i]);
    }
    d = pose_difference(displace(displace(nominal_[0], d), dt), nominal_[0]);
    if (last) break;
  }
  for (int i = 0; i < num_chains; ++i) {
    states_[i].J = lin[i].J;
    states_[i].H = lin[i].H;
    states_[i].linearized = states_[i].condensed = true;
  }
  K = Ksum;
  return true;
}

// Eq. (21) at a regular posture: the condensation the equilibrium left (solve_chain,
// coupled_equilibrium); else as vjm::loaded_stiffness computes it (no rigid direction, so its
// complement basis is the identity): K = W X W with X the 6x6 top-left block of A^-1.
bool LoadedPlatform::loaded_stiffness(int i, const FixedChainState& s, Mat6& K) const {
  if (s.condensed) {
    K = s.K;
    return true;
  }
  const FixedChain& c = chains[i];
  const int n = c.num_passive(), m = c.num_virtual();
  const Vec6 w = twist_scale(c.length_scale());
  ChainJacobian walked_J;
  CoordinateMatrix walked_H;
  if (!s.linearized) c.kinematics(s.x, walked_J, &s.wrench, &walked_H);
  const ChainJacobian& J = s.linearized ? s.J : walked_J;
  const CoordinateMatrix& H = s.linearized ? s.H : walked_H;
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

bool LoadedPlatform::solve_chains(const Vec6& d, int& steps) {
  for (int i = 0; i < num_chains; ++i)
    if (!solve_chain(i, displace(nominal_[i], d), states_[i], steps)) return false;
  return true;
}

// vjm::platform_equilibrium_under_wrench: Newton on the platform pose with the loaded stiffness as
// dF/dt, from the current states, the chains' equilibrium at d (at rest: d = 0).
bool LoadedPlatform::nested_equilibrium(const Vec6& wrench, Vec6& d, Mat6& K, int& steps) {
  const Vec6 w = twist_scale(length_scale_);
  const double ref = wrench.cwiseQuotient(w).norm();
  for (int it = 0;; ++it) {
    if (!platform_stiffness(K)) return false;
    Vec6 total = Vec6::Zero();
    for (int i = 0; i < num_chains; ++i) total += states_[i].wrench;
    const Vec6 R = (wrench - total).cwiseQuotient(w);
    const double res = ref > 0 ? R.norm() / ref : R.norm();
    if (res <= 100 * equilibrium_tolerance) break;
    if (it >= max_iterations) return false;
    const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
    const Eigen::FullPivLU<Mat6> lu(Kt);
    if (!lu.isInvertible()) return false;  // a free direction: the wrench cannot be resisted
    const Vec6 dt = lu.solve(R).cwiseQuotient(w);
    d = pose_difference(displace(displace(nominal_[0], d), dt), nominal_[0]);
    if (!solve_chains(d, steps)) return false;
  }
  return true;
}

void LoadedPlatform::reset_to_rest() {
  for (int i = 0; i < num_chains; ++i) {
    states_[i].x = rest_[i];
    states_[i].wrench.setZero();
    states_[i].linearized = states_[i].condensed = false;
  }
}

bool LoadedPlatform::equilibrium(const Vec6* displacement, const Vec6* wrench, bool at_rest, Vec6& d, Mat6& K,
                                 bool& have_K, int& steps) {
  have_K = false;
  if (!at_rest) {
    if (displacement) return solve_chains(d = *displacement, steps);
    return have_K = coupled_equilibrium(*wrench, d, K, steps, false);
  }
  // Under a wrench, first the coupled iteration from rest (its first step is the linear response),
  // kept where every Newton step reduces the residuals.
  if (wrench && (have_K = coupled_equilibrium(*wrench, d, K, steps, true))) return true;
  if (!fallbacks) return displacement && solve_chains(d = *displacement, steps);
  // Then the load in n equal increments, each from the previous one's equilibrium: n = 1 first (the
  // reference's start from rest); where that does not converge, 2, 4 and 8 increments (the natural
  // branch followed from rest, which a far first Newton step can miss). Under a wrench the nested
  // iteration's answer is then finished by the coupled one: its Newton steps on all the unknowns
  // reach the round-off floor (relative residuals ~1e-16, the nested iteration's ~1e-13), so that all
  // starts agree to the conditioning of the equilibrium, not to a tolerance (2e-10 apart in the
  // deflection next to the buckling limit without it).
  for (int n = 1; n <= 8; n *= 2) {
    reset_to_rest();
    d.setZero();
    bool ok = true;
    for (int k = 1; k <= n && ok; ++k) {
      const double share = static_cast<double>(k) / n;
      ok = displacement ? solve_chains(d = share * *displacement, steps)
                        : nested_equilibrium(share * *wrench, d, K, steps);
    }
    if (ok) return displacement || (have_K = coupled_equilibrium(*wrench, d, K, steps, false));
  }
  // Last, under a wrench, the coupled iteration itself from rest, in the same increments: where a
  // chain's own iteration fails on the way (measured: a 3-PRPaR corner under 5 kN, which warm starts
  // from all six neighbours reach in five steps), the platform and chains converge together.
  for (int n = 1; n <= 8 && wrench; n *= 2) {
    reset_to_rest();
    d.setZero();
    bool ok = true;
    for (int k = 1; k <= n && ok; ++k)
      ok = coupled_equilibrium(static_cast<double>(k) / n * *wrench, d, K, steps, false);
    if (ok) return have_K = true;
  }
  return false;
}

void LoadedPlatform::evaluate(const Vec3& point, const Vec6* displacement, const Vec6* wrench, const Mat6* unloaded,
                              bool warm, PostureResult& r) {
  length_scale_ = 0.0;
  ChainJacobian J;
  std::array<CoordinateVector, kMaxChains>& nominal = rest_;
  for (int i = 0; i < num_chains; ++i) {
    nominal[i] = chains[i].nominal();
    nominal_[i] = chains[i].kinematics(nominal[i], J);
    length_scale_ = std::max(length_scale_, chains[i].length_scale());
  }
  const Vec6 w = twist_scale(length_scale_);
  Vec6 d = Vec6::Zero();
  Mat6 K;
  bool have_K = false, found = false;
  r.newton_iterations = 0;
  // A prescribed displacement beyond kMaxWarmDeflection is solved from rest (part of the branch test
  // below, decided before the attempt).
  const bool within = !displacement || displacement->cwiseProduct(w).norm() <= kMaxWarmDeflection;
  // Under a wrench, |W (d - d0)| / (kMaxNonlinearity |W d0|) with d0 = K0^-1 W_ext the linear deflection
  // (K0 the unloaded stiffness, scaled twists); 0 without a wrench or K0, infinite where K0 is not
  // positive definite.
  Vec6 d0 = Vec6::Zero();
  bool have_d0 = false;
  const auto nonlinearity = [&](const Vec6& deflection) {
    if (!wrench || !unloaded) return 0.0;
    if (!have_d0) {
      const Mat6 K0t = w.cwiseInverse().asDiagonal() * *unloaded * w.cwiseInverse().asDiagonal();
      const Eigen::LLT<Mat6> llt(0.5 * (K0t + K0t.transpose()));
      if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
      d0 = llt.solve(wrench->cwiseQuotient(w));
      have_d0 = true;
    }
    return (deflection.cwiseProduct(w) - d0).norm() / (kMaxNonlinearity * d0.norm());
  };
  const int order = warm ? extrapolation_order(
                               point, [&](int k) { return solved_[k].point; }, solved_.size())
                         : 0;
  // No warm start where this point's nonlinearity, extrapolated along the path from the points before
  // (the line through the last two at most), fails the branch test below: the point would be solved
  // from rest besides.
  const auto predicted_nonlinearity = [&] {
    const double last = solved_[0].nonlinearity;
    if (order == 1) return last;
    const double before = solved_[1].nonlinearity;
    return std::isfinite(before) ? 2.0 * last - before : before;  // infinite: not tried
  };
  if (order > 0 && unloaded && within && predicted_nonlinearity() <= 1.0) {
    // The predictor: the neighbour's equilibrium carried over (each passive joint keeps its deflection
    // from its nominal angle, each spring its deflection, each chain its wrench, the platform its
    // displacement), extrapolated from the points before where the path goes straight on at their
    // spacing (path_extrapolation.hpp): the secant through two, the parabola through three (on the
    // 3-PUU's 5 mm grid under 500 N its residuals start at ~1e-5 where the secant's were ~2e-4, which
    // saves a chord step), the cubic through four (~1e-6) or the quartic through five (~3e-8, from
    // which one Newton step lands at the round-off floor: no chord step).
    const std::array<double, kMaxExtrapolationOrder>& c = kExtrapolationWeights[order - 1];
    d.setZero();
    for (int k = 0; k < order; ++k) d += c[k] * solved_[k].d;
    for (int i = 0; i < num_chains; ++i) {
      FixedChainState& s = states_[i];
      s.x = nominal[i];
      s.wrench.setZero();
      for (int k = 0; k < order; ++k) {
        s.x += c[k] * solved_[k].deflection[i];
        s.wrench += c[k] * solved_[k].wrench[i];
      }
      s.linearized = s.condensed = false;
    }
    found = equilibrium(displacement, wrench, false, d, K, have_K, r.newton_iterations);
    // The branch test: a warm start follows the neighbour's equilibrium branch, the start from rest
    // may find another where the load softens the robot much (next to a buckling limit, beyond which
    // Newton from rest can land on an unstable equilibrium) or where the equilibrium is far from the
    // linear response (several stiff equilibria: 1-3 points of 1331 of the 3-PUU's map differed by
    // up to 95 % under 14-20 kN, deflections of 9-38 mm). So the warm answer is kept only where the
    // load leaves more than kBranchSoftening of the stiffness in every direction, of the platform
    // (sym K - kBranchSoftening sym K0 positive definite, K0 unloaded, scaled twists) and of every
    // chain's springs (sym(K_theta - H_thetatheta) - kBranchSoftening K_theta: eq. 21's spring block),
    // and, under a wrench, where the deflection d is within kMaxNonlinearity of the linear one
    // d0 = K0^-1 W_ext, |W (d - d0)| <= kMaxNonlinearity |W d0|: d0 is the first step of the start
    // from rest (nested_equilibrium at rest, K = K0), which then lands on the equilibrium next to it.
    // Elsewhere the point is solved from rest, as it would be alone. (With kBranchSoftening 0.5 and
    // kMaxNonlinearity 0.1, warm answers kept next to the 3-PRPaR's buckling limit under 20 kN
    // differed from the start from rest by up to 4e-8, the conditioning of those equilibria.)
    if (found) {
      if (!have_K && !platform_stiffness(K)) found = false;
      have_K = found;
      const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
      const Mat6 K0t = w.cwiseInverse().asDiagonal() * *unloaded * w.cwiseInverse().asDiagonal();
      const Mat6 margin = 0.5 * (Kt + Kt.transpose()) - kBranchSoftening * 0.5 * (K0t + K0t.transpose());
      if (found && Eigen::LLT<Mat6>(margin).info() != Eigen::Success) found = false;
      if (found && wrench) found = nonlinearity(d) <= 1.0;
      for (int i = 0; i < num_chains && found; ++i) {
        const FixedChain& c = chains[i];
        const int m = c.num_virtual();
        const auto Hth = states_[i].H.bottomRightCorner(m, m);
        const CoordinateMatrix spring = (1.0 - kBranchSoftening) * c.spring_stiffness() - 0.5 * (Hth + Hth.transpose());
        found = states_[i].linearized && Eigen::LLT<CoordinateMatrix>(spring).info() == Eigen::Success;
      }
    }
  }
  if (!found) {
    reset_to_rest();
    d.setZero();
    found = equilibrium(displacement, wrench, true, d, K, have_K, r.newton_iterations);
  }
  // An extrapolation needs the points before on this path: not across a start from scratch (a path
  // chunk's first point), whose predecessor in this clone belongs to another chunk, nor across a point
  // that did not end kOk.
  if (!warm) solved_.clear();
  const auto fail = [&](PostureStatus status) {
    r.status = status;
    solved_.clear();
  };
  if (!found) return fail(PostureStatus::kFailed);
  if (!have_K && !platform_stiffness(K)) return fail(PostureStatus::kSingular);
  // vjm's aggregate: a singular value of the scaled K below rank_tolerance of the largest is a free
  // direction (the compliance is undefined).
  const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
  Mat6 Ct;
  if (!regular_inverse(Kt, rank_tolerance, Ct)) return fail(PostureStatus::kSingular);
  r.status = PostureStatus::kOk;
  set_stiffness(r, K, w.cwiseInverse().asDiagonal() * Ct * w.cwiseInverse().asDiagonal());
  r.deflection = d;
  Solved& latest = solved_.push();
  latest.point = point;
  for (int i = 0; i < num_chains; ++i) {
    latest.deflection[i] = states_[i].x - nominal[i];
    latest.wrench[i] = states_[i].wrench;
  }
  latest.d = d;
  latest.nonlinearity = nonlinearity(d);
}

}  // namespace kinestat::mechanisms::fixed_vjm
