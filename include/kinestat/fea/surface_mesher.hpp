// Tetrahedral meshing of a link from its closed triangle surface (STL, OFF, OBJ or PLY) with CGAL
// Mesh_3 (polyhedral domain with sharp features detected and protected). The surface is checked
// first: it must be closed, manifold, consistently oriented and free of self-intersections.
#pragma once

#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {

struct MeshingOptions {
  double unit_scale = 1e-3;  // file length unit in metres (1e-3: the file is in mm)
  // Criteria in metres (after scaling). size: bound on the tetrahedra's circumradius and on
  // surface facets and feature edges; facet_distance: surface approximation error (0 = size / 10).
  double size = 5e-3;
  double facet_distance = 0.0;
  double facet_angle = 25.0;            // degrees, lower bound on surface triangle angles
  double cell_radius_edge_ratio = 3.0;  // upper bound on circumradius / shortest edge of a tetrahedron
  double feature_angle = 60.0;          // degrees: dihedral angles sharper than this are protected edges
  bool optimize = true;                 // sliver exudation after refinement
  bool quadratic = true;                // add mid-edge nodes (straight edges, also on curved faces)
  unsigned random_seed = 0;             // Mesh_3 is randomized: a fixed seed makes meshes repeatable
  // Refuse to mesh when estimate_tetrahedra() exceeds this: 3e5 quadratic tetrahedra are ~1.3e6 dofs,
  // about 20 GB and minutes in the FEA that follows (benchmarks/README.md). Raised by the commands'
  // --max-elements and by `max_elements` in a model file's fea spring.
  double max_elements = kDefaultMaxElements;
};

struct SurfaceInfo {
  int triangles = 0;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // bounding box, in the file's unit
  double volume = 0.0;                        // enclosed volume, file unit^3
  double area = 0.0;                          // surface area, file unit^2
};

// The number of tetrahedra Mesh_3 makes for `surface` at element size `size` (m), to refuse a mesh
// before it is made: 4 V / h^3 + 1.3 A / h^2 with h the smaller of the size and the wall thickness
// 2 V / A (V volume, A area), fitted to the bundled meshes (docs/reliability.md: 1 to 1.7 times the
// real counts there).
double estimate_tetrahedra(const SurfaceInfo& surface, double unit_scale, double size);

// Reads and checks a closed surface; kInvalidInput names the file and the problem (unreadable, counts
// the file cannot hold, indices out of range, coordinates not finite or beyond 1e9 file units, open,
// non-manifold, inconsistently oriented, self-intersecting, or thinner on average (3 volume / area)
// than 1e-4 of its size: a needle or a sheet a tetrahedral mesh cannot resolve). A surface oriented
// consistently inward is accepted (reversed).
StatusOr<SurfaceInfo> check_surface_file(const std::string& path);

// Checks the surface, the options (the size in the range of a length, the coordinates in metres too)
// and the element estimate against options.max_elements, then meshes the interior.
StatusOr<TetMesh> mesh_surface_file(const std::string& path, const MeshingOptions& options);

}  // namespace kinestat::fea
