#include "kinestat/mechanisms/orthoglide_frame.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "kinestat/core/frame.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"

namespace kinestat::mechanisms {

namespace {

// Joint stiffness in the leg's joint frame (x, y = a2, z = a1): everything rigid except the
// rotations released about a2 (ry) and/or a1 (rz).
Vec6 released(bool about_a2, bool about_a1) {
  Vec6 k = Vec6::Constant(msa::kRigid);
  if (about_a2) k(4) = 0.0;
  if (about_a1) k(5) = 0.0;
  return k;
}

}  // namespace

StatusOr<msa::Structure> orthoglide_frame(const OrthoglideStiffnessModel& m, OrthoglideArchitecture a, const Vec3& p) {
  if (Status st = validate_stiffness_model(m); !st.ok()) return st;
  const double L = m.link_length;
  StatusOr<Vec3> rho = inverse_kinematics(OrthoglideGeometry{L}, p);
  if (!rho.ok()) return rho.status();
  const bool puu = a == OrthoglideArchitecture::kPUU;

  msa::Structure s;
  s.set_title(fmt::format("Orthoglide {} at p = ({:g}, {:g}, {:g}) m", puu ? "3-PUU" : "3-PRPaR", p.x(), p.y(), p.z()));
  Material bar_material = m.bar_material, foot_material = m.foot_material;
  bar_material.id = "bar";
  foot_material.id = "foot";
  Section bar_section = m.bar_section, foot_section = m.foot_section;
  bar_section.id = "bar";
  foot_section.id = "foot";
  const int bar_mat = s.add_material(bar_material), foot_mat = s.add_material(foot_material);
  const int bar_sec = s.add_section(bar_section), foot_sec = s.add_section(foot_section);
  const int tool = s.add_node("tool", p);

  for (int i = 0; i < 3; ++i) {
    const std::string leg = i == 0 ? "x" : i == 1 ? "y" : "z";
    const auto id = [&](const char* what) { return fmt::format("{} {}", leg, what); };
    // The VJM chain's base frame (orthoglide_chains): x = -e_i, y = -e_(i+1), z = e_(i+2) = a1.
    Mat3 R;
    R << -Vec3::Unit(i), -Vec3::Unit((i + 1) % 3), Vec3::Unit((i + 2) % 3);
    // Platform offset d: slider and leg end both moved by d e_i (orthoglide_stiffness.hpp), the leg
    // end joined to the tool node by a rigid link (the platform).
    const double d = m.platform_offset;
    const Vec3 slider = ((*rho)[i] + d) * Vec3::Unit(i), attach = p + d * Vec3::Unit(i);
    int platform = tool;
    if (d > 0) {
      platform = s.add_node(id("platform"), attach);
      s.add_rigid_link({.id = id("platform"), .master = tool, .slave = platform});
    }
    // Same q1 as the VJM builder; F = R R_z(q1) has y = a2 (the second rotation's axis) and z = a1.
    const Vec3 v = R.transpose() * (attach - slider) / L;
    const Mat3 F = R * axis_angle(Vec3::UnitZ(), std::atan2(v.y(), v.x()));
    const Vec3 a1 = F.col(2), a2 = F.col(1);

    // Actuator: a spring along the slider axis between the ground and the foot's clamped end.
    const Vec3 clamp = slider + m.foot_length * Vec3::Unit(i);
    const int ground = s.add_node(id("ground"), clamp), foot = s.add_node(id("foot clamp"), clamp);
    s.add_support({.node = ground});
    Vec6 k_act = Vec6::Constant(msa::kRigid);
    k_act(0) = m.actuator_stiffness;
    s.add_joint({.id = id("actuator"), .node1 = ground, .node2 = foot, .frame = R, .stiffness = k_act});
    // Foot: the cantilever of the VJM's foot spring, local x = R's x towards the slider, y = R's y.
    const int slider_node = s.add_node(id("slider"), slider);
    s.add_beam({.id = id("foot"),
                .node1 = foot,
                .node2 = slider_node,
                .material = foot_mat,
                .section = foot_sec,
                .orientation = R.col(1),
                .theory = BeamTheory::kTimoshenko});
    const int proximal = s.add_node(id(puu ? "leg start" : "proximal plate"), slider);
    s.add_joint({.id = id(puu ? "U1" : "R1"),
                 .node1 = slider_node,
                 .node2 = proximal,
                 .frame = F,
                 .stiffness = released(puu, true)});

    // A joint's rigid components tie node2 to node1 and a node can follow one master only, so the
    // joints at the tool end have the tool (or the distal plate) as node1.
    const auto bar = [&](int from, int to, const std::string& name) {
      s.add_beam({.id = name, .node1 = from, .node2 = to, .material = bar_mat, .section = bar_sec, .orientation = a2});
    };
    if (puu) {
      // Two bars between the same nodes: the VJM's leg spring is one bar of doubled A, I, J and shear areas.
      const int end = s.add_node(id("leg end"), attach);
      bar(proximal, end, id("leg bar 1"));
      bar(proximal, end, id("leg bar 2"));
      s.add_joint({.id = id("U2"), .node1 = platform, .node2 = end, .frame = F, .stiffness = released(true, true)});
      continue;
    }
    const int distal = s.add_node(id("distal plate"), attach);
    for (double side : {0.5, -0.5}) {
      const Vec3 bar_offset = side * m.parallelogram_width * a1;
      const std::string name = id(side > 0 ? "upper bar" : "lower bar");
      const int n0 = s.add_node(name + " proximal plate", slider + bar_offset);
      const int n1 = s.add_node(name + " proximal end", slider + bar_offset);
      const int n2 = s.add_node(name + " distal end", attach + bar_offset);
      const int n3 = s.add_node(name + " distal plate", attach + bar_offset);
      s.add_rigid_link({.id = name + " proximal plate", .master = proximal, .slave = n0});
      s.add_joint(
          {.id = name + " proximal pin", .node1 = n0, .node2 = n1, .frame = F, .stiffness = released(true, false)});
      bar(n1, n2, name);
      s.add_joint(
          {.id = name + " distal pin", .node1 = n3, .node2 = n2, .frame = F, .stiffness = released(true, false)});
      s.add_rigid_link({.id = name + " distal plate", .master = distal, .slave = n3});
    }
    s.add_joint(
        {.id = id("platform R"), .node1 = platform, .node2 = distal, .frame = F, .stiffness = released(false, true)});
  }
  s.set_report_node(tool);
  if (Status st = s.validate(); !st.ok()) return Status::Invalid("Orthoglide frame: " + st.message());
  return s;
}

}  // namespace kinestat::mechanisms
