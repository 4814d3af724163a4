// The serial chain of the virtual joint method (Pashkevich, Klimchik, Chablat, Wenger 2009, eq. (1)):
// base transform, actuated joint with its actuator spring, rigid links, 6-dof virtual springs,
// passive joints (R, P, U, S, coupled) and tool transform, as one product of elementary factors.
// Its kinematics: tool pose (eq. 4), the Jacobians J_q, J_theta (eq. 5) and the derivatives of
// J^T F that the loaded mode needs (the Hessians of eq. 20).
//
// Conventions (shared by every vjm function, and those of kinestat::CartesianStiffness):
// - SI units: m, rad, N, N m. Prismatic coordinates in m, revolute ones in rad.
// - A tool displacement (twist) is (dx dy dz, rx ry rz): the translation of the tool point and a
//   small rotation vector, both in global (base) axes. A wrench is (Fx Fy Fz, Mx My Mz): force and
//   moment about the tool point, global axes. Jacobian columns are such twists.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::vjm {

using Transform = Eigen::Isometry3d;

// The methods form dense matrices over a chain's coordinates (passive q and virtual theta, n + m):
// K_theta (m x m), the Hessians of the loaded mode ((n + m)^2) and their LU. Above this many
// coordinates a chain is refused before they are allocated (5000: 0.2 GB per matrix, seconds per
// factorization); StiffnessOptions and EquilibriumOptions raise it (the vjm command: --max-coordinates).
inline constexpr int kDefaultMaxChainCoordinates = 5000;

enum class JointType { kRevolute, kPrismatic };

// Passive joint coordinate q_k, or virtual (spring) coordinate theta_k.
enum class VariableKind { kPassive, kVirtual };

struct VariableRef {
  VariableKind kind = VariableKind::kPassive;
  int index = 0;
  double coefficient = 1.0;  // the factor moves by coefficient * variable (the parallelogram's -q)
};

// One factor of the product (1): a constant rigid transform, or an elementary rotation about /
// translation along a unit axis of the current frame by `offset + coefficient * variable`.
struct Factor {
  std::string label;  // names the factor in messages
  bool is_motion = false;
  Transform transform = Transform::Identity();  // the constant factor (is_motion == false)
  JointType type = JointType::kRevolute;
  Vec3 axis = Vec3::UnitZ();            // unit, in the current frame
  double offset = 0.0;                  // constant part, e.g. the actuated coordinate q_a of V_a(q_a + theta)
  std::optional<VariableRef> variable;  // none: a locked joint
};

// A block of K_theta (eq. 6): the stiffness of virtual coordinates first .. first+size-1.
struct Spring {
  std::string label;
  int first = 0;
  MatX stiffness;  // size x size; N/m, N/rad, N m/m, N m/rad as the coordinates require
};

class Chain {
 public:
  explicit Chain(std::string name = "chain") : name_(std::move(name)) {}

  // A rigid link: base, foot, leg or tool transform of eq. (1).
  void add_transform(const Transform& T, std::string label);
  void add_translation(const Vec3& d, std::string label);
  void add_rotation(const Vec3& axis, double angle, std::string label);

  // Actuated joint V_a(q_a + theta_0): value q_a (m or rad) and actuator stiffness k (N/m or
  // N m/rad). k = +infinity locks the joint (no virtual coordinate). Returns the theta index or -1.
  int add_actuator(JointType type, const Vec3& axis, double value, double stiffness, std::string label);

  // 6-dof virtual spring V_s(theta_1..theta_6): translations along x, y, z then rotations about
  // x, y, z of the current frame; K is its 6x6 stiffness in that frame (dofs ux uy uz rx ry rz),
  // symmetric positive definite. Returns the first theta index.
  int add_spring(const Mat6& K, std::string label);
  // Replaces the stiffness of springs()[index] (a spring computed after the chain was built, such
  // as a model file's FEA link spring). Checked by validate() like every spring; kInvalidInput
  // for an index that names no spring.
  Status set_spring_stiffness(int index, const Mat6& K);

  // Passive joint with nominal coordinate q0 (from the inverse kinematics). Returns its q index.
  int add_passive(JointType type, const Vec3& axis, double nominal, std::string label);
  // A factor that repeats the motion of passive joint `index` scaled by `coefficient`: the
  // parallelogram of eq. (22) is R_y(q) T_x(L) R_y(-q), i.e. coefficient -1.
  void add_coupled(JointType type, const Vec3& axis, int index, double coefficient, std::string label);
  // U joint: rotation about axis1, then about axis2 of the rotated frame. Returns the first q index.
  int add_universal(const Vec3& axis1, const Vec3& axis2, double q1, double q2, std::string label);
  // S joint: rotations about x, y, z of the current frame (singular when the middle angle is
  // +-pi/2). Returns the first q index.
  int add_spherical(const Vec3& angles, std::string label);

  const std::string& name() const { return name_; }
  const std::vector<Factor>& factors() const { return factors_; }
  const std::vector<Spring>& springs() const { return springs_; }
  int num_passive() const { return static_cast<int>(nominal_q_.size()); }
  int num_coordinates() const { return num_passive() + num_virtual(); }
  int num_virtual() const { return num_virtual_; }
  VecX nominal_passive() const { return Eigen::Map<const VecX>(nominal_q_.data(), num_passive()); }
  double nominal_passive(int index) const { return nominal_q_[index]; }
  void set_nominal_passive(const VecX& q) { nominal_q_.assign(q.data(), q.data() + q.size()); }
  // Posture updates of a chain built once (a posture kernel moves its chains from posture to
  // posture, no factor added or removed): the constant part of motion factor `factor` (an actuated
  // coordinate's value), the transform of constant factor `factor`. Out of range or the wrong kind
  // of factor: ignored (the builder knows its indices).
  void set_offset(int factor, double offset);
  void set_transform(int factor, const Transform& T);

  // K_theta = diag(K_theta,1 ... ), m x m (eq. 6).
  MatX spring_stiffness() const;
  // Sum of the rigid translation lengths (m): the scale that makes m and rad comparable.
  double length_scale() const;
  // Springs finite, symmetric and positive definite; axes non-zero; coordinates sized right; at most
  // `max_coordinates` coordinates (n + m). Messages name the chain and the factor.
  Status validate(int max_coordinates = kDefaultMaxChainCoordinates) const;

  // Tool pose T(q, theta) of eq. (1).
  Transform forward(const VecX& q, const VecX& theta) const;
  Transform nominal_pose() const { return forward(nominal_passive(), VecX::Zero(num_virtual_)); }

 private:
  int add_motion(JointType type, const Vec3& axis, double offset, std::optional<VariableRef> v, std::string label);

  std::string name_;
  std::vector<Factor> factors_;
  std::vector<Spring> springs_;
  std::vector<double> nominal_q_;  // grows by one per passive joint: a vector, not a VecX (O(n) growth)
  int num_virtual_ = 0;
};

// Tool pose and the Jacobians of eq. (5) at (q, theta): 6 x n and 6 x m, columns are twists.
struct ChainJacobians {
  Transform pose = Transform::Identity();
  MatX Jq;
  MatX Jtheta;
};
ChainJacobians jacobians(const Chain& chain, const VecX& q, const VecX& theta);
// The same into `J`, whose matrices keep their storage when already sized (a posture kernel's
// preallocated data): no heap allocation then.
void jacobians(const Chain& chain, const VecX& q, const VecX& theta, ChainJacobians& J);

// The partial products of (1) at (q, theta): the pose before each factor, then the tool pose
// (factors().size() + 1 poses). A factor's axis in base axes is poses[i].linear() * factor.axis.
std::vector<Transform> factor_poses(const Chain& chain, const VecX& q, const VecX& theta);

// H = d(J^T F)/d(q, theta) at fixed wrench F, the matrices of eq. (19)-(20): row i is the equation
// of coordinate i, column j the coordinate differentiated, e.g. Hthetaq(i, j) = d(J_theta,i . F)/dq_j.
// For a pure force this is the Hessian of F^T p(q, theta) (symmetric); with a moment it is the
// linearization of J^T F with J's rotation rows being angular velocities, which is not a Hessian and
// not symmetric (a constant moment does no path-independent work), see docs/vjm.md.
struct ChainHessians {
  MatX Hqq, Hqtheta, Hthetaq, Hthetatheta;
};
ChainHessians hessians(const Chain& chain, const VecX& q, const VecX& theta, const Vec6& F);

// The terms of H from the unit twists of a chain's moving factors in product order (anything with
// members v, w: the spatial twist, linear part = velocity of the point at the origin, times the
// factor's coefficient) and the tool point p: calls add(b, a, d(column b . F)/d(coordinate of a))
// for every pair; H sums them by coordinate. A factor before b moves b's screw axis by the Lie
// bracket [xi_a, xi_b] = (w_a x v_b - w_b x v_a, w_a x w_b); every factor moves the tool point by
// its point velocity v_a + w_a x p, which changes column b's lever arm. Shared with the posture
// kernels' fixed-size chains (mechanisms).
//
// With dv, dw the bracket (a before b) and u_a = v_a + w_a x p, the term is
//   f . (dv + dw x p + w_b x u_a) + m . dw = u_a . g_b + [a < b] (w_a . h_b - v_a . g_b),
//   g_b = f x w_b,  h_b = v_b x f + w_b x (p x f + m)
// (triple products rearranged): two cross products per column and dot products per pair.
template <class Twist, class Add>
void for_each_hessian_term(const Twist* tw, int count, const Vec3& p, const Vec6& F, Add&& add) {
  const Vec3 f = F.head<3>(), M = p.cross(f) + F.tail<3>();
  // g_b, h_b for a block of columns, then u_a once per row of the block: cross products per factor,
  // only dot products per pair (the loaded posture kernels call this at every Newton step).
  constexpr int kBlock = 32;
  std::array<Vec3, kBlock> g, h;
  for (int b0 = 0; b0 < count; b0 += kBlock) {
    const int nb = std::min(kBlock, count - b0);
    for (int j = 0; j < nb; ++j) {
      g[j] = f.cross(tw[b0 + j].w);
      h[j] = tw[b0 + j].v.cross(f) + tw[b0 + j].w.cross(M);
    }
    for (int a = 0; a < count; ++a) {
      const Vec3 u = tw[a].v + tw[a].w.cross(p);
      for (int j = 0; j < nb; ++j) {
        const int b = b0 + j;
        double term = u.dot(g[j]);
        if (a < b) term += tw[a].w.dot(h[j]) - tw[a].v.dot(g[j]);
        add(b, a, term);
      }
    }
  }
}

// The twist that takes pose `from` to pose `to`: (p_to - p_from, rotation vector of R_to R_from^T).
Vec6 pose_difference(const Transform& to, const Transform& from);
// `T` displaced by the twist d: p + d_p and exp([d_r]x) R.
Transform displace(const Transform& T, const Vec6& d);

}  // namespace kinestat::vjm
