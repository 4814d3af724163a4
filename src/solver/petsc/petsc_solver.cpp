// The PETSc backends (docs/fea.md, "Large meshes"): MUMPS's Cholesky (a SparseCholesky) and CG +
// GAMG (an iterative LinearSolver), each a KSP over the same distributed matrix. Factorize takes the
// whole matrix on every rank and gives PETSc only this rank's block of rows; FactorizeSum takes each
// rank's summand (the elements it assembled) and lets PETSc add them, sending entries of other
// ranks' rows to their owners, so that no rank holds the whole matrix. PETSc distributes the factor
// (MUMPS) or the multigrid hierarchy (GAMG); the solution is gathered back to every rank, so every
// rank computes the same 6x6. On the MUMPS backend SLEPc solves the generalized eigenproblem of
// solver/generalized_eigen.hpp with the same factor (petsc_generalized_eigenpairs), the pencil's
// other matrix assembled as K was. Built into the module solver/petsc_module.hpp loads on first use.
#include "solver/petsc_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/parallel.hpp"

#include <petscksp.h>
#include <slepceps.h>
#include <Eigen/QR>

namespace kinestat::solver {

namespace {

// PETSc and SLEPc calls return an error code; it becomes a Status (kInternal) naming the library,
// the call and the library's text (SLEPc's codes are PETSc's, so PetscErrorMessage reads both).
Status library_error(const char* library, PetscErrorCode code, const char* call) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  return Status::Internal(fmt::format("{}: {} failed: {}", library, call, text ? text : "unknown error"));
}
Status petsc_error(PetscErrorCode code, const char* call) { return library_error("PETSc", code, call); }
#define KINESTAT_PETSC(call)                                                         \
  do {                                                                               \
    if (PetscErrorCode code_ = (call); code_ != 0) return petsc_error(code_, #call); \
  } while (0)
#define KINESTAT_SLEPC(call)                                                                    \
  do {                                                                                          \
    if (PetscErrorCode code_ = (call); code_ != 0) return library_error("SLEPc", code_, #call); \
  } while (0)

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string petsc_version() {
  return fmt::format("PETSc {}.{}.{}", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR);
}

// Rows in blocks of 3 (x, y, z of a node) when the dofs come in triples, as GAMG's aggregates want.
PetscInt block_size(int n) { return n % 3 == 0 ? 3 : 1; }

// The offsets of every rank's block of rows (PETSc's split, whole blocks of block_size(n) rows):
// the same on every rank, and the same rows the PETSc matrix gives each rank.
StatusOr<std::vector<int>> split_rows(int n) {
  StatusOr<ProcessGroup> group = start_parallel();
  if (!group.ok()) return group.status();
  PetscInt local = PETSC_DECIDE, global = n;
  KINESTAT_PETSC(PetscSplitOwnershipBlock(PETSC_COMM_WORLD, block_size(n), &local, &global));
  std::vector<PetscInt> locals(group->size);
  if (MPI_Allgather(&local, 1, MPIU_INT, locals.data(), 1, MPIU_INT, PETSC_COMM_WORLD) != MPI_SUCCESS)
    return Status::Internal("MPI_Allgather of the row ownership failed");
  std::vector<int> offsets(group->size + 1, 0);
  for (int r = 0; r < group->size; ++r) offsets[r + 1] = offsets[r] + static_cast<int>(locals[r]);
  return offsets;
}

int owner_of(const std::vector<int>& offsets, int row) {
  return static_cast<int>(std::upper_bound(offsets.begin(), offsets.end(), row) - offsets.begin()) - 1;
}

// The distributed vector x whole on every rank, into `column` (its length): `gather` scatters x to
// `all` (VecScatterCreateToAll). A PETSc error code, for KINESTAT_PETSC.
PetscErrorCode gather_to_every_rank(VecScatter gather, Vec x, Vec all, Eigen::Ref<VecX> column) {
  PetscCall(VecScatterBegin(gather, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(gather, x, all, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* values = nullptr;
  PetscCall(VecGetArrayRead(all, &values));
  column = Eigen::Map<const VecX>(values, column.size());
  PetscCall(VecRestoreArrayRead(all, &values));
  return 0;
}

// A distributed matrix as the PETSc backends hold it (K) and the eigensolver adds (the pencil's
// other matrix): AIJ, in blocks of block_size(n) rows split over the ranks as split_rows says.
struct DistributedMatrix {
  Mat mat = nullptr;  // the caller destroys it, also on failure
  int n = 0;
  PetscInt rstart = 0, rend = 0;  // this rank's rows
  long nnz_lower = 0;             // stored entries of the lower triangle, over all ranks
};

// Makes out->mat from `parts`: with `summed`, the sum of every rank's parts (each rank inserts all
// its entries, PETSc's stash moves those of other ranks' rows during the assembly); without, every
// rank holds the whole matrix in parts[0] and inserts only its own rows. Collective.
Status assemble_matrix(std::span<const SparseMatrix> parts, bool summed, DistributedMatrix* out) {
  if (parts.empty()) return Status::Invalid("PETSc solver: no matrix given");
  const int n = out->n = static_cast<int>(parts[0].rows());
  for (const SparseMatrix& p : parts)
    if (p.rows() != n || p.cols() != n)
      return Status::Invalid(
          fmt::format("PETSc solver: a {} x {} matrix where a square one of {} rows is wanted", p.rows(), p.cols(), n));
  // Every rank must bring the same n (a collective call with different sizes would not return).
  int n_min = n, n_max = n;
  MPI_Allreduce(&n, &n_min, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  MPI_Allreduce(&n, &n_max, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (n_min != n_max)
    return Status::Internal(fmt::format("PETSc solver: the ranks hold matrices of {} to {} rows", n_min, n_max));
  StatusOr<std::vector<int>> offsets = split_rows(n);
  if (!offsets.ok()) return offsets.status();
  const int rank = process_group().rank;
  const PetscInt rstart = out->rstart = (*offsets)[rank];
  const PetscInt rend = out->rend = (*offsets)[rank + 1];
  const PetscInt local = rend - rstart;
  auto take = [&](PetscInt row) { return summed || (row >= rstart && row < rend); };

  // PETSc wants both triangles of its rows. The lower triangle (column-major) holds row c's upper
  // part in column c, and rows r > c's lower parts in the same column: each column is inserted as
  // one column of rows r >= c and one row c, without a second (full) copy of the matrix.
  auto for_each_column = [&](auto&& visit) -> Status {
    std::vector<PetscInt> lower_rows, upper_cols;
    std::vector<PetscScalar> lower_values, upper_values;
    for (const SparseMatrix& part : parts)
      for (PetscInt c = 0; c < n; ++c) {
        lower_rows.clear(), upper_cols.clear(), lower_values.clear(), upper_values.clear();
        for (SparseMatrix::InnerIterator it(part, static_cast<int>(c)); it; ++it) {
          if (it.row() < c) continue;  // an upper entry: ignored
          if (take(it.row())) lower_rows.push_back(it.row()), lower_values.push_back(it.value());
          if (it.row() != c && take(c)) upper_cols.push_back(it.row()), upper_values.push_back(it.value());
        }
        if (Status s = visit(c, lower_rows, lower_values, upper_cols, upper_values); !s.ok()) return s;
      }
    return Status::Ok();
  };

  // Preallocation: per owned row, the entries in the diagonal block (columns this rank owns) and
  // off it. Each rank counts what it inserts into every row (two O(n) arrays) and the counts are
  // summed onto the rows' owners. An entry that several ranks (summands) hold is counted once per
  // holder: an upper bound, capped at the row's length, whose excess is the ranks' shared rows only.
  std::vector<PetscInt> diagonal(n, 0), off(n, 0);
  auto count = [&](PetscInt row, PetscInt col) {
    ++(owner_of(*offsets, static_cast<int>(row)) == owner_of(*offsets, static_cast<int>(col)) ? diagonal : off)[row];
  };
  Status counted =
      for_each_column([&](PetscInt c, const auto& lower_rows, const auto&, const auto& upper_cols, const auto&) {
        for (PetscInt row : lower_rows) count(row, c);
        for (PetscInt col : upper_cols) count(c, col);
        return Status::Ok();
      });
  if (!counted.ok()) return counted;
  const int ranks = process_group().size;
  std::vector<int> local_sizes(ranks);
  for (int q = 0; q < ranks; ++q) local_sizes[q] = (*offsets)[q + 1] - (*offsets)[q];
  std::vector<PetscInt> diagonal_nnz(local), off_nnz(local);
  if (MPI_Reduce_scatter(diagonal.data(), diagonal_nnz.data(), local_sizes.data(), MPIU_INT, MPI_SUM,
                         PETSC_COMM_WORLD) != MPI_SUCCESS ||
      MPI_Reduce_scatter(off.data(), off_nnz.data(), local_sizes.data(), MPIU_INT, MPI_SUM, PETSC_COMM_WORLD) !=
          MPI_SUCCESS)
    return Status::Internal("MPI_Reduce_scatter of the preallocation counts failed");
  std::vector<PetscInt>().swap(diagonal), std::vector<PetscInt>().swap(off);
  for (PetscInt i = 0; i < local; ++i) {
    diagonal_nnz[i] = std::min(diagonal_nnz[i], local);
    off_nnz[i] = std::min(off_nnz[i], static_cast<PetscInt>(n) - local);
  }
  Mat& A = out->mat;
  KINESTAT_PETSC(MatCreate(PETSC_COMM_WORLD, &A));
  KINESTAT_PETSC(MatSetSizes(A, local, local, n, n));
  KINESTAT_PETSC(MatSetType(A, MATAIJ));
  KINESTAT_PETSC(MatSetBlockSize(A, block_size(n)));
  KINESTAT_PETSC(MatSeqAIJSetPreallocation(A, 0, diagonal_nnz.data()));
  KINESTAT_PETSC(MatMPIAIJSetPreallocation(A, 0, diagonal_nnz.data(), 0, off_nnz.data()));
  Status inserted = for_each_column([&](PetscInt c, const auto& lower_rows, const auto& lower_values,
                                        const auto& upper_cols, const auto& upper_values) -> Status {
    if (!lower_rows.empty())  // rows r >= c, column c
      KINESTAT_PETSC(MatSetValues(A, static_cast<PetscInt>(lower_rows.size()), lower_rows.data(), 1, &c,
                                  lower_values.data(), ADD_VALUES));
    if (!upper_cols.empty())  // row c, columns r > c
      KINESTAT_PETSC(MatSetValues(A, 1, &c, static_cast<PetscInt>(upper_cols.size()), upper_cols.data(),
                                  upper_values.data(), ADD_VALUES));
    return Status::Ok();
  });
  if (!inserted.ok()) return inserted;
  KINESTAT_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  KINESTAT_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  // Stored entries of the lower triangle of the assembled A, over all ranks.
  long lower = 0;
  for (PetscInt row = rstart; row < rend; ++row) {
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    KINESTAT_PETSC(MatGetRow(A, row, &ncols, &cols, nullptr));
    lower += std::count_if(cols, cols + ncols, [&](PetscInt col) { return col <= row; });
    KINESTAT_PETSC(MatRestoreRow(A, row, &ncols, &cols, nullptr));
  }
  MPI_Allreduce(&lower, &out->nnz_lower, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  return Status::Ok();
}

// What the two PETSc backends share: the distributed matrix, the KSP, and the solves with the true
// residual. `Interface` is the kind (SparseCholesky for MUMPS, LinearSolver for CG); the derived
// class configures the KSP (ConfigureKsp) and checks what its setup found (CheckSetup).
template <class Interface>
class PetscKspSolver : public Interface {
 public:
  explicit PetscKspSolver(const LinearSolverOptions& options) : options_(options) {}
  ~PetscKspSolver() override { Release(); }
  PetscKspSolver(const PetscKspSolver&) = delete;
  PetscKspSolver& operator=(const PetscKspSolver&) = delete;

  Status Factorize(const SparseMatrix& A, FactorizationReport* report) override {
    return FactorizeParts(std::span(&A, 1), /*summed=*/false, report);
  }

  Status FactorizeSum(std::span<const SparseMatrix> summands, FactorizationReport* report) override {
    return FactorizeParts(summands, /*summed=*/true, report);
  }

  int summing_ranks() const override {
    StatusOr<ProcessGroup> group = start_parallel();
    return group.ok() ? group->size : 1;  // PETSc failed to start: FactorizeSum will say so
  }

  int num_symbolic_analyses() const override { return analyses_; }

 protected:
  // An iterative solver: a stopping tolerance, iterations counted, CG restarted (DoSolve).
  virtual bool iterative() const = 0;
  // The options only this kind reads, checked before any collective work.
  virtual Status CheckOptions() const { return Status::Ok(); }
  // Once A_ is assembled: what the kind tells PETSc about it; then the KSP's type and preconditioner.
  virtual Status PrepareMatrix() { return Status::Ok(); }
  virtual Status ConfigureKsp(KSP ksp, PC pc, FactorizationReport* r) = 0;
  // After KSPSetUp succeeded: what the setup found (MUMPS's pivots).
  virtual Status CheckSetup(PC /*pc*/, FactorizationReport* /*r*/) { return Status::Ok(); }
  virtual std::string setup_stage() const = 0;  // for options_.progress
  // Solves the current right-hand side again from its last solution: updates the converged reason
  // and the true relative residual that Refine is given (by reference), adds the iterations.
  using SolveAgain = std::function<PetscErrorCode()>;
  // After a right-hand side's first solve: nothing for a direct solver; CG's restarts (PetscCgSolver).
  virtual PetscErrorCode Refine(KSP /*ksp*/, const SolveAgain& /*again*/, const KSPConvergedReason& /*reason*/,
                                const double& /*relative*/) const {
    return 0;
  }

  std::string ranks_description() const {
    const ProcessGroup group = process_group();
    return fmt::format("{} MPI rank{}", group.size, group.size == 1 ? "" : "s");
  }

  std::vector<PetscInt> owned_rows() const {
    std::vector<PetscInt> rows(rend_ - rstart_);
    for (PetscInt i = rstart_; i < rend_; ++i) rows[i - rstart_] = i;
    return rows;
  }

  LinearSolverOptions options_;
  Mat A_ = nullptr;
  int n_ = 0;
  PetscInt rstart_ = 0, rend_ = 0;
  bool summed_ = false;  // A_ is the sum of the ranks' parts (FactorizeSum), not every rank's whole A
  KSP ksp_ = nullptr;

 private:
  Status DoSolve(const MatX& B, MatX* X, SolveReport* report) const override {
    if (!ksp_) return Status::Internal("PETSc solver: Solve called without a successful Factorize");
    if (B.rows() != n_) return Status::Invalid(fmt::format("PETSc solver: B has {} rows, A has {}", B.rows(), n_));
    const auto t0 = std::chrono::steady_clock::now();
    SolveReport rep;
    rep.relative_tolerance = iterative() ? options_.relative_tolerance : 0.0;
    X->resize(n_, B.cols());
    Vec b = nullptr, x = nullptr, residual = nullptr, all = nullptr;
    VecScatter gather = nullptr;
    auto release = [&] {
      VecDestroy(&b), VecDestroy(&x), VecDestroy(&residual), VecDestroy(&all), VecScatterDestroy(&gather);
    };
    Status s = [&]() -> Status {
      KINESTAT_PETSC(MatCreateVecs(A_, &x, &b));
      KINESTAT_PETSC(VecDuplicate(b, &residual));
      KINESTAT_PETSC(VecScatterCreateToAll(x, &gather, &all));
      const std::vector<PetscInt> rows = owned_rows();
      for (Eigen::Index k = 0; k < B.cols(); ++k) {
        KINESTAT_PETSC(VecSetValues(b, rend_ - rstart_, rows.data(), B.col(k).data() + rstart_, INSERT_VALUES));
        KINESTAT_PETSC(VecAssemblyBegin(b));
        KINESTAT_PETSC(VecAssemblyEnd(b));
        // The true residual ||b - A x|| / ||b||, whatever the KSP measured: what the report promises.
        PetscReal norm_b = 0.0;
        KINESTAT_PETSC(VecNorm(b, NORM_2, &norm_b));
        auto true_residual = [&](double* relative) -> PetscErrorCode {
          PetscReal norm_r = 0.0;
          PetscCall(MatMult(A_, x, residual));
          PetscCall(VecAYPX(residual, -1.0, b));
          PetscCall(VecNorm(residual, NORM_2, &norm_r));
          *relative = norm_b > 0.0 ? norm_r / norm_b : norm_r;
          return 0;
        };
        Monitor monitor{this, static_cast<int>(k), static_cast<int>(B.cols()), norm_b,
                        std::chrono::steady_clock::now()};
        KINESTAT_PETSC(KSPMonitorCancel(ksp_));
        if (options_.progress) KINESTAT_PETSC(KSPMonitorSet(ksp_, &Monitor::call, &monitor, nullptr));
        KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
        PetscInt iterations = 0;
        double relative = 0.0;
        const SolveAgain solve = [&]() -> PetscErrorCode {  // from x, adding up the iterations
          PetscInt more = 0;
          PetscCall(KSPSolve(ksp_, b, x));
          PetscCall(KSPGetConvergedReason(ksp_, &reason));
          PetscCall(KSPGetIterationNumber(ksp_, &more));
          iterations += more;
          return true_residual(&relative);
        };
        KINESTAT_PETSC(KSPSetInitialGuessNonzero(ksp_, PETSC_FALSE));
        KINESTAT_PETSC(solve());
        KINESTAT_PETSC(Refine(ksp_, solve, reason, relative));
        if (reason < 0)
          return Status::Singular(fmt::format(
              "PETSc {} stopped on right-hand side {} after {} iterations ({}), relative residual {:.3e} > {:g}; "
              "the matrix is singular or not positive definite (a free motion), or give a larger --max-iterations",
              backend_name(options_.backend), k + 1, iterations, KSPConvergedReasons[reason], relative,
              options_.relative_tolerance));
        rep.iterations.push_back(iterative() ? static_cast<int>(iterations) : 0);  // preonly counts the one solve
        rep.relative_residual.push_back(relative);
        KINESTAT_PETSC(gather_to_every_rank(gather, x, all, X->col(k)));
      }
      return Status::Ok();
    }();
    release();
    rep.seconds = seconds_since(t0);
    if (report) *report = rep;
    return s;
  }

  // CG's progress on stderr (through options_.progress) at most every 10 s: a 3M-dof solve takes minutes.
  struct Monitor {
    const PetscKspSolver* solver;
    int column, columns;
    double norm_b;
    std::chrono::steady_clock::time_point last;
    static PetscErrorCode call(KSP, PetscInt iteration, PetscReal norm, void* context) {
      auto* m = static_cast<Monitor*>(context);
      if (seconds_since(m->last) < 10.0) return 0;
      m->last = std::chrono::steady_clock::now();
      m->solver->options_.progress(fmt::format("load case {} of {}: CG iteration {}, relative residual {:.2e}",
                                               m->column + 1, m->columns, iteration,
                                               m->norm_b > 0.0 ? norm / m->norm_b : norm));
      return 0;
    }
  };

  void Release() {
    if (!parallel_running()) return;  // PETSc already finished: its objects went with it
    KSPDestroy(&ksp_);
    MatDestroy(&A_);
  }

  Status FactorizeParts(std::span<const SparseMatrix> parts, bool summed, FactorizationReport* report) {
    FactorizationReport r;
    summed_ = summed;
    Status s = FactorizeImpl(parts, summed, &r);
    if (!s.ok()) Release();  // no Solve with a half-made or singular factor
    if (report) *report = r;
    return s;
  }

  // A_ from `parts` (assemble_matrix), and the report's size and entries.
  Status AssembleMatrix(std::span<const SparseMatrix> parts, bool summed, FactorizationReport* r) {
    DistributedMatrix m;
    Status s = assemble_matrix(parts, summed, &m);
    A_ = m.mat, n_ = m.n, rstart_ = m.rstart, rend_ = m.rend;
    r->n = m.n;
    r->nnz_matrix = m.nnz_lower;
    return s;
  }

  Status FactorizeImpl(std::span<const SparseMatrix> parts, bool summed, FactorizationReport* r) {
    if (StatusOr<ProcessGroup> g = start_parallel(); !g.ok()) return g.status();
    if (Status s = CheckOptions(); !s.ok()) return s;
    Release();
    ++analyses_;
    const auto t0 = std::chrono::steady_clock::now();
    if (Status s = AssembleMatrix(parts, summed, r); !s.ok()) return s;
    KINESTAT_PETSC(MatSetOption(A_, MAT_SYMMETRIC, PETSC_TRUE));
    if (Status s = PrepareMatrix(); !s.ok()) return s;
    r->analyze_seconds = seconds_since(t0);

    const auto t1 = std::chrono::steady_clock::now();
    KINESTAT_PETSC(KSPCreate(PETSC_COMM_WORLD, &ksp_));
    KINESTAT_PETSC(KSPSetOperators(ksp_, A_, A_));
    PC pc;
    KINESTAT_PETSC(KSPGetPC(ksp_, &pc));
    if (Status s = ConfigureKsp(ksp_, pc, r); !s.ok()) return s;
    // PETSC_OPTIONS (e.g. "-ksp_monitor -pc_gamg_threshold 0.01") may tune the solver further.
    KINESTAT_PETSC(KSPSetFromOptions(ksp_));
    if (options_.progress) options_.progress(setup_stage());
    KINESTAT_PETSC(KSPSetUp(ksp_));
    PCFailedReason failed = PC_NOERROR;
    KINESTAT_PETSC(PCGetFailedReason(pc, &failed));
    if (failed != PC_NOERROR) {
      r->failed_column = 0;  // MUMPS does not say which
      return Status::Singular(fmt::format("{} found the matrix singular or not positive definite ({})",
                                          iterative() ? "GAMG" : "MUMPS", PCFailedReasons[failed]));
    }
    if (Status s = CheckSetup(pc, r); !s.ok()) return s;
    r->factor_seconds = seconds_since(t1);
    return Status::Ok();
  }

  int analyses_ = 0;
};

// MUMPS's Cholesky (KSPPREONLY + PCCHOLESKY): a direct factorization distributed over the ranks.
class PetscMumpsCholesky final : public PetscKspSolver<SparseCholesky> {
 public:
  using PetscKspSolver<SparseCholesky>::PetscKspSolver;

  std::string backend_description() const override {
    return fmt::format("{} MUMPS Cholesky on {}", petsc_version(), ranks_description());
  }

  // solver/generalized_eigen.hpp on this backend: SLEPc's Krylov-Schur on the pencil A q = mu K q
  // with K = A_, A assembled as K was (summed_: `A` is this rank's summand; else every rank's whole
  // A). The spectral transformation is a shift by 0 (operator K^-1 A, the largest mu at the end
  // Krylov-Schur converges to first, as Spectra's regular-inverse mode) whose solves are this
  // object's KSP: K's MUMPS factor, made once by Factorize, not a second one. Collective.
  StatusOr<std::pair<VecX, MatX>> LargestGeneralizedEigenpairs(const SparseMatrix& A, int count,
                                                               const EigenConvergence& convergence) const {
    if (!ksp_) return Status::Internal("PETSc MUMPS: eigenpairs asked for without a successful Factorize");
    DistributedMatrix M;
    EPS eps = nullptr;
    Vec x = nullptr, Kx = nullptr, all = nullptr;
    VecScatter gather = nullptr;
    StatusOr<std::pair<VecX, MatX>> result = [&]() -> StatusOr<std::pair<VecX, MatX>> {
      if (Status s = assemble_matrix(std::span(&A, 1), summed_, &M); !s.ok()) return s;
      if (M.n != n_)  // the same on every rank (assemble_matrix checked): all return here
        return Status::Invalid(fmt::format("generalized eigenpairs: A has {} rows, K has {}", M.n, n_));
      KINESTAT_PETSC(MatSetOption(M.mat, MAT_SYMMETRIC, PETSC_TRUE));
      const PetscInt nev = std::min(count, n_);
      KINESTAT_SLEPC(EPSCreate(PETSC_COMM_WORLD, &eps));
      KINESTAT_SLEPC(EPSSetOperators(eps, M.mat, A_));
      KINESTAT_SLEPC(EPSSetProblemType(eps, EPS_GHEP));  // A symmetric, K positive definite: K-orthogonal q
      KINESTAT_SLEPC(EPSSetType(eps, EPSKRYLOVSCHUR));
      KINESTAT_SLEPC(EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL));  // Spectra's LargestAlge (buckling's mu < 0)
      KINESTAT_SLEPC(EPSSetDimensions(eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
      KINESTAT_SLEPC(EPSSetTolerances(eps, convergence.tolerance, convergence.max_restarts));
      ST st;
      KINESTAT_SLEPC(EPSGetST(eps, &st));
      KINESTAT_SLEPC(STSetType(st, STSHIFT));
      KINESTAT_SLEPC(STSetShift(st, 0.0));
      // The solves' CG monitor (DoSolve's, whose context is gone) must not fire inside the EPS.
      KINESTAT_PETSC(KSPMonitorCancel(ksp_));
      KINESTAT_SLEPC(STSetKSP(st, ksp_));
      // PETSC_OPTIONS (e.g. "-eps_monitor -eps_ncv 40") may tune the eigensolver, as the KSP's.
      KINESTAT_SLEPC(EPSSetFromOptions(eps));
      if (options_.progress) options_.progress(fmt::format("SLEPc Krylov-Schur for {} eigenpairs on {} dofs", nev, n_));
      KINESTAT_SLEPC(EPSSolve(eps));
      PetscInt converged = 0, restarts = 0;
      KINESTAT_SLEPC(EPSGetConverged(eps, &converged));
      KINESTAT_SLEPC(EPSGetIterationNumber(eps, &restarts));
      if (converged < nev)
        return Status::NotConverged(
            fmt::format("the Krylov-Schur eigensolver (SLEPc) converged to {} of {} eigenvalues after {} "
                        "restart{}; ask for fewer modes",
                        converged, nev, restarts, restarts == 1 ? "" : "s"));
      // Every rank gets all the eigenvalues and the whole vectors, K-normalized (q' K q = 1) as
      // the Spectra route gives them: the callers then work on one process's data.
      VecX mu(nev);
      MatX Q(n_, nev);
      KINESTAT_PETSC(MatCreateVecs(A_, &x, &Kx));
      KINESTAT_PETSC(VecScatterCreateToAll(x, &gather, &all));
      for (PetscInt k = 0; k < nev; ++k) {
        PetscScalar value = 0.0, qKq = 0.0;
        KINESTAT_SLEPC(EPSGetEigenpair(eps, k, &value, nullptr, x, nullptr));
        KINESTAT_PETSC(MatMult(A_, x, Kx));
        KINESTAT_PETSC(VecDot(x, Kx, &qKq));
        if (!(qKq > 0.0))
          return Status::Internal(fmt::format("SLEPc: eigenvector {} has q' K q = {:g}, not positive", k + 1, qKq));
        KINESTAT_PETSC(VecScale(x, 1.0 / std::sqrt(qKq)));
        KINESTAT_PETSC(gather_to_every_rank(gather, x, all, Q.col(k)));
        mu(k) = value;
      }
      return std::pair<VecX, MatX>{std::move(mu), std::move(Q)};
    }();
    EPSDestroy(&eps);  // releases its reference to ksp_, which stays this object's
    MatDestroy(&M.mat);
    VecDestroy(&x), VecDestroy(&Kx), VecDestroy(&all), VecScatterDestroy(&gather);
    return result;
  }

 private:
  bool iterative() const override { return false; }
  std::string setup_stage() const override { return fmt::format("factorizing {} dofs with MUMPS", n_); }

  Status ConfigureKsp(KSP ksp, PC pc, FactorizationReport* r) override {
    KINESTAT_PETSC(KSPSetType(ksp, KSPPREONLY));
    KINESTAT_PETSC(PCSetType(pc, PCCHOLESKY));
    KINESTAT_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    // Null-pivot detection (MUMPS ICNTL(24)): a free motion must stop here, not give numbers. A
    // pivot below CNTL(3) * ||A|| (of MUMPS's scaled matrix) is null: the mechanism's pivot is
    // round-off, which MUMPS's default threshold (1e-5 eps ||A||) lets pass; the same ratio as
    // CHOLMOD's pivot check. A_ is not marked SPD: MUMPS then runs its symmetric-indefinite LDL^T
    // (SYM=2), the one mode with null-pivot detection and a count of negative pivots (CheckSetup).
    KINESTAT_PETSC(PCFactorSetUpMatSolverType(pc));
    Mat factor;
    KINESTAT_PETSC(PCFactorGetMatrix(pc, &factor));
    KINESTAT_PETSC(MatMumpsSetIcntl(factor, 24, 1));
    KINESTAT_PETSC(MatMumpsSetCntl(factor, 3, options_.singular_pivot_ratio));
    r->ordering = "MUMPS automatic";
    return Status::Ok();
  }

  Status CheckSetup(PC pc, FactorizationReport* r) override {
    Mat factor;
    PetscInt entries = 0, null_pivots = 0, negative_pivots = 0;
    PetscReal flops = 0.0;
    KINESTAT_PETSC(PCFactorGetMatrix(pc, &factor));
    KINESTAT_PETSC(MatMumpsGetInfog(factor, 28, &null_pivots));
    KINESTAT_PETSC(MatMumpsGetInfog(factor, 12, &negative_pivots));
    if (null_pivots > 0 || negative_pivots > 0) {
      r->failed_column = 0;  // MUMPS does not say which
      return Status::Singular(
          fmt::format("MUMPS found {} null and {} negative pivots: the matrix is singular (a "
                      "free motion) or not positive definite",
                      null_pivots, negative_pivots));
    }
    KINESTAT_PETSC(MatMumpsGetInfog(factor, 29, &entries));  // entries of the factor (< 0: millions)
    KINESTAT_PETSC(MatMumpsGetRinfog(factor, 3, &flops));    // flops of the elimination (estimated)
    r->nnz_factor = entries >= 0 ? static_cast<long>(entries) : -1000000L * static_cast<long>(entries);
    r->flops = flops;
    r->supernodal = true;  // multifrontal
    return Status::Ok();
  }
};

// Conjugate gradients preconditioned by smoothed-aggregation multigrid (GAMG), whose coarse spaces
// start from the near-null space the caller gives (LinearSolverOptions::near_null_space).
class PetscCgSolver final : public PetscKspSolver<LinearSolver> {
 public:
  using PetscKspSolver<LinearSolver>::PetscKspSolver;

  std::string backend_description() const override {
    return fmt::format("{} CG + GAMG (rigid-body near-null space), relative tolerance {:g}, on {}", petsc_version(),
                       options_.relative_tolerance, ranks_description());
  }

 private:
  bool iterative() const override { return true; }
  std::string setup_stage() const override {
    return fmt::format("setting up the multigrid preconditioner (GAMG) for {} dofs", n_);
  }

  // CG updates its residual by recurrence, which drifts from the true one near 1e-10 (2.9M dofs: CG
  // stopped at 1e-10 with true residuals up to 1.6e-9): restart from x while the true residual is
  // above the tolerance and a restart still halves it. Round-off bounds what any restart reaches
  // (~1e-10 on the 41k-dof bar for the moment cases); what was reached is reported.
  PetscErrorCode Refine(KSP ksp, const SolveAgain& again, const KSPConvergedReason& reason,
                        const double& relative) const override {
    PetscCall(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE));
    for (double before = std::numeric_limits<double>::infinity();
         reason > 0 && relative > options_.relative_tolerance && relative < 0.5 * before;) {
      before = relative;
      PetscCall(again());
    }
    return 0;
  }

  Status CheckOptions() const override {
    if (!(options_.relative_tolerance > 0.0 && options_.relative_tolerance < 1.0))
      return Status::Invalid(
          fmt::format("PETSc CG: relative tolerance {:g} must lie in (0, 1)", options_.relative_tolerance));
    if (options_.max_iterations < 1)
      return Status::Invalid(fmt::format("PETSc CG: at most {} iterations; need at least 1", options_.max_iterations));
    return Status::Ok();
  }

  Status PrepareMatrix() override {
    KINESTAT_PETSC(MatSetOption(A_, MAT_SPD, PETSC_TRUE));
    if (!options_.near_null_space) return Status::Ok();
    const MatX modes = options_.near_null_space();
    if (modes.rows() == n_ && modes.cols() > 0) KINESTAT_PETSC(AttachNearNullSpace(modes));
    return Status::Ok();
  }

  Status ConfigureKsp(KSP ksp, PC pc, FactorizationReport* r) override {
    KINESTAT_PETSC(KSPSetType(ksp, KSPCG));
    KINESTAT_PETSC(PCSetType(pc, PCGAMG));
    // The true residual ||b - A x|| / ||b|| is what the tolerance bounds (not the preconditioned one).
    KINESTAT_PETSC(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
    KINESTAT_PETSC(KSPSetTolerances(ksp, options_.relative_tolerance, 0.0, PETSC_DEFAULT, options_.max_iterations));
    r->ordering = "none (algebraic multigrid)";
    return Status::Ok();
  }

  // The rigid-body modes, orthonormalized (MatNullSpaceCreate wants an orthonormal basis), each
  // rank setting its own rows.
  PetscErrorCode AttachNearNullSpace(const MatX& modes) {
    const MatX Q = Eigen::HouseholderQR<MatX>(modes).householderQ() * MatX::Identity(n_, modes.cols());
    std::vector<Vec> vectors(Q.cols(), nullptr);
    const std::vector<PetscInt> rows = owned_rows();
    for (Eigen::Index k = 0; k < Q.cols(); ++k) {
      PetscCall(MatCreateVecs(A_, &vectors[k], nullptr));
      PetscCall(VecSetValues(vectors[k], rend_ - rstart_, rows.data(), Q.col(k).data() + rstart_, INSERT_VALUES));
      PetscCall(VecAssemblyBegin(vectors[k]));
      PetscCall(VecAssemblyEnd(vectors[k]));
    }
    MatNullSpace space;
    PetscCall(
        MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, static_cast<PetscInt>(Q.cols()), vectors.data(), &space));
    PetscCall(MatSetNearNullSpace(A_, space));
    PetscCall(MatNullSpaceDestroy(&space));
    for (Vec& v : vectors) PetscCall(VecDestroy(&v));
    return 0;
  }
};

}  // namespace

Status petsc_available() { return Status::Ok(); }  // in the module, PETSc is here

std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions& options) {
  return std::make_unique<PetscMumpsCholesky>(options);
}

std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions& options) {
  return std::make_unique<PetscCgSolver>(options);
}

std::optional<StatusOr<std::pair<VecX, MatX>>> petsc_generalized_eigenpairs(const SparseMatrix& A,
                                                                            const LinearSolver& solver, int count,
                                                                            const EigenConvergence& convergence) {
  const auto* mumps = dynamic_cast<const PetscMumpsCholesky*>(&solver);
  if (!mumps) return std::nullopt;
  return mumps->LargestGeneralizedEigenpairs(A, count, convergence);
}

}  // namespace kinestat::solver
