// Loaded static equilibrium of VJM chains (Pashkevich et al. 2009, section 3.2, eq. 11-15):
// for a prescribed tool displacement, find (q, theta, F) with
//   t = f(q, theta),   J_theta^T F = K_theta theta,   J_q^T F = 0          (eq. 11)
// by the paper's iteration (eq. 15, with its right-hand side sign corrected, docs/vjm.md), falling
// back to a full Newton-Raphson on all of (11) when that iteration stalls or diverges. For a
// prescribed external wrench on a platform of several chains, an outer Newton iteration on the
// platform pose uses the loaded stiffness (eq. 21) as the Jacobian dF/dt.
#pragma once

#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/vjm/chain.hpp"
#include "kinestat/vjm/loaded_state.hpp"

namespace kinestat::vjm {

struct EquilibriumOptions {
  int max_fixed_point_iterations = 50;  // eq. (15)
  int max_newton_iterations = 50;       // full Newton-Raphson fallback (and outer platform iteration)
  bool newton_fallback = true;
  // Convergence: the relative static residual |J^T F - K theta| / (|J^T F| + |K theta|) below this,
  // and the kinematic residual |t - f| (translation / length scale, rotation in rad) below this times
  // the prescribed displacement (same scaling), or at the pose's round-off floor 16 eps. Under a
  // prescribed wrench, the relative wrench residual below 100 times this, or stalled at its round-off
  // floor ~eps |K| (very stiff springs).
  double tolerance = 1e-12;       // the round-off floor of the static residual is ~1e-14 for stiff chains
  double rank_tolerance = 1e-10;  // as StiffnessOptions::rank_tolerance
  int max_chain_coordinates = kDefaultMaxChainCoordinates;  // as StiffnessOptions::max_chain_coordinates
};

// Equilibrium of one chain whose tool is displaced by `displacement` (dx dy dz in m, rotation
// vector in rad, global axes) from its nominal pose (eq. 11). Starts from `start` if given, else
// from the unloaded configuration (q0, 0). kNotConverged carries the report in its message.
StatusOr<ChainState> chain_equilibrium(const Chain& chain, const Vec6& displacement,
                                       const EquilibriumOptions& options = {}, const ChainState* start = nullptr);

StatusOr<PlatformState> platform_equilibrium(const std::vector<Chain>& chains, const Vec6& displacement,
                                             const EquilibriumOptions& options = {});
// Prescribed external wrench W (N, N m about the tool point). A wrench component along a free
// direction of the platform cannot be resisted (kSingular); along a rigid one it is a reaction.
StatusOr<PlatformState> platform_equilibrium_under_wrench(const std::vector<Chain>& chains, const Vec6& wrench,
                                                          const EquilibriumOptions& options = {});

// Where the equilibrium under a load is not found (kNotConverged): how much of that load it reaches,
// by bisection on the load's share s in (0, 1), each share's equilibrium solved as the whole load's
// is (platform_equilibrium of s times the displacement, or _under_wrench of s times the wrench;
// exactly one of them given). `found`: the largest share with an equilibrium, 0 where none was found
// down to `failed`; `failed`: the smallest share above it without one, within `resolution` of it
// (at least 1e-9).
// The last load the solve reaches, not a buckling load: Newton may find equilibria past a buckling
// load, or lose them before it, far along a large deflection.
struct LoadShare {
  double found = 0.0;
  double failed = 1.0;
};
LoadShare load_share_reached(const std::vector<Chain>& chains, const Vec6* displacement, const Vec6* wrench,
                             const EquilibriumOptions& options = {}, double resolution = 1.0 / 128);

}  // namespace kinestat::vjm
