#include "kinestat/solver/linear_solver_factory.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "solver/cholmod_cholesky.hpp"
#include "solver/petsc_solver.hpp"

namespace kinestat::solver {
namespace {

// What the factory gives for a backend it cannot make (not built in, or not of the kind asked
// for): Factorize and Solve say why, so that the caller fails at its first solver call.
class RefusedSolver final : public SparseCholesky {
 public:
  RefusedSolver(Backend backend, Status why) : backend_(backend), why_(std::move(why)) {}
  Status Factorize(const SparseMatrix&, FactorizationReport*) override { return why_; }
  int num_symbolic_analyses() const override { return 0; }
  std::string backend_description() const override { return std::string(backend_name(backend_)) + " (refused)"; }

 private:
  Status DoSolve(const MatX&, MatX*, SolveReport*) const override { return why_; }
  Backend backend_;
  Status why_;
};

}  // namespace

std::unique_ptr<SparseCholesky> make_sparse_cholesky(const LinearSolverOptions& options) {
  if (Status s = check_backend_built(options.backend); !s.ok())
    return std::make_unique<RefusedSolver>(options.backend, s);
  switch (options.backend) {
    case Backend::kCholmod:
      return make_cholmod_cholesky(options);
    case Backend::kPetscMumps:
      return make_petsc_mumps(options);
    case Backend::kPetscCg:
      break;
  }
  return std::make_unique<RefusedSolver>(
      options.backend, Status::Invalid(fmt::format("solver {} is iterative, not a Cholesky factorization; use "
                                                   "cholmod or petsc-mumps",
                                                   backend_name(options.backend))));
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  if (options.backend == Backend::kPetscCg && backend_built(options.backend)) return make_petsc_cg(options);
  return make_sparse_cholesky(options);  // the direct backends, and the refusals
}

bool backend_built(Backend backend) { return backend == Backend::kCholmod || petsc_available().ok(); }

bool solves_generalized_eigenproblems(Backend backend) {
  return backend == Backend::kCholmod || backend == Backend::kPetscMumps;
}

double solution_tolerance(const LinearSolverOptions& options) {
  return options.backend == Backend::kPetscCg ? options.relative_tolerance : 0.0;
}

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
  if (backend == Backend::kCholmod) return Status::Ok();
  Status s = petsc_available();
  if (s.ok()) return s;
  // Not built in: the user can rebuild or choose cholmod. Built but not loadable: the loader's reasons.
  if (s.code() != StatusCode::kInvalidInput) return s;
  return Status::Invalid(std::string("solver ") + backend_name(backend) +
                         " is not built into this kinestat: " + s.message() + ", or use --solver cholmod");
}

Status LinearSolver::FactorizeSum(std::span<const SparseMatrix> summands, FactorizationReport* report) {
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
