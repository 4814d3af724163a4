// The MPI runtime (kinestat/solver/parallel.hpp) in the PETSc module: PETSc's and SLEPc's start and
// end, and the collectives the methods use, on PETSC_COMM_WORLD; finish_job's barrier on a duplicate
// of it, so that it never matches a collective a solver is waiting in. kinestat_solver's own
// parallel.cpp forwards to these once the module is loaded.
#include "kinestat/solver/parallel.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include <slepcsys.h>

namespace kinestat::solver {

namespace {

enum class Lifecycle { kNotStarted, kRunning, kFinished };
Lifecycle lifecycle = Lifecycle::kNotStarted;
MPI_Comm job_comm = MPI_COMM_NULL;  // finish_job's barrier only

// Rank `root`'s vector to every rank: its length, then its values in pieces that MPI's int counts hold.
template <class T>
Status broadcast_vector(std::vector<T>& values, MPI_Datatype type, int root) {
  if (process_group().size == 1) return Status::Ok();
  unsigned long long count = values.size();
  if (MPI_Bcast(&count, 1, MPI_UNSIGNED_LONG_LONG, root, PETSC_COMM_WORLD) != MPI_SUCCESS)
    return Status::Internal("MPI_Bcast of a length failed");
  values.resize(count);
  constexpr unsigned long long kPiece = 1ull << 30;
  for (unsigned long long first = 0; first < count; first += kPiece) {
    const int piece = static_cast<int>(std::min(kPiece, count - first));
    if (MPI_Bcast(values.data() + first, piece, type, root, PETSC_COMM_WORLD) != MPI_SUCCESS)
      return Status::Internal("MPI_Bcast of shared data failed");
  }
  return Status::Ok();
}

// Every rank's vector to rank 0, concatenated in rank order (counts in MPI's int: the pieces a
// split job gathers are small).
template <class T>
Status gather_vector(std::vector<T>& values, MPI_Datatype type) {
  const ProcessGroup group = process_group();
  if (group.size == 1) return Status::Ok();
  if (values.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return Status::Internal("MPI gather: a rank's data is larger than MPI's int counts");
  int mine = static_cast<int>(values.size());
  std::vector<int> counts(group.rank == 0 ? group.size : 0), offsets;
  if (MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, PETSC_COMM_WORLD) != MPI_SUCCESS)
    return Status::Internal("MPI_Gather of the lengths failed");
  std::vector<T> all;
  if (group.rank == 0) {
    long long total = 0;
    for (int c : counts) offsets.push_back(static_cast<int>(total)), total += c;
    if (total > std::numeric_limits<int>::max())
      return Status::Internal("MPI gather: the ranks' data is larger than MPI's int counts");
    all.resize(static_cast<std::size_t>(total));
  }
  if (MPI_Gatherv(values.data(), mine, type, all.data(), counts.data(), offsets.data(), type, 0, PETSC_COMM_WORLD) !=
      MPI_SUCCESS)
    return Status::Internal("MPI_Gatherv of the ranks' data failed");
  if (group.rank == 0) values = std::move(all);
  return Status::Ok();
}

}  // namespace

StatusOr<ProcessGroup> start_parallel() {
  if (lifecycle == Lifecycle::kFinished)
    return Status::Internal("PETSc was finished in this process and cannot start again");
  if (lifecycle == Lifecycle::kNotStarted) {
    // No command line: kinestat's options are not PETSc's; PETSC_OPTIONS still reaches PETSc.
    // SLEPc's start starts PETSc too (the eigensolver on petsc-mumps, solver/generalized_eigen.hpp).
    if (PetscErrorCode code = SlepcInitializeNoArguments(); code != 0) {
      const char* text = nullptr;
      PetscErrorMessage(code, &text, nullptr);
      return Status::Internal(fmt::format("SLEPc: SlepcInitialize failed: {}", text ? text : "unknown error"));
    }
    // Errors come back as codes (turned into Status), not as tracebacks on stderr.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    if (MPI_Comm_dup(PETSC_COMM_WORLD, &job_comm) != MPI_SUCCESS) job_comm = MPI_COMM_NULL;
    lifecycle = Lifecycle::kRunning;
    std::atexit(finish_parallel);
  }
  return process_group();
}

ProcessGroup process_group() {
  ProcessGroup g;
  if (lifecycle != Lifecycle::kRunning) return g;
  MPI_Comm_rank(PETSC_COMM_WORLD, &g.rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &g.size);
  return g;
}

bool parallel_running() { return lifecycle == Lifecycle::kRunning; }

void finish_parallel() {
  if (lifecycle != Lifecycle::kRunning) return;
  lifecycle = Lifecycle::kFinished;
  if (job_comm != MPI_COMM_NULL) MPI_Comm_free(&job_comm);
  SlepcFinalize();  // and PETSc, which SlepcInitialize started
}

Status broadcast_from_root(std::vector<double>& values) { return broadcast_vector(values, MPI_DOUBLE, 0); }
Status broadcast_from_root(std::vector<int>& values) { return broadcast_vector(values, MPI_INT, 0); }
Status gather_to_root(std::vector<double>& values) { return gather_vector(values, MPI_DOUBLE); }
Status gather_to_root(std::vector<char>& values) { return gather_vector(values, MPI_CHAR); }

Status sum_over_ranks(std::span<double> values) {
  if (process_group().size == 1) return Status::Ok();
  constexpr std::size_t kPiece = std::size_t{1} << 30;  // MPI's int counts
  for (std::size_t first = 0; first < values.size(); first += kPiece) {
    const int piece = static_cast<int>(std::min(kPiece, values.size() - first));
    if (MPI_Allreduce(MPI_IN_PLACE, values.data() + first, piece, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD) != MPI_SUCCESS)
      return Status::Internal("MPI_Allreduce of the ranks' sums failed");
  }
  return Status::Ok();
}

Status agree_on_status(const Status& mine) {
  const ProcessGroup group = process_group();
  if (group.size == 1) return mine;
  int failed = mine.ok() ? group.size : group.rank, first = group.size;
  if (MPI_Allreduce(&failed, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD) != MPI_SUCCESS)
    return Status::Internal("MPI_Allreduce of the ranks' outcomes failed");
  if (first == group.size) return Status::Ok();
  std::vector<int> code = {static_cast<int>(mine.code())};
  std::vector<char> text(mine.message().begin(), mine.message().end());
  if (Status s = broadcast_vector(code, MPI_INT, first); !s.ok()) return s;
  if (Status s = broadcast_vector(text, MPI_CHAR, first); !s.ok()) return s;
  return Status(static_cast<StatusCode>(code[0]), std::string(text.begin(), text.end()));
}

Status same_on_every_rank(const std::string& what, const std::string& value) {
  const ProcessGroup group = process_group();
  if (group.size == 1) return Status::Ok();
  std::vector<char> root(value.begin(), value.end());
  if (Status s = broadcast_vector(root, MPI_CHAR, 0); !s.ok()) return s;
  const std::string rank0(root.begin(), root.end());
  Status mine = Status::Ok();
  if (rank0 != value)
    mine =
        Status::Invalid(fmt::format("MPI rank {}: {} differs from rank 0's ('{}' against '{}'); every rank of a "
                                    "job must be given the same options and see the same files",
                                    group.rank, what, value, rank0));
  return agree_on_status(mine);
}

int finish_job(int exit_code, const std::string& message, double wait_seconds) {
  if (lifecycle != Lifecycle::kRunning || job_comm == MPI_COMM_NULL || process_group().size == 1) return exit_code;
  MPI_Request request;
  if (MPI_Ibarrier(job_comm, &request) != MPI_SUCCESS) return exit_code;
  if (exit_code == 0) {
    MPI_Wait(&request, MPI_STATUS_IGNORE);
    return exit_code;
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return exit_code;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > wait_seconds) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // The others wait in a collective this rank left: end them all, saying why.
  const ProcessGroup g = process_group();
  std::fprintf(stderr,
               "kinestat: MPI rank %d of %d failed while the other ranks went on: %s\nkinestat: ending the job "
               "(MPI_Abort) instead of leaving them waiting\n",
               g.rank, g.size, message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  return exit_code;
}

}  // namespace kinestat::solver
