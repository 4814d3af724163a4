// Chains shared by the vjm tests. SI units.
#pragma once

#include "kinestat/elements/section.hpp"
#include "kinestat/vjm/chain.hpp"
#include "kinestat/vjm/link_spring.hpp"

namespace kinestat::vjm::test_chains {

inline Material steel() { return Material::from_E_nu("steel", 2.1e11, 0.3); }

// Planar pendulum: rotational spring k (N m/rad) about z at the base, rigid link of length l (m)
// along x, axial spring ka (N/m), passive pin about z at the tip (the tool point). Rigid along z
// and about x, y; free to rotate about z at the tool.
inline Chain pendulum(double k, double ka, double l) {
  Chain c("pendulum");
  c.add_actuator(JointType::kRevolute, Vec3::UnitZ(), 0.0, k, "base spring");
  c.add_translation(Vec3(l, 0, 0), "link");
  c.add_actuator(JointType::kPrismatic, Vec3::UnitX(), 0.0, ka, "axial spring");
  c.add_passive(JointType::kRevolute, Vec3::UnitZ(), 0.0, "tip pin");
  return c;
}

// A chain with the structure of eq. (1): base, actuated prismatic joint with its spring, foot,
// 6-dof foot spring, U joint, leg, 6-dof leg spring, U joint (or S joint), tool. Off-axis geometry
// and non-zero nominal angles so that no term vanishes by symmetry.
inline Chain eq1_chain(bool spherical_end) {
  Chain c(spherical_end ? "eq1-S" : "eq1-U");
  c.add_rotation(Vec3(1, 1, 0), 0.3, "base");
  c.add_translation(Vec3(0.1, -0.2, 0.05), "base");
  c.add_actuator(JointType::kPrismatic, Vec3::UnitX(), 0.15, 2e6, "actuator");
  c.add_translation(Vec3(0.05, 0.02, 0.0), "foot");
  c.add_spring(cantilever_spring(steel(), circle_section(0.02), 0.05, BeamTheory::kEulerBernoulli), "foot spring");
  c.add_universal(Vec3::UnitY(), Vec3::UnitZ(), 0.2, -0.3, "U1");
  c.add_translation(Vec3(0.3, 0, 0), "leg");
  c.add_spring(cantilever_spring(steel(), circle_section(0.01), 0.3, BeamTheory::kEulerBernoulli), "leg spring");
  if (spherical_end) {
    c.add_spherical(Vec3(0.1, -0.2, 0.25), "S");  // tool point at the S centre: the chain carries no moment
  } else {
    c.add_universal(Vec3::UnitZ(), Vec3::UnitY(), 0.3, -0.2, "U2");
    c.add_translation(Vec3(0.02, 0.01, 0), "tool");
  }
  return c;
}

}  // namespace kinestat::vjm::test_chains
