// PETSc, SLEPc and MPI in a module of their own (libkinestat_petsc.so, built from src/solver/petsc/
// when PETSc is found), which a process loads the first time it needs them: when a PETSc backend is
// asked for, or start_parallel is called. Linked into every program, their ~100 shared libraries
// cost each start of the kinestat command 45-70 ms in the dynamic loader (benchmarks/README.md,
// "PETSc on demand"), most runs without a use for them. The module holds its own copy of the layers
// below it and exports only kinestat_petsc_module(), which gives this table of its entry points; the
// functions of parallel.hpp and petsc_solver.hpp in kinestat_solver forward to it.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/solver/parallel.hpp"
#include "solver/petsc_solver.hpp"

namespace kinestat::solver {

struct PetscModule {
  // sizeof(PetscModule) and kinestat's version: a module of another build is refused.
  std::size_t size = 0;
  const char* version = nullptr;
  const char* libraries = nullptr;  // "PETSc 3.18.4, SLEPc 3.18.2", as built against
  // parallel.hpp
  StatusOr<ProcessGroup> (*start_parallel)() = nullptr;
  ProcessGroup (*process_group)() = nullptr;
  bool (*parallel_running)() = nullptr;
  void (*finish_parallel)() = nullptr;
  Status (*broadcast_doubles)(std::vector<double>&) = nullptr;
  Status (*broadcast_ints)(std::vector<int>&) = nullptr;
  Status (*gather_doubles)(std::vector<double>&) = nullptr;
  Status (*gather_chars)(std::vector<char>&) = nullptr;
  Status (*sum_over_ranks)(std::span<double>) = nullptr;
  Status (*agree_on_status)(const Status&) = nullptr;
  Status (*same_on_every_rank)(const std::string&, const std::string&) = nullptr;
  int (*finish_job)(int, const std::string&, double) = nullptr;
  // petsc_solver.hpp
  std::unique_ptr<SparseCholesky> (*make_petsc_mumps)(const LinearSolverOptions&) = nullptr;
  std::unique_ptr<LinearSolver> (*make_petsc_cg)(const LinearSolverOptions&) = nullptr;
  std::optional<StatusOr<std::pair<VecX, MatX>>> (*generalized_eigenpairs)(const SparseMatrix&, const LinearSolver&,
                                                                           int, const EigenConvergence&) = nullptr;
};

// The module's exported function (extern "C"): returns its table.
inline constexpr const char* kPetscModuleEntry = "kinestat_petsc_module";

// Loads the module once per process (thread-safe) and returns its table: kInvalidInput when PETSc was
// not built in, kInternal when the module cannot be loaded (every path tried, and why). Looked for
// at $KINESTAT_PETSC_MODULE, then where `cmake --install` puts it relative to the running program
// or the Python module, then in the build tree.
StatusOr<const PetscModule*> load_petsc_module();
// The table once loaded; nullptr before (nothing of PETSc can exist yet).
const PetscModule* loaded_petsc_module();

}  // namespace kinestat::solver
