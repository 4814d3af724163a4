// One path from a link's surface file to its 6x6 stiffness: check the surface, mesh it (CGAL Mesh_3),
// run the FEA (fea/link_stiffness.hpp), through the result cache (fea/result_cache.hpp). Used by
// `kinestat link-stiffness` and by the `fea:` springs of VJM model files (resolved after reading,
// io/vjm_yaml.hpp) and of robot files' links (mechanisms::resolve_robot_fea_springs).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/mesh_convergence.hpp"
#include "kinestat/fea/surface_mesher.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {

struct LinkStiffnessRequest {
  std::string mesh_file;     // closed triangle surface: STL, OFF, OBJ or PLY
  double unit_scale = 1e-3;  // the mesh file's length unit in m (1e-3: the file is in mm)
  double mesh_size = 0.0;    // tetrahedron size in m; 0: default_mesh_size (1/20 of the largest extent)
  bool quadratic = true;     // element order: 10-node tetrahedra (4-node ones lock in bending)
  // Refuse a mesh estimated above this many tetrahedra before meshing (MeshingOptions::max_elements).
  double max_elements = MeshingOptions{}.max_elements;
  Material material = Material::from_E_nu("steel", 210e9, 0.3);
  // Clamp and reference regions and point (m, link frame), reference-body model, solver options,
  // whether to keep the fields (for VTK output), progress callback.
  LinkStiffnessOptions options;
  std::string cache_dir;  // reuse and store results in this directory; empty: no cache
};

struct LinkStiffnessRun {
  LinkStiffness result;         // result.cartesian: the 6x6 of the reference point in the link's axes
  std::optional<TetMesh> mesh;  // the mesh solved, kept with the fields (options.keep_fields)
  SurfaceInfo surface;          // triangles and bounding box of the surface file
  double mesh_size = 0.0;       // m, as used
  bool from_cache = false;      // read from cache_dir: no mesh, no fields, no solver report
  std::string cache_file;       // the entry read or written; empty without a cache
  // What the user should hear even with progress silenced (callers print them): a cache entry that
  // was rejected and recomputed, and why.
  std::vector<std::string> warnings;
  std::string report;  // what was done and the result, for people (link_stiffness_report)
};

// kInvalidInput naming the field: mesh_size 0 (the default size) or a positive length, unit_scale a
// positive length, max_elements positive. compute_link_stiffness and link_stiffness_convergence
// check it first.
Status validate(const LinkStiffnessRequest& request);

// Checks the surface, then serves the result from the cache or meshes and solves (and stores it).
// A result with fields (options.keep_fields) or modes (options.modes) is always computed. kInvalidInput names the file.
StatusOr<LinkStiffnessRun> compute_link_stiffness(const LinkStiffnessRequest& request);

// The request's link solved on meshes of the given sizes (m, >= 3, decreasing; no cache, no fields, no
// modes):
// the compliance per mesh and a Richardson estimate of each diagonal term (fea/mesh_convergence.hpp).
StatusOr<ConvergenceStudy> link_stiffness_convergence(const LinkStiffnessRequest& request,
                                                      const std::vector<double>& sizes);

}  // namespace kinestat::fea
