#include "io/roll_orientation.hpp"

#include <cmath>

namespace kinestat::io {

Vec3 roll_orientation(const Vec3& d, double roll) {
  const Vec3 x = d.normalized();
  if (std::abs(x.z()) == 1.0) return Vec3(-x.z() * std::sin(roll), std::cos(roll), 0.0);
  const Vec3 y0 = Vec3::UnitZ().cross(x).normalized();
  const Vec3 z0 = x.cross(y0);
  return std::cos(roll) * y0 + std::sin(roll) * z0;
}

}  // namespace kinestat::io
