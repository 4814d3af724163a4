#include "kinestat/fea/region.hpp"

#include <cmath>

#include <fmt/format.h>

namespace kinestat::fea {

Region Region::plane(const Vec3& point, const Vec3& normal, double tolerance) {
  return {Kind::kPlane, point, normal, Vec3::Zero(), Vec3::Zero(), tolerance};
}

Region Region::box(const Vec3& lo, const Vec3& hi, double tolerance) {
  return {Kind::kBox, Vec3::Zero(), Vec3::UnitX(), lo, hi, tolerance};
}

bool Region::contains(const Vec3& x, double tol) const {
  if (kind == Kind::kPlane) return std::abs((x - point).dot(normal.normalized())) <= tol;
  return (x.array() >= lo.array() - tol).all() && (x.array() <= hi.array() + tol).all();
}

std::string Region::describe() const {
  if (kind == Kind::kPlane)
    return fmt::format("plane through ({:g}, {:g}, {:g}) m with normal ({:g}, {:g}, {:g})", point.x(), point.y(),
                       point.z(), normal.x(), normal.y(), normal.z());
  return fmt::format("box ({:g}, {:g}, {:g}) - ({:g}, {:g}, {:g}) m", lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
}

double region_tolerance(const TetMesh& mesh, const Region& region) {
  if (region.tolerance > 0.0) return region.tolerance;
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  return 1e-6 * (hi - lo).norm();
}

std::vector<int> select_nodes(const TetMesh& mesh, const Region& region) {
  const double tol = region_tolerance(mesh, region);
  std::vector<int> nodes;
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if (region.contains(mesh.nodes[i], tol)) nodes.push_back(i);
  return nodes;
}

}  // namespace kinestat::fea
