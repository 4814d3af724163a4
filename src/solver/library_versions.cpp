#include "kinestat/solver/library_versions.hpp"

#include <cholmod.h>
#include <dlfcn.h>

#include <fstream>
#include <set>

#include <fmt/format.h>

namespace kinestat::solver {
namespace {

// The BLAS library actually mapped into this process (through the libblas.so.3 alternative).
std::string mapped_blas_files() {
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> libs;
  std::string line;
  while (std::getline(maps, line)) {
    const auto pos = line.find('/');
    if (pos == std::string::npos) continue;
    const std::string path = line.substr(pos);
    if (path.substr(path.rfind('/')).find("blas") != std::string::npos) libs.insert(path);  // the file, not its folder
  }
  std::string out;
  for (const auto& l : libs) out += (out.empty() ? "" : ", ") + l;
  return out.empty() ? "no BLAS mapped yet" : out;
}

// Optimized BLAS libraries name their version through a function of their own; the reference BLAS
// has none (then the file name is all there is).
std::string blas_self_description() {
  using Describe = const char* (*)();
  if (auto f = reinterpret_cast<Describe>(dlsym(RTLD_DEFAULT, "openblas_get_config"))) return f();
  if (auto f = reinterpret_cast<Describe>(dlsym(RTLD_DEFAULT, "bli_info_get_version_str")))
    return std::string("BLIS ") + f();
  return {};
}

}  // namespace

LibraryVersions library_versions() {
  int v[3] = {0, 0, 0};
  cholmod_version(v);  // the shared library's version, which may differ from the header's
  const std::string self = blas_self_description();
  const std::string files = mapped_blas_files();
  return {fmt::format("CHOLMOD {}.{}.{} (SuiteSparse)", v[0], v[1], v[2]),
          self.empty() ? files : fmt::format("{} ({})", self, files)};
}

}  // namespace kinestat::solver
