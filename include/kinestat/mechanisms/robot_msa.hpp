// The MSA model of any RobotModel at a solved posture (docs/robots.md, "Stiffness"): the model of
// robot_vjm_chains (robot_model.hpp) as a frame of beams, joints and rigid links, for
// msa::cartesian_stiffness at the platform node (the posture kernel's method kMsa, robot_kernel.hpp).
#pragma once

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::mechanisms {

// The structure, in SI, nodes at the posture's positions (robot_leg_frames):
// - every rigid body of the robot (what lies between two joints or springs of a leg, and the
//   platform) is a master node and rigid links to its other nodes; the base's nodes are fixed;
// - a link's `beam` is a beam element with the beam's material, section, theory and axes (the
//   spring's: x along the beam, y the section's y), from `length` before the link's end to its end:
//   the cantilever of the VJM spring, clamped on the body before it;
// - a 6x6 spring (a link's `spring:` at its end, a joint's before its motion; a parallelogram's
//   bars' at its `to`, at the posture's angle) is a joint element between coincident nodes in the
//   spring's axes, its off-diagonal terms the element's coupling (msa::Joint::coupling);
// - each robot joint is a joint element between coincident nodes (a parallelogram's at its `to`)
//   in a frame that splits its motion: the free components released (0), an actuated coordinate
//   its actuator's stiffness (through the frame: k / sin^2 of the angle between a universal
//   joint's axes), every other component rigid; a locked joint (rigid actuator) joins its bodies;
//   a joint's spring and the joint are one element when both are diagonal in the spring's axes
//   (components in series: the built-in five-bar's joints), else two about a node between them;
// - the platform node at the tool point, the report node (Structure::report_node()).
// Rigid components are exact: the structure's ties (master-slave elimination along trees from the
// base and the platform); a tie that closes a loop base - legs - platform (a robot whose legs are
// rigid but for their joints' motions: the bundled hexapod) is a constraint that msa eliminates
// after the trees (msa/dof_map.hpp). kInvalidInput naming the item: a leg locked from the base to
// the platform, a tie between the two sides of one body.
StatusOr<msa::Structure> robot_msa_structure(const RobotModel& model, const RobotPosture& posture);

}  // namespace kinestat::mechanisms
