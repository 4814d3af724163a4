// The symmetric 5R planar parallel manipulator (five-bar) of Gonçalves et al. 2010, sections 4-5:
// inverse and direct kinematics, singularity measures, and the 8-node MSA model of section 5.
//
// Geometry (paper, Fig. 1): base joints A1 = (-r3, 0) and A2 = (r3, 0); actuated links A_iB_i of
// length r1 at input angles theta_i (rad, from the x axis); distal links B_iP of length r2 meeting
// at the platform point P. Units: m, rad, N, Pa.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::mechanisms {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

struct FiveBarParams {
  // Link lengths (m): OA1 = OA2 = r3, A_iB_i = r1, B_iP = r2 (paper: all 0.1 m).
  double r1 = 0.1;
  double r2 = 0.1;
  double r3 = 0.1;
  // The four links (section 5): steel, solid circular section of diameter 0.005 m.
  Material link_material{"steel", 2e11, 0.8e11};
  Section link_section = circle_section(0.005);
  // Passive revolute joints B1, P, B2 in the joint frame (z normal to the plane = joint axis):
  // kt_x, kt_y, kt_z (N/m), kr_x, kr_y, kr_z (N m/rad); kr_z = 0 is the free rotation.
  Vec6 joint_stiffness = (Vec6() << 2e11, 2e11, 2e11, 2e11, 2e11, 0.0).finished();
  // Magnitude (N) of the two load cases at P: Fx, then Fy.
  double load = 1.0;
};

// Working mode: the sign chosen in eq. (18) for each leg (+1 or -1). The "+" root of eq. (18) is
// theta_i = phi_i + alpha_i (phi_i the direction of A_iP, alpha_i the angle at A_i of the triangle
// A_iB_iP), i.e. the leg bends clockwise at B_i: (B_i - A_i) x (P - B_i) < 0.
struct WorkingMode {
  int sign1 = 1;
  int sign2 = 1;
  bool operator==(const WorkingMode&) const = default;
};
std::string to_string(WorkingMode m);                                        // "+-" etc.
std::optional<WorkingMode> working_mode_from_name(const std::string& name);  // "++", "+-", "-+", "--"

// Assembly mode of the direct kinematics (eq. (26)): kUp has P to the left of B1->B2,
// (B2 - B1) x (P - B1) > 0, which is the solution of larger y whenever x_B1 < x_B2 (always for
// r1 < r3; for r1 = r3 all but theta1 = 0, theta2 = 180 deg). Unlike "larger y" it does not swap along x_B1 = x_B2,
// where the two solutions have equal y and eq. (23)-(24) divide by zero; it changes only through a parallel
// singularity, as an assembly mode should.
enum class Assembly { kUp, kDown };
const char* to_string(Assembly a);
std::optional<Assembly> assembly_from_name(const std::string& name);  // "up", "down"

// One configuration: input angles, joint centres, and its labels.
struct FiveBarPosture {
  double theta1 = 0.0, theta2 = 0.0;  // rad
  Vec2 A1, B1, P, B2, A2;             // m
  WorkingMode working_mode;
  Assembly assembly = Assembly::kUp;
};

// r1, r2, r3 positive and finite; otherwise kInvalidInput naming the parameter.
Status validate(const FiveBarParams& p);

// Eq. (14)-(19): the input angles that put the platform at `point`, for the four working modes
// (order ++, +-, -+, --). Computed as theta_i = phi_i +- alpha_i (same roots as eq. (17)-(18),
// but well defined where a_i = 0 and z_i is infinite). kInvalidInput naming the point and the leg
// when it is out of reach (|A_iP| outside [|r1 - r2|, r1 + r2]) or theta_i is undetermined
// (P = A_i with r1 = r2).
StatusOr<std::array<FiveBarPosture, 4>> inverse_kinematics(const FiveBarParams& p, const Vec2& point);
StatusOr<FiveBarPosture> inverse_kinematics(const FiveBarParams& p, const Vec2& point, WorkingMode mode);
// The same posture without a message (nullopt where inverse_kinematics fails) and without heap
// allocation, for posture sweeps; `p` must be valid (validate).
std::optional<FiveBarPosture> try_inverse_kinematics(const FiveBarParams& p, const Vec2& point, WorkingMode mode);

// Eq. (20)-(27): the platform point for input angles (rad), both assembly modes ([0] up, [1] down).
// Solved as the intersection of the circles of radius r2 about B1 and B2, which has no division by
// the denominator 2 r3 + r1 cos t2 - r1 cos t1 of eq. (23)-(24). kInvalidInput when
// |B1B2| > 2 r2 (the loop cannot close) or B1 = B2 (P undetermined).
StatusOr<std::array<FiveBarPosture, 2>> direct_kinematics(const FiveBarParams& p, double theta1, double theta2);
StatusOr<FiveBarPosture> direct_kinematics(const FiveBarParams& p, double theta1, double theta2, Assembly a);

// Velocity equations of the closure constraints |P - B_i|^2 = r2^2: A dP = B dtheta with
// A = [(P - B1)^T; (P - B2)^T] and B = diag((P - B_i) . dB_i/dtheta_i).
// det A = 0: parallel (type-2, direct) singularity, B1P and PB2 aligned, P free with the
// actuators locked. B_ii = 0: serial (type-1, inverse) singularity, A_iB_i aligned with B_iP
// (leg i stretched or folded, workspace boundary).
struct FiveBarJacobians {
  Mat2 A;
  Mat2 B;
  // Distances to the singularities, dimensionless in [0, 1]: |sin| of the angle between B1P and
  // B2P, and the smaller over the legs of |sin| of the angle between A_iB_i and B_iP. Near a
  // singularity the kinematics has a square root (eq. (26), eq. (18)), so a posture that is singular
  // in exact arithmetic comes out with a measure of ~1e-8, not 1e-16: hence the default tolerance.
  double parallel_measure = 0.0;
  double serial_measure = 0.0;
  bool parallel_singular(double tol = 1e-6) const { return parallel_measure < tol; }
  bool serial_singular(double tol = 1e-6) const { return serial_measure < tol; }
};
FiveBarJacobians five_bar_jacobians(const FiveBarPosture& q);

// Index of node "5" (the platform point P, where the loads act and the report node).
inline constexpr int kFiveBarPlatformNode = 4;

// The MSA model of section 5 at a posture: nodes "1".."8" (A1, B1, B1, P, P, B2, B2, A2); beams
// A1B1 = 1-2, B1P = 3-4, PB2 = 5-6, B2A2 = 7-8; revolute joints B1 = 2-3, P = 4-5, B2 = 6-7
// (joint_stiffness in the global frame, z the joint axis); nodes 1 and 8 fully fixed (blocked
// actuators); load cases "Fx" and "Fy" of `load` N at node 5, the report node.
msa::Structure make_five_bar_structure(const FiveBarParams& p, const FiveBarPosture& q);
StatusOr<msa::Structure> make_five_bar_structure(const FiveBarParams& p, double theta1, double theta2, Assembly a);
StatusOr<msa::Structure> make_five_bar_structure(const FiveBarParams& p, const Vec2& point, WorkingMode mode);

}  // namespace kinestat::mechanisms
