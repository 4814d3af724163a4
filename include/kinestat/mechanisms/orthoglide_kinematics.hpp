// Orthoglide (3-PRPaR) kinematics: Pashkevich, Wenger, Chablat, "Design Strategies for the Geometric
// Synthesis of Orthoglide-type Mechanisms", MMT 40(8) 2005, sections 2-4.
//
// Simplified model (paper Fig. 2a): three bars of length L join the tool point p by spherical joints
// to three sliders at rho_x e_x, rho_y e_y, rho_z e_z on mutually orthogonal axes through the origin:
//   (p_x - rho_x)^2 + p_y^2 + p_z^2 = L^2, and cyclically (eq. 1).
// The isotropic "zero" posture is p = (0, 0, 0), rho = (L, L, L), where J = I.
// Units: m for p, rho and L; Jacobians and transmission factors are dimensionless.
#pragma once

#include <array>
#include <optional>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::mechanisms {

struct OrthoglideGeometry {
  double link_length = 1.0;  // L (m), the parallelogram principal links
};

// L positive and finite; otherwise kInvalidInput.
Status validate(const OrthoglideGeometry& g);

// Configuration indices of eq. (3): s_i = sign(rho_i - p_i), each +1 or -1. All +1 is the working
// mode (the only inverse solution inside the sphere |p| < L that respects 0 < rho <= 2L).
using OrthoglideSigns = std::array<int, 3>;
inline constexpr OrthoglideSigns kOrthoglideWorkingSigns{1, 1, 1};

// Eq. (3): rho_i = p_i + s_i sqrt(L^2 - p_j^2 - p_k^2). kInvalidInput (naming the point and the
// chain) when p lies outside the cylinder of that chain, or a sign is not +-1.
StatusOr<Vec3> inverse_kinematics(const OrthoglideGeometry& g, const Vec3& p,
                                  const OrthoglideSigns& s = kOrthoglideWorkingSigns);

// The working-mode solution of eq. (3) without a message (nullopt where inverse_kinematics fails)
// and without heap allocation, for posture sweeps; `g` must be valid.
std::optional<Vec3> try_inverse_kinematics(const OrthoglideGeometry& g, const Vec3& p);

// Direct-kinematics branch index of section 2.3: m = sgn(sum_i p_i / rho_i - 1). The working mode
// (containing the zero posture) is m = -1; m = 0 is the parallel ("flat") singularity.
inline constexpr int kOrthoglideWorkingBranch = -1;
int direct_kinematics_branch(const Vec3& p, const Vec3& rho);

// Eq. (4): p_i = rho_i / 2 + t / rho_i with t a root of A t^2 + B t + C = 0. Both solutions,
// [0] the working branch m = -1 and [1] m = +1 (equal on the parallel singularity B^2 = 4AC).
// kInvalidInput when a rho_i <= 0 (eq. 2) or B^2 < 4AC (rho outside the reachable region R_L).
StatusOr<std::array<Vec3, 2>> direct_kinematics(const OrthoglideGeometry& g, const Vec3& rho);
// The solution of one branch, m = -1 or +1.
StatusOr<Vec3> direct_kinematics(const OrthoglideGeometry& g, const Vec3& rho, int branch);

// Eq. (5): the inverse Jacobian d(rho)/d(p), row i = (p - rho_i e_i)^T / (p_i - rho_i).
// kSingular at a serial singularity (a bar orthogonal to its slider axis, p_i = rho_i).
StatusOr<Mat3> inverse_jacobian(const Vec3& p, const Vec3& rho);

// True where inverse_jacobian fails: a chain at a serial singularity, |p_i - rho_i| <= 1e-12 of the
// posture's size.
bool serial_singular(const Vec3& p, const Vec3& rho);

// Eq. (6), closed form of det(J^-1); kSingular where eq. (5) is.
StatusOr<double> inverse_jacobian_determinant(const Vec3& p, const Vec3& rho);

// Dexterity of one posture from the singular values sigma of J^-1 (SVD, any point, not only the
// Q-axis closed forms). The transmission factor along a unit direction e is
// lambda(e) = ||J^-1 e||^-1 (section 4.3), so over all e it spans [1/sigma_max, 1/sigma_min].
struct VelocityTransmission {
  Vec3 singular_values = Vec3::Zero();  // of J^-1, descending
  double mu_min = 0.0;                  // 1 / sigma_max
  double mu_max = 0.0;                  // 1 / sigma_min (+inf at a parallel singularity)
  double manipulability = 0.0;          // w = sigma_1 sigma_2 sigma_3 = |det J^-1| (section 4.1)
  double condition_number = 0.0;        // sigma_max / sigma_min (section 4.2; +inf when singular)
};
VelocityTransmission velocity_transmission(const Mat3& inverse_jacobian);

// Inverse kinematics in the working mode, eq. (5) and the SVD at a Cartesian point.
StatusOr<VelocityTransmission> velocity_transmission_at(const OrthoglideGeometry& g, const Vec3& p);

}  // namespace kinestat::mechanisms
