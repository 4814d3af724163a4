// kinestat/solver/parallel.hpp: the MPI runtime lives in the PETSc module (solver/petsc_module.hpp,
// src/solver/petsc/parallel.cpp), which start_parallel loads. Until then, and without PETSc, every
// function acts as one process alone.
#include "kinestat/solver/parallel.hpp"

#include <utility>

#include "solver/petsc_module.hpp"

namespace kinestat::solver {

StatusOr<ProcessGroup> start_parallel() {
  const StatusOr<const PetscModule*> m = load_petsc_module();
  if (m.ok()) return (*m)->start_parallel();
  if (m.status().code() == StatusCode::kInvalidInput) return ProcessGroup{};  // not built in: one process
  return m.status();
}

namespace {

// The loaded module's `entry` called with `args`; before the module is loaded, and without PETSc,
// `alone`: one process's answer.
template <class Entry, class Alone, class... Args>
auto forward(Entry PetscModule::*entry, Alone alone, Args&&... args) {
  const PetscModule* m = loaded_petsc_module();
  return m ? (m->*entry)(std::forward<Args>(args)...) : alone;
}

}  // namespace

ProcessGroup process_group() { return forward(&PetscModule::process_group, ProcessGroup{}); }

bool parallel_running() { return forward(&PetscModule::parallel_running, false); }

void finish_parallel() {
  if (const PetscModule* m = loaded_petsc_module()) m->finish_parallel();
}

Status broadcast_from_root(std::vector<double>& values) {
  return forward(&PetscModule::broadcast_doubles, Status::Ok(), values);
}

Status broadcast_from_root(std::vector<int>& values) {
  return forward(&PetscModule::broadcast_ints, Status::Ok(), values);
}

Status gather_to_root(std::vector<double>& values) {
  return forward(&PetscModule::gather_doubles, Status::Ok(), values);
}

Status gather_to_root(std::vector<char>& values) { return forward(&PetscModule::gather_chars, Status::Ok(), values); }

Status sum_over_ranks(std::span<double> values) { return forward(&PetscModule::sum_over_ranks, Status::Ok(), values); }

Status agree_on_status(const Status& mine) { return forward(&PetscModule::agree_on_status, mine, mine); }

Status same_on_every_rank(const std::string& what, const std::string& value) {
  return forward(&PetscModule::same_on_every_rank, Status::Ok(), what, value);
}

int finish_job(int exit_code, const std::string& message, double wait_seconds) {
  return forward(&PetscModule::finish_job, exit_code, exit_code, message, wait_seconds);
}

}  // namespace kinestat::solver
