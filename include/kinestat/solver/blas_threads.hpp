// The BLAS's idle threads at the start of a short-lived program.
#pragma once

namespace kinestat::solver {

// OpenBLAS's pthreads build (Debian's libblas.so.3 alternative) starts its worker threads when it is
// loaded, and each spins on sched_yield for 2^28 cycles (~0.1 s) before it sleeps, whether or not the
// program ever calls the BLAS: (cores - 1) x ~0.1 s of CPU at every start, taken from the program's own
// threads (benchmarks/README.md, "OpenBLAS's idle threads"). This stops them; OpenBLAS starts them
// again at its next threaded call. Call it where no other thread is in the BLAS (the start of main).
// Nothing happens under another BLAS. Returns whether OpenBLAS's threads were stopped.
bool release_idle_blas_threads();

}  // namespace kinestat::solver
