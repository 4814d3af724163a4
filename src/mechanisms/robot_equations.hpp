// The loop-closure and task equations of a RobotModel and their Jacobians (robot_kinematics.cpp),
// shared by the kinematics and the model's checks.
#pragma once

#include <string>
#include <vector>

#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::mechanisms {

// A planar robot's pose components (x y rz of x y z rx ry rz): its closure equations and platform
// unknowns.
inline constexpr int kPlanarComponents[3] = {0, 1, 5};

// Unknowns: the joint coordinates (model.coordinates() order), then the platform's twist
// components (x y z rx ry rz; planar: x y rz). Equations: each leg's closure (its end minus the
// tool pose: 6, planar 3), then the task coordinates minus their targets.
struct RobotJacobians {
  VecX residual;
  MatX inverse;  // d(all equations)/d(all unknowns): square; singular at Type 1 singularities
  MatX direct;   // d(closure)/d(passive coordinates, platform): square; singular at Type 2 ones
  std::vector<int> inverse_columns, direct_columns;  // unknown index of each column
};
RobotJacobians robot_jacobians(const RobotModel& model, const RobotPosture& posture, RobotData& data, const VecX& task);

// "leg 2 joint 3 (universal) coordinate 2" or "the platform's rz", for an unknown index.
std::string column_name(const RobotModel& model, int unknown);

// Where each of a leg's items starts in the chain's factors: `begin` before its move to its point,
// `first` after it (and after a joint's spring), `end` after the item.
struct LegItemFactors {
  int begin = 0, first = 0, end = 0;
};

// Appends the leg's factors to `chain` (robot_model.cpp); with `items`, records where each item's
// factors are.
// With `vjm_leg` (not kinematic), records the factors that a posture moves (RobotVjmChains::Leg).
void append_leg(const RobotLeg& leg, const double* q, bool kinematic, vjm::Chain& chain, const Vec3& tool,
                std::vector<LegItemFactors>* items = nullptr, RobotVjmChains::Leg* vjm_leg = nullptr);

}  // namespace kinestat::mechanisms
