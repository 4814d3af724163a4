// The robot model: its checks (make_robot_model) and its chains (one builder for the kinematic
// chains and the VJM chains, so the two cannot disagree on the geometry).
#include "kinestat/mechanisms/robot_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include <Eigen/QR>

#include "fixed_size_vjm.hpp"
#include "robot_equations.hpp"

namespace kinestat::mechanisms {

const char* to_string(RobotJointType t) {
  switch (t) {
    case RobotJointType::kRevolute:
      return "revolute";
    case RobotJointType::kPrismatic:
      return "prismatic";
    case RobotJointType::kUniversal:
      return "universal";
    case RobotJointType::kSpherical:
      return "spherical";
    case RobotJointType::kCylindrical:
      return "cylindrical";
    case RobotJointType::kParallelogram:
      return "parallelogram";
  }
  return "?";
}

int coordinate_count(RobotJointType t) {
  switch (t) {
    case RobotJointType::kUniversal:
    case RobotJointType::kCylindrical:
      return 2;
    case RobotJointType::kSpherical:
      return 3;
    default:
      return 1;
  }
}

bool coordinate_is_length(RobotJointType t, int index) {
  return t == RobotJointType::kPrismatic || (t == RobotJointType::kCylindrical && index == 1);
}

namespace {
// A coordinate in the unit of messages: m, or deg for an angle.
double shown(RobotJointType t, int index, double v) { return coordinate_is_length(t, index) ? v : v * 180.0 / M_PI; }
const char* shown_unit(RobotJointType t, int index) { return coordinate_is_length(t, index) ? "m" : "deg"; }
}  // namespace

std::string coordinate_text(RobotJointType t, int index, double value) {
  return fmt::format("{:.6g} {}", shown(t, index, value), shown_unit(t, index));
}

std::string limits_text(RobotJointType t, int index, double lo, double hi) {
  return fmt::format("[{:g}, {:g}] {}", shown(t, index, lo), shown(t, index, hi), shown_unit(t, index));
}

const char* to_string(TaskCoordinate c) {
  static constexpr const char* kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
  return kNames[static_cast<int>(c)];
}

const char* to_string(KinematicsStatus s) {
  switch (s) {
    case KinematicsStatus::kOk:
      return "ok";
    case KinematicsStatus::kUnreachable:
      return "unreachable";
    case KinematicsStatus::kSingular:
      return "singular";
    case KinematicsStatus::kOtherBranch:
      return "other branch";
  }
  return "?";
}

std::string RobotModel::coordinate_name(int k) const {
  const Coordinate& c = coords_[k];
  const RobotJoint& j = joint(c);
  return coordinate_count(j.type) == 1 ? j.label : fmt::format("{} coordinate {}", j.label, c.index + 1);
}

VecX RobotModel::home_task() const { return task_values(*this, home_.tool); }

namespace {

using vjm::JointType;

// A parallelogram's bars at q, NaN where they lie on one line (the VJM refuses it, naming the spring).
Mat6 bars_spring(const RobotJoint& j, double q) {
  const StatusOr<Mat6> K = robot_parallelogram_spring(j, q);
  return K.ok() ? *K : Mat6::Constant(std::numeric_limits<double>::quiet_NaN());
}

// A spring in `axes` (columns in the current frame): turn into its frame, spring, turn back. Returns
// its index in the chain's springs().
int add_spring(vjm::Chain& c, const RobotSpring& s) {
  if (s.axes.isIdentity(0.0)) {
    c.add_spring(s.stiffness, s.label);
  } else {
    vjm::Transform R = vjm::Transform::Identity();
    R.linear() = s.axes;
    c.add_transform(R, s.label + " (its axes)");
    c.add_spring(s.stiffness, s.label);
    c.add_transform(R.inverse(), s.label + " (back to base axes)");
  }
  return static_cast<int>(c.springs().size()) - 1;
}

// RobotModel::Reach of a kinematic chain: the tool point is origin + a sum of its translations after
// the first motion, each turned by the rotations before it, so no farther than their lengths summed;
// after a first revolute, the translations up to the next motion (U) turn about its axis only, on a
// circle, and the ones after the next motion reach no farther than their lengths summed from it.
RobotModel::Reach chain_reach(const vjm::Chain& c) {
  RobotModel::Reach r;
  vjm::Transform T = vjm::Transform::Identity(), U = vjm::Transform::Identity();
  int motions = 0;
  bool revolute = false;
  for (const vjm::Factor& f : c.factors()) {
    if (!f.is_motion) {
      if (motions == 0) {
        T = T * f.transform;
        continue;
      }
      r.radius += f.transform.translation().norm();
      if (motions == 1)
        U = U * f.transform;
      else
        r.ring_reach += f.transform.translation().norm();
      continue;
    }
    if (f.type == JointType::kPrismatic) {
      const double travel = f.variable ? std::numeric_limits<double>::infinity() : std::abs(f.offset);
      r.radius += travel;
      if (motions >= 1) r.ring_reach += travel;
    }
    if (motions == 0) {
      revolute = f.type == JointType::kRevolute;
      if (revolute) r.axis = (T.linear() * f.axis).normalized();
    }
    ++motions;
  }
  r.origin = T.translation();
  if (revolute) {
    const Vec3 v = T.linear() * U.translation();  // the next motion's point, at the first angle 0
    const double along = r.axis.dot(v);
    r.ring_center = r.origin + along * r.axis;
    r.ring_radius = (v - along * r.axis).norm();
  }
  return r;
}

}  // namespace

double RobotModel::Reach::ring_distance(const Vec3& x) const {
  const Vec3 y = x - ring_center;
  const double h = axis.dot(y);
  return std::hypot(h, (y - h * axis).norm() - ring_radius);
}

// Appends a leg to `chain`: with `q` (the leg's coordinates), `kinematic` makes every coordinate a
// passive variable and leaves the springs out; otherwise actuated coordinates become actuators at
// their values (rigid ones locked) and passive ones passive joints, springs in place.
void append_leg(const RobotLeg& leg, const double* q, bool kinematic, vjm::Chain& chain, const Vec3& tool,
                std::vector<LegItemFactors>* items, RobotVjmChains::Leg* vjm_leg) {
  Vec3 at = Vec3::Zero();
  auto move_to = [&](const Vec3& p, const std::string& label) {
    if (p != at) chain.add_translation(p - at, label);
    at = p;
  };
  auto count = [&] { return static_cast<int>(chain.factors().size()); };
  int k = 0;
  for (const auto& item : leg.items) {
    if (items) items->push_back({count(), count(), count()});
    if (const auto* link = std::get_if<RobotLink>(&item)) {
      move_to(link->to, link->label);
      if (!kinematic && link->spring) add_spring(chain, *link->spring);
      if (items) items->back().end = count();
      continue;
    }
    const RobotJoint& j = std::get<RobotJoint>(item);
    move_to(j.at, j.label + " (its point)");
    if (!kinematic && j.spring) add_spring(chain, *j.spring);
    if (items) items->back().first = count();
    // One elementary motion: the first coordinate of an actuated joint is its actuator.
    auto motion = [&](JointType type, const Vec3& axis, int index, const std::string& label) {
      const double value = q[k++];
      if (!kinematic && j.actuated && index == 0) {
        if (vjm_leg) {
          vjm_leg->actuator_factor.push_back(count());
          vjm_leg->actuator_coordinate.push_back(k - 1);
        }
        chain.add_actuator(type, axis, value, j.actuator_stiffness, label + " (actuator)");
        return -1;
      }
      if (vjm_leg) vjm_leg->passive_coordinate.push_back(k - 1);
      return chain.add_passive(type, axis, value, label);
    };
    switch (j.type) {
      case RobotJointType::kRevolute:
        motion(JointType::kRevolute, j.axes[0], 0, j.label);
        break;
      case RobotJointType::kPrismatic:
        motion(JointType::kPrismatic, j.axes[0], 0, j.label);
        break;
      case RobotJointType::kUniversal:
        motion(JointType::kRevolute, j.axes[0], 0, j.label + " axis 1");
        motion(JointType::kRevolute, j.axes[1], 1, j.label + " axis 2");
        break;
      case RobotJointType::kSpherical:
        for (int i = 0; i < 3; ++i)
          motion(JointType::kRevolute, j.axes[i], i, fmt::format("{} axis {}", j.label, i + 1));
        break;
      case RobotJointType::kCylindrical:
        motion(JointType::kRevolute, j.axes[0], 0, j.label + " rotation");
        motion(JointType::kPrismatic, j.axes[0], 1, j.label + " translation");
        break;
      case RobotJointType::kParallelogram: {
        const int v = motion(JointType::kRevolute, j.axes[0], 0, j.label + " (proximal hinges)");
        chain.add_translation(j.to - j.at, j.label + " (bars)");
        chain.add_coupled(JointType::kRevolute, j.axes[0], v, -1.0, j.label + " (distal hinges, -q)");
        at = j.to;
        if (!kinematic && j.bars) {
          // The bars' spring at the distal plate, set per posture (set_robot_vjm_posture).
          RobotSpring bars;
          bars.label = j.label + " bars";
          bars.stiffness = bars_spring(j, q[k - 1]);
          bars.axes = robot_parallelogram_axes(j);
          const int index = add_spring(chain, bars);
          if (vjm_leg) vjm_leg->posture_springs.push_back({index, k - 1, static_cast<int>(&item - leg.items.data())});
        }
        break;
      }
    }
    if (items) items->back().end = count();
  }
  move_to(tool, "to the tool point");
}

std::vector<RobotItemFrames> robot_leg_frames(const RobotModel& model, int leg, const RobotPosture& posture) {
  const RobotLeg& l = model.description().legs[leg];
  const double* q = posture.q.data() + model.leg_offset(leg);
  vjm::Chain chain(l.name);
  std::vector<LegItemFactors> marks;
  append_leg(l, q, true, chain, model.description().tool, &marks);
  const std::vector<vjm::Transform> poses =
      vjm::factor_poses(chain, Eigen::Map<const VecX>(q, model.leg_coordinates(leg)), VecX());
  std::vector<RobotItemFrames> frames(l.items.size());
  for (std::size_t i = 0; i < l.items.size(); ++i) {
    const LegItemFactors& m = marks[i];
    RobotItemFrames& f = frames[i];
    const bool link = std::holds_alternative<RobotLink>(l.items[i]);
    f.at = poses[link ? m.begin : m.first];
    f.after = poses[m.end];
    if (!link)
      for (int k = m.first; k < m.end; ++k) f.motions.push_back(poses[k]);
  }
  return frames;
}

StatusOr<RobotModel> make_robot_model(RobotDescription d) {
  const std::string src = d.source;  // a copy: d moves into the model before the last checks
  auto invalid = [&](const std::string& what) { return Status::Invalid(fmt::format("{}: {}", src, what)); };
  if (d.legs.empty()) return invalid("a robot needs legs; add `legs:`");
  if (d.task.empty()) return invalid("`task:` names no coordinate; give e.g. [x, y, z]");
  for (std::size_t i = 0; i < d.task.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (d.task[i] == d.task[k])
        return invalid(fmt::format("task coordinate {} is named twice", to_string(d.task[i])));
  RobotModel m;
  double scale = d.tool.norm();
  int actuated = 0;
  m.leg_offset_.push_back(0);
  for (std::size_t l = 0; l < d.legs.size(); ++l) {
    RobotLeg& leg = d.legs[l];
    int joints = 0;
    for (std::size_t i = 0; i < leg.items.size(); ++i) {
      const std::optional<RobotSpring>& spring =
          std::visit([](const auto& x) -> const std::optional<RobotSpring>& { return x.spring; }, leg.items[i]);
      if (spring && !spring->stiffness.allFinite())
        return Status::Invalid(spring->fea
                                   ? fmt::format("{}: this `fea:` spring is not computed yet; resolve it first "
                                                 "(mechanisms::resolve_robot_fea_springs, as the kinestat commands and "
                                                 "robots.load do)",
                                                 spring->fea_where)
                                   : fmt::format("{}: {}: its spring is not finite", src, spring->label));
      if (auto* link = std::get_if<RobotLink>(&leg.items[i])) {
        scale = std::max(scale, link->to.norm());
        continue;
      }
      RobotJoint& j = std::get<RobotJoint>(leg.items[i]);
      ++joints;
      scale = std::max({scale, j.at.norm(), j.to.norm()});
      const int n = coordinate_count(j.type);
      const int axes = j.type == RobotJointType::kSpherical ? 3 : j.type == RobotJointType::kUniversal ? 2 : 1;
      for (int a = 0; a < axes; ++a) {
        if (!j.axes[a].allFinite() || j.axes[a].norm() == 0.0)
          return invalid(fmt::format("{}: axis {} is zero or not finite; give a direction", j.label, a + 1));
        j.axes[a].normalize();
      }
      if (axes == 2 && j.axes[0].cross(j.axes[1]).norm() < 1e-6)
        return invalid(
            fmt::format("{}: its two axes are parallel; a universal joint's axes cross at an angle", j.label));
      if (axes == 3 && std::abs(j.axes[0].dot(j.axes[1].cross(j.axes[2]))) < 1e-6)
        return invalid(fmt::format("{}: its three axes are coplanar; give three independent axes", j.label));
      if (j.type == RobotJointType::kParallelogram) {
        if ((j.to - j.at).norm() < 1e-9 * std::max(1.0, scale))
          return invalid(fmt::format("{}: `to` is at `at`; the parallelogram's bars need a length", j.label));
        if (j.actuated)
          return invalid(
              fmt::format("{}: a parallelogram cannot be actuated here; actuate the joint "
                          "before it",
                          j.label));
        if (j.bars) {
          if (std::abs((j.to - j.at).normalized().dot(j.axes[0])) > 1e-9)
            return invalid(fmt::format("{}: its bars (`at` to `to`) must be normal to its axis", j.label));
          if (!(j.bars->width > 0.0) || !std::isfinite(j.bars->width))
            return invalid(fmt::format("{}: the bars' width {:g} must be positive", j.label, j.bars->width));
          if (!j.bars->stiffness.allFinite() || Eigen::LLT<Mat6>(j.bars->stiffness).info() != Eigen::Success)
            return invalid(fmt::format("{}: a bar's spring is not positive definite", j.label));
        }
      } else if (j.bars) {
        return invalid(fmt::format("{}: only a parallelogram has bars", j.label));
      }
      if (j.actuated) {
        ++actuated;
        if (!(j.actuator_stiffness > 0.0))
          return invalid(fmt::format("{}: actuator stiffness {:g} must be positive (omit it for a rigid actuator)",
                                     j.label, j.actuator_stiffness));
      }
      if (!j.limits.empty() && static_cast<int>(j.limits.size()) != n)
        return invalid(fmt::format("{}: {} limits for {} coordinates", j.label, j.limits.size(), n));
      for (std::size_t c = 0; c < j.limits.size(); ++c)
        if (const auto [lo, hi] = j.limits[c]; !(lo <= 0.0 && 0.0 <= hi))
          return invalid(
              fmt::format("{}: limits {} exclude the home posture (0: coordinates are measured from the drawing)",
                          j.label, limits_text(j.type, static_cast<int>(c), lo, hi)));
      if (d.planar) {
        const bool in_plane = j.type == RobotJointType::kPrismatic ? std::abs(j.axes[0].z()) < 1e-9
                              : (j.type == RobotJointType::kRevolute || j.type == RobotJointType::kParallelogram)
                                  ? j.axes[0].head<2>().norm() < 1e-9
                                  : false;
        if (!in_plane)
          return invalid(
              fmt::format("{}: a planar robot has revolute joints about z and prismatic ones in the x-y "
                          "plane only ({} with axis ({:g}, {:g}, {:g}))",
                          j.label, to_string(j.type), j.axes[0].x(), j.axes[0].y(), j.axes[0].z()));
      }
      for (int c = 0; c < coordinate_count(j.type); ++c)
        m.coords_.push_back({static_cast<int>(l), static_cast<int>(i), c});
    }
    if (joints == 0) return invalid(fmt::format("{} has no joint; a leg is a chain of joints", leg.name));
    m.leg_offset_.push_back(static_cast<int>(m.coords_.size()));
  }
  if (d.planar)
    for (TaskCoordinate c : d.task)
      if (c != TaskCoordinate::kX && c != TaskCoordinate::kY && c != TaskCoordinate::kRz)
        return invalid(fmt::format("task coordinate {}: a planar robot commands x, y and rz only", to_string(c)));
  if (actuated != static_cast<int>(d.task.size()))
    return invalid(
        fmt::format("{} actuated joint{} for {} task coordinate{}; a parallel robot has one actuator per "
                    "commanded coordinate (mark joints `actuated: true`)",
                    actuated, actuated == 1 ? "" : "s", d.task.size(), d.task.size() == 1 ? "" : "s"));
  m.num_q_ = static_cast<int>(m.coords_.size());
  const int e = d.planar ? 3 : 6;
  const int unknowns = m.num_q_ + e, equations = static_cast<int>(d.legs.size()) * e + static_cast<int>(d.task.size());
  if (unknowns > equations)
    return invalid(fmt::format(
        "the legs have {} joint coordinates and the platform {} pose components ({} unknowns), but the legs' closure "
        "gives {} x {} equations and the task {} ({}): the robot has idle motions (e.g. a leg with two spherical "
        "joints spins about itself); use a universal joint at one end",
        m.num_q_, e, unknowns, d.legs.size(), e, d.task.size(), equations));
  for (int l = 0; l < static_cast<int>(d.legs.size()); ++l) {
    m.closure_offset_.push_back(static_cast<int>(m.closure_.size()));
    for (int i = 0; i < e; ++i) m.closure_.push_back({l, d.planar ? kPlanarComponents[i] : i});
  }
  m.closure_offset_.push_back(static_cast<int>(m.closure_.size()));
  m.length_scale_ = scale > 0.0 ? scale : 1.0;
  m.home_.q = VecX::Zero(m.num_q_);
  m.home_.tool = vjm::Transform::Identity();
  m.home_.tool.translation() = d.tool;
  m.d_ = std::move(d);
  for (int l = 0; l < m.num_legs(); ++l) {
    vjm::Chain c(m.d_.legs[l].name);
    append_leg(m.d_.legs[l], m.home_.q.data() + m.leg_offset(l), true, c, m.d_.tool);
    m.reach_.push_back(chain_reach(c));
    m.kinematic_.push_back(std::move(c));
  }
  // An overconstrained robot: the closure equations whose rows of the direct Jacobian (passive joints
  // and platform) at home are independent, by a column-pivoted QR of its transpose. The others must
  // depend on them with the actuators' columns too, else the legs leave the platform fewer motions
  // than task coordinates. A rank-deficient direct Jacobian keeps every equation: the check below
  // names its free motion.
  if (equations > unknowns) {
    RobotData all = make_robot_data(m);
    const RobotJacobians J = robot_jacobians(m, m.home_, all, m.home_task());
    const int closure = static_cast<int>(m.closure_.size()), needed = static_cast<int>(J.direct.cols());
    Eigen::ColPivHouseholderQR<MatX> direct, full;
    direct.setThreshold(1e-9).compute(J.direct.transpose());
    full.setThreshold(1e-9).compute(J.inverse.topRows(closure).transpose());
    if (direct.rank() == needed && full.rank() > needed)
      return invalid(
          fmt::format("the legs over-constrain the platform: at home they leave it {} motion{} for {} task "
                      "coordinate{}; remove a constraint or add a joint",
                      J.inverse.cols() - full.rank(), J.inverse.cols() - full.rank() == 1 ? "" : "s", m.d_.task.size(),
                      m.d_.task.size() == 1 ? "" : "s"));
    if (direct.rank() == needed) {
      std::vector<bool> keep(closure, false);
      for (int i = 0; i < needed; ++i) keep[direct.colsPermutation().indices()(i)] = true;
      const std::vector<RobotModel::ClosureEquation> rows = std::move(m.closure_);
      m.closure_.clear();
      m.closure_offset_.clear();
      for (int l = 0; l < m.num_legs(); ++l) {
        m.closure_offset_.push_back(static_cast<int>(m.closure_.size()));
        for (int r = 0; r < closure; ++r)
          if (rows[r].leg == l) (keep[r] ? m.closure_ : m.redundant_).push_back(rows[r]);
      }
      m.closure_offset_.push_back(static_cast<int>(m.closure_.size()));
    }
  }
  // The Jacobians at home: full rank, else the free motion or the redundant equation is named.
  RobotData data = make_robot_data(m);
  const RobotJacobians J = robot_jacobians(m, m.home_, data, m.home_task());
  for (const auto& [name, A, columns] :
       {std::tuple{"inverse kinematics (all joints and the platform, given the task)", &J.inverse, &J.inverse_columns},
        std::tuple{"direct kinematics (passive joints and the platform, given the actuators)", &J.direct,
                   &J.direct_columns}}) {
    Eigen::JacobiSVD<MatX> svd(*A, Eigen::ComputeFullV);
    const VecX& s = svd.singularValues();
    // Near-singular too: a map's singularity measure is relative to home's conditioning, which
    // would hide the singular loci (the bundled robots' ratios: 0.036 to 0.17).
    constexpr double kNearSingularHome = 1e-3;
    if (s.size() == 0 || s(s.size() - 1) > kNearSingularHome * s(0)) continue;
    const VecX v = svd.matrixV().col(s.size() - 1);
    std::string moving;
    for (int k = 0; k < v.size(); ++k)
      if (std::abs(v(k)) > 0.1 * v.cwiseAbs().maxCoeff())
        moving += (moving.empty() ? "" : ", ") + column_name(m, (*columns)[k]);
    if (s(s.size() - 1) > 1e-9 * s(0))
      return invalid(fmt::format(
          "the {} Jacobian is nearly singular at home (sigma_min / sigma_max = {:.2g}, below {:g}): maps measure "
          "singularity relative to home, so draw the robot at a well-conditioned posture; the weakest motion "
          "involves {}",
          name, s(s.size() - 1) / s(0), kNearSingularHome, moving));
    return invalid(
        fmt::format("the {} Jacobian loses rank at home (sigma_min / sigma_max = {:.2g}): the drawing is a "
                    "singular posture, or a motion is free or constrained twice; the motion involves {}",
                    name, s(s.size() - 1) / s(0), moving));
  }
  if (J.inverse.rows() != J.inverse.cols())
    return invalid(
        fmt::format("the legs over-constrain the platform ({} equations for {} unknowns) and their "
                    "constraints at home cannot be told apart from a loss of rank; remove a constraint",
                    equations, unknowns));
  m.inverse_sign_ = J.inverse.partialPivLu().determinant() > 0 ? 1 : -1;
  m.direct_sign_ = J.direct.partialPivLu().determinant() > 0 ? 1 : -1;
  // Every spring symmetric positive definite and every axis non-zero (vjm::Chain::validate, its
  // message names the spring's FILE:LINE), checked once here: a map's kernels assume it, and would
  // otherwise fail at every posture without saying why.
  for (const vjm::Chain& c : robot_vjm_chains(m, m.home_))
    if (Status st = c.validate(std::numeric_limits<int>::max()); !st.ok()) return st;
  // The singularity measure's reference: solve_posture's estimate at home (home_rcond_ is 1 here).
  RobotPosture home = m.home_;
  const KinematicsResult at_home = solve_posture(m, m.home_task(), home, data);
  if (at_home.status != KinematicsStatus::kOk)
    return invalid(fmt::format("the home drawing is not a posture of the robot: {}", at_home.message));
  m.home_rcond_ = at_home.singularity_measure;
  return m;
}

Mat3 robot_parallelogram_axes(const RobotJoint& j) {
  Mat3 R;
  R.col(0) = (j.to - j.at).normalized();
  R.col(1) = j.axes[0];
  R.col(2) = R.col(0).cross(R.col(1));
  return R;
}

StatusOr<Mat6> robot_parallelogram_spring(const RobotJoint& j, double q) {
  if (!j.bars) return Status::Invalid(fmt::format("{}: no bars", j.label));
  Mat6 K;
  if (!fixed_vjm::parallelogram_stiffness(fixed_vjm::spd_inverse<6>(Eigen::LLT<Mat6>(j.bars->stiffness)),
                                          (j.to - j.at).norm(), j.bars->width, std::cos(q), std::sin(q), K))
    return Status::Singular(fmt::format("{}: its bars lie on one line at {:.6g} deg: nothing holds the plate's turn",
                                        j.label, q * 180.0 / M_PI));
  return K;
}

RobotVjmChains make_robot_vjm_chains(const RobotModel& model) {
  RobotVjmChains out;
  const RobotDescription& d = model.description();
  const RobotPosture& home = model.home();
  for (int l = 0; l < model.num_legs(); ++l) {
    vjm::Chain c(d.legs[l].name);
    RobotVjmChains::Leg leg;
    append_leg(d.legs[l], home.q.data() + model.leg_offset(l), false, c, d.tool, nullptr, &leg);
    // Each chain ends at the tool point with base axes: its tool transform takes the leg's end
    // (the platform frame at the posture) back to base axes (identity at home).
    leg.tool_factor = static_cast<int>(c.factors().size());
    c.add_transform(vjm::Transform::Identity(), "tool (base axes)");
    leg.passive = VecX::Zero(static_cast<int>(leg.passive_coordinate.size()));
    out.chains.push_back(std::move(c));
    out.legs.push_back(std::move(leg));
  }
  return out;
}

void set_robot_vjm_posture(const RobotModel& model, const RobotPosture& posture, RobotVjmChains& chains) {
  vjm::Transform back = vjm::Transform::Identity();
  back.linear() = posture.tool.linear().transpose();
  for (int l = 0; l < model.num_legs(); ++l) {
    vjm::Chain& c = chains.chains[l];
    RobotVjmChains::Leg& leg = chains.legs[l];
    const double* q = posture.q.data() + model.leg_offset(l);
    for (std::size_t a = 0; a < leg.actuator_factor.size(); ++a)
      c.set_offset(leg.actuator_factor[a], q[leg.actuator_coordinate[a]]);
    for (std::size_t i = 0; i < leg.passive_coordinate.size(); ++i)
      leg.passive(static_cast<Eigen::Index>(i)) = q[leg.passive_coordinate[i]];
    c.set_nominal_passive(leg.passive);
    c.set_transform(leg.tool_factor, back);
    for (const RobotVjmChains::Leg::PostureSpring& p : leg.posture_springs)  // indices of the builder's: Ok
      (void)c.set_spring_stiffness(
          p.spring, bars_spring(std::get<RobotJoint>(model.description().legs[l].items[p.item]), q[p.coordinate]));
  }
}

std::vector<vjm::Chain> robot_vjm_chains(const RobotModel& model, const RobotPosture& posture) {
  RobotVjmChains c = make_robot_vjm_chains(model);
  set_robot_vjm_posture(model, posture, c);
  return std::move(c.chains);
}

}  // namespace kinestat::mechanisms
