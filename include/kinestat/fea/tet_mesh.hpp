// Tetrahedral volume meshes of a link: linear (4-node) or quadratic (10-node) tetrahedra.
// Coordinates are in metres, in the link's own frame (the frame the 6x6 link stiffness is given in).
// Node order of a 10-node tetrahedron follows VTK_QUADRATIC_TETRA: vertices 0-3, then the mid-edge
// nodes of edges (0,1), (1,2), (2,0), (0,3), (1,3), (2,3).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::fea {

inline constexpr std::array<std::array<int, 2>, 6> kTet10Edges = {{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};

struct TetMesh {
  std::vector<Vec3> nodes;
  int nodes_per_element = 4;      // 4 (linear) or 10 (quadratic)
  std::vector<int> connectivity;  // nodes_per_element entries per element

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_elements() const {
    return nodes_per_element > 0 ? static_cast<int>(connectivity.size()) / nodes_per_element : 0;
  }
  const int* element(int e) const { return connectivity.data() + static_cast<long>(e) * nodes_per_element; }
  bool quadratic() const { return nodes_per_element == 10; }
};

// Structured mesh of the box [lo, hi] with nx x ny x nz hexahedral cells, each split into six
// tetrahedra around its main diagonal (the Kuhn split: the same split in every cell keeps the
// faces conforming). Independent of CGAL: the validation meshes of the tests.
TetMesh make_box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);

// The default limit on a mesh's tetrahedra (MeshingOptions::max_elements, surface_mesher.hpp).
inline constexpr double kDefaultMaxElements = 3e5;

// kInvalidInput naming the argument: lo and hi finite lengths with lo < hi on every axis, nx, ny,
// nz >= 1 cells, and the 6 nx ny nz tetrahedra, estimated before anything is allocated, at most
// `max_elements`. make_box_mesh trusts its arguments: callers check first.
Status check_box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz,
                      double max_elements = kDefaultMaxElements);

// Adds one node at the midpoint of every edge: 4-node -> 10-node elements (straight-sided).
TetMesh to_quadratic(const TetMesh& linear);

// Checks indices, node count per element and a positive volume of every element (vertices
// 0-3 must form a right-handed tetrahedron). The message names the first bad element.
Status validate(const TetMesh& mesh);

// Volume of element e from its four vertices (m^3), signed.
double element_volume(const TetMesh& mesh, int e);

// Axis-aligned bounding box of the nodes.
void bounding_box(const TetMesh& mesh, Vec3& lo, Vec3& hi);

// SHA-256 of the mesh content (coordinates and connectivity) as 64 hex digits, for the result cache.
std::string content_hash(const TetMesh& mesh);

}  // namespace kinestat::fea
