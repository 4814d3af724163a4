// The loader of the PETSc module (solver/petsc_module.hpp), and petsc_solver.hpp's functions, which
// forward to it. Without PETSc (KINESTAT_PETSC_MODULE_BUILD undefined) nothing is loaded.
#include "solver/petsc_module.hpp"

#include <dlfcn.h>
#include <link.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "kinestat/core/version.hpp"
#include "kinestat/solver/library_versions.hpp"

namespace kinestat::solver {
namespace {

std::atomic<const PetscModule*> loaded{nullptr};
std::string loaded_path;  // written once, before `loaded`

#ifdef KINESTAT_PETSC_MODULE_BUILD
// Where to look, in order: $KINESTAT_PETSC_MODULE; the install layout relative to the running program
// (PREFIX/bin/kinestat) and, when this code is in another object, relative to it (the Python module
// in its package folder); the build tree.
std::vector<std::filesystem::path> module_paths() {
  namespace fs = std::filesystem;
  std::vector<fs::path> paths;
  if (const char* env = std::getenv("KINESTAT_PETSC_MODULE"); env && *env) paths.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    paths.push_back(
        (exe.parent_path() / KINESTAT_PETSC_MODULE_FROM_BINDIR / KINESTAT_PETSC_MODULE_NAME).lexically_normal());
  // The shared object holding this code, if it is not the program (whose link map has no name).
  Dl_info info;
  link_map* object = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&load_petsc_module), &info, reinterpret_cast<void**>(&object), RTLD_DL_LINKMAP) !=
          0 &&
      object && object->l_name && *object->l_name)
    paths.push_back(
        (fs::path(object->l_name).parent_path() / KINESTAT_PETSC_MODULE_FROM_PYTHON / KINESTAT_PETSC_MODULE_NAME)
            .lexically_normal());
  paths.emplace_back(KINESTAT_PETSC_MODULE_BUILD);
  return paths;
}

StatusOr<const PetscModule*> open_module() {
  std::string tried;
  for (const std::filesystem::path& path : module_paths()) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      tried += fmt::format("\n  {}: no such file", path.string());
      continue;
    }
    // RTLD_GLOBAL: Open MPI loads plugins of its own that look for its symbols in the global scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
      tried += fmt::format("\n  {}: {}", path.string(), dlerror());
      continue;
    }
    using Entry = const PetscModule* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kPetscModuleEntry));
    const PetscModule* m = entry ? entry() : nullptr;
    if (!m || m->size != sizeof(PetscModule) || std::string(m->version) != kVersion) {
      tried += fmt::format("\n  {}: not the PETSc module of kinestat {}", path.string(), kVersion);
      continue;  // not unloaded: its constructors ran, and unloading MPI is not supported
    }
    loaded_path = path.string();
    loaded.store(m);
    return m;
  }
  return Status::Internal(
      fmt::format("the PETSc backends are built in, but their module {} was not found or does not load; set "
                  "KINESTAT_PETSC_MODULE to its path, or reinstall kinestat. Tried:{}",
                  KINESTAT_PETSC_MODULE_NAME, tried));
}
#else
StatusOr<const PetscModule*> open_module() {
  return Status::Invalid(
      "PETSc was not found when this kinestat was configured; install libpetsc-real-dev and slepc-dev "
      "(scripts/install-deps.sh --petsc) and rebuild");
}
#endif

}  // namespace

StatusOr<const PetscModule*> load_petsc_module() {
  static const StatusOr<const PetscModule*> module = open_module();  // once, thread-safe
  return module;
}

const PetscModule* loaded_petsc_module() { return loaded.load(); }

// library_versions.hpp's, here so that library_versions.cpp (which the module's copy of the CHOLMOD
// backend needs) does not bring this loader into the module.
std::string petsc_versions() {
  const StatusOr<const PetscModule*> m = load_petsc_module();
  if (m.ok()) return fmt::format("{} (module {})", (*m)->libraries, loaded_path);
  if (m.status().code() == StatusCode::kInvalidInput) return "not built in";
  return m.status().message();
}

Status petsc_available() { return load_petsc_module().status(); }

std::unique_ptr<SparseCholesky> make_petsc_mumps(const LinearSolverOptions& options) {
  const StatusOr<const PetscModule*> m = load_petsc_module();
  return m.ok() ? (*m)->make_petsc_mumps(options) : nullptr;
}

std::unique_ptr<LinearSolver> make_petsc_cg(const LinearSolverOptions& options) {
  const StatusOr<const PetscModule*> m = load_petsc_module();
  return m.ok() ? (*m)->make_petsc_cg(options) : nullptr;
}

std::optional<StatusOr<std::pair<VecX, MatX>>> petsc_generalized_eigenpairs(const SparseMatrix& A,
                                                                            const LinearSolver& solver, int count,
                                                                            const EigenConvergence& convergence) {
  // A PETSc solver exists only once the module is loaded.
  const PetscModule* m = loaded_petsc_module();
  if (!m) return std::nullopt;
  return m->generalized_eigenpairs(A, solver, count, convergence);
}

}  // namespace kinestat::solver
