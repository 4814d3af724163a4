// The posture kernel (posture_kernel.hpp) of any RobotModel: maps, design sweeps and Python for a
// robot given as a file (docs/robots.md).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "kinestat/mechanisms/posture_kernel.hpp"
#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::mechanisms {

struct RobotKernelOptions {
  std::shared_ptr<const RobotModel> model;
  // Task coordinate values (m, rad) at every point, in the model's task order; the mapped ones are
  // replaced by the point's. Empty: home's.
  VecX task;
  // Which task coordinate each of the point's x, y, z sets (index into the task; -1: none, the
  // grid must be flat along that axis). Default: the task's x, y, z where it has them.
  std::optional<std::array<int, 3>> map_axes;
  // VJM (robot_vjm_chains) or MSA (robot_msa_structure, msa::cartesian_stiffness at the platform
  // node): the same model, two methods. MSA: unloaded only.
  StiffnessMethod method = StiffnessMethod::kVjm;
  // Loaded mode (at most one), as OrthoglideKernelOptions: an external wrench at the tool point
  // (N, N m) or a prescribed tool displacement (m, rad); PostureResult::deflection is the
  // equilibrium displacement.
  std::optional<Vec6> wrench;
  std::optional<Vec6> displacement;
};

// The default map axes of a model: grid x, y, z set the task's x, y, z (-1 where it has none).
std::array<int, 3> default_map_axes(const RobotModel& model);

// kInvalidInput naming the bad value: no model, a task vector of the wrong size or not finite,
// a map axis out of range or used twice, a wrench and a displacement together, non-finite loads,
// a load with the MSA method.
Status validate(const RobotKernelOptions& options);

// VJM stiffness at each point (vjm::platform_unloaded_stiffness / the loaded mode of
// vjm::platform_equilibrium*), or MSA (msa::cartesian_stiffness of robot_msa_structure at the
// platform node; kFailed at every reachable point when the model has no MSA structure, e.g. a loop
// of rigid ties: robot_msa_structure says why), with the kinematics of solve_posture: evaluate() walks from home
// (continuation), evaluate_next() starts from the previous point's closure (along a row of the path, from the
// extrapolation of the last two postures; also a closure that was unreachable, KinematicsResult::closed) and
// falls back to evaluate().
// kUnreachable: no closure on home's branch (out of reach, joint limit, other working or assembly
// mode); kSingular: the kinematics or the stiffness lose rank (a free direction); kFailed: no loaded
// equilibrium. A rigid direction (no spring deforms it, e.g. rigid legs holding the orientation)
// is kept as infinite stiffness: `stiffness` is the finite part, `compliance` zero along it.
std::unique_ptr<PostureKernel> make_robot_kernel(const RobotKernelOptions& options);

}  // namespace kinestat::mechanisms
