#include "kinestat/vjm/chain.hpp"

#include <fmt/format.h>

#include <cmath>

#include "kinestat/core/input_checks.hpp"

namespace kinestat::vjm {

void Chain::add_transform(const Transform& T, std::string label) {
  Factor f;
  f.label = std::move(label);
  f.transform = T;
  factors_.push_back(std::move(f));
}

void Chain::add_translation(const Vec3& d, std::string label) {
  Transform T = Transform::Identity();
  T.translation() = d;
  add_transform(T, std::move(label));
}

void Chain::add_rotation(const Vec3& axis, double angle, std::string label) {
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  add_transform(T, std::move(label));
}

int Chain::add_motion(JointType type, const Vec3& axis, double offset, std::optional<VariableRef> v,
                      std::string label) {
  Factor f;
  f.label = std::move(label);
  f.is_motion = true;
  f.type = type;
  f.axis = axis.norm() > 0 ? Vec3(axis.normalized()) : axis;  // zero axis: reported by validate()
  f.offset = offset;
  f.variable = v;
  factors_.push_back(std::move(f));
  return v ? v->index : -1;
}

int Chain::add_actuator(JointType type, const Vec3& axis, double value, double stiffness, std::string label) {
  if (std::isinf(stiffness) && stiffness > 0) return add_motion(type, axis, value, std::nullopt, std::move(label));
  const int index = num_virtual_++;
  springs_.push_back({label, index, MatX::Constant(1, 1, stiffness)});
  return add_motion(type, axis, value, VariableRef{VariableKind::kVirtual, index, 1.0}, std::move(label));
}

int Chain::add_spring(const Mat6& K, std::string label) {
  const int first = num_virtual_;
  springs_.push_back({label, first, K});
  static const char* kNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  for (int i = 0; i < 6; ++i) {
    const JointType type = i < 3 ? JointType::kPrismatic : JointType::kRevolute;
    add_motion(type, Vec3::Unit(i % 3), 0.0, VariableRef{VariableKind::kVirtual, num_virtual_++, 1.0},
               fmt::format("{} {}", label, kNames[i]));
  }
  return first;
}

Status Chain::set_spring_stiffness(int index, const Mat6& K) {
  if (index < 0 || index >= static_cast<int>(springs_.size()))
    return Status::Invalid(fmt::format("chain '{}' has no spring {} (it has {})", name_, index, springs_.size()));
  springs_[index].stiffness = K;
  return Status::Ok();
}

void Chain::set_offset(int factor, double offset) {
  if (factor >= 0 && factor < static_cast<int>(factors_.size()) && factors_[factor].is_motion)
    factors_[factor].offset = offset;
}

void Chain::set_transform(int factor, const Transform& T) {
  if (factor >= 0 && factor < static_cast<int>(factors_.size()) && !factors_[factor].is_motion)
    factors_[factor].transform = T;
}

int Chain::add_passive(JointType type, const Vec3& axis, double nominal, std::string label) {
  const int index = num_passive();
  nominal_q_.push_back(nominal);
  return add_motion(type, axis, 0.0, VariableRef{VariableKind::kPassive, index, 1.0}, std::move(label));
}

void Chain::add_coupled(JointType type, const Vec3& axis, int index, double coefficient, std::string label) {
  add_motion(type, axis, 0.0, VariableRef{VariableKind::kPassive, index, coefficient}, std::move(label));
}

int Chain::add_universal(const Vec3& axis1, const Vec3& axis2, double q1, double q2, std::string label) {
  const int first = add_passive(JointType::kRevolute, axis1, q1, label + " (1st axis)");
  add_passive(JointType::kRevolute, axis2, q2, label + " (2nd axis)");
  return first;
}

int Chain::add_spherical(const Vec3& angles, std::string label) {
  const int first = add_passive(JointType::kRevolute, Vec3::UnitX(), angles.x(), label + " (x)");
  add_passive(JointType::kRevolute, Vec3::UnitY(), angles.y(), label + " (y)");
  add_passive(JointType::kRevolute, Vec3::UnitZ(), angles.z(), label + " (z)");
  return first;
}

MatX Chain::spring_stiffness() const {
  MatX K = MatX::Zero(num_virtual_, num_virtual_);
  for (const Spring& s : springs_) K.block(s.first, s.first, s.stiffness.rows(), s.stiffness.cols()) = s.stiffness;
  return K;
}

double Chain::length_scale() const {
  double L = 0.0;
  for (const Factor& f : factors_) {
    if (!f.is_motion)
      L += f.transform.translation().norm();
    else if (f.type == JointType::kPrismatic)
      L += std::abs(f.offset);
  }
  return L > 0.0 ? L : 1.0;
}

Status Chain::validate(int max_coordinates) const {
  const double n = num_coordinates();
  if (Status s =
          check_size(n, max_coordinates, fmt::format("chain '{}'", name_),
                     fmt::format("coordinates (passive and virtual: dense matrices of {:.2g} bytes each)", 8.0 * n * n),
                     "use fewer springs and joints, or raise the limit (vjm --max-coordinates)");
      !s.ok())
    return s;
  for (const Factor& f : factors_) {
    if (f.is_motion && !(std::abs(f.axis.norm() - 1.0) < 1e-12))
      return Status::Invalid(
          fmt::format("chain '{}', joint '{}': the axis is zero or not finite; give a non-zero axis", name_, f.label));
    if (f.is_motion && f.variable && f.variable->kind == VariableKind::kPassive &&
        (f.variable->index < 0 || f.variable->index >= num_passive()))
      return Status::Invalid(fmt::format("chain '{}', joint '{}': coupled to passive joint {} which does not exist",
                                         name_, f.label, f.variable->index));
    if (!f.is_motion && !f.transform.matrix().allFinite())
      return Status::Invalid(fmt::format("chain '{}', transform '{}' is not finite", name_, f.label));
  }
  for (const Spring& s : springs_) {
    const MatX& K = s.stiffness;
    const double scale = K.cwiseAbs().maxCoeff();
    if (!K.allFinite() || !(scale > 0))
      return Status::Invalid(
          fmt::format("chain '{}', spring '{}': the stiffness is zero or not finite (N/m, N m/rad); "
                      "give positive values or lock the joint (+inf for an actuator)",
                      name_, s.label));
    if ((K - K.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
      return Status::Invalid(
          fmt::format("chain '{}', spring '{}': the stiffness matrix is not symmetric", name_, s.label));
    Eigen::SelfAdjointEigenSolver<MatX> eig(K);
    if (!(eig.eigenvalues().minCoeff() > 1e-14 * scale))
      return Status::Invalid(
          fmt::format("chain '{}', spring '{}': the stiffness matrix is not positive definite "
                      "(smallest eigenvalue {:.3g}); a spring must resist every deflection",
                      name_, s.label, eig.eigenvalues().minCoeff()));
  }
  return Status::Ok();
}

namespace {

double coordinate(const Factor& f, const VecX& q, const VecX& theta) {
  if (!f.variable) return f.offset;
  const VecX& x = f.variable->kind == VariableKind::kPassive ? q : theta;
  return f.offset + f.variable->coefficient * x[f.variable->index];
}

// T = T * (the factor's elementary transform at `value`) without forming the 4x4 product: a
// revolute factor turns T's axes, a prismatic one moves its origin, and zero (a spring at rest, every
// virtual coordinate of the unloaded stiffness) leaves T as it is.
void advance(Transform& T, const Factor& f, double value) {
  if (value == 0.0) return;
  if (f.type == JointType::kRevolute)
    T.linear() = T.linear() * Eigen::AngleAxisd(value, f.axis).toRotationMatrix();
  else
    T.translation() += T.linear() * (value * f.axis);
}

// A moving factor's unit twist in global axes, spatial form (linear part = velocity of the point
// at the global origin), scaled by its coefficient, and which coordinate drives it.
struct FactorTwist {
  Vec3 v, w;
  VariableRef var;
};

// Walks the product (1); returns the tool pose and fills the twists of the moving factors in
// product order (a twist depends only on the factors before it).
Transform walk(const Chain& chain, const VecX& q, const VecX& theta, std::vector<FactorTwist>* twists,
               std::vector<Transform>* poses = nullptr) {
  Transform T = Transform::Identity();
  for (const Factor& f : chain.factors()) {
    if (poses) poses->push_back(T);
    if (!f.is_motion) {
      T = T * f.transform;
      continue;
    }
    if (twists && f.variable) {
      const Vec3 a = T.linear() * f.axis;
      const double c = f.variable->coefficient;
      if (f.type == JointType::kRevolute)
        twists->push_back({c * T.translation().cross(a), c * a, *f.variable});
      else
        twists->push_back({c * a, Vec3::Zero(), *f.variable});
    }
    advance(T, f, coordinate(f, q, theta));
  }
  return T;
}

}  // namespace

Transform Chain::forward(const VecX& q, const VecX& theta) const { return walk(*this, q, theta, nullptr); }

std::vector<Transform> factor_poses(const Chain& chain, const VecX& q, const VecX& theta) {
  std::vector<Transform> poses;
  poses.reserve(chain.factors().size() + 1);
  const Transform tool = walk(chain, q, theta, nullptr, &poses);
  poses.push_back(tool);
  return poses;
}

ChainJacobians jacobians(const Chain& chain, const VecX& q, const VecX& theta) {
  ChainJacobians J;
  jacobians(chain, q, theta, J);
  return J;
}

void jacobians(const Chain& chain, const VecX& q, const VecX& theta, ChainJacobians& J) {
  J.Jq.setZero(6, chain.num_passive());
  J.Jtheta.setZero(6, chain.num_virtual());
  // The walk of (1) with each moving factor's twist summed into its coordinate's column as it goes
  // (spatial form: the linear part is the velocity of the point at the origin); the tool point's
  // velocity v + w x p needs the tool point, so the w x p part is added once at the end (linear in
  // w: the same sum).
  Transform T = Transform::Identity();
  for (const Factor& f : chain.factors()) {
    if (!f.is_motion) {
      T = T * f.transform;
      continue;
    }
    if (f.variable) {
      const Vec3 a = T.linear() * f.axis;
      const double c = f.variable->coefficient;
      auto col = (f.variable->kind == VariableKind::kPassive ? J.Jq : J.Jtheta).col(f.variable->index);
      if (f.type == JointType::kRevolute) {
        col.head<3>() += c * T.translation().cross(a);
        col.tail<3>() += c * a;
      } else {
        col.head<3>() += c * a;
      }
    }
    advance(T, f, coordinate(f, q, theta));
  }
  J.pose = T;
  const Vec3 p = T.translation();
  for (MatX* M : {&J.Jq, &J.Jtheta})
    for (Eigen::Index k = 0; k < M->cols(); ++k) M->col(k).head<3>() += M->col(k).tail<3>().cross(p);
}

ChainHessians hessians(const Chain& chain, const VecX& q, const VecX& theta, const Vec6& F) {
  std::vector<FactorTwist> tw;
  const Transform pose = walk(chain, q, theta, &tw);
  const int n = chain.num_passive();
  // Coordinates ordered (q, theta) in one matrix, split at the end.
  MatX H = MatX::Zero(n + chain.num_virtual(), n + chain.num_virtual());
  auto slot = [n](const VariableRef& v) { return v.kind == VariableKind::kPassive ? v.index : n + v.index; };
  for_each_hessian_term(tw.data(), static_cast<int>(tw.size()), pose.translation(), F,
                        [&](int b, int a, double value) { H(slot(tw[b].var), slot(tw[a].var)) += value; });
  ChainHessians out;
  const int mv = chain.num_virtual();
  out.Hqq = H.topLeftCorner(n, n);
  out.Hqtheta = H.topRightCorner(n, mv);
  out.Hthetaq = H.bottomLeftCorner(mv, n);
  out.Hthetatheta = H.bottomRightCorner(mv, mv);
  return out;
}

Vec6 pose_difference(const Transform& to, const Transform& from) {
  Vec6 d;
  d.head<3>() = to.translation() - from.translation();
  const Eigen::AngleAxisd aa(Mat3(to.linear() * from.linear().transpose()));
  d.tail<3>() = aa.angle() * aa.axis();
  return d;
}

Transform displace(const Transform& T, const Vec6& d) {
  Transform out = T;
  out.translation() += d.head<3>();
  const double angle = d.tail<3>().norm();
  if (angle > 0) out.linear() = Eigen::AngleAxisd(angle, d.tail<3>() / angle).toRotationMatrix() * T.linear();
  return out;
}

}  // namespace kinestat::vjm
