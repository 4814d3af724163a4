#include "kinestat/mechanisms/orthoglide_stiffness.hpp"

#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <utility>

#include "kinestat/core/input_checks.hpp"

#include "kinestat/mechanisms/orthoglide_kinematics.hpp"
#include "kinestat/vjm/link_spring.hpp"

namespace kinestat::mechanisms {

using vjm::Chain;
using vjm::JointType;

std::optional<OrthoglideArchitecture> architecture_from_name(const std::string& name) {
  if (name == "3-PUU") return OrthoglideArchitecture::kPUU;
  if (name == "3-PRPaR") return OrthoglideArchitecture::kPRPaR;
  return std::nullopt;
}

Vec3 paper_table_point(double coordinate_mm) { return Vec3::Constant(-coordinate_mm / 1000.0); }

namespace {

// One parallelogram bar: the override or an Euler-Bernoulli cantilever. The 3-PUU leg is twice it
// (a cantilever's stiffness is linear in A, I, J and As: the same as doubling the section).
Mat6 bar_spring(const OrthoglideStiffnessModel& m) {
  if (m.bar_spring) return *m.bar_spring;
  return vjm::cantilever_spring(m.bar_material, m.bar_section, m.link_length, BeamTheory::kEulerBernoulli);
}

}  // namespace

Status validate_stiffness_model(const OrthoglideStiffnessModel& m) {
  // Each value named as the struct's field (the Python attribute), in its range (core/input_checks).
  const std::string model = "Orthoglide stiffness model: ";
  const std::tuple<const char*, double, Quantity, Sign> values[] = {
      {"link_length", m.link_length, Quantity::kLength, Sign::kPositive},
      {"parallelogram_width", m.parallelogram_width, Quantity::kLength, Sign::kPositive},
      {"actuator_stiffness", m.actuator_stiffness, Quantity::kTranslationalStiffness, Sign::kPositive},
      {"foot_length", m.foot_length, Quantity::kLength, Sign::kPositive},
      {"platform_offset", m.platform_offset, Quantity::kLength, Sign::kNonNegative},
      {"bar_material.E", m.bar_material.E, Quantity::kModulus, Sign::kPositive},
      {"bar_material.G", m.bar_material.G, Quantity::kModulus, Sign::kPositive},
      {"foot_material.E", m.foot_material.E, Quantity::kModulus, Sign::kPositive},
      {"foot_material.G", m.foot_material.G, Quantity::kModulus, Sign::kPositive},
  };
  for (const auto& [name, value, quantity, sign] : values)
    if (Status s = check_quantity(value, quantity, model + name, {}, sign); !s.ok()) return s;
  for (const auto& [name, s] : {std::pair{"bar_section", &m.bar_section}, std::pair{"foot_section", &m.foot_section}})
    for (const auto& [field, value, quantity] :
         {std::tuple{".A", s->A, Quantity::kArea}, std::tuple{".Iy", s->Iy, Quantity::kInertia},
          std::tuple{".Iz", s->Iz, Quantity::kInertia}, std::tuple{".J", s->J, Quantity::kInertia}})
      if (Status st = check_quantity(value, quantity, model + name + field, {}, Sign::kPositive); !st.ok()) return st;
  return Status::Ok();
}

StatusOr<Mat6> parallelogram_spring(const OrthoglideStiffnessModel& m, double q) {
  if (Status s = validate_stiffness_model(m); !s.ok()) return s;
  const double L = m.link_length, w = m.parallelogram_width;
  const Mat6 bar = bar_spring(m);
  // The two bars, pinned about y at both plates, from the proximal plate to the distal plate centre.
  std::vector<Chain> bars;
  for (double side : {0.5, -0.5}) {
    Chain c(side > 0 ? "upper bar" : "lower bar");
    c.add_translation(side * w * Vec3::UnitZ(), "proximal plate");
    c.add_passive(JointType::kRevolute, Vec3::UnitY(), q, "proximal pin");
    c.add_translation(L * Vec3::UnitX(), "bar");
    c.add_spring(bar, "bar");
    c.add_passive(JointType::kRevolute, Vec3::UnitY(), -q, "distal pin");
    c.add_translation(-side * w * Vec3::UnitZ(), "distal plate");
    bars.push_back(std::move(c));
  }
  StatusOr<CartesianStiffness> K = vjm::platform_unloaded_stiffness(bars);
  if (!K.ok()) return K.status();
  // Exactly one free motion: the plate's translation along the arc, u = R_y(q) e_z (pure translation).
  if (K->free_directions.size() != 1 || !K->rigid_directions.empty())
    return Status::Singular(
        fmt::format("parallelogram at q = {:.4f} rad: expected one free motion, found {} free and "
                    "{} rigid directions",
                    q, K->free_directions.size(), K->rigid_directions.size()));
  const Vec6 u = K->free_directions[0];
  // Add a force stiffness k0 u u^T along the free motion (k0 = the axial stiffness scale); the passive
  // q2 of eq. (22) produces exactly that motion, so the chain's stiffness does not depend on k0.
  const double k0 = K->stiffness.topLeftCorner<3, 3>().trace();
  return Mat6(K->stiffness + k0 * u * u.transpose());
}

StatusOr<std::vector<Chain>> orthoglide_chains(const OrthoglideStiffnessModel& m, OrthoglideArchitecture a,
                                               const Vec3& p) {
  if (Status s = validate_stiffness_model(m); !s.ok()) return s;
  const double L = m.link_length;
  StatusOr<Vec3> rho = inverse_kinematics(OrthoglideGeometry{L}, p);
  if (!rho.ok()) return rho.status();
  const Mat6 foot =
      m.foot_spring ? *m.foot_spring
                    : vjm::cantilever_spring(m.foot_material, m.foot_section, m.foot_length, BeamTheory::kTimoshenko);
  const Mat6 leg = 2.0 * bar_spring(m);
  std::vector<Chain> chains;
  for (int i = 0; i < 3; ++i) {
    const char* axis = i == 0 ? "x" : i == 1 ? "y" : "z";
    Chain c(fmt::format("{} leg {}", a == OrthoglideArchitecture::kPUU ? "PUU" : "PRPaR", axis));
    // Base frame: local x = -e_i (from the slider towards the workspace), y = -e_(i+1), z = e_(i+2).
    Mat3 R;
    R << -Vec3::Unit(i), -Vec3::Unit((i + 1) % 3), Vec3::Unit((i + 2) % 3);
    vjm::Transform base = vjm::Transform::Identity();
    base.linear() = R;
    c.add_transform(base, "base");
    const double d = m.platform_offset;  // slider moved out by d: same leg vector (header)
    c.add_actuator(JointType::kPrismatic, -Vec3::UnitX(), (*rho)[i] + d, m.actuator_stiffness, "actuator");
    c.add_spring(foot, "foot");
    // Leg direction in the base frame from the inverse kinematics: R_z(q1) R_y(q2) e_x = v / L. Both
    // U axes are normal to the leg at Q0 (an axis along the leg would make Q0 a U-joint singularity).
    const Vec3 v = R.transpose() * (p - (*rho)[i] * Vec3::Unit(i)) / L;
    const double q1 = std::atan2(v.y(), v.x()), q2 = std::atan2(-v.z(), std::hypot(v.x(), v.y()));
    c.add_passive(JointType::kRevolute, Vec3::UnitZ(), q1, "U1 (1st axis)");
    if (a == OrthoglideArchitecture::kPUU) {
      c.add_passive(JointType::kRevolute, Vec3::UnitY(), q2, "U1 (2nd axis)");
      c.add_translation(L * Vec3::UnitX(), "leg");
      c.add_spring(leg, "leg (bar with doubled section)");
      c.add_passive(JointType::kRevolute, Vec3::UnitY(), -q2, "U2 (1st axis)");
    } else {
      StatusOr<Mat6> plg = parallelogram_spring(m, q2);
      if (!plg.ok()) return plg.status();
      const int k = c.add_passive(JointType::kRevolute, Vec3::UnitY(), q2, "parallelogram");
      c.add_translation(L * Vec3::UnitX(), "parallelogram");
      c.add_coupled(JointType::kRevolute, Vec3::UnitY(), k, -1.0, "parallelogram (coupled -q2, eq. 22)");
      c.add_spring(*plg, "parallelogram");
    }
    c.add_passive(JointType::kRevolute, Vec3::UnitZ(), -q1,
                  a == OrthoglideArchitecture::kPUU ? "U2 (2nd axis)" : "platform R");
    if (d > 0) c.add_translation(d * Vec3::UnitX(), "platform (attachment to tool point)");
    c.add_transform(base.inverse(), "tool (global axes)");
    chains.push_back(std::move(c));
  }
  return chains;
}

StatusOr<OrthoglideStiffness> orthoglide_stiffness(const OrthoglideStiffnessModel& m, OrthoglideArchitecture a,
                                                   const Vec3& p, const Vec6& displacement) {
  StatusOr<std::vector<Chain>> chains = orthoglide_chains(m, a, p);
  if (!chains.ok()) return chains.status();
  OrthoglideStiffness out;
  StatusOr<CartesianStiffness> K0 = vjm::platform_unloaded_stiffness(*chains);
  if (!K0.ok()) return K0.status();
  out.unloaded = std::move(*K0);
  StatusOr<vjm::PlatformState> st = vjm::platform_equilibrium(*chains, displacement);
  if (!st.ok()) return st.status();
  out.loaded_state = std::move(*st);
  StatusOr<CartesianStiffness> KF = vjm::platform_loaded_stiffness(*chains, out.loaded_state);
  if (!KF.ok()) return KF.status();
  out.loaded = std::move(*KF);
  return out;
}

}  // namespace kinestat::mechanisms
