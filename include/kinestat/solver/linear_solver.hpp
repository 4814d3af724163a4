// The linear-solver interface of kinestat, as Ceres Solver's LinearSolver: A X = B for a symmetric
// positive definite sparse A and many right-hand sides. Two kinds sit behind it: a direct sparse
// Cholesky (solver/sparse_cholesky.hpp: CHOLMOD, MUMPS), and CG preconditioned by multigrid (PETSc's
// GAMG). Methods (MSA, FEA) make their solver objects through solver/linear_solver_factory.hpp and
// choose the kind by LinearSolverOptions::backend only: a new backend is an implementation of one
// of these classes and a factory entry, not a change to the methods.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::solver {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class Ordering { kAuto, kAmd, kMetis, kNatural };

// The implementations (solver/linear_solver_factory.hpp makes them): CHOLMOD (shared memory), and
// PETSc over MPI (docs/fea.md, "Large meshes"): MUMPS's distributed Cholesky, or conjugate gradients
// preconditioned by smoothed-aggregation multigrid (GAMG).
enum class Backend { kCholmod, kPetscMumps, kPetscCg };

// What the caller chooses; passed unchanged to every solver object made for that caller (its
// solves, the null-space diagnosis, a regularized solve), only the pivot check varies.
struct LinearSolverOptions {
  Backend backend = Backend::kCholmod;

  // Direct backends (SparseCholesky).
  Ordering ordering = Ordering::kAuto;
  // A column whose Cholesky pivot d_j falls below this fraction of its diagonal entry A_jj has lost
  // all but -log10(ratio) of the ~16 digits of double precision to cancellation: it is (numerically)
  // a linear combination of earlier columns, i.e. a free motion. 1e-12 leaves ~4 digits; a
  // mechanism's null mode gives ~1e-16, and stiff-spring models (joint springs 1e9 times stiffer
  // than the beams) still pass with ~1e-10.
  double singular_pivot_ratio = 1e-12;
  // Memory the numeric factorization may take, bytes; 0: MemAvailable of /proc/meminfo at the time
  // of the symbolic analysis. A factorization estimated above it (FactorizationReport::factor_bytes)
  // is refused after the analysis, before its memory is allocated (kInvalidInput naming both).
  double memory_limit_bytes = 0.0;

  // Iterative backend (kPetscCg): stop when ||b - A x|| <= relative_tolerance ||b|| (true residual)
  // for each right-hand side. The 6x6 of a link is read off the solutions, so its relative error
  // follows the residual's: on meshes/bar.off (5 289 dofs) max |dC_ij| / sqrt(C_ii C_jj) was 0.07-0.2
  // x the tolerance (7e-6 at 1e-4, 1.2e-7 at 1e-6, 1.7e-9 at 1e-8). The bound grows with the
  // condition number (finer meshes), so the default 1e-10 keeps the 6x6 within 1e-6 with four orders
  // of margin, for ~30 % more iterations than 1e-7 (tests/mpi/compare_link_stiffness.py checks 1e-6
  // against CHOLMOD).
  double relative_tolerance = 1e-10;
  int max_iterations = 20000;
  // The rigid-body modes of A's unconstrained structure (n x 6, the columns need not be
  // orthonormal): the near-null space a multigrid preconditioner builds its coarse spaces from.
  // Called only by a solver that uses it (kPetscCg), so the n x 6 numbers are made for it alone.
  std::function<MatX()> near_null_space = nullptr;

  // Told, when set, what the solver is about to do (a factorization's flops and memory once the
  // analysis is done, the multigrid setup, CG's progress): for large models (the caller prints it
  // on stderr).
  std::function<void(const std::string& stage)> progress = nullptr;
};

// What a solve did, per right-hand side (iterative backends; a direct one reports 0 iterations).
struct SolveReport {
  std::vector<int> iterations;            // per column of B
  std::vector<double> relative_residual;  // ||b - A x|| / ||b|| per column (empty: not measured)
  double relative_tolerance = 0.0;        // the stopping tolerance (0: direct solve)
  double seconds = 0.0;
};

// What Factorize did and found (a factorization, or an iterative solver's preconditioner setup);
// printed by the MSA/FEA summaries.
struct FactorizationReport {
  int n = 0;
  long nnz_matrix = 0;           // stored entries of the lower triangle
  long nnz_factor = 0;           // entries of L
  double flops = 0.0;            // floating-point operations of the numeric factorization
  bool reused_symbolic = false;  // the sparsity pattern matched the previous call: no new analysis
  bool supernodal = false;
  std::string ordering;  // "AMD", "METIS", "natural", ...
  double analyze_seconds = 0.0;
  double factor_seconds = 0.0;
  // Memory: the analysis's estimate for the numeric factorization (the factor with its supernodes'
  // padding, the update workspace, the permuted matrix), what was available, and what the backend
  // counted at its peak (0 when it does not count).
  double factor_bytes = 0.0;
  double memory_available_bytes = 0.0;
  double peak_bytes = 0.0;
  bool refused_for_memory() const { return factor_bytes > memory_available_bytes && memory_available_bytes > 0.0; }
  // Pivot check, in the user's (unpermuted) column numbering.
  int failed_column = -1;         // first column whose pivot was not positive (factorization stopped)
  std::vector<int> weak_columns;  // columns with pivot ratio below the tolerance (free motions)
  double min_pivot_ratio = 0.0;   // min over columns of d_j / A_jj
  int min_pivot_column = -1;
  bool singular() const { return failed_column >= 0 || !weak_columns.empty(); }
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;

  // Prepares the solves with the symmetric matrix A (both triangles stored or only the lower one;
  // the upper triangle is ignored): a direct solver factorizes it, an iterative one builds its
  // preconditioner. Returns kSingular (with the report filled) when A has a free motion (a failed or
  // too small pivot, a failed preconditioner); the solver is then unusable for Solve. On several MPI
  // ranks (summing_ranks() > 1) every rank passes the whole A and keeps its own rows.
  virtual Status Factorize(const SparseMatrix& A, FactorizationReport* report) = 0;

  // Distributed assembly (docs/fea.md, "Large meshes"): Factorize for A = the sum of `summands` over
  // all of them and over the summing_ranks() MPI ranks, so that no rank holds A. Each summand is
  // n x n, stored as for Factorize (lower triangle read); a rank passes what it assembled (its
  // elements), which may reach into rows other ranks own (the PETSc backends send those entries to
  // their owners). Collective on those ranks. The default (one process) adds the summands and calls
  // Factorize.
  virtual Status FactorizeSum(std::span<const SparseMatrix> summands, FactorizationReport* report);

  // How many MPI ranks share FactorizeSum's summands: process_group().size for the PETSc backends,
  // 1 for a backend on one process (CHOLMOD), whose summands on each process must add up to all of A.
  virtual int summing_ranks() const { return 1; }

  // Solves A X = B for all columns of B with the last successful Factorize; `report` (may be null)
  // is told the iterations and true residuals per column.
  Status Solve(const MatX& B, MatX* X, SolveReport* report = nullptr) const { return DoSolve(B, X, report); }

  // How many symbolic analyses this object has done (a posture sweep should do one).
  virtual int num_symbolic_analyses() const = 0;

  // Name of the backend and of the BLAS it runs on, for reports and benchmarks.
  virtual std::string backend_description() const = 0;

 private:
  // Solve's work; the report, when given, is set whole (also on failure, as far as it got).
  virtual Status DoSolve(const MatX& B, MatX* X, SolveReport* report) const = 0;
};

}  // namespace kinestat::solver
