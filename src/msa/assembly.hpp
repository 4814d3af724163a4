// Global stiffness of an msa::Structure: element matrices rotated to global axes and summed
// (Gonçalves et al. 2010, eq. (4)-(5)), as a sparse 6N x 6N matrix with no supports applied.
#pragma once

#include <string>
#include <vector>

#include "kinestat/msa/structure.hpp"
#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::msa {

// What assembly and post-processing share for one beam.
struct BeamMatrices {
  Mat12 local;      // local stiffness after end releases
  Mat12 transform;  // u_local = T u_global
};

StatusOr<BeamMatrices> beam_matrices(const Structure& s, const Beam& b);

// Assembles K (6N x 6N, both triangles). Fails only for invalid end releases (item named).
StatusOr<solver::SparseMatrix> assemble_stiffness(const Structure& s);

// The geometric stiffness of the beams' axial forces (buckling and the second-order solve): each
// beam's local K_G (elements/beam_element.hpp) for its axial force `axial_force[i]` (N, tension
// positive), and their sum rotated to global axes (6N x 6N, every beam's 12 x 12 blocks kept as
// structural entries, so K + K_G has one sparsity pattern whatever the forces). `torsion_term`: the
// Wagner term N Ip / (A L), Ip = polar_moment(section) (BucklingOptions::torsion_term says why).
// The structure's GeometricStiffnessConvention says whether K_G has the axial term; Timoshenko
// beams get the shear-deformation terms of their K_G (GeometricStiffnessTerms::shear).
struct GeometricStiffness {
  std::vector<Mat12> local;     // per beam, local axes
  solver::SparseMatrix global;  // 6N x 6N, global axes, no supports applied
};
GeometricStiffness assemble_geometric_stiffness(const Structure& s, const std::vector<double>& axial_force,
                                                bool torsion_term);

// The global mass matrix (6N x 6N, no supports applied): the beams' masses (beam_local_mass, consistent
// or `lumped`, with the cross-sections' `rotary_inertia` when consistent) rotated to global axes, and
// the structure's nodal masses and rotary inertias on the diagonal (msa/modes.hpp).
solver::SparseMatrix assemble_mass(const Structure& s, bool lumped, bool rotary_inertia);

// Each beam's axial force (N, tension positive) from its end forces (forces on the beam), as the
// structure's GeometricStiffnessConvention says: the mean (N2 - N1) / 2, the force at midspan under a
// uniform axial load or self-weight along the beam (kKinestat), or the first end's -N1 (kFrame3dd).
std::vector<double> beam_axial_forces(const Structure& s, const std::vector<Vec12>& end_forces);

// Fixed-end forces of a load case's member loads and self-weight: one per beam, local axes, end
// releases condensed (elements/member_loads.hpp). Empty when the case has neither.
StatusOr<std::vector<Vec12>> fixed_end_forces(const Structure& s, const LoadCase& lc);

// The equivalent nodal loads -T' FEF of every beam, summed into a 6N global vector (zero for an
// empty `fef`). Each beam's pair has the resultant (force and moment) of its span loads.
VecX equivalent_nodal_loads(const Structure& s, const std::vector<Vec12>& fef);

}  // namespace kinestat::msa
