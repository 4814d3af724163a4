// The PETSc backends (docs/fea.md, "Large meshes"): MUMPS's Cholesky (a SparseCholesky) and CG +
// GAMG (an iterative LinearSolver), each a KSP over the same distributed matrix. Factorize takes the
// whole matrix on every rank and gives PETSc only this rank's block of rows; FactorizeSum takes each
// rank's summand (the elements it assembled) and lets PETSc add them, sending entries of other
// ranks' rows to their owners, so that no rank holds the whole matrix. PETSc distributes the factor
// (MUMPS) or the multigrid hierarchy (GAMG); the solution is gathered back to every rank, so every
// rank computes the same 6x6. Compiled without PETSc (KINESTAT_HAVE_PETSC unset) petsc_built() is
// false and the factory makes neither.
#include "solver/petsc_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/parallel.hpp"

#if KINESTAT_HAVE_PETSC
#include <petscksp.h>
#include <Eigen/QR>
#endif

namespace kinestat::solver {

#if KINESTAT_HAVE_PETSC

namespace {

// PETSc calls return an error code; it becomes a Status (kInternal) naming the call and PETSc's text.
Status petsc_error(PetscErrorCode code, const char* call) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  return Status::Internal(fmt::format("PETSc: {} failed: {}", call, text ? text : "unknown error"));
}
#define KINESTAT_PETSC(call)                                                         \
  do {                                                                               \
    if (PetscErrorCode code_ = (call); code_ != 0) return petsc_error(code_, #call); \
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
        KINESTAT_PETSC(VecScatterBegin(gather, x, all, INSERT_VALUES, SCATTER_FORWARD));
        KINESTAT_PETSC(VecScatterEnd(gather, x, all, INSERT_VALUES, SCATTER_FORWARD));
        const PetscScalar* values = nullptr;
        KINESTAT_PETSC(VecGetArrayRead(all, &values));
        X->col(k) = Eigen::Map<const VecX>(values, n_);
        KINESTAT_PETSC(VecRestoreArrayRead(all, &values));
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
    Status s = FactorizeImpl(parts, summed, &r);
    if (!s.ok()) Release();  // no Solve with a half-made or singular factor
    if (report) *report = r;
    return s;
  }

  // Makes A_ from `parts`: with `summed`, A = the sum of every rank's parts (each rank inserts all
  // its entries, PETSc's stash moves those of other ranks' rows during the assembly); without, every
  // rank holds the whole A in parts[0] and inserts only its own rows.
  Status AssembleMatrix(std::span<const SparseMatrix> parts, bool summed, FactorizationReport* r) {
    if (parts.empty()) return Status::Invalid("PETSc solver: no matrix given");
    n_ = static_cast<int>(parts[0].rows());
    for (const SparseMatrix& p : parts)
      if (p.rows() != n_ || p.cols() != n_)
        return Status::Invalid(fmt::format("PETSc solver: a {} x {} matrix where a square one of {} rows is wanted",
                                           p.rows(), p.cols(), n_));
    // Every rank must bring the same n (a collective call with different sizes would not return).
    int n_min = n_, n_max = n_;
    MPI_Allreduce(&n_, &n_min, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
    MPI_Allreduce(&n_, &n_max, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
    if (n_min != n_max)
      return Status::Internal(fmt::format("PETSc solver: the ranks hold matrices of {} to {} rows", n_min, n_max));
    r->n = n_;
    StatusOr<std::vector<int>> offsets = split_rows(n_);
    if (!offsets.ok()) return offsets.status();
    const int rank = process_group().rank;
    rstart_ = (*offsets)[rank];
    rend_ = (*offsets)[rank + 1];
    const PetscInt local = rend_ - rstart_;
    auto take = [&](PetscInt row) { return summed || (row >= rstart_ && row < rend_); };

    // PETSc wants both triangles of its rows. The lower triangle (column-major) holds row c's upper
    // part in column c, and rows r > c's lower parts in the same column: each column is inserted as
    // one column of rows r >= c and one row c, without a second (full) copy of the matrix.
    auto for_each_column = [&](auto&& visit) -> Status {
      std::vector<PetscInt> lower_rows, upper_cols;
      std::vector<PetscScalar> lower_values, upper_values;
      for (const SparseMatrix& part : parts)
        for (PetscInt c = 0; c < n_; ++c) {
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
    std::vector<PetscInt> diagonal(n_, 0), off(n_, 0);
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
      off_nnz[i] = std::min(off_nnz[i], static_cast<PetscInt>(n_) - local);
    }
    KINESTAT_PETSC(MatCreate(PETSC_COMM_WORLD, &A_));
    KINESTAT_PETSC(MatSetSizes(A_, local, local, n_, n_));
    KINESTAT_PETSC(MatSetType(A_, MATAIJ));
    KINESTAT_PETSC(MatSetBlockSize(A_, block_size(n_)));
    KINESTAT_PETSC(MatSeqAIJSetPreallocation(A_, 0, diagonal_nnz.data()));
    KINESTAT_PETSC(MatMPIAIJSetPreallocation(A_, 0, diagonal_nnz.data(), 0, off_nnz.data()));
    Status inserted = for_each_column([&](PetscInt c, const auto& lower_rows, const auto& lower_values,
                                          const auto& upper_cols, const auto& upper_values) -> Status {
      if (!lower_rows.empty())  // rows r >= c, column c
        KINESTAT_PETSC(MatSetValues(A_, static_cast<PetscInt>(lower_rows.size()), lower_rows.data(), 1, &c,
                                    lower_values.data(), ADD_VALUES));
      if (!upper_cols.empty())  // row c, columns r > c
        KINESTAT_PETSC(MatSetValues(A_, 1, &c, static_cast<PetscInt>(upper_cols.size()), upper_cols.data(),
                                    upper_values.data(), ADD_VALUES));
      return Status::Ok();
    });
    if (!inserted.ok()) return inserted;
    KINESTAT_PETSC(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
    KINESTAT_PETSC(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
    // Stored entries of the lower triangle of the assembled A, over all ranks.
    long lower = 0;
    for (PetscInt row = rstart_; row < rend_; ++row) {
      PetscInt ncols = 0;
      const PetscInt* cols = nullptr;
      KINESTAT_PETSC(MatGetRow(A_, row, &ncols, &cols, nullptr));
      lower += std::count_if(cols, cols + ncols, [&](PetscInt col) { return col <= row; });
      KINESTAT_PETSC(MatRestoreRow(A_, row, &ncols, &cols, nullptr));
    }
    MPI_Allreduce(&lower, &r->nnz_matrix, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
    return Status::Ok();
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

  KSP ksp_ = nullptr;
  int analyses_ = 0;
};

// MUMPS's Cholesky (KSPPREONLY + PCCHOLESKY): a direct factorization distributed over the ranks.
class PetscMumpsCholesky final : public PetscKspSolver<SparseCholesky> {
 public:
  using PetscKspSolver<SparseCholesky>::PetscKspSolver;

  std::string backend_description() const override {
    return fmt::format("{} MUMPS Cholesky on {}", petsc_version(), ranks_description());
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

bool petsc_built() { return true; }

std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions& options) {
  return std::make_unique<PetscMumpsCholesky>(options);
}

std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions& options) {
  return std::make_unique<PetscCgSolver>(options);
}

#else  // PETSc not built in

bool petsc_built() { return false; }

std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions&) { return nullptr; }
std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions&) { return nullptr; }

#endif

}  // namespace kinestat::solver
