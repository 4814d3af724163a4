// VJM Cartesian stiffness: one chain unloaded (eq. 9-10), one chain loaded (eq. 19-21), and the
// aggregation over the chains that share a platform (K = sum K_i, section 3.3).
//
// Singular postures: the matrix of eq. (9) loses rank when a tool direction is neither compliant
// nor free (a "rigid" direction: no spring and no passive joint moves the tool along it, infinite
// stiffness) or when the passive joints have a self-motion (several q give the same tool motion;
// it changes nothing in K). Both are solved by orthogonal elimination instead of inverting eq. (9):
// the stiffness that exists is returned and the lost directions are named. See docs/vjm.md.
#pragma once

#include <vector>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/vjm/chain.hpp"
#include "kinestat/vjm/loaded_state.hpp"

namespace kinestat::vjm {

struct StiffnessOptions {
  // Relative tolerance (on dimensionless, length-scaled quantities) below which a singular value
  // or eigenvalue counts as zero: a lost direction. 1e-10 keeps ~6 digits of double precision for
  // what is kept and still separates a spring 1e6 times stiffer than the others.
  double rank_tolerance = 1e-10;
  int max_chain_coordinates = kDefaultMaxChainCoordinates;  // a longer chain is refused (vjm/chain.hpp)
};

// Results are kinestat::CartesianStiffness (core/cartesian_stiffness.hpp): the tool point, global
// axes; `stiffness` is the finite part, the lost directions are listed, and a passive self-motion
// (several q giving the same tool motion) is named in `note`.

// Unloaded stiffness of one chain at its nominal passive coordinates, theta = 0 (eq. 9-10).
StatusOr<CartesianStiffness> unloaded_stiffness(const Chain& chain, const StiffnessOptions& options = {});

// Loaded-mode stiffness dF = K^F dt of one chain at an equilibrium (q, theta, F) (eq. 19-21).
// Asymmetric when the wrench has a moment (docs/vjm.md). kSingular error when K_theta - H_thetatheta
// is singular (the springs buckle under this load).
StatusOr<CartesianStiffness> loaded_stiffness(const Chain& chain, const ChainState& state,
                                              const StiffnessOptions& options = {});

// Platform stiffness: sum of the chains' matrices; a free direction of the sum (the platform is a
// mechanism there) is reported with kSingular and leaves the compliance undefined.
CartesianStiffness aggregate(const std::vector<CartesianStiffness>& chains, double length_scale,
                             const StiffnessOptions& options = {});

StatusOr<CartesianStiffness> platform_unloaded_stiffness(const std::vector<Chain>& chains,
                                                         const StiffnessOptions& options = {});

// platform_unloaded_stiffness for a posture kernel, which moves the same chains from posture to
// posture (Chain::set_offset, set_transform, set_nominal_passive): the chains' structure is checked
// and K_theta factored once, spring by spring (prepare_regular_stiffness; again where a spring changed:
// Chain::set_spring_stiffness), and each posture computes eq. (10) with
// preallocated data and no rank-revealing decomposition, K = N (N^T S N)^-1 N^T (bordered_system.hpp)
// with N from a Householder QR of the scaled J_q, N^T S N and the platform's sum by Cholesky.
// It answers only where platform_unloaded_stiffness would find every rank full: each decision of
// the reference (rank of J_q, rigid directions of a chain, free directions of the platform: a
// singular value or eigenvalue below rank_tolerance of the largest) is certified with a margin of
// 10 by the bounds sigma_min >= 1 / ||R^-1||_F, lambda_max <= trace, lambda_min >= 1 / trace(inverse).
// Anywhere else (a singular posture or near one, chains changed in size, tool points apart) it
// returns false and the caller calls platform_unloaded_stiffness, which diagnoses as always.
struct RegularStiffnessData {
  // K_theta is block diagonal, one block per spring (at most 6 x 6): each factored on its own.
  struct SpringFactor {
    int first = 0;
    Mat6 stiffness = Mat6::Zero();  // as factored (top-left size x size): a spring changed since is factored again
    Eigen::LLT<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>> factor;
  };
  struct ChainData {
    int passive = 0, virtual_ = 0;
    std::vector<SpringFactor> springs;
    VecX q, theta;
    ChainJacobians J;
    MatX compliance_rhs;  // L^-1 J_theta^T, L L^T = K_theta
  };
  std::vector<ChainData> chains;
};
// kInvalidInput: what validate_platform says.
Status prepare_regular_stiffness(const std::vector<Chain>& chains, RegularStiffnessData& data,
                                 const StiffnessOptions& options = {});
bool regular_platform_unloaded_stiffness(const std::vector<Chain>& chains, RegularStiffnessData& data,
                                         CartesianStiffness& out, const StiffnessOptions& options = {});
StatusOr<CartesianStiffness> platform_loaded_stiffness(const std::vector<Chain>& chains, const PlatformState& state,
                                                       const StiffnessOptions& options = {});

}  // namespace kinestat::vjm
