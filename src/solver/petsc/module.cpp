// The PETSc module's one exported function (solver/petsc_module.hpp): the table of its entry points,
// this module's own parallel.cpp and petsc_solver.cpp.
#include <string>

#include <fmt/format.h>
#include <petscversion.h>
#include <slepcversion.h>

#include "kinestat/core/version.hpp"
#include "solver/petsc_module.hpp"

extern "C" __attribute__((visibility("default"))) const kinestat::solver::PetscModule* kinestat_petsc_module() {
  using namespace kinestat::solver;
  static const PetscModule table = [] {
    PetscModule t;
    t.size = sizeof(PetscModule);
    t.version = kinestat::kVersion;
    static const std::string libraries =
        fmt::format("PETSc {}.{}.{}, SLEPc {}.{}.{}", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR,
                    SLEPC_VERSION_MAJOR, SLEPC_VERSION_MINOR, SLEPC_VERSION_SUBMINOR);
    t.libraries = libraries.c_str();
    t.start_parallel = &start_parallel;
    t.process_group = &process_group;
    t.parallel_running = &parallel_running;
    t.finish_parallel = &finish_parallel;
    t.broadcast_doubles = [](std::vector<double>& v) { return broadcast_from_root(v); };
    t.broadcast_ints = [](std::vector<int>& v) { return broadcast_from_root(v); };
    t.gather_doubles = [](std::vector<double>& v) { return gather_to_root(v); };
    t.gather_chars = [](std::vector<char>& v) { return gather_to_root(v); };
    t.sum_over_ranks = &sum_over_ranks;
    t.agree_on_status = &agree_on_status;
    t.same_on_every_rank = &same_on_every_rank;
    t.finish_job = &finish_job;
    t.make_petsc_mumps = &make_petsc_mumps;
    t.make_petsc_cg = &make_petsc_cg;
    t.generalized_eigenpairs = &petsc_generalized_eigenpairs;
    return t;
  }();
  return &table;
}
