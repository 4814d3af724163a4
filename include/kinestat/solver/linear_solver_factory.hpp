// The one place that turns a backend choice into a solver object (as Ceres' LinearSolver::Create).
// Every factorization in kinestat is made here, from the caller's SparseCholeskyOptions.
// A new backend (PETSc, MUMPS) is one implementation file pair in src/solver/, one enumerator of
// solver::Backend and one entry in this factory; the methods (MSA, FEA) do not change.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::solver {

// A solver object for options.backend, configured by `options` (ordering, pivot tolerance).
std::unique_ptr<SparseCholesky> make_sparse_cholesky(const SparseCholeskyOptions& options = {});

// The backends built into this library, and their names for options and reports ("cholmod").
std::vector<Backend> available_backends();
const char* backend_name(Backend backend);
std::optional<Backend> backend_from_name(std::string_view name);

}  // namespace kinestat::solver
