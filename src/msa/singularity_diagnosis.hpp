// The diagnosis of a singular structure (internal: msa::solve runs it; the result types are public
// in kinestat/msa/singularity.hpp).
#pragma once

#include "kinestat/msa/singularity.hpp"
#include "kinestat/msa/structure.hpp"
#include "kinestat/solver/linear_solver.hpp"
#include "msa/dof_map.hpp"

namespace kinestat::msa {

// From the failed factorization of K_r: the dofs whose pivots vanished (mapped back from CHOLMOD's
// column to node and dof) and the free motions (near-null space of K_r with stiffness ratio below
// `tolerance`, the pivot tolerance), described per node. Parts joined to no support (or a model with
// no supports) are named first ("nodes {...} are not connected to any support"), with their six
// rigid-body motions in the canonical basis (FreeMotion). The near-null space is computed with the
// caller's solver `options`.
SingularityDiagnosis diagnose_singularity(const Structure& s, const DofMap& map, const solver::SparseMatrix& Kr,
                                          const solver::FactorizationReport& report, double tolerance,
                                          const solver::LinearSolverOptions& options);

}  // namespace kinestat::msa
