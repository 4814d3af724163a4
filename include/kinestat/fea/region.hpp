// Boundary regions of a link chosen by geometry, in the link's frame (the mesh coordinates, m):
// a plane (the clamped end face, the reference end face) or a box (a bore surface, an end cap).
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/types.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {

struct Region {
  enum class Kind { kPlane, kBox };
  Kind kind = Kind::kPlane;
  Vec3 point = Vec3::Zero();                  // plane: a point on it
  Vec3 normal = Vec3::UnitX();                // plane: its normal (any length)
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // box corners
  // Distance (m) within which a node belongs to the plane or box; 0 = 1e-6 x the mesh's
  // bounding-box diagonal (round-off of mesh coordinates).
  double tolerance = 0.0;

  static Region plane(const Vec3& point, const Vec3& normal, double tolerance = 0.0);
  static Region box(const Vec3& lo, const Vec3& hi, double tolerance = 0.0);
  // Whether x lies in the region with an absolute tolerance tol (m).
  bool contains(const Vec3& x, double tol) const;
  // "plane through (x, y, z) m with normal (nx, ny, nz)" / "box (..) - (..) m".
  std::string describe() const;
};

// The nodes of `mesh` inside the region, ascending.
std::vector<int> select_nodes(const TetMesh& mesh, const Region& region);
// The tolerance used for `region` on `mesh`.
double region_tolerance(const TetMesh& mesh, const Region& region);

}  // namespace kinestat::fea
