// A parallel robot as data (docs/robots.md): legs of joints and links from the base to one platform,
// drawn at the home posture, and what the user commands (the task coordinates). Built once by
// make_robot_model (which checks it), then only read, like Pinocchio's Model; what changes per
// posture lives in a RobotData, one per thread. Kinematics, the VJM chains and the posture kernel
// (robot_kernel.hpp) are free functions of the model.
//
// Geometry is a product of exponentials (Brockett 1984): every joint is given by a point and axes
// at the home posture, in base axes, and its coordinates are measured from there (home: all 0).
// A leg's chain is, from the base: a translation to each joint's point, the joint's motions about
// or along its home axes (in the frame moved by the joints before it), springs where they are
// written, and at its end the translation to the tool point. The platform frame has base axes at home.
//
// SI units throughout: m, rad, N, N m; prismatic coordinates in m, revolute ones in rad.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Geometry>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::mechanisms {

enum class RobotJointType : std::uint8_t {
  kRevolute,       // 1 coordinate: rotation about axes[0]
  kPrismatic,      // 1: translation along axes[0]
  kUniversal,      // 2: rotation about axes[0], then about axes[1] (moved by the first)
  kSpherical,      // 3: rotations about axes[0], axes[1], axes[2] (singular when the middle one is at +-90 deg)
  kCylindrical,    // 2: rotation about axes[0], then translation along it
  kParallelogram,  // 1 (Pa): the plate at `to` swings about axes[0] without turning: R(q) T(to - at) R(-q)
};
const char* to_string(RobotJointType t);
int coordinate_count(RobotJointType t);
// Whether coordinate `index` of such a joint is a length (m; else an angle, rad).
bool coordinate_is_length(RobotJointType t, int index);
// A coordinate's value ("0.25 m", or "80 deg" for an angle) and its limits ("[lo, hi] m" or deg) in
// a message.
std::string coordinate_text(RobotJointType t, int index, double value);
std::string limits_text(RobotJointType t, int index, double lo, double hi);

// A 6x6 spring at the chain's current point (eq. (1) of Pashkevich et al. 2009: a virtual spring).
struct RobotSpring {
  std::string label;             // names it in messages: "leg 2 link 1"
  Mat6 stiffness;                // dofs ux uy uz rx ry rz along `axes`: N/m, N/rad, N m/m, N m/rad
  Mat3 axes = Mat3::Identity();  // columns: the spring's x, y, z in base axes at home (orthonormal)
  // A `fea:` spring (docs/robots.md): the FEA of a mesh whose axes are `axes` and whose reference
  // point is the link's end or the joint's point; `stiffness` is NaN (refused by make_robot_model)
  // until resolve_robot_fea_springs computes it.
  std::optional<fea::LinkStiffnessRequest> fea;
  std::string fea_where;  // "FILE:LINE: ITEM fea", for messages
  int fea_entry = -1;     // the file's `fea:` entry: the same in a leg pattern's copies (computed once)
};

// The beam a link's spring is the cantilever of (vjm::cantilever_spring): kept so that MSA models
// the beam itself (robot_msa.hpp). Its local axes are the spring's axes (x along the beam, y and z
// the section's); the beam ends at the link's end and starts `length` before it along x.
struct RobotBeam {
  Material material;
  Section section;
  double length = 0.0;  // m
  BeamTheory theory = BeamTheory::kEulerBernoulli;
};

// A parallelogram's two bars (the flexibility of a Pa joint, as the Orthoglide 3-PRPaR's): beams
// from hinge to hinge (`to - at`), `width` apart across the joint, pinned about its axis at both
// plates. Their spring between the plates depends on the joint's angle (robot_parallelogram_spring).
struct RobotParallelogramBars {
  RobotBeam beam;                 // one bar: its section's y along the hinges' axis, z = x cross y
  double width = 0.0;             // m between the two bars' axes
  Mat6 stiffness = Mat6::Zero();  // one bar's cantilever spring (vjm::cantilever_spring) in its axes
};

struct RobotJoint {
  std::string label;  // "leg 2 joint 3 (universal)"
  RobotJointType type = RobotJointType::kRevolute;
  Vec3 at = Vec3::Zero();                                                 // a point of its axes at home (m)
  std::array<Vec3, 3> axes{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};  // unit, at home
  Vec3 to = Vec3::Zero();  // kParallelogram: the second hinge's point at home
  bool actuated = false;   // the first coordinate is driven by a motor
  // Actuator stiffness (N/m or N m/rad) when actuated; +infinity: a rigid actuator.
  double actuator_stiffness = std::numeric_limits<double>::infinity();
  // The joint's own compliance (its bearing), placed at `at` before its motion; its stiffness along
  // the joint's free motion does not matter (the motion is passive) but must be positive.
  std::optional<RobotSpring> spring;
  // Per coordinate, measured from home; empty: no limits.
  std::vector<std::pair<double, double>> limits;
  // kParallelogram: its bars; without, a rigid parallelogram.
  std::optional<RobotParallelogramBars> bars;
};

// The spring of a parallelogram joint's bars between its plates at its coordinate q (rad), about
// `to` in the axes (x along to - at, y the joint's axis, z = x cross y) of the frame before the joint
// (the plate does not turn): each bar's cantilever pinned at both plates, the two summed, plus a
// stiffness along the plates' free translation that the joint's motion makes irrelevant
// (fixed_size_vjm.hpp, parallelogram_stiffness; eq. 22 of Pashkevich et al. 2009). Its axes are
// robot_parallelogram_axes(j). kSingular where it is singular (the bars on one line: q = +-90 deg).
StatusOr<Mat6> robot_parallelogram_spring(const RobotJoint& j, double q);
Mat3 robot_parallelogram_axes(const RobotJoint& j);

// A link from the chain's current point to `to`. Its spring, if any, sits at `to` (the free end of
// a cantilever clamped at the link's start): a beam of the link or a given 6x6.
struct RobotLink {
  std::string label;
  Vec3 to = Vec3::Zero();  // m, at home
  std::optional<RobotSpring> spring;
  std::optional<RobotBeam> beam;  // set when `spring` is a beam's cantilever spring
};

struct RobotLeg {
  std::string name;                                        // "leg 2"
  std::vector<std::variant<RobotJoint, RobotLink>> items;  // from the base to the platform
};

enum class TaskCoordinate : std::uint8_t { kX, kY, kZ, kRx, kRy, kRz };
const char* to_string(TaskCoordinate c);

// What a robot file describes, in SI, parameters already evaluated (io::read_robot_yaml).
struct RobotDescription {
  std::string name;    // "Delta (Clavel)"
  std::string source;  // the file, for messages
  std::vector<RobotLeg> legs;
  Vec3 tool = Vec3::Zero();  // the tool point at home (m, base frame)
  // All motion in the base x-y plane: loop closure and task in x, y, rz only; joints must keep to
  // the plane (revolute axes along z, prismatic axes in the plane).
  bool planar = false;
  // The commanded components of the tool pose. The orientation is R = Rz(rz) Ry(ry) Rx(rx) (angles
  // about the fixed base axes, applied x first), the platform's rotation from home.
  std::vector<TaskCoordinate> task;
  // The map region (m) when the command line gives none; lo == hi on an axis: a slice. With
  // workspace_angular, ranges of rx, ry, rz (rad) at the home position: an orientation map.
  std::optional<std::array<std::pair<double, double>, 3>> workspace;
  bool workspace_angular = false;
  // Named parameters and their values in the file's units, for reports and design sweeps.
  std::vector<std::pair<std::string, double>> params;
};

class RobotModel;

// A solved posture: every joint coordinate (legs in order, each leg's joints in order) and the
// tool pose.
struct RobotPosture {
  VecX q;
  vjm::Transform tool = vjm::Transform::Identity();
};

// A Jacobian of the loop closure's structure factored leg by leg (robot_kinematics.cpp): leg l's
// e equations (rows `row` .. + `equations`) involve only its own columns (`column` .. + `count`) and
// the platform's np (the last columns); the rows after the legs' (the task's) the platform's only.
// Each leg's e x count block is factored by a Householder QR, B = Q [R; 0]: its first `count` transformed rows
// give the leg's unknowns from the platform's, the other e - count rows join the task's rows in
// the np x np Schur complement S (S x_p = ..., an LU). The inverse kinematics Jacobian and the
// direct one (the passive columns and the platform) have this structure. Solves (and solves with
// the transpose, for the condition estimate) cost O(legs e^2) instead of a dense LU's O(size^3).
// S is held as 6 x 6, the identity past np (a planar robot's np = 3): fixed-size LU and solves, the
// same pivots, determinant and solution on its np x np block.
struct RobotBlockFactors {
  struct Leg {
    int row = 0, equations = 6, column = 0, count = 0, reflections = 0;
    Mat6 Q = Mat6::Identity(), R = Mat6::Zero();  // R: the top-left count x count
    Mat6 G = Mat6::Zero();                        // Q^T times the leg's platform columns (e x np)
    Vec6 t = Vec6::Zero();                        // scratch of the solves
  };
  std::vector<Leg> legs;
  int platform = 6, size = 0;
  Mat6 S = Mat6::Identity();
  Eigen::PartialPivLU<Mat6> lu;
  bool regular = false;    // every R and S of non-zero pivots
  double norm = 0.0;       // the matrix's 1-norm
  VecX x, sign, old_sign;  // scratch of the condition estimate
};

// Per-thread scratch of the kinematics, everything that changes per posture (sized once by
// make_robot_data: solve_posture allocates nothing along a map's path).
struct RobotData {
  VecX residual, step;
  MatX jacobian;
  double redundant_residual = 0.0;                 // the largest of the redundant equations' (length-scaled)
  std::vector<VecX> leg_q;                         // each leg's coordinates
  std::vector<vjm::ChainJacobians> leg_jacobians;  // each leg's kinematic chain at them
  VecX no_theta;                                   // the kinematic chains have no springs
  // The length-scaled Jacobians (Newton's and robot_jacobians') and their factorizations.
  VecX row_scale, column_scale;
  std::vector<int> direct_columns;
  MatX scaled_inverse, direct;
  RobotBlockFactors inverse_factors, direct_factors;
  // Continuation: the start's task values, the walk's direction, a trial posture, and the residual
  // and factors at the walk's last closure (its next steps start there).
  VecX start, delta, target;
  RobotPosture trial;
  VecX closed_residual;
  RobotBlockFactors closed_factors;
};
RobotData make_robot_data(const RobotModel& model);

enum class KinematicsStatus : std::uint8_t {
  kOk,
  kUnreachable,  // no closure near the start on this branch (out of reach, or a joint limit)
  kSingular,     // the closure equations lose rank (a Type 1 or Type 2 singularity)
  kOtherBranch,  // closed, but on another working or assembly mode than home's
};
const char* to_string(KinematicsStatus s);

struct KinematicsResult {
  KinematicsStatus status = KinematicsStatus::kUnreachable;
  int iterations = 0;
  // The reciprocal condition number (1-norm estimate) of the length-scaled Jacobians, the smaller
  // of the inverse kinematics' (legs, Type 1) and the direct kinematics' (platform, Type 2), over
  // its value at home, at most 1: 1 at home and wherever the Jacobians are as well conditioned, 0 at
  // a singularity. (The estimate itself is ~0.005 at a healthy hexapod posture, 0.018 at the
  // Delta's home: the map's near-singular threshold, 0.01, would flag whole workspaces.)
  double singularity_measure = 0.0;
  // The loop closes at `posture` on home's working mode (the inverse sign), both Jacobians regular:
  // kOk, kUnreachable with a joint beyond its limits, or kOtherBranch (another assembly mode). Such
  // a posture is a start for a neighbouring task's Newton (RobotKernel::evaluate_next).
  bool closed = false;
  std::string message;  // why, when not kOk
};

class RobotModel {
 public:
  const RobotDescription& description() const { return d_; }
  int num_legs() const { return static_cast<int>(d_.legs.size()); }
  int num_coordinates() const { return num_q_; }
  int leg_offset(int leg) const { return leg_offset_[leg]; }
  int leg_coordinates(int leg) const { return leg_offset_[leg + 1] - leg_offset_[leg]; }
  // Per coordinate (all legs in order): its leg, its joint's item index in the leg, and which of the
  // joint's coordinates it is.
  struct Coordinate {
    int leg = 0, item = 0, index = 0;
  };
  const std::vector<Coordinate>& coordinates() const { return coords_; }
  const RobotJoint& joint(const Coordinate& c) const { return std::get<RobotJoint>(d_.legs[c.leg].items[c.item]); }
  bool actuated(const Coordinate& c) const { return c.index == 0 && joint(c).actuated; }
  // "leg 2 joint 3 (universal) coordinate 2"
  std::string coordinate_name(int k) const;
  // The closure equations the kinematics solves, legs in order: a leg's end minus the tool pose in
  // one pose component (0..5: x y z rx ry rz). Every leg's six (planar: x, y, rz) unless the legs
  // over-constrain the platform (an overconstrained robot, e.g. the Orthoglide 3-PRPaR: the
  // constraint moments of its three legs span three rotations twice): then as many independent
  // ones as the unknowns need, chosen at home; the others (redundant_equations) hold by the
  // geometry, and solve_posture checks them at every solution.
  struct ClosureEquation {
    int leg = 0, component = 0;
  };
  const std::vector<ClosureEquation>& closure_equations() const { return closure_; }
  int closure_offset(int leg) const { return closure_offset_[leg]; }  // leg's first; leg = num_legs(): the count
  const std::vector<ClosureEquation>& redundant_equations() const { return redundant_; }
  // The largest distance from the base origin to a joint or the tool (m): the scale that makes m and
  // rad comparable.
  double length_scale() const { return length_scale_; }
  // The home posture: all coordinates 0, the tool at `tool` with base axes.
  const RobotPosture& home() const { return home_; }
  VecX home_task() const;  // task coordinate values at home
  // The kinematic chain of each leg: every joint coordinate a passive variable, no springs.
  const vjm::Chain& kinematic_chain(int leg) const { return kinematic_[leg]; }
  // Signs of det of the inverse and direct kinematics Jacobians at home: a posture with other signs
  // is on another working (inverse) or assembly (direct) mode.
  int home_inverse_sign() const { return inverse_sign_; }
  int home_direct_sign() const { return direct_sign_; }
  // The reciprocal condition estimate of KinematicsResult::singularity_measure at home.
  double home_rcond() const { return home_rcond_; }
  // A leg's reach: its tool point stays within `radius` (m) of `origin` (base axes), the point before
  // its first motion, at every posture (the lengths of its rigid translations summed: rotations keep
  // them); infinite for a leg with a prismatic or cylindrical coordinate. Where the first motion is a
  // revolute about `axis` (unit; zero otherwise), the point it carries to the next motion turns on
  // the circle of `ring_radius` about `ring_center` in the plane normal to it, and the tool point
  // stays within `ring_reach` of that circle (the annulus or torus of a Delta's arm and forearm).
  // solve_posture refuses a task beyond either without a Newton step.
  struct Reach {
    Vec3 origin = Vec3::Zero();
    double radius = 0.0;
    Vec3 axis = Vec3::Zero(), ring_center = Vec3::Zero();
    double ring_radius = 0.0, ring_reach = 0.0;
    // The distance from x (base axes, m) to the circle.
    double ring_distance(const Vec3& x) const;
  };
  const Reach& leg_reach(int leg) const { return reach_[leg]; }

 private:
  friend StatusOr<RobotModel> make_robot_model(RobotDescription d);
  RobotDescription d_;
  int num_q_ = 0;
  std::vector<int> leg_offset_;
  std::vector<Coordinate> coords_;
  std::vector<vjm::Chain> kinematic_;
  std::vector<Reach> reach_;
  std::vector<ClosureEquation> closure_, redundant_;
  std::vector<int> closure_offset_;
  double length_scale_ = 1.0;
  RobotPosture home_;
  int inverse_sign_ = 1, direct_sign_ = 1;
  double home_rcond_ = 1.0;
};

// Computes the links' and joints' `fea:` springs not yet computed (fea::compute_link_stiffness: meshing and FEA,
// or the spring's cache), each file entry once (a pattern's copies share it: the turn moves the
// axes, not the mesh). `progress` (optional) hears the long stages, `warning` (optional) what the
// user must hear even when quiet ("FILE:LINE: ...: a rejected cache entry, recomputed"). A bad mesh
// or region: kInvalidInput "FILE:LINE: ITEM fea: MESH: ...".
Status resolve_robot_fea_springs(RobotDescription& d, const std::function<void(const std::string&)>& progress = {},
                                 const std::function<void(const std::string&)>& warning = {});

// Checks and builds: axes unit and non-zero, actuated joints as many as task coordinates, unknowns
// as many as equations, the Jacobians of full rank at home (else the free or redundant motion is
// named), a planar robot in its plane, every spring computed (a `fea:` one not yet resolved is
// refused naming its FILE:LINE). kInvalidInput naming the description's source and item.
StatusOr<RobotModel> make_robot_model(RobotDescription d);

// Task coordinate values of a tool pose (m, rad).
VecX task_values(const RobotModel& model, const vjm::Transform& tool);

// Inverse kinematics by Newton on the loop closure (every leg's end at the tool pose) and the task
// equations, from `posture` (a neighbour's solution, or home), which it overwrites with the
// solution. With `continuation`, walks from the start's task values to `task` in steps, halving a
// step whose Newton fails (evaluate from home); without, one Newton solve (a grid neighbour).
KinematicsResult solve_posture(const RobotModel& model, const VecX& task, RobotPosture& posture, RobotData& data,
                               bool continuation = true);

// Where a leg's items are at a posture, in base axes, from the leg's kinematic chain (the partial
// products of its factors). A joint: its frame at its point before its motion (`at`), before each
// of its elementary motions (`motions`, one per coordinate; a parallelogram's three factors: the
// proximal hinges, the bars, the distal hinges), and after it (`after`; a parallelogram's at `to`).
// A link: its frame at its start (`at`) and at its end (`after`); `motions` empty. A joint's axis i
// at the posture is motions[i].linear() * axes[i]; a spring's axes are at.linear() * spring.axes
// (a joint's) or after.linear() * spring.axes (a link's). Home: every frame has base axes.
struct RobotItemFrames {
  vjm::Transform at = vjm::Transform::Identity();
  std::vector<vjm::Transform> motions;
  vjm::Transform after = vjm::Transform::Identity();
};
std::vector<RobotItemFrames> robot_leg_frames(const RobotModel& model, int leg, const RobotPosture& posture);

// The VJM chains (vjm/chain.hpp) of the legs at a solved posture: actuated joints as actuators
// with their springs (rigid: locked), passive joints at their values, the springs in place; each
// chain ends at the tool point with base axes.
std::vector<vjm::Chain> robot_vjm_chains(const RobotModel& model, const RobotPosture& posture);

// The same chains built once (make_robot_vjm_chains: at home) and moved to a posture in place
// (set_robot_vjm_posture: the actuators' values, the passive joints' nominal values, the tool
// transform and the springs that depend on the posture; no allocation), as a posture kernel keeps
// them. robot_vjm_chains is the two in a row. A parallelogram whose bars lie on one line gets a NaN
// spring, which the VJM refuses (vjm::Chain::validate).
struct RobotVjmChains {
  std::vector<vjm::Chain> chains;
  struct Leg {
    std::vector<int> actuator_factor, actuator_coordinate;  // the leg's coordinate index of each actuator
    std::vector<int> passive_coordinate;                    // of each passive joint, in the chain's order
    // Springs that depend on the posture (a parallelogram's bars): the chain's spring index, the
    // leg's coordinate index of the joint and the joint's item index in the leg.
    struct PostureSpring {
      int spring = 0, coordinate = 0, item = 0;
    };
    std::vector<PostureSpring> posture_springs;
    int tool_factor = -1;  // the transform back to base axes
    VecX passive;          // scratch: the passive joints' values
  };
  std::vector<Leg> legs;
};
RobotVjmChains make_robot_vjm_chains(const RobotModel& model);
void set_robot_vjm_posture(const RobotModel& model, const RobotPosture& posture, RobotVjmChains& chains);

}  // namespace kinestat::mechanisms
