#include "kinestat/mechanisms/five_bar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "kinestat/core/units.hpp"

namespace kinestat::mechanisms {

namespace {

// Relative tolerance on lengths: a point a few ulps outside the reach still counts as reachable
// (a round trip at a workspace boundary or a parallel singularity must not fail).
constexpr double kLengthTol = 1e-12;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

Vec2 base_joint(const FiveBarParams& p, int leg) { return {leg == 1 ? -p.r3 : p.r3, 0.0}; }

// Joint centres and labels of a posture whose P is known. At a singularity a label is ambiguous
// (both roots coincide); callers then overwrite it with the mode they were asked for.
FiveBarPosture make_posture(const FiveBarParams& p, double theta1, double theta2, const Vec2& point) {
  FiveBarPosture q;
  q.theta1 = theta1;
  q.theta2 = theta2;
  q.A1 = base_joint(p, 1);
  q.A2 = base_joint(p, 2);
  q.B1 = q.A1 + p.r1 * unit(theta1);
  q.B2 = q.A2 + p.r1 * unit(theta2);
  q.P = point;
  // "+" root of eq. (18) <=> clockwise bend at B_i (see WorkingMode).
  q.working_mode.sign1 = cross2(q.B1 - q.A1, q.P - q.B1) <= 0.0 ? 1 : -1;
  q.working_mode.sign2 = cross2(q.B2 - q.A2, q.P - q.B2) <= 0.0 ? 1 : -1;
  q.assembly = cross2(q.B2 - q.B1, q.P - q.B1) >= 0.0 ? Assembly::kUp : Assembly::kDown;
  return q;
}

std::string point_text(const Vec2& point) { return fmt::format("P = ({:g}, {:g}) m", point.x(), point.y()); }

// Input angle of leg `leg` putting the platform at `point`, for the sign of eq. (18), without a
// message: `failure` says why there is none (posture sweeps call this at every grid point).
enum class LegFailure { kNone, kOutOfReach, kAtBaseJoint };
struct LegAngle {
  double theta = 0.0;
  LegFailure failure = LegFailure::kNone;
  double distance = 0.0;  // |A_iP| (m)
};

LegAngle leg_angle_value(const FiveBarParams& p, const Vec2& point, int leg, int sign) {
  const Vec2 v = point - base_joint(p, leg);
  LegAngle out;
  const double d = out.distance = v.norm();
  const double reach_max = p.r1 + p.r2, reach_min = std::abs(p.r1 - p.r2);
  const double tol = kLengthTol * reach_max;
  if (d > reach_max + tol || d < reach_min - tol) {
    out.failure = LegFailure::kOutOfReach;
  } else if (d <= tol) {
    out.failure = LegFailure::kAtBaseJoint;
  } else {
    // Law of cosines in triangle A_iB_iP; equal to the roots of eq. (17)-(18).
    const double cos_alpha = std::clamp((p.r1 * p.r1 + d * d - p.r2 * p.r2) / (2.0 * p.r1 * d), -1.0, 1.0);
    const double theta = std::atan2(v.y(), v.x()) + sign * std::acos(cos_alpha);
    out.theta = std::remainder(theta, 2.0 * std::numbers::pi);
  }
  return out;
}

StatusOr<double> leg_angle(const FiveBarParams& p, const Vec2& point, int leg, int sign) {
  const LegAngle a = leg_angle_value(p, point, leg, sign);
  if (a.failure == LegFailure::kOutOfReach) {
    return Status::Invalid(fmt::format(
        "five-bar inverse kinematics: {} is out of reach of leg {} (|A{}P| = {:g} m, reachable {:g} to {:g} m)",
        point_text(point), leg, leg, a.distance, std::abs(p.r1 - p.r2), p.r1 + p.r2));
  }
  if (a.failure == LegFailure::kAtBaseJoint) {
    return Status::Invalid(
        fmt::format("five-bar inverse kinematics: {} coincides with base joint A{} (r1 = r2): theta{} is undetermined",
                    point_text(point), leg, leg));
  }
  return a.theta;
}

}  // namespace

std::string to_string(WorkingMode m) { return std::string(1, m.sign1 > 0 ? '+' : '-') + (m.sign2 > 0 ? '+' : '-'); }

std::optional<WorkingMode> working_mode_from_name(const std::string& name) {
  const auto sign = [](char c) { return c == '+' ? 1 : c == '-' ? -1 : 0; };
  if (name.size() != 2 || sign(name[0]) == 0 || sign(name[1]) == 0) return std::nullopt;
  return WorkingMode{sign(name[0]), sign(name[1])};
}

const char* to_string(Assembly a) { return a == Assembly::kUp ? "up" : "down"; }

std::optional<Assembly> assembly_from_name(const std::string& name) {
  if (name == "up") return Assembly::kUp;
  if (name == "down") return Assembly::kDown;
  return std::nullopt;
}

Status validate(const FiveBarParams& p) {
  const std::array<std::pair<const char*, double>, 3> lengths = {{{"r1", p.r1}, {"r2", p.r2}, {"r3", p.r3}}};
  for (const auto& [name, value] : lengths) {
    if (!(std::isfinite(value) && value > 0.0)) {
      return Status::Invalid(
          fmt::format("five-bar parameter {} = {:g} m: a link length must be positive", name, value));
    }
  }
  return Status::Ok();
}

std::optional<FiveBarPosture> try_inverse_kinematics(const FiveBarParams& p, const Vec2& point, WorkingMode mode) {
  if (!point.allFinite()) return std::nullopt;
  const LegAngle t1 = leg_angle_value(p, point, 1, mode.sign1);
  const LegAngle t2 = leg_angle_value(p, point, 2, mode.sign2);
  if (t1.failure != LegFailure::kNone || t2.failure != LegFailure::kNone) return std::nullopt;
  FiveBarPosture q = make_posture(p, t1.theta, t2.theta, point);
  // At a serial singularity both roots coincide; keep the requested label.
  q.working_mode = mode;
  return q;
}

StatusOr<FiveBarPosture> inverse_kinematics(const FiveBarParams& p, const Vec2& point, WorkingMode mode) {
  if (Status s = validate(p); !s.ok()) return s;
  if (!point.allFinite()) return Status::Invalid("five-bar inverse kinematics: the point has a non-finite coordinate");
  if (std::optional<FiveBarPosture> q = try_inverse_kinematics(p, point, mode)) return *q;
  // No posture: the first leg that fails says why.
  for (int leg : {1, 2})
    if (StatusOr<double> t = leg_angle(p, point, leg, leg == 1 ? mode.sign1 : mode.sign2); !t.ok()) return t.status();
  return Status::Internal("five-bar inverse kinematics: no posture and no failing leg");
}

StatusOr<std::array<FiveBarPosture, 4>> inverse_kinematics(const FiveBarParams& p, const Vec2& point) {
  std::array<FiveBarPosture, 4> out;
  const std::array<WorkingMode, 4> modes = {{{1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
  for (std::size_t i = 0; i < modes.size(); ++i) {
    StatusOr<FiveBarPosture> q = inverse_kinematics(p, point, modes[i]);
    if (!q.ok()) return q.status();
    out[i] = *q;
  }
  return out;
}

StatusOr<std::array<FiveBarPosture, 2>> direct_kinematics(const FiveBarParams& p, double theta1, double theta2) {
  if (Status s = validate(p); !s.ok()) return s;
  if (!std::isfinite(theta1) || !std::isfinite(theta2)) {
    return Status::Invalid("five-bar direct kinematics: an input angle is not finite");
  }
  const Vec2 B1 = base_joint(p, 1) + p.r1 * unit(theta1);
  const Vec2 B2 = base_joint(p, 2) + p.r1 * unit(theta2);
  const Vec2 D = B2 - B1;
  const double dist = D.norm();
  const double tol = kLengthTol * (p.r1 + p.r2 + p.r3);
  const auto where = [&] {
    return fmt::format("theta1 = {:g} deg, theta2 = {:g} deg", theta1 / units::kDeg, theta2 / units::kDeg);
  };
  if (dist > 2.0 * p.r2 + tol) {
    return Status::Invalid(
        fmt::format("five-bar direct kinematics: {} cannot be assembled (|B1B2| = {:g} m > 2 r2 = {:g} m)", where(),
                    dist, 2.0 * p.r2));
  }
  if (dist <= tol) {
    return Status::Invalid(fmt::format(
        "five-bar direct kinematics: {} puts B1 on B2, so P can be anywhere on a circle about them", where()));
  }
  // Circle-circle intersection: P = M +- h n, n the unit normal to the left of B1->B2.
  const Vec2 M = 0.5 * (B1 + B2);
  const Vec2 n = Vec2(-D.y(), D.x()) / dist;
  const double h = std::sqrt(std::max(0.0, p.r2 * p.r2 - 0.25 * dist * dist));
  std::array<FiveBarPosture, 2> out = {make_posture(p, theta1, theta2, M + h * n),
                                       make_posture(p, theta1, theta2, M - h * n)};
  out[0].assembly = Assembly::kUp;  // by construction, also where h = 0
  out[1].assembly = Assembly::kDown;
  return out;
}

StatusOr<FiveBarPosture> direct_kinematics(const FiveBarParams& p, double theta1, double theta2, Assembly a) {
  StatusOr<std::array<FiveBarPosture, 2>> both = direct_kinematics(p, theta1, theta2);
  if (!both.ok()) return both.status();
  return (*both)[a == Assembly::kUp ? 0 : 1];
}

FiveBarJacobians five_bar_jacobians(const FiveBarPosture& q) {
  FiveBarJacobians J;
  const Vec2 e1 = q.P - q.B1, e2 = q.P - q.B2;
  const Vec2 l1 = q.B1 - q.A1, l2 = q.B2 - q.A2;
  J.A.row(0) = e1.transpose();
  J.A.row(1) = e2.transpose();
  // dB_i/dtheta_i = l_i rotated by +90 degrees, so (P - B_i) . dB_i/dtheta_i = l_i x (P - B_i).
  J.B = Mat2::Zero();
  J.B(0, 0) = cross2(l1, e1);
  J.B(1, 1) = cross2(l2, e2);
  const auto sine = [](const Vec2& a, const Vec2& b) { return std::abs(cross2(a, b)) / (a.norm() * b.norm()); };
  J.parallel_measure = sine(e1, e2);
  J.serial_measure = std::min(sine(l1, e1), sine(l2, e2));
  return J;
}

msa::Structure make_five_bar_structure(const FiveBarParams& p, const FiveBarPosture& q) {
  msa::Structure s;
  s.set_title(fmt::format("5R five-bar (Gonçalves et al. 2010), theta1 = {:g} deg, theta2 = {:g} deg, {} assembly",
                          q.theta1 / units::kDeg, q.theta2 / units::kDeg, to_string(q.assembly)));
  const auto at = [](const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); };
  // Section 5, Fig. 4a: each joint centre carries one node per link end.
  const std::array<Vec2, 8> positions = {q.A1, q.B1, q.B1, q.P, q.P, q.B2, q.B2, q.A2};
  for (std::size_t i = 0; i < positions.size(); ++i) s.add_node(std::to_string(i + 1), at(positions[i]));

  Material material = p.link_material;
  if (material.id.empty()) material.id = "link material";
  Section section = p.link_section;
  if (section.id.empty()) section.id = "link section";
  const int mat = s.add_material(material);
  const int sec = s.add_section(section);
  const std::array<std::pair<const char*, int>, 4> links = {{{"A1B1", 0}, {"B1P", 2}, {"PB2", 4}, {"B2A2", 6}}};
  for (const auto& [id, first] : links) {
    msa::Beam b;
    b.id = id;
    b.node1 = first;
    b.node2 = first + 1;
    b.material = mat;
    b.section = sec;
    s.add_beam(b);
  }
  const std::array<std::pair<const char*, int>, 3> joints = {{{"B1", 1}, {"P", 3}, {"B2", 5}}};
  for (const auto& [id, first] : joints) {
    msa::Joint j;
    j.id = id;
    j.node1 = first;
    j.node2 = first + 1;
    j.stiffness = p.joint_stiffness;  // frame = global axes: z is the joint axis
    s.add_joint(j);
  }
  s.add_support({0, msa::kAllDofs, Mat3::Identity()});
  s.add_support({7, msa::kAllDofs, Mat3::Identity()});
  const std::array<std::string, 2> load_names = {"Fx", "Fy"};
  for (int axis = 0; axis < 2; ++axis) {
    msa::NodalLoad load{kFiveBarPlatformNode, Vec6::Zero()};
    load.wrench[axis] = p.load;
    s.add_load_case(msa::LoadCase{load_names[axis], {load}, {}});
  }
  s.set_report_node(kFiveBarPlatformNode);
  return s;
}

StatusOr<msa::Structure> make_five_bar_structure(const FiveBarParams& p, double theta1, double theta2, Assembly a) {
  StatusOr<FiveBarPosture> q = direct_kinematics(p, theta1, theta2, a);
  if (!q.ok()) return q.status();
  return make_five_bar_structure(p, *q);
}

StatusOr<msa::Structure> make_five_bar_structure(const FiveBarParams& p, const Vec2& point, WorkingMode mode) {
  StatusOr<FiveBarPosture> q = inverse_kinematics(p, point, mode);
  if (!q.ok()) return q.status();
  return make_five_bar_structure(p, *q);
}

}  // namespace kinestat::mechanisms
