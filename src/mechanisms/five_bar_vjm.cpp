#include "kinestat/mechanisms/five_bar_vjm.hpp"

#include <cmath>
#include <limits>

#include "kinestat/vjm/link_spring.hpp"

namespace kinestat::mechanisms {
namespace {

double direction(const Vec2& from, const Vec2& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }

// The MSA revolute joint (joint_stiffness, kr_z = 0) as a spring plus a passive rotation about z:
// the passive joint makes the spring's rz entry irrelevant, so it is set to kr_x to keep the
// spring positive definite.
Mat6 joint_spring(const FiveBarParams& p) {
  Vec6 k = p.joint_stiffness;
  k(5) = k(3);
  return k.asDiagonal();
}

// From the motor at points[0] through the links to P, in global axes at P. Every frame has z =
// global z, so the joints' springs (isotropic in x-y) need no rotation.
vjm::Chain leg(const FiveBarParams& p, const std::vector<Vec2>& points, bool joint_at_end, const char* name) {
  vjm::Chain c(name);
  vjm::Transform base = vjm::Transform::Identity();
  base.translation() = Vec3(points[0].x(), points[0].y(), 0.0);
  c.add_transform(base, "motor");
  double angle = direction(points[0], points[1]);
  c.add_actuator(vjm::JointType::kRevolute, Vec3::UnitZ(), angle, std::numeric_limits<double>::infinity(),
                 "locked actuator");
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double length = (points[i] - points[i - 1]).norm();
    c.add_translation(length * Vec3::UnitX(), "link");
    c.add_spring(vjm::cantilever_spring(p.link_material, p.link_section, length, BeamTheory::kEulerBernoulli), "link");
    if (i + 1 < points.size() || joint_at_end) {
      const double next = i + 1 < points.size() ? direction(points[i], points[i + 1]) : angle;
      c.add_spring(joint_spring(p), "joint");
      c.add_passive(vjm::JointType::kRevolute, Vec3::UnitZ(), next - angle, "joint");
      angle = next;
    }
  }
  c.add_rotation(Vec3::UnitZ(), -angle, "tool (global axes)");
  return c;
}

}  // namespace

std::vector<vjm::Chain> five_bar_vjm_chains(const FiveBarParams& p, const FiveBarPosture& q) {
  return {leg(p, {q.A1, q.B1, q.P}, true, "left leg"), leg(p, {q.A2, q.B2, q.P}, false, "right leg")};
}

}  // namespace kinestat::mechanisms
