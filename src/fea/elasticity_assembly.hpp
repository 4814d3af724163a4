// Sparse assembly of the linear-elastic stiffness and the consistent mass of a tetrahedral mesh, in
// parallel (TBB), with clamped nodes removed and an exact rigid coupling (multipoint constraint)
// eliminated on the fly.
#pragma once

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::fea {

// How each mesh dof (3 per node: ux, uy, uz) is expressed in the solved (reduced) dofs:
// u = sum_k coef[k] * reduced[index[k]]. A free dof has one term, a clamped dof none, and a dof of a
// node rigidly coupled to the 6-dof reference node (u, theta) has up to three: u_node = u + theta x r
// with r = node - reference point, which eliminates the constraint instead of adding multipliers.
struct DofMap {
  struct Terms {
    int count = 0;
    std::array<int, 3> index{};
    std::array<double, 3> coef{};
  };
  std::vector<Terms> terms;  // 3 per mesh node
  int num_dofs = 0;          // reduced dofs
  int reference_dof = -1;    // first of the 6 reference-node dofs (ux uy uz rx ry rz), -1 if none
};

// Clamped nodes lose their dofs; `coupled` nodes follow a reference node at `reference_point`
// whose 6 dofs are numbered last. The two sets must be disjoint (checked by the caller).
DofMap make_dof_map(const TetMesh& mesh, const std::vector<int>& clamped, const std::vector<int>& coupled,
                    const Vec3& reference_point);

// All 3 dofs of every node free, in node order (the unconstrained stiffness).
DofMap free_dof_map(const TetMesh& mesh);

// Mesh displacements (per node, m) from the reduced solution.
std::vector<Vec3> expand(const DofMap& map, const Eigen::Ref<const VecX>& reduced);

// Lower triangle of the reduced stiffness (N/m, and N or N m for the reference node's dofs), compressed
// with sorted rows (what CHOLMOD reads in place), into *stiffness (an output argument: Eigen's
// SparseMatrix has no move constructor, and a returned StatusOr would copy it twice).
// Element e uses the elasticity matrix D[material[e]] (material empty: D[0] for all). Only the
// listed elements are assembled (empty: all), one MPI rank's summand of a distributed stiffness.
// Elements are integrated in parallel; fails (kInvalidInput) on an element with a non-positive
// Jacobian.
Status assemble_stiffness(const TetMesh& mesh, const std::vector<Mat6>& D, const std::vector<int>& material,
                          const DofMap& map, solver::SparseMatrix* stiffness, std::span<const int> elements = {});

// The consistent mass (kg; kg m and kg m^2 for the reference node's rotations) on the same dof map and
// pattern as assemble_stiffness (the same code: clamped dofs dropped, coupled nodes' masses carried by
// the reference node): element e has the density density[material[e]] (kg/m^3; material empty:
// density[0] for all). The elements `elements` (empty: all), as assemble_stiffness: a distributed
// assembly's summand of M.
Status assemble_mass(const TetMesh& mesh, const std::vector<double>& density, const std::vector<int>& material,
                     const DofMap& map, solver::SparseMatrix* mass, std::span<const int> elements = {});

// The elements in slabs: sorted by their centre's coordinate along the bounding box's longest axis.
// Consecutive ranges of this order are the ranks' shares of a distributed assembly: a rank's
// summand then overlaps its neighbours' on a slab face only. (CGAL numbers elements in no spatial
// order: equal ranges of its numbering gave each of two ranks 74 % of the entries at 2.9M dofs.)
std::vector<int> elements_along_longest_axis(const TetMesh& mesh);

// The elements rank `rank` of `ranks` assembles in a distributed assembly: the rank-th of `ranks`
// consecutive ranges of equal length (within one element) of an element order.
std::pair<int, int> element_range(int num_elements, int rank, int ranks);

}  // namespace kinestat::fea
