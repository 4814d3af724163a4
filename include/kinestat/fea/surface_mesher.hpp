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
  double unit_scale = 1e-3;        // file length unit in metres (1e-3: the file is in mm)
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
};

struct SurfaceInfo {
  int triangles = 0;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // bounding box, in the file's unit
};

// Reads and checks a closed surface; kInvalidInput names the file and the problem (unreadable,
// open, non-manifold, inconsistently oriented, self-intersecting). A surface oriented consistently
// inward is accepted (reversed).
StatusOr<SurfaceInfo> check_surface_file(const std::string& path);

// Checks the surface, then meshes its interior.
StatusOr<TetMesh> mesh_surface_file(const std::string& path, const MeshingOptions& options);

}  // namespace kinestat::fea
