#include "kinestat/core/frame.hpp"

#include <cmath>

#include <fmt/format.h>

namespace kinestat {

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

bool element_axes(const Vec3& p1, const Vec3& p2, const Vec3& orientation, Mat3& axes) {
  const Vec3 d = p2 - p1;
  const double L = d.norm();
  if (!(L > 0.0)) return false;
  const Vec3 ex = d / L;
  // Local z is normal to the plane spanned by the element and the orientation vector.
  Vec3 ez = ex.cross(orientation);
  const double n = ez.norm();
  if (!(n > 1e-9 * orientation.norm()) || orientation.norm() == 0.0) return false;
  ez /= n;
  const Vec3 ey = ez.cross(ex);
  axes.col(0) = ex;
  axes.col(1) = ey;
  axes.col(2) = ez;
  return true;
}

Vec3 default_orientation(const Vec3& dir) {
  const Vec3 d = dir.normalized();
  // Orientation lies in the local x-y plane; for an element in the global x-y plane choose an
  // in-plane vector perpendicular to it so that local z = global z.
  if (std::abs(d.z()) > 0.999) return Vec3::UnitY();
  return Vec3::UnitZ().cross(d);
}

Mat6 rotation6(const Mat3& R) {
  Mat6 T = Mat6::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  return T;
}

Mat6 rigid_transfer(const Vec3& offset) {
  Mat6 A = Mat6::Identity();
  A.topRightCorner<3, 3>() = -skew(offset);
  return A;
}

std::string direction_words(const Vec3& v) {
  const double n = v.norm();
  for (int i = 0; i < 3; ++i)
    if (std::abs(v(i)) > 0.999 * n) return fmt::format("{}{}", v(i) > 0 ? '+' : '-', "xyz"[i]);
  const Vec3 d = v / n;
  return fmt::format("({:.3f}, {:.3f}, {:.3f})", d.x() + 0.0, d.y() + 0.0, d.z() + 0.0);  // + 0.0: no "-0.000"
}

Mat3 axis_angle(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace kinestat
