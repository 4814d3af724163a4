// Fuzz harness: the surface-mesh readers (OFF, STL, OBJ, PLY through CGAL) and every check of
// fea::mesh_surface_file up to the mesher: the input is written to a file whose extension the first
// byte chooses, and the element limit is 0, so an input that passes every check (a closed solid with a
// positive volume, hence a positive estimate) is refused by the estimate instead of being meshed.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "kinestat/fea/surface_mesher.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* kExtensions[] = {".off", ".stl", ".obj", ".ply"};
  const std::string path = "/tmp/kinestat-fuzz-" + std::to_string(getpid()) + kExtensions[data[0] % 4];
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  kinestat::fea::MeshingOptions options;
  options.max_elements = 0;
  const auto mesh = kinestat::fea::mesh_surface_file(path, options);
  if (mesh.ok() || mesh.status().message().empty()) std::abort();  // nothing is meshed at a limit of 0
  std::remove(path.c_str());
  return 0;
}
