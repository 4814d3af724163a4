#include "kinestat/fea/link_stiffness_request.hpp"

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/result_cache.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/parallel.hpp"

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

// What rank 0 alone computes, shared with the other MPI ranks (one process: computed here). The
// surface is read and checked, and the volume mesh made, once: CGAL's meshing is not bit-repeatable
// at some sizes, so ranks meshing on their own could solve different meshes. Rank 0's failure
// becomes every rank's (solver::agree_on_status) before anything is sent.
StatusOr<SurfaceInfo> surface_from_rank0(const std::string& file) {
  const bool root = solver::process_group().rank == 0;
  StatusOr<SurfaceInfo> surface = root ? check_surface_file(file) : StatusOr<SurfaceInfo>(SurfaceInfo{});
  if (Status s = solver::agree_on_status(surface.status()); !s.ok()) return s;
  SurfaceInfo& info = *surface;
  std::vector<double> values = {static_cast<double>(info.triangles),
                                info.lo.x(),
                                info.lo.y(),
                                info.lo.z(),
                                info.hi.x(),
                                info.hi.y(),
                                info.hi.z(),
                                info.volume,
                                info.area};
  if (Status s = solver::broadcast_from_root(values); !s.ok()) return s;
  info = {static_cast<int>(values[0]), Vec3(values[1], values[2], values[3]), Vec3(values[4], values[5], values[6]),
          values[7], values[8]};
  return surface;
}

// The mesh goes as its node coordinates and connectivity: 24 bytes per node and 4 per element node,
// ~18 bytes per dof for 10-node tetrahedra, about 2 % of the ~1 KB per dof of the stiffness matrix
// PETSc stores (both triangles, ~80 entries per row); its element ranges are then assembled apart.
StatusOr<TetMesh> mesh_from_rank0(const std::string& file, const MeshingOptions& meshing) {
  const solver::ProcessGroup group = solver::process_group();
  StatusOr<TetMesh> mesh = group.rank == 0 ? mesh_surface_file(file, meshing) : StatusOr<TetMesh>(TetMesh{});
  if (Status s = solver::agree_on_status(mesh.status()); !s.ok()) return s;
  if (group.size == 1) return mesh;
  TetMesh& m = *mesh;
  std::vector<double> xyz;
  xyz.reserve(3 * m.nodes.size());
  for (const Vec3& x : m.nodes) xyz.insert(xyz.end(), x.data(), x.data() + 3);
  std::vector<int> nodes_per_element = {m.nodes_per_element};
  if (Status s = solver::broadcast_from_root(xyz); !s.ok()) return s;
  if (Status s = solver::broadcast_from_root(m.connectivity); !s.ok()) return s;
  if (Status s = solver::broadcast_from_root(nodes_per_element); !s.ok()) return s;
  m.nodes_per_element = nodes_per_element[0];
  if (group.rank != 0) {
    m.nodes.resize(xyz.size() / 3);
    for (size_t n = 0; n < m.nodes.size(); ++n) m.nodes[n] = Vec3(xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]);
  }
  return mesh;
}

}  // namespace

Status validate(const LinkStiffnessRequest& request) {
  if (Status s = check_quantity(request.unit_scale, Quantity::kLength, "unit_scale", {}, Sign::kPositive); !s.ok())
    return s;
  // 0 asks for the default size; NaN used to pass as "not > 0" and silently meant the default.
  if (request.mesh_size != 0.0)
    if (Status s = check_quantity(request.mesh_size, Quantity::kLength, "mesh_size", {}, Sign::kPositive); !s.ok())
      return s;
  return check_quantity(request.max_elements, Quantity::kRatio, "max_elements", {}, Sign::kPositive);
}

StatusOr<LinkStiffnessRun> compute_link_stiffness(const LinkStiffnessRequest& request) {
  if (Status s = validate(request); !s.ok()) return s;
  LinkStiffnessRun run;
  StatusOr<SurfaceInfo> surface = surface_from_rank0(request.mesh_file);
  if (!surface.ok()) return surface.status();
  run.surface = *surface;
  run.mesh_size = request.mesh_size > 0.0 ? request.mesh_size : default_mesh_size(*surface, request.unit_scale);
  const MeshingOptions meshing = meshing_options(request, run.mesh_size);
  const std::string header = fmt::format(
      "{}: {} triangles, meshed with size {:g} m; material {} (E = {:g} Pa, nu = {:g})\n", request.mesh_file,
      surface->triangles, run.mesh_size, request.material.id, request.material.E, request.material.nu());

  std::string key;
  if (!request.cache_dir.empty()) {
    // Every rank reads the file for the key: one that cannot stops them all (node-local files).
    StatusOr<std::string> identity = surface_mesh_identity(request.mesh_file, meshing);
    if (Status s = solver::agree_on_status(identity.status()); !s.ok()) return s;
    key = link_stiffness_cache_key(*identity, request.material, request.options);
    run.cache_file = link_stiffness_cache_path(request.cache_dir, key);
    // The cache holds the 6x6 only: fields and modes are always computed (and the 6x6 stored).
    if (!request.options.keep_fields && request.options.modes == 0) {
      StatusOr<CachedLinkStiffness> cached = load_cached_link_stiffness(request.cache_dir, key);
      if (Status s = solver::agree_on_status(cached.status()); !s.ok()) return s;
      // Node-local caches may hold the entry on some ranks only: serve it when every rank can, or
      // the ranks that compute would wait in the solver for those that did not.
      // (Collective: every rank asks, whatever it found.)
      const bool everywhere =
          solver::agree_on_status(cached->result ? Status::Ok() : Status::NotConverged("not in this cache")).ok();
      if (cached->result && everywhere) {
        run.result = std::move(*cached->result);
        run.from_cache = true;
        run.report = fmt::format("(from cache {})\n", run.cache_file) + link_stiffness_report(run.result);
        return run;
      }
      // A damaged entry is recomputed (and replaced), never used; the caller shows why.
      if (!cached->rejected.empty()) run.warnings.push_back(cached->rejected + "; recomputing it");
    }
  }
  if (request.options.progress)
    request.options.progress(fmt::format("meshing {} with size {:g} m", request.mesh_file, run.mesh_size));
  StatusOr<TetMesh> mesh = mesh_from_rank0(request.mesh_file, meshing);
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
  if (Status s = validate(request); !s.ok()) return s;
  auto make = [&](double h) { return mesh_from_rank0(request.mesh_file, meshing_options(request, h)); };
  LinkStiffnessOptions options = request.options;  // the 6x6 only: no fields, no modes
  options.keep_fields = false;
  options.modes = 0;
  return mesh_convergence_study(make, sizes, request.material, options);
}

}  // namespace kinestat::fea
