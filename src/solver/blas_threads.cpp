#include "kinestat/solver/blas_threads.hpp"

#include <dlfcn.h>

namespace kinestat::solver {

bool release_idle_blas_threads() {
  // OpenBLAS's own entry for this (its fork handler calls it, and exec_blas re-creates the threads on
  // demand); looked up at run time, since the BLAS behind libblas.so.3 is chosen by the system.
  using Shutdown = int (*)();
  auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  return shutdown && shutdown() == 0;
}

}  // namespace kinestat::solver
