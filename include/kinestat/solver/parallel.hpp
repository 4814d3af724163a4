// The process-wide MPI runtime of the distributed backends: starting and ending it, the ranks, and
// the few collectives the methods need (sharing what rank 0 computed, agreeing on an outcome).
// Without PETSc built in, or before start_parallel, every function acts as one process alone.
// docs/reliability.md, "MPI", says how a job fails together.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"

namespace kinestat::solver {

// The MPI processes a distributed backend runs on (rank 0 of 1 without MPI).
struct ProcessGroup {
  int rank = 0;
  int size = 1;
};

// Starts PETSc and SLEPc (and MPI) once per process for the PETSc backends: call it first thing when the
// program may run under mpirun, so that every rank knows its rank before writing anything. The PETSc
// backends also start it themselves when needed. Ok without effect when PETSc is not built in.
StatusOr<ProcessGroup> start_parallel();
ProcessGroup process_group();  // {0, 1} until start_parallel
bool parallel_running();       // started and not yet finished
// Ends PETSc and MPI (no solver object may outlive it); also done at exit.
void finish_parallel();

// Sharing what rank 0 alone computed (e.g. the FEA mesh: rank 0 meshes, the others receive it).
// Collective: every rank of process_group() calls them, in the same order; without PETSc, before
// start_parallel or on one rank they do nothing. On return every rank holds rank 0's `values`
// (resized on the others).
Status broadcast_from_root(std::vector<double>& values);
Status broadcast_from_root(std::vector<int>& values);
// Collecting what every rank computed of a split job (e.g. a design sweep's designs, round-robin).
// Collective: on return rank 0's `values` holds every rank's, one after another in rank order (its
// own first); the other ranks' are unchanged. Without PETSc, before start_parallel or on one rank
// they do nothing.
Status gather_to_root(std::vector<double>& values);
Status gather_to_root(std::vector<char>& values);
// The sum over the ranks of what each computed from its share of a distributed assembly (e.g. K q
// from its summand of K). Collective: `values` has the same length on every rank, and on return
// holds the sum on every rank. Without PETSc, before start_parallel or on one rank it does nothing.
Status sum_over_ranks(std::span<double> values);
// Every rank's outcome of a step that may fail on some ranks only (rank 0's meshing, a rank's own
// elements): returns to every rank the failure of the lowest failing rank (code and message), or Ok.
// Call it before the next collective step, so that a failure stops every rank instead of leaving the
// others waiting for the failed one. Returns `mine` without MPI.
Status agree_on_status(const Status& mine);
// Collective: kInvalidInput on every rank when some rank's `value` differs from rank 0's ("MPI rank
// 1: WHAT differs from rank 0's: ..."): ranks that were given other options, or see other files,
// would compute different things and wait for each other in different collectives.
Status same_on_every_rank(const std::string& what, const std::string& value);

// The end of a job under MPI, on every rank, before finish_parallel. A rank whose command failed
// waits up to `wait_seconds` for the others at a barrier of its own (a communicator apart from the
// solvers'); when they do not come (they wait in a collective this rank will never join) it prints
// `message` with its rank on `err` and ends the whole job with MPI_Abort(exit_code), so no rank
// hangs. A rank that succeeded waits for the others. Returns `exit_code`; no effect on one process.
int finish_job(int exit_code, const std::string& message, double wait_seconds = 10.0);

}  // namespace kinestat::solver
