// Closed-loop kinematics of a RobotModel (docs/robots.md, "Kinematics"): Newton on the loop
// closure and task equations with the Jacobians from the joint screws (vjm::jacobians of each leg's
// kinematic chain), continuation from a solved posture, and the branch test by the signs of the
// Jacobians' determinants.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinestat/mechanisms/robot_model.hpp"
#include "robot_equations.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr int kPlanarComponents[3] = {0, 1, 5};
constexpr double kTolerance = 1e-12;  // scaled residual (m / length scale, rad): ~1e4 eps
constexpr int kMaxNewton = 25;
constexpr double kMaxNewtonStep = 0.3;     // scaled: a larger step is shortened (damped Newton)
constexpr double kContinuationStep = 0.05;  // scaled task distance per continuation step
constexpr double kMinContinuationStep = 1e-3;

int platform_components(const RobotModel& m) { return m.description().planar ? 3 : 6; }
int platform_component(const RobotModel& m, int i) { return m.description().planar ? kPlanarComponents[i] : i; }
bool is_angle(TaskCoordinate c) { return c >= TaskCoordinate::kRx; }

// Rotation angles (rx, ry, rz) of R = Rz(rz) Ry(ry) Rx(rx) and E with omega = E (rx', ry', rz').
Vec3 angles(const Mat3& R) {
  return {std::atan2(R(2, 1), R(2, 2)), std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0))), std::atan2(R(1, 0), R(0, 0))};
}
Mat3 angle_rates(const Vec3& a) {
  const Eigen::AngleAxisd Rz(a.z(), Vec3::UnitZ()), Ry(a.y(), Vec3::UnitY());
  Mat3 E;
  E.col(0) = Rz * (Ry * Vec3::UnitX());
  E.col(1) = Rz * Vec3::UnitY();
  E.col(2) = Vec3::UnitZ();
  return E;
}

// Scale of each unknown / equation: lengths divided by the length scale, angles as they are.
bool unknown_is_length(const RobotModel& m, int u) {
  const int n = m.num_coordinates();
  if (u >= n) return platform_component(m, u - n) < 3;
  const auto& c = m.coordinates()[u];
  const RobotJointType t = m.joint(c).type;
  return t == RobotJointType::kPrismatic || (t == RobotJointType::kCylindrical && c.index == 1);
}
bool equation_is_length(const RobotModel& m, int r) {
  const int e = m.equations_per_leg(), closure = m.num_legs() * e;
  if (r < closure) return platform_component(m, r % e) < 3;
  return !is_angle(m.description().task[r - closure]);
}

// Residual and inverse Jacobian at (posture, task) into data.residual and data.jacobian.
void evaluate(const RobotModel& m, const RobotPosture& p, const VecX& task, RobotData& data) {
  const int n = m.num_coordinates(), e = m.equations_per_leg(), np = platform_components(m);
  const auto& d = m.description();
  data.residual.setZero();
  data.jacobian.setZero();
  const VecX no_theta;
  for (int l = 0; l < m.num_legs(); ++l) {
    const int off = m.leg_offset(l), nl = m.leg_coordinates(l);
    const vjm::ChainJacobians J = vjm::jacobians(m.kinematic_chain(l), p.q.segment(off, nl), no_theta);
    const Vec6 diff = vjm::pose_difference(J.pose, p.tool);
    for (int i = 0; i < e; ++i) {
      const int comp = d.planar ? kPlanarComponents[i] : i;
      data.residual(l * e + i) = diff(comp);
      data.jacobian.row(l * e + i).segment(off, nl) = J.Jq.row(comp);
      data.jacobian(l * e + i, n + i) = -1.0;
    }
  }
  const int closure = m.num_legs() * e;
  const Vec3 a = angles(p.tool.linear());
  Mat3 Einv = Mat3::Identity();
  bool need_rates = false;
  for (TaskCoordinate c : d.task) need_rates |= is_angle(c) && !d.planar;
  if (need_rates) Einv = angle_rates(a).inverse();
  for (std::size_t t = 0; t < d.task.size(); ++t) {
    const int c = static_cast<int>(d.task[t]), row = closure + static_cast<int>(t);
    if (c < 3) {
      data.residual(row) = p.tool.translation()(c) - task(t);
      for (int i = 0; i < np; ++i)
        if (platform_component(m, i) == c) data.jacobian(row, n + i) = 1.0;
    } else {
      data.residual(row) = std::remainder(a(c - 3) - task(t), 2.0 * M_PI);
      for (int i = 0; i < np; ++i) {
        const int comp = platform_component(m, i);
        if (comp >= 3) data.jacobian(row, n + i) = d.planar ? 1.0 : Einv(c - 3, comp - 3);
      }
    }
  }
}

double scaled_norm(const RobotModel& m, const VecX& v, bool equations) {
  double s = 0.0;
  for (int i = 0; i < v.size(); ++i) {
    const bool length = equations ? equation_is_length(m, i) : unknown_is_length(m, i);
    const double x = length ? v(i) / m.length_scale() : v(i);
    s += x * x;
  }
  return std::sqrt(s);
}

void apply_step(const RobotModel& m, const VecX& dx, RobotPosture& p) {
  const int n = m.num_coordinates();
  p.q += dx.head(n);
  Vec6 twist = Vec6::Zero();
  for (int i = 0; i < platform_components(m); ++i) twist(platform_component(m, i)) = dx(n + i);
  p.tool = vjm::displace(p.tool, twist);
}

// Damped Newton from `p` to the target; the inverse Jacobian's LU at the solution stays in data.lu.
// A residual that does not at least halve after a full (undamped) step, from the third on, is not
// converging (Newton from a good start converges quadratically): the caller shortens its step
// instead of iterating on.
bool newton(const RobotModel& m, const VecX& task, RobotPosture& p, RobotData& data, int& iterations) {
  double previous = std::numeric_limits<double>::infinity();
  bool damped = true;
  for (int it = 0; it < kMaxNewton; ++it) {
    evaluate(m, p, task, data);
    if (!data.residual.allFinite()) return false;
    const double r = scaled_norm(m, data.residual, true);
    data.lu.compute(data.jacobian);
    if (r < kTolerance) return true;
    if (it >= 2 && !damped && r > 0.5 * previous) return false;
    previous = r;
    ++iterations;
    data.step = -data.lu.solve(data.residual);
    if (!data.step.allFinite()) return false;
    const double s = scaled_norm(m, data.step, false);
    damped = s > kMaxNewtonStep;
    if (damped) data.step *= kMaxNewtonStep / s;
    apply_step(m, data.step, p);
  }
  return false;
}

int sign_of(double x) { return x > 0 ? 1 : -1; }

}  // namespace

RobotData make_robot_data(const RobotModel& model) {
  const int size = model.num_coordinates() + platform_components(model);
  RobotData d;
  d.x = VecX::Zero(size);
  d.residual = VecX::Zero(size);
  d.step = VecX::Zero(size);
  d.jacobian = MatX::Zero(size, size);
  d.lu = Eigen::PartialPivLU<MatX>(size);
  return d;
}

VecX task_values(const RobotModel& model, const vjm::Transform& tool) {
  const auto& task = model.description().task;
  VecX v(static_cast<int>(task.size()));
  const Vec3 a = angles(tool.linear());
  for (std::size_t t = 0; t < task.size(); ++t) {
    const int c = static_cast<int>(task[t]);
    v(static_cast<int>(t)) = c < 3 ? tool.translation()(c) : a(c - 3);
  }
  return v;
}

std::string column_name(const RobotModel& model, int unknown) {
  const int n = model.num_coordinates();
  if (unknown < n) return model.coordinate_name(unknown);
  static constexpr const char* kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
  return fmt::format("the platform's {}", kNames[platform_component(model, unknown - n)]);
}

RobotJacobians robot_jacobians(const RobotModel& model, const RobotPosture& posture, RobotData& data,
                               const VecX& task) {
  evaluate(model, posture, task, data);
  RobotJacobians J;
  J.residual = data.residual;
  // Length-scaled, so that singular values compare m and rad.
  const int size = static_cast<int>(data.jacobian.rows());
  VecX rows(size), cols(size);
  for (int i = 0; i < size; ++i) {
    rows(i) = equation_is_length(model, i) ? 1.0 / model.length_scale() : 1.0;
    cols(i) = unknown_is_length(model, i) ? model.length_scale() : 1.0;
    J.inverse_columns.push_back(i);
  }
  J.inverse = rows.asDiagonal() * data.jacobian * cols.asDiagonal();
  const int closure = model.num_legs() * model.equations_per_leg();
  for (int u = 0; u < size; ++u)
    if (u >= model.num_coordinates() || !model.actuated(model.coordinates()[u])) J.direct_columns.push_back(u);
  J.direct.resize(closure, static_cast<int>(J.direct_columns.size()));
  for (std::size_t k = 0; k < J.direct_columns.size(); ++k)
    J.direct.col(static_cast<int>(k)) = J.inverse.col(J.direct_columns[k]).head(closure);
  return J;
}

KinematicsResult solve_posture(const RobotModel& model, const VecX& task, RobotPosture& posture, RobotData& data,
                               bool continuation) {
  KinematicsResult out;
  auto same_branch = [&] { return sign_of(data.lu.determinant()) == model.home_inverse_sign(); };
  if (!continuation) {
    if (!newton(model, task, posture, data, out.iterations) || !same_branch()) {
      out.message = "no closure from the neighbouring posture on its branch";
      return out;
    }
  } else {
    const VecX start = task_values(model, posture.tool);
    VecX delta = task - start;
    for (int t = 0; t < delta.size(); ++t)
      if (is_angle(model.description().task[t])) delta(t) = std::remainder(delta(t), 2.0 * M_PI);
    double distance = 0.0;
    for (int t = 0; t < delta.size(); ++t) {
      const double x = is_angle(model.description().task[t]) ? delta(t) : delta(t) / model.length_scale();
      distance += x * x;
    }
    distance = std::sqrt(distance);
    const double max_h = distance > kContinuationStep ? kContinuationStep / distance : 1.0;
    double s = 0.0, h = max_h;
    RobotPosture trial;
    while (s < 1.0) {
      const double next = std::min(1.0, s + h);
      trial = posture;
      if (newton(model, start + next * delta, trial, data, out.iterations) && same_branch()) {
        posture = trial;
        s = next;
        h = std::min(2.0 * h, max_h);
      } else {
        h *= 0.5;
        if (h < kMinContinuationStep * max_h) {
          out.message = fmt::format("no closure beyond {:.3g} of the way from the start posture", s);
          return out;
        }
      }
    }
  }
  // Joint limits (coordinates from home).
  for (int k = 0; k < model.num_coordinates(); ++k) {
    const auto& c = model.coordinates()[k];
    const RobotJoint& j = model.joint(c);
    if (j.limits.empty()) continue;
    const auto [lo, hi] = j.limits[c.index];
    if (posture.q(k) < lo || posture.q(k) > hi) {
      out.message = fmt::format("{} at {:.6g}, outside its limits [{:g}, {:g}]", model.coordinate_name(k), posture.q(k),
                                lo, hi);
      return out;
    }
  }
  const RobotJacobians J = robot_jacobians(model, posture, data, task);
  // The reciprocal condition numbers (LAPACK's 1-norm estimate on the LU, O(n^2)) of the
  // length-scaled Jacobians: a singular value decomposition per posture would cost more than the
  // rest of the kinematics.
  const Eigen::PartialPivLU<MatX> inverse(J.inverse), direct(J.direct);
  out.singularity_measure = std::min(inverse.rcond(), direct.rcond());
  if (!(out.singularity_measure >= 1e-12)) {
    out.singularity_measure = 0.0;
    out.status = KinematicsStatus::kSingular;
    out.message = "the closure equations lose rank here";
    return out;
  }
  if (sign_of(direct.determinant()) != model.home_direct_sign()) {
    out.status = KinematicsStatus::kOtherBranch;
    out.message = "the platform is on another assembly mode than at home";
    return out;
  }
  out.status = KinematicsStatus::kOk;
  return out;
}

}  // namespace kinestat::mechanisms
