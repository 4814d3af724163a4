// kinestat/solver/parallel.hpp: the MPI runtime lives in the PETSc module (solver/petsc_module.hpp,
// src/solver/petsc/parallel.cpp), which start_parallel loads. Until then, and without PETSc, every
// function acts as one process alone.
#include "kinestat/solver/parallel.hpp"

#include "solver/petsc_module.hpp"

namespace kinestat::solver {

StatusOr<ProcessGroup> start_parallel() {
  const StatusOr<const PetscModule*> m = load_petsc_module();
  if (m.ok()) return (*m)->start_parallel();
  if (m.status().code() == StatusCode::kInvalidInput) return ProcessGroup{};  // not built in: one process
  return m.status();
}

ProcessGroup process_group() {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->process_group() : ProcessGroup{};
}

bool parallel_running() {
  const PetscModule* m = loaded_petsc_module();
  return m && m->parallel_running();
}

void finish_parallel() {
  if (const PetscModule* m = loaded_petsc_module()) m->finish_parallel();
}

Status broadcast_from_root(std::vector<double>& values) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->broadcast_doubles(values) : Status::Ok();
}

Status broadcast_from_root(std::vector<int>& values) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->broadcast_ints(values) : Status::Ok();
}

Status gather_to_root(std::vector<double>& values) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->gather_doubles(values) : Status::Ok();
}

Status gather_to_root(std::vector<char>& values) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->gather_chars(values) : Status::Ok();
}

Status sum_over_ranks(std::span<double> values) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->sum_over_ranks(values) : Status::Ok();
}

Status agree_on_status(const Status& mine) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->agree_on_status(mine) : mine;
}

Status same_on_every_rank(const std::string& what, const std::string& value) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->same_on_every_rank(what, value) : Status::Ok();
}

int finish_job(int exit_code, const std::string& message, double wait_seconds) {
  const PetscModule* m = loaded_petsc_module();
  return m ? m->finish_job(exit_code, message, wait_seconds) : exit_code;
}

}  // namespace kinestat::solver
