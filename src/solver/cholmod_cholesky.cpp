// CHOLMOD backend of SparseCholesky. Internal: cholmod.h is seen by this file and library_versions.cpp only.
#include "solver/cholmod_cholesky.hpp"

#include <cholmod.h>
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "kinestat/core/huge_page_allocator.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/solver/library_versions.hpp"
#include "solver/available_memory.hpp"

namespace kinestat::solver {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

const char* ordering_name(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_GIVEN:
      return "given";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    case CHOLMOD_POSTORDERED:
      return "postordered";
    default:
      return "unknown";
  }
}

// CHOLMOD's allocations (the factor L, its update workspace) through allocate_large: L's hundreds of
// MB are touched first inside the numeric factorization, one 2 MB page fault instead of 512 small
// ones. Process-wide (SuiteSparse_config is one global), set once before the first CHOLMOD call.
void* cholmod_calloc(std::size_t count, std::size_t size) {
  if (size != 0 && count > static_cast<std::size_t>(-1) / size) return nullptr;
  void* p = allocate_large(count * size);
  if (p) std::memset(p, 0, count * size);
  return p;
}

void use_huge_pages_for_cholmod() {
  static std::once_flag once;
  std::call_once(once, [] {
    SuiteSparse_config.malloc_func = allocate_large;
    SuiteSparse_config.calloc_func = cholmod_calloc;
    SuiteSparse_config.realloc_func = std::realloc;
    SuiteSparse_config.free_func = std::free;
  });
}

// The process's thread decision for a factorization: the BLAS (OpenBLAS, its own pthreads) uses the
// cores; CHOLMOD's OpenMP loops run on the calling thread only. Debian's CHOLMOD 3.0.14 scatters each
// supernode's update in `omp parallel` regions with a fixed team of 4, whatever OMP_NUM_THREADS says:
// on 2 cores the ~90 000 regions of an 88k-dof factorization cost 90 000 futex sleeps and ~2 s of
// system time, and the team's spinning threads take the cores from OpenBLAS's (benchmarks/README.md,
// "Factorization rate"). max-active-levels 0 makes every parallel region inactive (a team of one).
// kinestat itself uses TBB, not OpenMP, but a program around it (the Python module's users) may:
// the previous value comes back when the last concurrent factorization ends (GCC 12's libgomp keeps
// the value process-wide, hence the count; it is set on every entry for runtimes that keep it per
// thread). The runtime is the one CHOLMOD loaded, found at run time; without one, nothing to do.
class SerialOpenMpRegions {
 public:
  SerialOpenMpRegions() {
    const Runtime& rt = runtime();
    if (!rt.set) return;
    std::lock_guard lock(mutex());
    if (depth()++ == 0) saved() = rt.get();
    rt.set(0);
  }
  ~SerialOpenMpRegions() {
    const Runtime& rt = runtime();
    if (!rt.set) return;
    std::lock_guard lock(mutex());
    if (--depth() == 0) rt.set(saved());
  }
  SerialOpenMpRegions(const SerialOpenMpRegions&) = delete;
  SerialOpenMpRegions& operator=(const SerialOpenMpRegions&) = delete;

 private:
  struct Runtime {
    int (*get)() = nullptr;
    void (*set)(int) = nullptr;
  };
  static const Runtime& runtime() {
    static const Runtime r = [] {
      auto* get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
      auto* set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
      return get && set ? Runtime{get, set} : Runtime{};
    }();
    return r;
  }
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& depth() {
    static int d = 0;
    return d;
  }
  static int& saved() {
    static int v = 0;
    return v;
  }
};

// Bytes the numeric factorization of `A` (lower triangle, nnz_lower entries) will hold at its
// peak, from the symbolic factor L: a supernodal L stores xsize values (nnz(L) plus the zeros of
// relaxed amalgamation) and ssize row indices, and the factorization adds the largest supernode
// update (maxcsize values); a simplicial L one value and one index per entry of L. Both add CHOLMOD's
// permuted copy of A (value + index per entry) and O(n) workspace.
double numeric_factorization_bytes(const cholmod_factor& L, const cholmod_common& c, double nnz_lower) {
  constexpr double kValue = sizeof(double), kIndex = sizeof(int);
  const double n = static_cast<double>(L.n);
  const double factor = L.is_super ? kValue * static_cast<double>(L.xsize + L.maxcsize) +
                                         kIndex * static_cast<double>(L.ssize + 4 * L.nsuper)
                                   : (kValue + kIndex) * c.lnz + 2 * kIndex * n;
  return factor + (kValue + kIndex) * nnz_lower + 16 * kValue * n;
}

// A fill-reducing ordering from METIS on the graph of column groups: consecutive columns with the
// same pattern in A + A' (a mesh node's 3 dofs, a frame node's 6) are one vertex, and the groups'
// order is expanded back to columns. METIS on the scalar graph took 0.75 s of the 0.9 s analysis at
// 88k dofs (benchmarks/README.md, "Factorization rate"); the node graph has ~9 times fewer edges.
// Empty when no two columns group (nothing to gain) or on failure: CHOLMOD then orders alone.
std::vector<int> grouped_metis_ordering(cholmod_sparse* lower, cholmod_common* c) {
  cholmod_sparse* full = cholmod_copy(lower, 0, 0, c);  // both triangles, pattern, with the diagonal
  if (!full) return {};
  if (!full->sorted) cholmod_sort(full, c);
  const int n = static_cast<int>(full->ncol);
  const int* p = static_cast<const int*>(full->p);
  const int* i = static_cast<const int*>(full->i);
  std::vector<int> group_start = {0};
  for (int j = 1; j < n; ++j)
    if (!std::equal(i + p[j - 1], i + p[j], i + p[j], i + p[j + 1])) group_start.push_back(j);
  const int groups = static_cast<int>(group_start.size());
  group_start.push_back(n);
  std::vector<int> perm;
  if (groups < n) {
    std::vector<int> group_of(n);
    for (int g = 0; g < groups; ++g)
      std::fill(group_of.begin() + group_start[g], group_of.begin() + group_start[g + 1], g);
    // The groups' graph, lower triangle: the rows of each group's first column, as groups (ascending).
    cholmod_sparse* G = cholmod_allocate_sparse(groups, groups, p[n], 1, 1, -1, CHOLMOD_PATTERN, c);
    if (G) {
      int* gp = static_cast<int*>(G->p);
      int* gi = static_cast<int*>(G->i);
      int nz = 0;
      for (int g = 0; g < groups; ++g) {
        gp[g] = nz;
        const int j = group_start[g];
        for (int k = p[j]; k < p[j + 1]; ++k)
          if (const int h = group_of[i[k]]; h >= g && (nz == gp[g] || gi[nz - 1] != h)) gi[nz++] = h;
      }
      gp[groups] = nz;
      std::vector<int> group_perm(groups);
      if (cholmod_metis(G, nullptr, 0, 0, group_perm.data(), c)) {
        perm.reserve(n);
        for (int g : group_perm)
          for (int j = group_start[g]; j < group_start[g + 1]; ++j) perm.push_back(j);
      }
      cholmod_free_sparse(&G, c);
    }
  }
  cholmod_free_sparse(&full, c);
  return perm;
}

class CholmodCholesky final : public SparseCholesky {
 public:
  explicit CholmodCholesky(const LinearSolverOptions& options) : options_(options) {
    use_huge_pages_for_cholmod();
    cholmod_start(&common_);
    common_.print = 0;  // failures are reported through FactorizationReport
    common_.error_handler = nullptr;
    switch (options_.ordering) {
      case Ordering::kAuto:
        break;  // METIS on the column groups and AMD, the better one (Factorize)
      case Ordering::kAmd:
        set_single_ordering(CHOLMOD_AMD);
        break;
      case Ordering::kMetis:
        set_single_ordering(CHOLMOD_METIS);
        break;
      case Ordering::kNatural:
        set_single_ordering(CHOLMOD_NATURAL);
        break;
    }
  }
  ~CholmodCholesky() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodCholesky(const CholmodCholesky&) = delete;
  CholmodCholesky& operator=(const CholmodCholesky&) = delete;

  Status Factorize(const SparseMatrix& A, FactorizationReport* report) override {
    FactorizationReport local;
    FactorizationReport& r = report ? *report : local;
    r = FactorizationReport{};
    factor_ok_ = false;
    if (A.rows() != A.cols()) return Status::Internal("sparse Cholesky: matrix is not square");
    // The lower triangle CHOLMOD reads: A itself when it stores nothing else (the FEA and MSA
    // assemblies keep the lower triangle only), else a copy; at 1M dofs the copy would be ~0.5 GB.
    const bool lower_only = is_compressed_sorted_lower(A);
    SparseMatrix copy;
    if (!lower_only) {
      copy = A.triangularView<Eigen::Lower>();
      copy.makeCompressed();
    }
    const SparseMatrix& lower = lower_only ? A : copy;
    const int n = static_cast<int>(lower.rows());
    r.n = n;
    r.nnz_matrix = lower.nonZeros();
    cholmod_sparse M = view(lower);

    const auto t0 = std::chrono::steady_clock::now();
    const bool same_pattern = factor_ != nullptr && lower.rows() == static_cast<long>(pattern_outer_.size()) - 1 &&
                              std::equal(pattern_outer_.begin(), pattern_outer_.end(), lower.outerIndexPtr()) &&
                              static_cast<long>(pattern_inner_.size()) == lower.nonZeros() &&
                              std::equal(pattern_inner_.begin(), pattern_inner_.end(), lower.innerIndexPtr());
    if (!same_pattern) {
      if (factor_) cholmod_free_factor(&factor_, &common_);
      // METIS (alone, or after AMD in the automatic choice) runs on the column groups' graph; CHOLMOD
      // keeps the better of that and AMD (its default suite: the given order, then AMD).
      const bool metis = options_.ordering == Ordering::kAuto || options_.ordering == Ordering::kMetis;
      const std::vector<int> perm = metis ? grouped_metis_ordering(&M, &common_) : std::vector<int>{};
      if (!perm.empty()) {
        const int nmethods = common_.nmethods, first = common_.method[0].ordering;
        common_.nmethods = options_.ordering == Ordering::kAuto ? 2 : 1;
        common_.method[0].ordering = CHOLMOD_GIVEN;
        factor_ = cholmod_analyze_p(&M, const_cast<int*>(perm.data()), nullptr, 0, &common_);
        common_.nmethods = nmethods;
        common_.method[0].ordering = first;
      } else {
        factor_ = cholmod_analyze(&M, &common_);
      }
      if (common_.status == CHOLMOD_TOO_LARGE)  // e.g. 2.9M dofs of a 10-node tetrahedral mesh
        return Status::Invalid(fmt::format(
            "sparse Cholesky of {} unknowns: the factor would have more than 2^31 entries, beyond CHOLMOD's 32-bit "
            "indices (at least 26 GB); make the model smaller or use the iterative or distributed backend (--solver "
            "petsc-cg or petsc-mumps, docs/fea.md \"Large meshes\")",
            n));
      if (!factor_ || common_.status < CHOLMOD_OK)
        return Status::Internal(fmt::format("CHOLMOD analysis failed (status {})", common_.status));
      ++analyses_;
      pattern_outer_.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + n + 1);
      pattern_inner_.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
      last_flops_ = common_.fl;
      last_lnz_ = common_.lnz;
      const int selected = common_.method[common_.selected].ordering;
      last_ordering_ = selected == CHOLMOD_GIVEN ? "METIS (node graph)" : ordering_name(selected);
      last_bytes_ = numeric_factorization_bytes(*factor_, common_, static_cast<double>(lower.nonZeros()));
      last_available_ = options_.memory_limit_bytes > 0.0 ? options_.memory_limit_bytes : available_memory_bytes();
    }
    r.reused_symbolic = same_pattern;
    r.analyze_seconds = same_pattern ? 0.0 : seconds_since(t0);
    r.flops = last_flops_;
    r.nnz_factor = static_cast<long>(last_lnz_);
    r.ordering = last_ordering_;
    r.factor_bytes = last_bytes_;
    r.memory_available_bytes = last_available_;
    // Refused before cholmod_factorize allocates the factor; the symbolic factor is kept (a retry with
    // the same pattern does not redo the analysis).
    if (r.refused_for_memory())
      return check_size(r.factor_bytes * 1e-9, r.memory_available_bytes * 1e-9,
                        fmt::format("sparse Cholesky of {} unknowns (nnz(L) = {:.3g}): memory", n, last_lnz_),
                        "GB (the memory available)",
                        "make the model smaller or use the distributed backend (--solver petsc)");
    if (options_.progress)
      options_.progress(fmt::format("factorizing: {:.3g} Gflop, {:.3g} GB of {:.3g} GB available", r.flops * 1e-9,
                                    r.factor_bytes * 1e-9, r.memory_available_bytes * 1e-9));

    const auto t1 = std::chrono::steady_clock::now();
    {
      SerialOpenMpRegions serial;
      cholmod_factorize(&M, factor_, &common_);
    }
    r.factor_seconds = seconds_since(t1);
    r.peak_bytes = static_cast<double>(common_.memory_usage);
    r.supernodal = factor_->is_super != 0;
    if (common_.status < CHOLMOD_OK)
      return Status::Internal(fmt::format("CHOLMOD factorization failed (status {}, out of memory?)", common_.status));

    const int computed = (common_.status == CHOLMOD_NOT_POSDEF) ? static_cast<int>(factor_->minor) : n;
    const int* perm = static_cast<const int*>(factor_->Perm);
    if (computed < n) r.failed_column = perm ? perm[computed] : computed;
    check_pivots(lower, computed, r);
    if (r.singular()) {
      return Status::Singular(r.failed_column >= 0 ? fmt::format("pivot of column {} is not positive", r.failed_column)
                                                   : fmt::format("{} column(s) with pivot ratio below {:g}",
                                                                 r.weak_columns.size(), options_.singular_pivot_ratio));
    }
    factor_ok_ = true;
    return Status::Ok();
  }

  int num_symbolic_analyses() const override { return analyses_; }

  std::string backend_description() const override {
    const LibraryVersions v = library_versions();
    return fmt::format("{}, BLAS: {}", v.cholmod, v.blas);
  }

 private:
  // Exact to round-off: no iterations, no residual measured.
  Status DoSolve(const MatX& B, MatX* X, SolveReport* report) const override {
    if (report) {
      *report = SolveReport{};
      report->iterations.assign(B.cols(), 0);
    }
    if (!factor_ok_) return Status::Internal("sparse Cholesky: no valid factorization to solve with");
    if (B.rows() != static_cast<long>(factor_->n)) return Status::Internal("sparse Cholesky: right-hand side size");
    MatX Bc = B;  // CHOLMOD wants a mutable pointer; it does not write to B
    cholmod_dense Bd{};
    Bd.nrow = Bc.rows();
    Bd.ncol = Bc.cols();
    Bd.nzmax = Bc.size();
    Bd.d = Bc.rows();
    Bd.x = Bc.data();
    Bd.xtype = CHOLMOD_REAL;
    Bd.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* Xd = cholmod_solve(CHOLMOD_A, factor_, &Bd, &common_);
    if (!Xd) return Status::Internal("CHOLMOD solve failed");
    *X = Eigen::Map<const MatX>(static_cast<const double*>(Xd->x), Bc.rows(), Bc.cols());
    cholmod_free_dense(&Xd, &common_);
    return Status::Ok();
  }

  void set_single_ordering(int ordering) {
    common_.nmethods = 1;
    common_.method[0].ordering = ordering;
    common_.postorder = 1;
  }

  // Every column's row indices strictly increasing and on or below the diagonal.
  static bool is_compressed_sorted_lower(const SparseMatrix& A) {
    if (!A.isCompressed()) return false;
    const int* p = A.outerIndexPtr();
    const int* i = A.innerIndexPtr();
    for (int j = 0; j < A.outerSize(); ++j)
      for (int k = p[j]; k < p[j + 1]; ++k)
        if (i[k] < j || (k > p[j] && i[k] <= i[k - 1])) return false;
    return true;
  }

  // CHOLMOD's analysis and factorization read the matrix only (cholmod_sparse has no const view).
  static cholmod_sparse view(const SparseMatrix& S) {
    cholmod_sparse M{};
    M.nrow = S.rows();
    M.ncol = S.cols();
    M.nzmax = S.nonZeros();
    M.p = const_cast<int*>(S.outerIndexPtr());
    M.i = const_cast<int*>(S.innerIndexPtr());
    M.x = const_cast<double*>(S.valuePtr());
    M.stype = -1;  // symmetric, lower triangle stored
    M.itype = CHOLMOD_INT;
    M.xtype = CHOLMOD_REAL;
    M.dtype = CHOLMOD_DOUBLE;
    M.sorted = 1;
    M.packed = 1;
    return M;
  }

  // Pivot d_j of each computed column (diag(L)^2 for LL', D for LDL'), against A_jj.
  void check_pivots(const SparseMatrix& lower, int computed, FactorizationReport& r) const {
    const int n = static_cast<int>(factor_->n);
    std::vector<double> pivot(n, 0.0);
    const double* x = static_cast<const double*>(factor_->x);
    if (factor_->is_super) {
      const int* super = static_cast<const int*>(factor_->super);
      const int* pi = static_cast<const int*>(factor_->pi);
      const int* px = static_cast<const int*>(factor_->px);
      for (size_t s = 0; s < factor_->nsuper; ++s) {
        const int nsrow = pi[s + 1] - pi[s];
        for (int j = super[s]; j < super[s + 1]; ++j) {
          const double l = x[px[s] + (j - super[s]) * nsrow + (j - super[s])];
          pivot[j] = l * l;
        }
      }
    } else {
      const int* p = static_cast<const int*>(factor_->p);
      for (int j = 0; j < n; ++j) {
        const double l = x[p[j]];
        pivot[j] = factor_->is_ll ? l * l : l;
      }
    }
    const int* perm = static_cast<const int*>(factor_->Perm);
    r.min_pivot_ratio = std::numeric_limits<double>::infinity();
    for (int j = 0; j < computed; ++j) {
      const int col = perm ? perm[j] : j;
      const double ajj = lower.coeff(col, col);
      const double ratio = ajj > 0 ? pivot[j] / ajj : 0.0;
      if (ratio < r.min_pivot_ratio) {
        r.min_pivot_ratio = ratio;
        r.min_pivot_column = col;
      }
      if (ratio < options_.singular_pivot_ratio) r.weak_columns.push_back(col);
    }
    if (computed < n) {
      r.min_pivot_ratio = 0.0;
      r.min_pivot_column = r.failed_column;
    }
  }

  LinearSolverOptions options_;
  mutable cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  std::vector<int> pattern_outer_, pattern_inner_;
  double last_flops_ = 0.0, last_lnz_ = 0.0, last_bytes_ = 0.0, last_available_ = 0.0;
  std::string last_ordering_;
  int analyses_ = 0;
  bool factor_ok_ = false;
};

}  // namespace

std::unique_ptr<SparseCholesky> make_cholmod_cholesky(const LinearSolverOptions& options) {
  return std::make_unique<CholmodCholesky>(options);
}

}  // namespace kinestat::solver
