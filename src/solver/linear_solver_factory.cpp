#include "kinestat/solver/linear_solver_factory.hpp"

#include <fmt/format.h>

#include "solver/cholmod_cholesky.hpp"
#include "solver/petsc_solver.hpp"

namespace kinestat::solver {

std::unique_ptr<SparseCholesky> make_sparse_cholesky(const SparseCholeskyOptions& options) {
  switch (options.backend) {
    case Backend::kCholmod:
      return make_cholmod_cholesky(options);
    case Backend::kPetscMumps:
    case Backend::kPetscCg:
      return make_petsc_solver(options);
  }
  return nullptr;  // unreachable: every enumerator has a case (-Wswitch checks it)
}

bool backend_built(Backend backend) { return backend == Backend::kCholmod || petsc_built(); }

std::vector<Backend> available_backends() {
  std::vector<Backend> built;
  for (Backend b : {Backend::kCholmod, Backend::kPetscMumps, Backend::kPetscCg})
    if (backend_built(b)) built.push_back(b);
  return built;
}

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::kCholmod:
      return "cholmod";
    case Backend::kPetscMumps:
      return "petsc-mumps";
    case Backend::kPetscCg:
      return "petsc-cg";
  }
  return "unknown";
}

std::optional<Backend> backend_from_name(std::string_view name) {
  for (Backend b : {Backend::kCholmod, Backend::kPetscMumps, Backend::kPetscCg})
    if (name == backend_name(b)) return b;
  return std::nullopt;
}

Status check_backend_built(Backend backend) {
  if (backend_built(backend)) return Status::Ok();
  return Status::Invalid(std::string("solver ") + backend_name(backend) +
                         " is not built into this kinestat: PETSc was not found when it was configured; install "
                         "libpetsc-real-dev (scripts/install-deps.sh --petsc) and rebuild, or use --solver cholmod");
}

Status SparseCholesky::SolveAndReport(const MatX& B, MatX* X, SolveReport* report) const {
  Status s = Solve(B, X);
  if (s.ok() && report) {
    *report = SolveReport{};
    report->iterations.assign(B.cols(), 0);
  }
  return s;
}

Status SparseCholesky::FactorizeSum(std::span<const SparseMatrix> summands, FactorizationReport* report) {
  if (summands.empty()) return Status::Invalid("FactorizeSum: no summand given");
  if (summands.size() == 1) return Factorize(summands[0], report);
  SparseMatrix A = summands[0];
  for (const SparseMatrix& s : summands.subspan(1)) {
    if (s.rows() != A.rows() || s.cols() != A.cols())
      return Status::Invalid(
          fmt::format("FactorizeSum: a {} x {} summand of a {} x {} matrix", s.rows(), s.cols(), A.rows(), A.cols()));
    A += s;
  }
  return Factorize(A, report);
}

}  // namespace kinestat::solver
