// Linear (eigenvalue) buckling of an msa::Structure: the critical load factors lambda of one load
// case from K phi = -lambda K_G phi, where K is the elastic stiffness and K_G the geometric stiffness
// of the beams' axial forces under that case (elements/beam_element.hpp), both on the reduced dofs
// u = C q of the static solve (supports and rigid ties). lambda = 1 means the case's loads are
// critical; lambda = 2, that twice the loads are. Documented in docs/stability-and-modes.md.
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {

struct BucklingOptions {
  SolveOptions solve;  // of the linear solve that gives the axial forces (and of K's factorization)
  int load_case = 0;   // index into Structure::load_cases()
  int count = 3;       // how many of the smallest positive load factors
  // Include the torsion (Wagner) term N Ip / (A L) of K_G (Ip: polar_moment, elements/section.hpp):
  // torsional buckling of open thin sections is outside a 12-dof beam anyway, but the term keeps a
  // compressed member's twist from being stiffer than it is.
  bool torsion_term = true;
};

struct BucklingMode {
  double load_factor = 0.0;  // lambda (-): critical loads = lambda x the load case's loads
  std::vector<Vec6> shape;   // per node, global: translations and rotations, max |translation| = 1
  double residual = 0.0;     // ||K phi + lambda K_G phi|| / ||K phi|| on the reduced dofs
};

struct BucklingResult {
  // kInvalidInput (bad model, no compressed beam), kSingular (K singular:
  // see linear.singularity), kNotConverged (the eigensolver did not converge), kInternal.
  Status status;
  Solution linear;  // the static solve of every load case (its status: see `status`)
  int load_case = 0;
  std::string load_case_name;
  std::vector<double>
      axial_force;  // per beam, N (positive in tension), the N of K_G: (N2 - N1) / 2, or -N1 (kFrame3dd)
  std::vector<BucklingMode> modes;  // ascending load factor; may be fewer than asked (see docs)
  int num_free_dofs = 0;
};

BucklingResult buckling(const Structure& s, const BucklingOptions& options = {});

}  // namespace kinestat::msa
