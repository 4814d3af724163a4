// VJM stiffness models of the Orthoglide: the 3-PUU mechanism and the 3-PRPaR (parallelogram legs),
// Pashkevich, Klimchik, Chablat, Wenger 2009, section 5, Tables 1-3.
//
// Geometry (orthoglide_kinematics.hpp): slider i at rho_i e_i on the global axis e_i, a leg of
// length L from the slider to the tool point p; p = 0 is the isotropic posture Q0. Each chain,
// in eq. (1)'s order: base frame (local x = -e_i, towards the workspace), actuated prismatic joint
// with its spring, foot spring, U joint (axes local z then y, both normal to the leg at Q0), leg, leg
// spring,
// then
//   3-PUU:   a second U joint (q3, q4 independent, nominally -q2, -q1);
//   3-PRPaR: the parallelogram R_y(q2) T_x(L) R_y(-q2) V_s of eq. (22), whose 6x6 spring is derived by
//            the VJM from its two bars (parallelogram_spring), then the platform R joint (q4).
// then, with platform_offset d > 0, the platform (leg end p + d e_i to the tool point p).
// The paper publishes neither its link stiffness nor its actuator stiffness: the defaults below are
// nominal choices (docs/vjm.md), so values differ from Tables 1-2 while the structure (isotropy at
// Q0, sign patterns, orderings) does not depend on them; orthoglide_identification.hpp identifies
// the inputs from the tables (models/orthoglide_*.yaml).
//
// Point convention: the tables' Q1 (x = y = z = -73.65 mm) and Q2 (126.35 mm) are the corners of
// the 200 mm design cube only with the axes reversed (p = -x): p = +126.35 mm on the kinematics'
// axes is 0.5 mm from the flat parallel singularity L/sqrt(6) = 126.8 mm. paper_table_point()
// converts; the tables' loaded displacement (0.5, 0.5, 0.5) mm converts the same way.
#pragma once

#include <optional>
#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::mechanisms {

enum class OrthoglideArchitecture { kPUU, kPRPaR };
// "3-PUU" / "3-PRPaR" (the model files' spelling); nullopt for anything else.
std::optional<OrthoglideArchitecture> architecture_from_name(const std::string& name);

// SI units. Defaults: the prototype's L (design paper, strategy 1); aluminium tube bars; the other
// values are assumptions stated in docs/vjm.md.
struct OrthoglideStiffnessModel {
  double link_length = 0.3106;        // L (m)
  double parallelogram_width = 0.08;  // distance between the two bars' axes (m)
  Material bar_material = Material::from_E_nu("aluminium", 70e9, 0.33);
  Section bar_section = tube_section(0.020, 0.002);  // one parallelogram bar; the PUU leg has twice A, I, J
  double actuator_stiffness = 2e7;                   // N/m, ball-screw axial stiffness (assumed)
  Material foot_material = Material::from_E_nu("steel", 210e9, 0.3);
  Section foot_section = hollow_rectangle_section(0.06, 0.06, 0.005);
  double foot_length = 0.1;  // m, foot modelled as a cantilever along the slider axis
  // Leg i meets the platform at p + d e_i, not at the tool point p (the platform's half-width along
  // the slider axes, m). The slider moves out by d, so the legs' vectors, and with them the
  // kinematics of orthoglide_kinematics.hpp, are unchanged (only the slider origin shifts); the leg
  // forces gain a lever arm d on the platform rotation wherever the legs are not parallel to the
  // sliders (everywhere but Q0).
  double platform_offset = 0.0;
  // Optional 6x6 link springs (e.g. from FEA, fea::link_stiffness) replacing the beam-built ones;
  // empty: built from the sections above. Frames are those of the chain where the spring enters:
  //  foot_spring: the foot's end relative to the slider, axes x = -e_i (along the slider axis,
  //    towards the workspace), y = -e_(i+1), z = e_(i+2) (the first U / R joint axis), about the
  //    joint's centre, i.e. the frame of cantilever_spring(foot_section, foot_length);
  //  bar_spring: the distal end of one parallelogram bar relative to its proximal end, axes x along
  //    the bar (proximal to distal pin), y = the pin axis, about the distal pin, i.e. the frame of
  //    cantilever_spring(bar_section, link_length). The 3-PUU leg spring is twice it.
  // Checked like every chain spring (finite, symmetric, positive definite) when the chains are used.
  std::optional<Mat6> foot_spring, bar_spring;
};

// Kinematics-frame point of the tables' "x, y, z = c" (mm): p = -c/1000 (1, 1, 1) m.
Vec3 paper_table_point(double coordinate_mm);

// Positive, finite lengths, actuator stiffness, section properties and moduli; kInvalidInput otherwise.
Status validate_stiffness_model(const OrthoglideStiffnessModel& m);

// 6x6 stiffness of the parallelogram's distal plate relative to its proximal plate, in the
// proximal frame at the distal plate centre, at bar angle q (rad), from the VJM of its two pinned
// bars. The closed loop leaves the parallelogram's own motion free; the spring of eq. (22) adds a
// stiffness along that motion, which the passive q2 of eq. (22) cancels exactly.
StatusOr<Mat6> parallelogram_spring(const OrthoglideStiffnessModel& m, double q);

// The three chains at the Cartesian point p (kinematics frame, m), working-mode inverse kinematics.
StatusOr<std::vector<vjm::Chain>> orthoglide_chains(const OrthoglideStiffnessModel& m, OrthoglideArchitecture a,
                                                    const Vec3& p);

struct OrthoglideStiffness {
  CartesianStiffness unloaded;
  CartesianStiffness loaded;
  vjm::PlatformState loaded_state;  // wrench, convergence report
};

// Unloaded and loaded (platform displaced by `displacement`, m and rad) stiffness at p.
StatusOr<OrthoglideStiffness> orthoglide_stiffness(const OrthoglideStiffnessModel& m, OrthoglideArchitecture a,
                                                   const Vec3& p, const Vec6& displacement);

}  // namespace kinestat::mechanisms
