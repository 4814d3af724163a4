// The loop-closure and task equations of a RobotModel and their Jacobians (robot_kinematics.cpp),
// shared by the kinematics and the model's checks.
#pragma once

#include <string>
#include <vector>

#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::mechanisms {

// Unknowns: the joint coordinates (model.coordinates() order), then the platform's twist
// components (x y z rx ry rz; planar: x y rz). Equations: each leg's closure (its end minus the
// tool pose: 6, planar 3), then the task coordinates minus their targets.
struct RobotJacobians {
  VecX residual;
  MatX inverse;  // d(all equations)/d(all unknowns): square; singular at Type 1 singularities
  MatX direct;   // d(closure)/d(passive coordinates, platform): square; singular at Type 2 ones
  std::vector<int> inverse_columns, direct_columns;  // unknown index of each column
};
RobotJacobians robot_jacobians(const RobotModel& model, const RobotPosture& posture, RobotData& data,
                               const VecX& task);

// "leg 2 joint 3 (universal) coordinate 2" or "the platform's rz", for an unknown index.
std::string column_name(const RobotModel& model, int unknown);

// Appends the leg's factors to `chain` (robot_model.cpp).
void append_leg(const RobotLeg& leg, const double* q, bool kinematic, vjm::Chain& chain, const Vec3& tool);

}  // namespace kinestat::mechanisms
