// kinestat link-stiffness MESH --material ... --clamp ... --reference ... [--vtk DIR] [--json FILE]
// The 6x6 stiffness of one link by FEA (fea/link_stiffness.hpp; docs/fea.md).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/fea/mesh_convergence.hpp"
#include "kinestat/io/fea_vtk.hpp"

namespace kinestat::cli {

namespace {

nlohmann::json matrix_json(const Mat6& A) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) rows.push_back({A(i, 0), A(i, 1), A(i, 2), A(i, 3), A(i, 4), A(i, 5)});
  return rows;
}

nlohmann::json result_json(const std::string& mesh_file, const fea::LinkStiffness& r, bool from_cache) {
  auto vec = [](const auto& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  return {{"schema", "kinestat-link-stiffness"},
          {"version", 1},
          {"mesh", {{"file", mesh_file}, {"nodes", r.num_nodes}, {"elements", r.num_elements},
                    {"nodes_per_element", r.nodes_per_element}, {"dofs", r.num_dofs}}},
          {"from_cache", from_cache},
          {"reference_model", fea::reference_model_name(r.reference_model)},
          {"reference_point_m", vec(r.cartesian.point)},
          {"units", {{"dofs", "ux uy uz rx ry rz in the mesh (link) frame"},
                     {"stiffness", "N/m | N/rad (rows ux uy uz), N | N m/rad (rows rx ry rz)"},
                     {"compliance", "m/N | m/(N m) (rows ux uy uz), rad/N | rad/(N m) (rows rx ry rz)"}}},
          {"stiffness", matrix_json(r.cartesian.stiffness)},
          {"compliance", matrix_json(r.cartesian.compliance)},
          {"symmetry_error", {{"compliance", r.compliance_symmetry_error}, {"stiffness", r.stiffness_symmetry_error}}},
          {"eigenvalues_SI_mixed_units",
           {{"stiffness", r.cartesian.indices ? vec(r.cartesian.indices->eigenvalues) : std::vector<double>{}},
            {"compliance", vec(r.compliance_eigenvalues)}}}};
}

}  // namespace

void register_link_stiffness_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string mesh, material = "steel", clamp, reference, unit = "mm", model = "rigid", vtk_dir, json_file, cache_dir;
    std::string reference_point;
    double size = 0.0, stiff_ratio = 1e4;
    bool linear = false;
    bool convergence = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "link-stiffness", "6x6 stiffness of one link by FEA: clamped at --clamp, loaded through a reference body at "
                        "--reference (docs/fea.md)");
  cmd->add_option("mesh", args->mesh, "closed triangle surface of the link (STL, OFF, OBJ, PLY)")->required();
  cmd->add_option("--material", args->material, "steel, aluminium, or E=PA,nu=V")->capture_default_str();
  cmd->add_option("--clamp", args->clamp, "fixed region: x=V | plane:PX,PY,PZ,NX,NY,NZ | box:X0,Y0,Z0,X1,Y1,Z1 (mesh units)")
      ->required();
  cmd->add_option("--reference", args->reference, "reference-end region, same syntax as --clamp")->required();
  cmd->add_option("--unit", args->unit, "length unit of the mesh file and the regions: mm or m")
      ->check(CLI::IsMember({"mm", "m"}))
      ->capture_default_str();
  cmd->add_option("--size", args->size, "tetrahedron size in mesh units (default: 1/20 of the part's largest extent)");
  cmd->add_flag("--linear", args->linear, "4-node tetrahedra (default 10-node; linear ones lock in bending)");
  cmd->add_flag("--convergence", args->convergence,
                "also solve meshes of size 2h and 1.41h and print a Richardson estimate of each compliance term: "
                "how many digits of the 6x6 to trust");
  cmd->add_option("--model", args->model, "reference body: rigid (exact coupling) or stiff-body (the paper's)")
      ->check(CLI::IsMember({"rigid", "stiff-body"}))
      ->capture_default_str();
  cmd->add_option("--stiff-ratio", args->stiff_ratio, "E of the stiff body / E of the link")->capture_default_str();
  cmd->add_option("--reference-point", args->reference_point,
                  "X,Y,Z (mesh units): the point whose motion is reported (default: centre of the reference nodes' box)");
  cmd->add_option("--vtk", args->vtk_dir, "write the six deformed-link .vtu files (ParaView) to this directory");
  cmd->add_option("--json", args->json_file, "write the matrices (SI units) as JSON to this file");
  cmd->add_option("--cache", args->cache_dir, "reuse / store results in this directory (keyed by mesh, material, options)");
  cmd->callback([args, &ctx] {
    auto fail = [&ctx](const Status& s) { ctx.exit_code = report_failure(ctx, "link-stiffness", s); };
    auto write_json = [&](const fea::LinkStiffness& r, bool from_cache) {
      if (args->json_file.empty()) return;
      std::ofstream out(args->json_file);
      out << result_json(args->mesh, r, from_cache).dump(2) << "\n";
      if (!out) fail(Status::Invalid(args->json_file + ": cannot write the JSON file"));
    };
    const double scale = args->unit == "mm" ? 1e-3 : 1.0;
    fea::LinkStiffnessRequest request;
    request.mesh_file = args->mesh;
    request.unit_scale = scale;
    request.mesh_size = args->size * scale;  // 0: the default size
    request.quadratic = !args->linear;
    request.cache_dir = args->cache_dir;
    auto material = fea::parse_material(args->material, "--material " + args->material);
    if (!material.ok()) return fail(material.status());
    request.material = *material;
    fea::LinkStiffnessOptions& options = request.options;
    auto clamp = fea::parse_region(args->clamp, scale, "--clamp " + args->clamp);
    if (!clamp.ok()) return fail(clamp.status());
    auto reference = fea::parse_region(args->reference, scale, "--reference " + args->reference);
    if (!reference.ok()) return fail(reference.status());
    options.clamp = *clamp;
    options.reference = *reference;
    options.reference_model = args->model == "rigid" ? fea::ReferenceModel::kRigidCoupling : fea::ReferenceModel::kStiffBody;
    options.stiff_body_ratio = args->stiff_ratio;
    if (!args->reference_point.empty()) {
      auto p = fea::parse_numbers(args->reference_point, 3, "--reference-point");
      if (!p.ok()) return fail(p.status());
      options.reference_point = Vec3((*p)[0], (*p)[1], (*p)[2]) * scale;
    }
    options.keep_fields = !args->vtk_dir.empty();
    options.progress = [&ctx](const std::string& stage) { ctx.err << "link-stiffness: " << stage << " ...\n"; };

    auto run = fea::compute_link_stiffness(request);
    if (!run.ok()) return fail(run.status());
    ctx.out << run->report;
    if (run->mesh) {
      std::vector<std::string> written;
      const std::string stem = std::filesystem::path(args->mesh).stem().string();
      if (Status s = io::write_link_vtu_files(args->vtk_dir, stem, *run->mesh, run->result, &written); !s.ok())
        return fail(s);
      for (const auto& w : written) ctx.out << "wrote " << w << "\n";
    }
    if (args->convergence) {
      // The finest mesh is the one just solved; two coarser ones give the three points Richardson needs.
      const double h = run->mesh_size;
      auto study = fea::link_stiffness_convergence(request, {2.0 * h, std::sqrt(2.0) * h, h});
      if (!study.ok()) return fail(study.status());
      ctx.out << "\n" << fea::convergence_report(*study);
    }
    write_json(run->result, run->from_cache);
  });
}

}  // namespace kinestat::cli
