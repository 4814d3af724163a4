// The Orthoglide (3-PUU or 3-PRPaR) as an MSA frame: the same mechanism and the same inputs as the
// VJM chains of orthoglide_stiffness.hpp, element for element, so the two methods can be compared
// (the frame's Cartesian stiffness at the tool node equals vjm::platform_unloaded_stiffness of
// orthoglide_chains, tests/mechanisms/orthoglide_frame_test.cpp).
//
// Per leg i (slider axis e_i, slider at rho_i e_i from the inverse kinematics, leg direction d):
//   ground node (fully supported) --actuator joint: k_act along e_i, rigid in the other 5 dofs-->
//   foot clamp node at (rho_i + foot_length) e_i --foot beam (Timoshenko)--> slider node
//   3-PUU:   --U joint (rotations about a1, a2 released)--> leg: two bars of bar_section between the
//            same nodes (the VJM's one bar of doubled section) --U joint (a2, a1)--> tool node;
//   3-PRPaR: --revolute a1--> proximal plate (rigid links to the bars' ends at +-w/2 a1) --pins
//            about a2--> two bars of bar_section --pins about a2--> distal plate (rigid links) at the
//            tool point --revolute a1 (platform R)--> tool node.
// a1 = e_(i+2) is the U joint's first axis, a2 = the axis of the second rotation (normal to a1 and d),
// the VJM's base frame rotated by q1 about a1. Joints: released rotations 0, everything else
// msa::kRigid. With platform_offset d = 0 the legs end at the tool point and the platform is the
// tool node itself (three joints into it); with d > 0 slider and leg end move by d e_i and a rigid link
// (the platform) joins each leg end to the tool node. Report node = the tool node. Units: SI (m, N,
// Pa), as the model.
#pragma once

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::mechanisms {

// The frame at the Cartesian point p (kinematics frame, m), working-mode inverse kinematics. No load
// cases. kInvalidInput for an unreachable point or bad model values (the message names them).
StatusOr<msa::Structure> orthoglide_frame(const OrthoglideStiffnessModel& model, OrthoglideArchitecture architecture,
                                          const Vec3& point);

}  // namespace kinestat::mechanisms
