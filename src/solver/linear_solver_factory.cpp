#include "kinestat/solver/linear_solver_factory.hpp"

#include "solver/cholmod_cholesky.hpp"

namespace kinestat::solver {

std::unique_ptr<SparseCholesky> make_sparse_cholesky(const SparseCholeskyOptions& options) {
  switch (options.backend) {
    case Backend::kCholmod: return make_cholmod_cholesky(options);
  }
  return nullptr;  // unreachable: every enumerator has a case (-Wswitch checks it)
}

std::vector<Backend> available_backends() { return {Backend::kCholmod}; }

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::kCholmod: return "cholmod";
  }
  return "unknown";
}

std::optional<Backend> backend_from_name(std::string_view name) {
  for (Backend b : available_backends())
    if (name == backend_name(b)) return b;
  return std::nullopt;
}

}  // namespace kinestat::solver
