// Global stiffness of an msa::Structure: element matrices rotated to global axes and summed
// (Gonçalves et al. 2010, eq. (4)-(5)), as a sparse 6N x 6N matrix with no supports applied.
#pragma once

#include <vector>

#include "kinestat/msa/structure.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::msa {

// What assembly and post-processing share for one beam.
struct BeamMatrices {
  Mat12 local;      // local stiffness after end releases
  Mat12 transform;  // u_local = T u_global
};

StatusOr<BeamMatrices> beam_matrices(const Structure& s, const Beam& b);

// Assembles K (6N x 6N, both triangles). Fails only for invalid end releases (item named).
StatusOr<solver::SparseMatrix> assemble_stiffness(const Structure& s);

// Fixed-end forces of a load case's member loads and self-weight: one per beam, local axes, end
// releases condensed (elements/member_loads.hpp). Empty when the case has neither.
StatusOr<std::vector<Vec12>> fixed_end_forces(const Structure& s, const LoadCase& lc);

// The equivalent nodal loads -T' FEF of every beam, summed into a 6N global vector (zero for an
// empty `fef`). Each beam's pair has the resultant (force and moment) of its span loads.
VecX equivalent_nodal_loads(const Structure& s, const std::vector<Vec12>& fef);

}  // namespace kinestat::msa
