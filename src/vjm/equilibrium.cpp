#include "kinestat/vjm/equilibrium.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/vjm/platform.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "vjm/bordered_system.hpp"

namespace kinestat::vjm {

std::string ConvergenceReport::summary() const {
  return fmt::format(
      "{} after {} eq. (15) and {} Newton iterations via {}: kinematic residual {:.2e}, static "
      "residual {:.2e}",
      converged ? "converged" : "NOT converged", fixed_point_iterations, newton_iterations,
      method.empty() ? "none" : method, kinematic_residual, static_residual);
}

namespace {

// Everything one iteration needs at (q, theta, F).
struct Linearization {
  ChainJacobians J;
  Vec6 r;        // t - f(q, theta) as a twist
  VecX gq, gth;  // J_q^T F and J_theta^T F - K_theta theta (both zero at equilibrium)
  double kin = 0.0, stat = 0.0;
  double merit() const { return kin + stat; }
};

Linearization linearize(const Chain& chain, const MatX& Kth, const Transform& target, const Vec6& w, const VecX& q,
                        const VecX& th, const Vec6& F) {
  Linearization l;
  l.J = jacobians(chain, q, th);
  l.r = pose_difference(target, l.J.pose);
  l.kin = l.r.cwiseProduct(w).norm();
  const VecX JtF = l.J.Jtheta.transpose() * F, Kt = Kth * th;
  l.gq = l.J.Jq.transpose() * F;
  l.gth = JtF - Kt;
  const double num = std::sqrt(l.gq.squaredNorm() + l.gth.squaredNorm());
  const double den = l.gq.norm() + JtF.norm() + Kt.norm();
  l.stat = num > 0 ? num / den : 0.0;
  return l;
}

}  // namespace

StatusOr<ChainState> chain_equilibrium(const Chain& chain, const Vec6& displacement, const EquilibriumOptions& opt,
                                       const ChainState* start) {
  if (Status s = chain.validate(opt.max_chain_coordinates); !s.ok()) return s;
  if (!displacement.allFinite())
    return Status::Invalid(fmt::format("chain '{}': the prescribed displacement is not finite", chain.name()));
  const int n = chain.num_passive(), m = chain.num_virtual();
  const double L = chain.length_scale();
  const Vec6 w = twist_scale(L);
  const MatX Kth = chain.spring_stiffness();
  const Eigen::LLT<MatX> Kllt(Kth);
  const Transform target = displace(chain.nominal_pose(), displacement);

  ChainState s;
  s.q = start ? start->q : chain.nominal_passive();
  s.theta = start ? start->theta : VecX::Zero(m);
  s.wrench = start ? start->wrench : Vec6::Zero();
  if (s.q.size() != n || s.theta.size() != m)
    return Status::Invalid(
        fmt::format("chain '{}': the start state has {} passive and {} virtual coordinates, the "
                    "chain {} and {}",
                    chain.name(), s.q.size(), s.theta.size(), n, m));
  ConvergenceReport& rep = s.report;
  Linearization lin = linearize(chain, Kth, target, w, s.q, s.theta, s.wrench);
  // The pose error's share of the force is what counts: relative to the prescribed displacement (a
  // 1e-12 m displacement of a 1e12 N/m spring carries 1 N), down to the pose's round-off (~eps of
  // the length scale), below which no iteration can go.
  const double kin_tolerance =
      std::max(opt.tolerance * displacement.cwiseProduct(w).norm(), 16 * std::numeric_limits<double>::epsilon());
  auto done = [&](const Linearization& l) { return l.kin <= kin_tolerance && l.stat <= opt.tolerance; };

  // Paper's iteration (eq. 15): linearize the geometry only, statics with the old Jacobians.
  // From (12)-(13): S F + J_q dq = t - f + J_theta theta_i (the printed sign of the J terms is
  // wrong, docs/vjm.md), then theta_{i+1} = K_theta^-1 J_theta^T F.
  rep.method = "eq. (15) iteration";
  double best = lin.merit();
  VecX best_q = s.q, best_theta = s.theta;
  Vec6 best_wrench = s.wrench;
  int worse = 0;
  while (!done(lin) && rep.fixed_point_iterations < opt.max_fixed_point_iterations) {
    const BorderedSystem B =
        factor_bordered_system(lin.J.Jq, spring_compliance(lin.J.Jtheta, Kth), L, opt.rank_tolerance);
    VecX dq;
    Vec6 F;
    B.solve(lin.r + lin.J.Jtheta * s.theta, &F, &dq);
    s.q += dq;
    s.theta = m > 0 ? VecX(Kllt.solve(lin.J.Jtheta.transpose() * F)) : VecX(0);
    s.wrench = F;
    ++rep.fixed_point_iterations;
    lin = linearize(chain, Kth, target, w, s.q, s.theta, s.wrench);
    // Stalled or diverging (near buckling the fixed point is repelling): hand over to Newton.
    if (lin.merit() < 0.5 * best) {
      best = lin.merit();
      best_q = s.q;
      best_theta = s.theta;
      best_wrench = s.wrench;
      worse = 0;
    } else if (++worse >= 3) {
      break;
    }
  }
  if (lin.merit() > best) {  // Newton starts from the best iterate, not from a diverged one
    s.q = best_q;
    s.theta = best_theta;
    s.wrench = best_wrench;
    lin = linearize(chain, Kth, target, w, s.q, s.theta, s.wrench);
  }

  // Full Newton-Raphson on (11): unknowns (dq, dtheta, dF), rows (kinematics, J_q^T F, J_theta^T F - K theta).
  if (!done(lin) && opt.newton_fallback) {
    rep.method = "Newton-Raphson (after eq. (15) stalled)";
    while (!done(lin) && rep.newton_iterations < opt.max_newton_iterations) {
      const ChainHessians H = hessians(chain, s.q, s.theta, s.wrench);
      const int N = n + m + 6;
      MatX A = MatX::Zero(N, N);
      VecX b(N);
      // Kinematic rows scaled by W and the force unknown as W^-1 F: every block is then O(1) in length.
      A.block(0, 0, 6, n) = w.asDiagonal() * lin.J.Jq;
      A.block(0, n, 6, m) = w.asDiagonal() * lin.J.Jtheta;
      A.block(6, 0, n, n) = H.Hqq;
      A.block(6, n, n, m) = H.Hqtheta;
      A.block(6, n + m, n, 6) = lin.J.Jq.transpose() * w.asDiagonal();
      A.block(6 + n, 0, m, n) = H.Hthetaq;
      A.block(6 + n, n, m, m) = H.Hthetatheta - Kth;
      A.block(6 + n, n + m, m, 6) = lin.J.Jtheta.transpose() * w.asDiagonal();
      b << lin.r.cwiseProduct(w), -lin.gq, -lin.gth;
      const VecX d = Eigen::CompleteOrthogonalDecomposition<MatX>(A).solve(b);
      // Backtracking on the merit: a full step may overshoot far from the solution.
      double step = 1.0;
      for (int k = 0; k < 20; ++k, step *= 0.5) {
        const VecX q = s.q + step * d.head(n), th = s.theta + step * d.segment(n, m);
        const Vec6 F = s.wrench + step * d.tail<6>().cwiseProduct(w);
        Linearization trial = linearize(chain, Kth, target, w, q, th, F);
        if (trial.merit() < lin.merit() || k == 19) {
          s.q = q;
          s.theta = th;
          s.wrench = F;
          lin = std::move(trial);
          break;
        }
      }
      ++rep.newton_iterations;
    }
  }
  rep.converged = done(lin);
  rep.kinematic_residual = lin.kin;
  rep.static_residual = lin.stat;
  s.pose = lin.J.pose;
  if (!rep.converged)
    return Status::NotConverged(
        fmt::format("chain '{}': the loaded equilibrium was not found ({}). The load may "
                    "exceed the buckling load, or the displacement asks for motion along a "
                    "direction the chain cannot move in",
                    chain.name(), rep.summary()));
  return s;
}

namespace {

// Sets every chain's share of the reaction to the external wrench W and returns the unbalanced rest
// W^-1 (W - sum F_i), scaled and free of reactions. A chain's wrench is defined only up to its
// rigid directions (J_i^T F = 0: no joint or spring feels it), so that part is first removed; the
// reaction part of W - sum F_i is then split over the chains' rigid spaces by minimum norm (scaled
// wrenches), which is unique when those spaces are independent (one chain, or chains rigid in
// different directions). Chains rigid in one common direction share its reaction equally in that
// sense: the idealization of exact rigidity does not say how (docs/vjm.md).
Vec6 assign_reactions(const std::vector<Chain>& chains, const Vec6& w, const Vec6& W, double rank_tolerance,
                      PlatformState& P) {
  std::vector<MatX> rigid(chains.size());
  Eigen::Index total = 0;
  P.wrench.setZero();
  for (size_t i = 0; i < chains.size(); ++i) {
    const Chain& c = chains[i];
    ChainState& s = P.chains[i];
    const ChainJacobians J = jacobians(c, s.q, s.theta);
    // Rigid span in the chain's own scaling (as its stiffness decides), as scaled platform wrenches.
    const Vec6 wc = twist_scale(c.length_scale());
    const MatX Fr = wc.asDiagonal() * split_tool_space(J.Jq, J.Jtheta, wc, rank_tolerance).rigid();
    if (Fr.cols() > 0)
      rigid[i] =
          Eigen::HouseholderQR<MatX>(w.cwiseInverse().asDiagonal() * Fr).householderQ() * MatX::Identity(6, Fr.cols());
    else
      rigid[i] = MatX(6, 0);
    Vec6 f = s.wrench.cwiseQuotient(w);
    f -= rigid[i] * (rigid[i].transpose() * f);
    s.wrench = f.cwiseProduct(w);
    P.wrench += s.wrench;
    total += Fr.cols();
  }
  Vec6 R = (W - P.wrench).cwiseQuotient(w);
  if (total == 0) return R;
  MatX B(6, total);
  Eigen::Index col = 0;
  for (const MatX& r : rigid) {
    B.middleCols(col, r.cols()) = r;
    col += r.cols();
  }
  const VecX a = Eigen::CompleteOrthogonalDecomposition<MatX>(B).solve(R);
  col = 0;
  for (size_t i = 0; i < chains.size(); ++i) {
    const Vec6 share = (rigid[i] * a.segment(col, rigid[i].cols())).cwiseProduct(w);
    col += rigid[i].cols();
    P.chains[i].wrench += share;
    P.wrench += share;
  }
  return R - B * a;
}

StatusOr<PlatformState> solve_chains(const std::vector<Chain>& chains, const Vec6& displacement,
                                     const EquilibriumOptions& opt, const PlatformState* start) {
  PlatformState P;
  P.displacement = displacement;
  P.report.converged = true;
  for (size_t i = 0; i < chains.size(); ++i) {
    StatusOr<ChainState> s = chain_equilibrium(chains[i], displacement, opt, start ? &start->chains[i] : nullptr);
    if (!s.ok()) return s.status();
    P.wrench += s->wrench;
    const ConvergenceReport& r = s->report;
    // The platform's report is the worst chain's.
    if (r.fixed_point_iterations + r.newton_iterations >=
        P.report.fixed_point_iterations + P.report.newton_iterations) {
      P.report.method = r.method;
      P.report.fixed_point_iterations = r.fixed_point_iterations;
      P.report.newton_iterations = r.newton_iterations;
    }
    P.report.kinematic_residual = std::max(P.report.kinematic_residual, r.kinematic_residual);
    P.report.static_residual = std::max(P.report.static_residual, r.static_residual);
    P.chains.push_back(std::move(*s));
  }
  return P;
}

// Each component finite and in its physical range (core/input_checks.hpp), named in the message.
Status check_twist_or_wrench(const Vec6& v, bool wrench) {
  static const char* kNames[2][6] = {{"dx", "dy", "dz", "rx", "ry", "rz"}, {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}};
  for (int k = 0; k < 6; ++k) {
    const Quantity q =
        wrench ? (k < 3 ? Quantity::kForce : Quantity::kMoment) : (k < 3 ? Quantity::kLength : Quantity::kAngle);
    const std::string item =
        fmt::format("the prescribed {} {}", wrench ? "wrench" : "displacement", kNames[wrench ? 1 : 0][k]);
    if (Status s = check_quantity(v[k], q, item); !s.ok()) return s;
  }
  return Status::Ok();
}

}  // namespace

StatusOr<PlatformState> platform_equilibrium(const std::vector<Chain>& chains, const Vec6& displacement,
                                             const EquilibriumOptions& opt) {
  if (Status s = validate_platform(chains, opt.max_chain_coordinates); !s.ok()) return s;
  if (Status s = check_twist_or_wrench(displacement, false); !s.ok()) return s;
  return solve_chains(chains, displacement, opt, nullptr);
}

StatusOr<PlatformState> platform_equilibrium_under_wrench(const std::vector<Chain>& chains, const Vec6& wrench,
                                                          const EquilibriumOptions& opt) {
  if (Status s = validate_platform(chains, opt.max_chain_coordinates); !s.ok()) return s;
  if (Status s = check_twist_or_wrench(wrench, true); !s.ok()) return s;
  const double L = platform_length_scale(chains);
  const Vec6 w = twist_scale(L);
  const StiffnessOptions sopt{opt.rank_tolerance, opt.max_chain_coordinates};
  StatusOr<PlatformState> P = solve_chains(chains, Vec6::Zero(), opt, nullptr);
  if (!P.ok()) return P;
  const Transform nominal = chains[0].nominal_pose();
  // Outer Newton on the platform pose: dF/dt is the loaded stiffness (eq. 21), so each step solves
  // K^F dt = W - F(t) and re-solves every chain's equilibrium at the new pose.
  const double ref = wrench.cwiseQuotient(w).norm();
  double previous = std::numeric_limits<double>::infinity();
  int it = 0;
  for (;; ++it) {
    // The residual's part along rigid directions is a reaction: distributed over the chains before
    // K^F is formed, because it enters their Hessians (the F / l of a pulled rigid link).
    const Vec6 R = assign_reactions(chains, w, wrench, opt.rank_tolerance, *P);
    StatusOr<CartesianStiffness> K = platform_loaded_stiffness(chains, *P, sopt);
    if (!K.ok()) return K.status();
    // Scaled system K~ dt~ = R~ with K~ = W^-1 K W^-1.
    const Mat6 Kt = w.cwiseInverse().asDiagonal() * K->stiffness * w.cwiseInverse().asDiagonal();
    const double res = ref > 0 ? R.norm() / ref : R.norm();
    P->report.method = "Newton-Raphson on the platform pose (loaded stiffness, eq. 21)";
    P->report.newton_iterations = it;
    if (res <= 100 * opt.tolerance) break;
    // Round-off floor: each chain's wrench is K times a pose known to ~eps (relative to the length
    // scale), so with very stiff springs (1e12 N/m) |R~| cannot go below ~eps |K~| however small the
    // load (measured: ~0.1 eps |K~|). Once Newton stops halving the residual there, that is convergence.
    const double floor = 100 * std::numeric_limits<double>::epsilon() * Kt.norm();
    if (R.norm() <= floor && res > 0.5 * previous) break;
    previous = res;
    for (const Vec6& u : K->free_directions) {
      const Vec6 us = u.cwiseProduct(w).normalized();  // u^T F = (W u)^T (W^-1 F)
      if (std::abs(us.dot(R)) > 1e-6 * R.norm())
        return Status::Singular(
            fmt::format("the platform cannot resist the wrench: it moves freely along {}", describe_twist(u)));
    }
    if (it >= opt.max_newton_iterations) {
      P->report.converged = false;
      return Status::NotConverged(
          fmt::format("the platform equilibrium under the wrench did not converge in {} "
                      "iterations (relative wrench residual {:.2e}); the load may exceed the "
                      "buckling load",
                      it, res));
    }
    // Minimum norm along lost directions.
    const Vec6 dt = Eigen::CompleteOrthogonalDecomposition<Mat6>(Kt).solve(R).cwiseQuotient(w);
    const Vec6 d = pose_difference(displace(displace(nominal, P->displacement), dt), nominal);
    StatusOr<PlatformState> next = solve_chains(chains, d, opt, &*P);
    if (!next.ok()) return next;
    P = std::move(next);
  }
  // Report the applied wrench, reactions included.
  P->wrench = wrench;
  return P;
}

LoadShare load_share_reached(const std::vector<Chain>& chains, const Vec6* displacement, const Vec6* wrench,
                             const EquilibriumOptions& options, double resolution) {
  const auto reached = [&](double share) {
    return displacement ? platform_equilibrium(chains, share * *displacement, options).ok()
                        : platform_equilibrium_under_wrench(chains, share * *wrench, options).ok();
  };
  LoadShare s;
  if (!displacement == !wrench) return s;
  const double step = resolution > 1e-9 ? resolution : 1e-9;  // a bisection that ends, NaN included
  while (s.failed - s.found > step) {
    const double mid = 0.5 * (s.found + s.failed);
    (reached(mid) ? s.found : s.failed) = mid;
  }
  return s;
}

}  // namespace kinestat::vjm
