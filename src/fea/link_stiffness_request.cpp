#include "kinestat/fea/link_stiffness_request.hpp"

#include <fmt/format.h>

#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/result_cache.hpp"

namespace kinestat::fea {
namespace {

MeshingOptions meshing_options(const LinkStiffnessRequest& r, double size) {
  MeshingOptions m;
  m.unit_scale = r.unit_scale;
  m.quadratic = r.quadratic;
  m.size = size;
  m.max_elements = r.max_elements;
  return m;
}

}  // namespace

StatusOr<LinkStiffnessRun> compute_link_stiffness(const LinkStiffnessRequest& request) {
  LinkStiffnessRun run;
  StatusOr<SurfaceInfo> surface = check_surface_file(request.mesh_file);
  if (!surface.ok()) return surface.status();
  run.surface = *surface;
  run.mesh_size = request.mesh_size > 0.0 ? request.mesh_size : default_mesh_size(*surface, request.unit_scale);
  const MeshingOptions meshing = meshing_options(request, run.mesh_size);
  const std::string header =
      fmt::format("{}: {} triangles, meshed with size {:g} m; material {} (E = {:g} Pa, nu = {:g})\n", request.mesh_file,
                  surface->triangles, run.mesh_size, request.material.id, request.material.E, request.material.nu());

  std::string key;
  if (!request.cache_dir.empty()) {
    StatusOr<std::string> identity = surface_mesh_identity(request.mesh_file, meshing);
    if (!identity.ok()) return identity.status();
    key = link_stiffness_cache_key(*identity, request.material, request.options);
    run.cache_file = link_stiffness_cache_path(request.cache_dir, key);
    if (!request.options.keep_fields) {
      if (std::optional<LinkStiffness> cached = load_cached_link_stiffness(request.cache_dir, key)) {
        run.result = std::move(*cached);
        run.from_cache = true;
        run.report = fmt::format("(from cache {})\n", run.cache_file) + link_stiffness_report(run.result);
        return run;
      }
    }
  }
  if (request.options.progress)
    request.options.progress(fmt::format("meshing {} with size {:g} m", request.mesh_file, run.mesh_size));
  StatusOr<TetMesh> mesh = mesh_surface_file(request.mesh_file, meshing);
  if (!mesh.ok()) return mesh.status();
  StatusOr<LinkStiffness> result = link_stiffness(*mesh, request.material, request.options);
  if (!result.ok()) return Status(result.status().code(), request.mesh_file + ": " + result.status().message());
  run.result = std::move(*result);
  if (!key.empty())
    if (Status s = store_cached_link_stiffness(request.cache_dir, key, run.result); !s.ok()) return s;
  if (request.options.keep_fields) run.mesh = std::move(*mesh);
  run.report = header + link_stiffness_report(run.result);
  return run;
}

StatusOr<ConvergenceStudy> link_stiffness_convergence(const LinkStiffnessRequest& request,
                                                      const std::vector<double>& sizes) {
  auto make = [&](double h) { return mesh_surface_file(request.mesh_file, meshing_options(request, h)); };
  return mesh_convergence_study(make, sizes, request.material, request.options);
}

}  // namespace kinestat::fea
