// The CHOLMOD backend of SparseCholesky (internal: made through solver/linear_solver_factory.hpp).
#pragma once

#include <memory>

#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

std::unique_ptr<SparseCholesky> make_cholmod_cholesky(const LinearSolverOptions& options);

}  // namespace kinestat::solver
