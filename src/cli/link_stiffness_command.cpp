// kinestat link-stiffness MESH --material ... --clamp ... --reference ... [--modes N] [--vtk DIR] [--json FILE|-]
//     [--convergence] [--solver cholmod|petsc-mumps|petsc-cg [--cg-rtol R]] [--quiet]
// Under `mpirun -np N` with a PETSc solver rank 0 meshes, every rank assembles its share of the
// elements and solves, rank 0 alone writes.
// The 6x6 stiffness of one link by FEA (fea/link_stiffness.hpp; docs/fea.md).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/fea/mesh_convergence.hpp"
#include "kinestat/io/fea_vtk.hpp"
#include "kinestat/io/link_stiffness_json.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::cli {
namespace {

using units::kMm;
using units::kMPa;

// The convergence study's meshes: the coarsest has at least kElementsAcross elements across the
// part's thinnest extent, each next one is kRefinement times finer (dofs ~3.4 times more). Measured
// on meshes/bar.off (20 x 30 x 200 mm, steel; the earlier 2h, 1.41h, h from the default 10 mm gave
// 4 473, 4 578 and 5 289 dofs, about one element across the 20 mm, and no estimate): from 10 mm
// (two elements across) the differences between meshes still grow (pre-asymptotic: n/a), from
// 6.67 mm (three) every term converges with an observed order 1.5-3.6 and the limits agree to 1e-4
// with those of 5, 3.33 and 2.5 mm.
constexpr double kElementsAcross = 3.0;
constexpr double kRefinement = 1.5;

// The estimated relative error of each diagonal compliance term of `C` (the result printed above,
// on a mesh of the study or not) against the study's Richardson limit.
std::string result_error_line(const fea::ConvergenceStudy& study, const Mat6& C, double size) {
  std::string out = fmt::format("  {:>20}", fmt::format("rel. error at {:g} m", size));
  for (int k = 0; k < 6; ++k) {
    const auto& e = study.diagonal[k];
    out += e.ok() ? fmt::format(" {:12.3e}", (C(k, k) - e->extrapolated) / e->extrapolated)
                  : fmt::format(" {:>12}", "n/a");
  }
  return out + "  (the 6x6 printed above)\n";
}

}  // namespace

void register_link_stiffness_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string mesh, material = "steel", clamp, reference, unit = "mm", model = "rigid", vtk_dir, cache_dir;
    std::string reference_point, solver = "cholmod";
    std::optional<double> size_mm;  // absent: the default size; given: checked, never replaced
    double stiff_ratio = 1e4, max_elements = fea::MeshingOptions{}.max_elements;
    double cg_rtol = solver::LinearSolverOptions{}.relative_tolerance;
    int max_iterations = solver::LinearSolverOptions{}.max_iterations;
    std::optional<int> modes;  // absent: none; given: 1 to kMaxLinkModes
    bool linear = false;
    bool convergence = false;
    OutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("link-stiffness",
                         "6x6 stiffness of one link by FEA: clamped at --clamp, loaded through a reference body at "
                         "--reference (docs/fea.md); the report, JSON and VTK are in SI units");
  cmd->add_option("mesh", args->mesh, "closed triangle surface of the link (STL, OFF, OBJ, PLY), in --unit")
      ->required();
  cmd->add_option("--material", args->material,
                  "steel (7850 kg/m^3), aluminium (2700 kg/m^3), or E=MPA,nu=V[,rho=KG_M3] (Young's modulus in MPa, "
                  "density in kg/m^3, needed by --modes only)")
      ->capture_default_str();
  cmd->add_option("--clamp", args->clamp,
                  "fixed region: x=V | plane:PX,PY,PZ,NX,NY,NZ | box:X0,Y0,Z0,X1,Y1,Z1 (coordinates of the mesh "
                  "file, in --unit)")
      ->required();
  cmd->add_option("--reference", args->reference, "reference-end region, same syntax and unit as --clamp")->required();
  cmd->add_option("--unit", args->unit,
                  "length unit of the mesh file and so of --clamp, --reference, "
                  "--reference-point: mm or m")
      ->check(CLI::IsMember({"mm", "m"}))
      ->capture_default_str();
  cmd->add_option("--size", args->size_mm, "tetrahedron size (mm; default: 1/20 of the part's largest extent)");
  cmd->add_option("--max-elements", args->max_elements,
                  "refuse to mesh when more tetrahedra than this are estimated (4 V/h^3 + 1.3 A/h^2, "
                  "docs/reliability.md)")
      ->capture_default_str();
  cmd->add_flag("--linear", args->linear, "4-node tetrahedra (default 10-node; linear ones lock in bending)");
  cmd->add_flag("--convergence", args->convergence,
                "also solve three meshes of size h, h/1.5, h/2.25 (h: --size, at most 1/3 of the part's thinnest "
                "extent) and print a Richardson estimate of each compliance term and the error of the result: how "
                "many digits of the 6x6 to trust");
  cmd->add_option("--model", args->model, "reference body: rigid (exact coupling) or stiff-body (the paper's)")
      ->check(CLI::IsMember({"rigid", "stiff-body"}))
      ->capture_default_str();
  cmd->add_option("--stiff-ratio", args->stiff_ratio, "E of the stiff body / E of the link (dimensionless)")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            // The library's range (fea::LinkStiffnessOptions), said as the option's.
            char* end = nullptr;
            const double x = std::strtod(text.c_str(), &end);
            return end != text.c_str() && *end == '\0' && x > 1.0 && x <= fea::kMaxStiffBodyRatio
                       ? std::string()
                       : fmt::format(
                             "'{}' is not a ratio above 1 and at most {:g} (the stiff body's E over the link's)", text,
                             fea::kMaxStiffBodyRatio);
          },
          "RATIO"));
  cmd->add_option("--reference-point", args->reference_point,
                  "X,Y,Z in --unit: the point whose motion is reported (default: centre of the reference nodes' box)");
  cmd->add_option("--modes", args->modes,
                  "also the N lowest natural frequencies (Hz) and mode shapes of the clamped link, reference body "
                  "massless (count, 1 to 100; needs the material's density: steel, aluminium or ...,rho=KG_M3)");
  cmd->add_option("--vtk", args->vtk_dir,
                  "write the six deformed-link .vtu files and a .pvd that groups them (ParaView, SI units) to DIR; "
                  "with --modes also one .vtu per mode and PREFIX_modes.pvd");
  cmd->add_option("--cache", args->cache_dir,
                  "reuse / store results in this directory (keyed by mesh, material, options)");
  cmd->add_option("--solver", args->solver,
                  "cholmod (direct, shared memory), petsc-mumps (MUMPS direct over MPI) or petsc-cg (CG + multigrid "
                  "over MPI, for meshes no factor fits); run the PETSc ones under mpirun -np N (docs/fea.md)")
      ->check(CLI::IsMember({"cholmod", "petsc-mumps", "petsc-cg"}))
      ->capture_default_str();
  cmd->add_option("--cg-rtol", args->cg_rtol,
                  "petsc-cg: stop at ||b - Kx|| <= R ||b|| per load case (dimensionless, 0 < R < 1)")
      ->capture_default_str();
  cmd->add_option("--max-iterations", args->max_iterations, "petsc-cg: iterations per load case (count, >= 1)")
      ->capture_default_str();
  add_output_options(*cmd, args->out, "kinestat-link-stiffness");
  cmd->callback([args, &ctx] {
    // Under mpirun every rank fails alike (solver::agree_on_status): rank 0 alone says why. A rank
    // that fails alone keeps its reason for solver::finish_job, which then ends the job with it.
    int rank = 0;
    auto fail = [&ctx, &rank](const Status& s) {
      ctx.failure = "kinestat link-stiffness: " + s.message();
      ctx.exit_code = rank == 0 ? report_failure(ctx, "link-stiffness", s) : exit_code_for(s);
    };
    const solver::Backend backend = *solver::backend_from_name(args->solver);  // checked by IsMember
    if (Status s = solver::check_backend_built(backend); !s.ok()) return fail(s);
    if (backend != solver::Backend::kCholmod) {
      // Under mpirun every rank runs this command; only rank 0 writes the report, JSON and VTK.
      auto group = solver::start_parallel();
      if (!group.ok()) return fail(group.status());
      rank = group->rank;
      if (rank != 0) args->out = OutputOptions{.json = "", .quiet = true}, args->vtk_dir.clear();
      // Ranks given other options would mesh, cache and solve different things.
      if (Status s = solver::same_on_every_rank("the command line", ctx.command_line); !s.ok()) return fail(s);
    }
    if (!(args->cg_rtol > 0.0 && args->cg_rtol < 1.0))
      return fail(Status::Invalid(
          fmt::format("--cg-rtol {:g}: give a relative tolerance between 0 and 1 (e.g. 1e-10)", args->cg_rtol)));
    if (args->max_iterations < 1)
      return fail(Status::Invalid(fmt::format("--max-iterations {}: give at least 1", args->max_iterations)));
    // --modes is checked before meshing: a count out of range or a massless material fails at once.
    const int modes = args->modes.value_or(0);
    if (args->modes && (modes < 1 || modes > fea::kMaxLinkModes))
      return fail(Status::Invalid(fmt::format("--modes {}: give a count from 1 to {}", modes, fea::kMaxLinkModes)));
    if (modes > 0 && !solver::solves_generalized_eigenproblems(backend))
      return fail(Status::Invalid(
          fmt::format("--modes with --solver {}: the natural frequencies need a direct solver (exact solves for "
                      "the eigensolver); use --solver petsc-mumps (any number of MPI ranks) or cholmod",
                      args->solver)));
    Output out(ctx, args->out);
    const double scale = args->unit == "mm" ? kMm : 1.0;
    fea::LinkStiffnessRequest request;
    request.mesh_file = args->mesh;
    request.unit_scale = scale;
    if (args->size_mm) {
      if (Status s = check_quantity(*args->size_mm, Quantity::kLength, "--size", {kMm, "mm"}, Sign::kPositive); !s.ok())
        return fail(s);
      request.mesh_size = *args->size_mm * kMm;
    }
    request.max_elements = args->max_elements;
    request.quadratic = !args->linear;
    request.cache_dir = args->cache_dir;
    auto material = fea::parse_material(args->material, "--material " + args->material, kMPa);
    if (!material.ok()) return fail(material.status());
    request.material = *material;
    if (modes > 0 && !(material->density > 0.0))
      return fail(
          Status::Invalid(fmt::format("--material {} has no density, which --modes needs (the link's mass); "
                                      "give steel, aluminium or E=MPA,nu=V,rho=KG_M3 (kg/m^3)",
                                      args->material)));
    fea::LinkStiffnessOptions& options = request.options;
    auto clamp = fea::parse_region(args->clamp, scale, "--clamp " + args->clamp);
    if (!clamp.ok()) return fail(clamp.status());
    auto reference = fea::parse_region(args->reference, scale, "--reference " + args->reference);
    if (!reference.ok()) return fail(reference.status());
    options.clamp = *clamp;
    options.reference = *reference;
    options.reference_model =
        args->model == "rigid" ? fea::ReferenceModel::kRigidCoupling : fea::ReferenceModel::kStiffBody;
    options.stiff_body_ratio = args->stiff_ratio;
    if (!args->reference_point.empty()) {
      auto p = fea::parse_point(args->reference_point, scale, "--reference-point");
      if (!p.ok()) return fail(p.status());
      options.reference_point = *p;
    }
    options.solver.backend = backend;
    options.solver.relative_tolerance = args->cg_rtol;
    options.solver.max_iterations = args->max_iterations;
    options.keep_fields = !args->vtk_dir.empty();
    options.modes = modes;
    options.progress = [&out](const std::string& stage) { out.progress() << "link-stiffness: " << stage << " ...\n"; };

    auto run = fea::compute_link_stiffness(request);
    if (!run.ok()) return fail(run.status());
    // On stderr even with --quiet: the result did not come from where the user expected.
    for (const std::string& w : run->warnings) ctx.err << "link-stiffness: warning: " << w << "\n";
    out.report() << fmt::format("material {} (E = {:g} MPa, nu = {:g})\n", material->id, material->E / kMPa,
                                material->nu())
                 << run->report;
    if (run->mesh) {
      std::vector<std::string> written;
      const std::string stem = std::filesystem::path(args->mesh).stem().string();
      if (Status s = io::write_link_vtu_files(args->vtk_dir, stem, *run->mesh, run->result, &written); !s.ok())
        return fail(s);
      if (!run->result.modes.empty())
        if (Status s = io::write_link_mode_vtu_files(args->vtk_dir, stem, *run->mesh, run->result, &written); !s.ok())
          return fail(s);
      for (const auto& w : written) out.report() << "wrote " << w << "\n";
    }
    std::optional<fea::ConvergenceStudy> study;
    if (args->convergence) {
      const double thinnest = (run->surface.hi - run->surface.lo).minCoeff() * scale;
      const double h = std::min(run->mesh_size, thinnest / kElementsAcross);
      auto s = fea::link_stiffness_convergence(request, {h, h / kRefinement, h / (kRefinement * kRefinement)});
      if (!s.ok()) return fail(s.status());
      study = *s;
      out.report() << "\n"
                   << fea::convergence_report(*study)
                   << result_error_line(*study, run->result.cartesian.compliance, run->mesh_size);
    }
    if (out.json_wanted()) {
      nlohmann::json j = io::link_stiffness_to_json(args->mesh, run->mesh_size, run->result, run->from_cache);
      if (study) j["convergence"] = io::convergence_study_to_json(*study);
      if (Status s = out.write_json(j); !s.ok()) return fail(s);
    }
    ctx.exit_code = kExitOk;
  });
}

}  // namespace kinestat::cli
