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

}  // namespace kinestat::msa
