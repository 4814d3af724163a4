#include "kinestat/mechanisms/orthoglide_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

namespace kinestat::mechanisms {

namespace {

constexpr const char* kAxis[3] = {"x", "y", "z"};

std::string format_point(const Vec3& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g}) m", v.x(), v.y(), v.z()); }

// A bar orthogonal to its slider (p_i = rho_i) is a serial singularity; compare with the size of the
// posture so that the test does not depend on the unit of length.
int serial_singular_chain(const Vec3& p, const Vec3& rho) {
  const double scale = std::max(p.cwiseAbs().maxCoeff(), rho.cwiseAbs().maxCoeff());
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(p[i] - rho[i]) > 1e-12 * scale)) return i;
  return -1;
}

Status check_serial_regular(const Vec3& p, const Vec3& rho) {
  if (const int i = serial_singular_chain(p, rho); i >= 0)
    return Status::Singular(
        fmt::format("Orthoglide posture p = {}, rho = {}: chain {} is at a serial singularity (p_{} = rho_{}, the bar "
                    "is orthogonal to its slider); J^-1 is unbounded there",
                    format_point(p), format_point(rho), kAxis[i], kAxis[i], kAxis[i]));
  return Status::Ok();
}

// Eq. (3) for chain i: L^2 - p_j^2 - p_k^2, negative when p is outside the chain's cylinder.
double radicand(const OrthoglideGeometry& g, const Vec3& p, int i) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  return g.link_length * g.link_length - p[j] * p[j] - p[k] * p[k];
}

}  // namespace

Status validate(const OrthoglideGeometry& g) {
  if (!(std::isfinite(g.link_length) && g.link_length > 0.0))
    return Status::Invalid(fmt::format("Orthoglide link length L = {} m: must be positive and finite", g.link_length));
  return Status::Ok();
}

StatusOr<Vec3> inverse_kinematics(const OrthoglideGeometry& g, const Vec3& p, const OrthoglideSigns& s) {
  if (Status st = validate(g); !st.ok()) return st;
  if (!p.allFinite())
    return Status::Invalid(fmt::format("Orthoglide point p = {}: a coordinate is not finite", format_point(p)));
  Vec3 rho;
  for (int i = 0; i < 3; ++i) {
    if (s[i] != 1 && s[i] != -1)
      return Status::Invalid(fmt::format("Orthoglide configuration index s_{} = {}: must be +1 or -1", kAxis[i], s[i]));
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double r2 = radicand(g, p, i);
    if (r2 < 0.0)
      return Status::Invalid(fmt::format(
          "Orthoglide point p = {} is out of reach of chain {}: p_{}^2 + p_{}^2 exceeds L^2 = ({:.6g} m)^2; "
          "choose a point inside the workspace",
          format_point(p), kAxis[i], kAxis[j], kAxis[k], g.link_length));
    rho[i] = p[i] + s[i] * std::sqrt(r2);  // eq. (3)
  }
  return rho;
}

std::optional<Vec3> try_inverse_kinematics(const OrthoglideGeometry& g, const Vec3& p) {
  Vec3 rho;
  for (int i = 0; i < 3; ++i) {
    const double r2 = radicand(g, p, i);
    if (!(r2 >= 0.0)) return std::nullopt;
    rho[i] = p[i] + std::sqrt(r2);  // eq. (3), s_i = +1
  }
  return rho;
}

bool serial_singular(const Vec3& p, const Vec3& rho) { return serial_singular_chain(p, rho) >= 0; }

int direct_kinematics_branch(const Vec3& p, const Vec3& rho) {
  const double v = p.cwiseQuotient(rho).sum() - 1.0;
  return (v > 0.0) - (v < 0.0);
}

StatusOr<std::array<Vec3, 2>> direct_kinematics(const OrthoglideGeometry& g, const Vec3& rho) {
  if (Status st = validate(g); !st.ok()) return st;
  for (int i = 0; i < 3; ++i)
    if (!(rho[i] > 0.0 && std::isfinite(rho[i])))
      return Status::Invalid(fmt::format("Orthoglide joints rho = {}: rho_{} must be positive and finite (eq. 2)",
                                         format_point(rho), kAxis[i]));
  // Eq. (4) divided by B = (rho_x rho_y rho_z)^2: a t^2 + t + c = 0, a = sum 1/rho_i^2 = A/B,
  // c = (sum rho_i^2 - 4 L^2) / 4 = C/B. Same roots, no sixth powers of rho.
  const double a = rho.cwiseInverse().squaredNorm();
  const double c = (rho.squaredNorm() - 4.0 * g.link_length * g.link_length) / 4.0;
  const double disc = 1.0 - 4.0 * a * c;
  if (disc < 0.0)
    return Status::Invalid(fmt::format(
        "Orthoglide joints rho = {}: no assembly exists for L = {} m ((sum rho^2 - 4L^2) * sum rho^-2 = {:.6g} > 1, "
        "outside the reachable joint region of section 2.3)",
        format_point(rho), g.link_length, 4.0 * a * c));
  // Roots without cancellation: q = -(1 + sqrt(disc)) / 2, t(m = -1) = q / a, t(m = +1) = c / q.
  const double q = -0.5 * (1.0 + std::sqrt(disc));
  const double t[2] = {q / a, c / q};
  std::array<Vec3, 2> p;
  for (int b = 0; b < 2; ++b) p[b] = rho / 2.0 + t[b] * rho.cwiseInverse();
  return p;
}

StatusOr<Vec3> direct_kinematics(const OrthoglideGeometry& g, const Vec3& rho, int branch) {
  if (branch != -1 && branch != 1)
    return Status::Invalid(fmt::format("Orthoglide direct kinematics branch m = {}: must be -1 or +1", branch));
  auto both = direct_kinematics(g, rho);
  if (!both.ok()) return both.status();
  return (*both)[branch == -1 ? 0 : 1];
}

StatusOr<Mat3> inverse_jacobian(const Vec3& p, const Vec3& rho) {
  if (Status st = check_serial_regular(p, rho); !st.ok()) return st;
  Mat3 Jinv;
  for (int i = 0; i < 3; ++i) {
    Vec3 bar = p;
    bar[i] -= rho[i];
    Jinv.row(i) = bar.transpose() / bar[i];  // eq. (5)
  }
  return Jinv;
}

StatusOr<double> inverse_jacobian_determinant(const Vec3& p, const Vec3& rho) {
  if (Status st = check_serial_regular(p, rho); !st.ok()) return st;
  // Eq. (6).
  const double num =
      p.x() * rho.y() * rho.z() + rho.x() * p.y() * rho.z() + rho.x() * rho.y() * p.z() - rho.x() * rho.y() * rho.z();
  return num / ((p.x() - rho.x()) * (p.y() - rho.y()) * (p.z() - rho.z()));
}

VelocityTransmission velocity_transmission(const Mat3& inverse_jacobian) {
  VelocityTransmission v;
  // Dynamic-size SVD: the fixed-size 3x3 JacobiSVD trips a false -Wmaybe-uninitialized in GCC 12.
  v.singular_values = Eigen::JacobiSVD<MatX>(MatX(inverse_jacobian)).singularValues();
  const double smax = v.singular_values[0], smin = v.singular_values[2];
  constexpr double inf = std::numeric_limits<double>::infinity();
  v.mu_min = 1.0 / smax;
  v.mu_max = smin > 0.0 ? 1.0 / smin : inf;
  v.manipulability = v.singular_values.prod();
  v.condition_number = smin > 0.0 ? smax / smin : inf;
  return v;
}

StatusOr<VelocityTransmission> velocity_transmission_at(const OrthoglideGeometry& g, const Vec3& p) {
  auto rho = inverse_kinematics(g, p);
  if (!rho.ok()) return rho.status();
  auto Jinv = inverse_jacobian(p, *rho);
  if (!Jinv.ok()) return Jinv.status();
  return velocity_transmission(*Jinv);
}

}  // namespace kinestat::mechanisms
