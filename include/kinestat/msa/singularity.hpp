// Diagnosis of a singular structure: which nodes and dofs move freely, and how, in words.
#pragma once

#include "msa/dof_map.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {

// From the failed factorization of K_r: the dofs whose pivots vanished (mapped back from CHOLMOD's
// column to node and dof) and the free motions (near-null space of K_r with stiffness ratio below
// `tolerance`, the pivot tolerance), described per node. Parts joined to no support (or a model with
// no supports) are named first ("nodes {...} are not connected to any support"), with their six
// rigid-body motions in the canonical basis (FreeMotion).
SingularityDiagnosis diagnose_singularity(const Structure& s, const DofMap& map, const solver::SparseMatrix& Kr,
                                          const solver::FactorizationReport& report, double tolerance);

// "node '5' translates along +y" / "rotates about (0.71, 0.71, 0)": one node's motion in words.
std::string describe_node_motion(const Vec6& motion, double length_scale);

}  // namespace kinestat::msa
