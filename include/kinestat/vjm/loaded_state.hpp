// The loaded configuration of a chain and of a platform: what the equilibrium (vjm/equilibrium.hpp,
// eq. 11-15) finds and the loaded stiffness (vjm/stiffness.hpp, eq. 19-21) starts from.
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/types.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::vjm {

struct ConvergenceReport {
  bool converged = false;
  std::string method;  // "eq. (15) iteration" or "Newton-Raphson (after eq. (15) stalled)"
  int fixed_point_iterations = 0;
  int newton_iterations = 0;
  double kinematic_residual = 0.0;  // dimensionless, see EquilibriumOptions::tolerance
  double static_residual = 0.0;     // relative
  std::string summary() const;      // one line in words
};

// One chain at equilibrium.
struct ChainState {
  VecX q;                      // passive coordinates (m, rad)
  VecX theta;                  // virtual spring coordinates (m, rad)
  Vec6 wrench = Vec6::Zero();  // F: external wrench on the tool carried by this chain (N, N m about the tool point)
  Transform pose = Transform::Identity();
  ConvergenceReport report;
};

// Several chains sharing one platform: every chain's tool frame is the platform's reference point.
struct PlatformState {
  std::vector<ChainState> chains;
  Vec6 displacement = Vec6::Zero();  // of the tool point from the nominal pose (m, rad)
  Vec6 wrench = Vec6::Zero();        // total external wrench, sum of the chains' (N, N m)
  ConvergenceReport report;          // of the outer iteration (wrench-prescribed) or the worst chain
};

}  // namespace kinestat::vjm
