// The direct kind of linear solver (solver/linear_solver.hpp), as Ceres keeps SparseCholesky apart
// from its iterative solvers: Factorize computes A = L D L' and checks its pivots against
// LinearSolverOptions::singular_pivot_ratio (FactorizationReport's pivot fields), and Solve is
// exact to round-off with no iteration and no tolerance. The symbolic analysis is redone only when
// A's sparsity pattern differs from the last one analysed (num_symbolic_analyses). What needs exact solves with one
// factor asks for this type: the null-space diagnosis (solver/null_space.hpp) and the MSA's solves and eigenproblems.
// Made by make_sparse_cholesky (solver/linear_solver_factory.hpp): CHOLMOD, MUMPS.
#pragma once

#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::solver {

class SparseCholesky : public LinearSolver {};

}  // namespace kinestat::solver
