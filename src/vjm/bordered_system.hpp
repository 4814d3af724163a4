// The bordered system of eq. (9),  [S J_q; J_q^T 0] [F; dq] = [dt; 0],  S = J_theta K_theta^-1 J_theta^T,
// solved by orthogonal elimination rather than by inverting it, so that singular postures give the
// stiffness that exists. Used by the unloaded stiffness (eq. 10) and by each step of the loaded
// equilibrium iteration (eq. 15).
//
// Method: the second block row says F lies in null(J_q^T) = span(N), N from the SVD of J_q. Then
// F = N y and N^T (first row) gives (N^T S N) y = N^T dt, so K = N (N^T S N)^-1 N^T (eq. 10). A zero
// eigenvalue of N^T S N is a rigid direction (no spring and no passive joint moves the tool along
// it); a zero singular value of J_q is a passive self-motion (it does not affect K). All rank
// decisions are made on twists scaled by the chain length L (translations in units of L, rotations
// in rad), so they do not depend on the unit of length.
#pragma once

#include <vector>

#include "kinestat/core/types.hpp"

namespace kinestat::vjm {

// Twist scaling W = diag(I/L, I): a scaled twist is W t, a scaled wrench W^-1 F, K = W K~ W.
Vec6 twist_scale(double length_scale);

struct BorderedSystem {
  Mat6 S = Mat6::Zero();               // unscaled spring compliance at the tool, S = J_theta K_theta^-1 J_theta^T
  Mat6 K = Mat6::Zero();               // unscaled chain stiffness (finite part), eq. (10)
  std::vector<Vec6> rigid_directions;  // unit twists nothing produces
  std::vector<VecX> self_motions;      // unit dq with J_q dq = 0
  MatX Jq_pinv;                        // n x 6 pseudo-inverse of J_q (rank-truncated)

  // Solves (9) with right-hand side (dt, 0): F = K dt and dq = J_q^+ (dt - S F). Components of dt
  // along rigid directions cannot be produced and are ignored (their force is a reaction).
  void solve(const Vec6& dt, Vec6* F, VecX* dq) const;
};

// S from the Jacobian J_theta and the chain's springs (block solves, no inverse of K_theta).
Mat6 spring_compliance(const MatX& Jtheta, const MatX& Ktheta);

BorderedSystem factor_bordered_system(const MatX& Jq, const Mat6& S, double length_scale, double rank_tolerance);

// A scaled direction mapped back to twist units (W^-1 t~) and unit-normalized, for reporting.
Vec6 unscaled_direction(const Vec6& scaled, double length_scale);

// Orthonormal split of the scaled tool space by the range of [W J_q, W J_theta] (columns normalized):
// U's first `rank` columns span the tool motions that some joint or spring produces, the others the
// rigid directions. A scaled wrench W^-1 F in the rigid part is a reaction: J^T F = 0, it loads no
// joint and no spring (but it does enter the Hessians of the loaded mode).
struct ToolSpaceSplit {
  Mat6 U = Mat6::Identity();
  int rank = 0;
  MatX rigid() const { return U.rightCols(6 - rank); }
};
ToolSpaceSplit split_tool_space(const MatX& Jq, const MatX& Jtheta, const Vec6& w, double rank_tolerance);

}  // namespace kinestat::vjm
