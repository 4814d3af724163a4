// kinestat design orthoglide --cube C --mu MU [--strategy 1|2|3] [--vtk DIR] [--encoder-offsets E1,E2]
//                            [--json FILE|-]
// Geometric synthesis of the Orthoglide (Pashkevich, Wenger, Chablat 2005, Table 3): link length,
// joint limits and cube location for a cube of edge C and transmission factors in [MU, 1/MU]; the
// paper's other analyses (section 5.2 switch points, Fig. 3 and Table 2 volumes, encoder offsets).
#include "cli/design_commands.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/orthoglide_results_json.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"

namespace kinestat::cli {
namespace {

using units::kMm;  // lengths are printed in mm

struct DesignArgs {
  double cube_mm = 0.0;
  double mu = 0.0;
  std::optional<int> strategy;  // all three when absent
  std::string vtk_dir;
  int vtk_grid = 21;
  int search_points = 41;
  std::vector<double> encoder_offsets_mm = {5.0, 10.0};  // section 6's examples
  double max_points = mechanisms::kDefaultMaxSearchPoints;
  OutputOptions out;
};

// Grid of the volume fractions of Fig. 3 and Table 2 (n^3 cells over [-L, L]^3; ~0.5 % from the
// paper's own ray method, tests/mechanisms/orthoglide_design_test.cpp).
constexpr int kVolumeGrid = 80;

const char* strategy_summary(int s) {
  switch (s) {
    case 1:
      return "cube vertices at Q+ and Q-, upper joint limit raised to reach the cube";
    case 2:
      return "joint limits at Q+ and Q-, the largest cube inside the joint-bounded workspace";
    default:
      return "joint limits so that the whole joint-bounded workspace meets the bounds, cube inside it";
  }
}

std::string range(const mechanisms::TransmissionRange& r) {
  if (!(r.max < std::numeric_limits<double>::infinity())) return fmt::format("[{:.3f}, inf), singular", r.min);
  return fmt::format("[{:.3f}, {:.3f}]", r.min, r.max);
}

void print_design(std::ostream& out, const mechanisms::OrthoglideDesign& d,
                  const mechanisms::OrthoglideDesignCheck& check) {
  const double L = d.link_length;
  out << fmt::format("strategy {}: {}\n", d.strategy, strategy_summary(d.strategy));
  out << fmt::format("  link length L               {:.1f} mm\n", L / kMm);
  out << fmt::format("  joint limits rho            [{:.1f}, {:.1f}] mm (stroke {:.1f} mm)\n", d.rho_min / kMm,
                     d.rho_max / kMm, (d.rho_max - d.rho_min) / kMm);
  out << fmt::format("  cube p_x, p_y, p_z          [{:.1f}, {:.1f}] mm (isotropic point at p = 0, rho = L)\n",
                     d.p_min / kMm, d.p_max / kMm);
  if (std::isfinite(d.joint_sum_limit))
    out << fmt::format(
        "  software joint limit        rho_x + rho_y + rho_z <= {:.1f} mm (= 3 rho(Q+); the joint box "
        "reaches the parallel singularity)\n",
        d.joint_sum_limit / kMm);
  out << fmt::format("  unit manipulator (L = 1)    rho in [{:.4f}, {:.4f}], p in [{:.4f}, {:.4f}]\n", d.rho_min / L,
                     d.rho_max / L, d.p_min / L, d.p_max / L);
  if (std::isfinite(d.joint_sum_limit))
    out << fmt::format("  joint box kept              {:.2f} % of [rho_min, rho_max]^3 within the software limit\n",
                       100.0 * d.joint_box_kept);
  out << "  velocity transmission factors (dimensionless):\n";
  out << fmt::format("    cube                      {} (Proposition 1); numerical search {}\n", range(d.cube),
                     range(check.cube.range));
  out << fmt::format("    joint-bounded workspace   {} (critical points Q, R, S); numerical search {}{}\n",
                     range(d.joint_space), range(check.joint_space.range),
                     std::isfinite(d.joint_sum_limit) ? " with the software limit" : "");
  for (const mechanisms::EncoderOffsetEffect& e : check.encoder_offsets)
    out << fmt::format("    {:<26}{} (numerical search; every slider {:.1f} mm {} than commanded)\n",
                       fmt::format("cube, encoders {:+.1f} mm", e.offset / kMm), range(e.cube.range),
                       std::abs(e.offset) / kMm, e.offset >= 0 ? "further out" : "further in");
}

// The paper's analyses that depend on neither the cube nor the strategy (unit manipulator, L = 1).
void print_paper_analyses(std::ostream& out, const mechanisms::MinimumSwitchPoints& m,
                          const mechanisms::DexterousVolumes& v) {
  out << "Workspace analyses of the paper (unit manipulator L = 1; the same for every cube and strategy):\n";
  out << "  section 5.2, mu_min over the joint box [rho_min, 1]^3 (Fig. 9a):\n";
  out << fmt::format("    S-|R- switch of the formulas   rho_SR = {:.4f}, mu = {:.4f}; numerical search there {:.4f}\n",
                     m.rho_sr, m.mu_sr, m.search_mu_at_rho_sr);
  out << fmt::format("    R-|Q- switch of the formulas   rho_RQ = {:.4f}, mu = {:.4f}; numerical search there {:.4f}\n",
                     m.rho_rq, m.mu_rq, m.search_mu_at_rho_rq);
  out << fmt::format(
      "    true switch to Q-              rho = {:.4f}, mu = {:.4f} (below it the minimum is at no "
      "critical point: on the edge (rho_min, rho_min, t), or near S- on a face)\n",
      m.rho_q, m.mu_q);
  out << fmt::format("  Fig. 3: singularity-free workspace V0 = {:.1f} % of the sphere |p| < L (paper: 97.2 %)\n",
                     100.0 * v.singularity_free_of_sphere);
  out << fmt::format(
      "  Table 2, factors bounded by 1/3 and 3: lower {:.3f} V0, two-sided {:.3f} V0, upper {:.3f} V0 "
      "(paper: 0.84, 0.67, 0.72)\n",
      v.lower_of_w0, v.two_sided_of_w0, v.upper_of_w0);
}

int run_design(const DesignArgs& a, Context& ctx) {
  auto fail = [&ctx](const Status& s) { return report_failure(ctx, "design orthoglide", s); };
  // Checked here too, to name the option and its unit in the message.
  if (Status s = check_quantity(a.cube_mm, Quantity::kLength, "--cube (the cube edge)", {kMm, "mm"}, Sign::kPositive);
      !s.ok())
    return fail(s);
  if (!(a.mu > 0.0 && a.mu < 1.0))
    return fail(Status::Invalid(
        fmt::format("--mu {}: must lie strictly between 0 and 1 (the factors are bounded to [mu, 1/mu])", a.mu)));
  if (a.strategy && (*a.strategy < 1 || *a.strategy > 3))
    return fail(Status::Invalid(fmt::format("--strategy {}: must be 1, 2 or 3", *a.strategy)));
  // Sizes estimated before anything is allocated or searched.
  using mechanisms::check_grid_points, mechanisms::check_search_points;
  for (const Status& s : {check_grid_points(a.vtk_grid, a.max_points, "--vtk-grid", "--max-points"),
                          check_search_points(a.search_points, a.max_points, "--search-points", "--max-points")})
    if (!s.ok()) return fail(s);
  for (double e : a.encoder_offsets_mm)
    if (!std::isfinite(e))
      return fail(Status::Invalid(fmt::format("--encoder-offsets {} mm: every offset must be a finite number", e)));
  std::vector<double> offsets;
  for (double e : a.encoder_offsets_mm) offsets.push_back(e * kMm);
  const std::vector<int> strategies = a.strategy ? std::vector<int>{*a.strategy} : std::vector<int>{1, 2, 3};
  std::vector<mechanisms::OrthoglideDesign> designs;
  std::vector<mechanisms::OrthoglideDesignCheck> checks;
  for (int s : strategies) {
    auto d = mechanisms::design_orthoglide(s, a.mu, a.cube_mm * kMm);
    if (!d.ok()) return fail(d.status());
    designs.push_back(*d);
    checks.push_back(mechanisms::check_design(*d, a.search_points, offsets));
  }
  Output out(ctx, a.out);
  out.report() << fmt::format(
      "Orthoglide design (Pashkevich, Wenger, Chablat 2005): cube {:.1f} mm, velocity transmission factors in "
      "[{:.3f}, {:.3f}]\n\n",
      a.cube_mm, a.mu, 1.0 / a.mu);
  for (std::size_t i = 0; i < designs.size(); ++i) {
    print_design(out.report(), designs[i], checks[i]);
    if (!a.vtk_dir.empty()) {
      std::vector<std::string> written;
      if (Status st = io::write_orthoglide_workspace_vtk(designs[i], a.vtk_grid, a.vtk_dir, &written, a.max_points);
          !st.ok())
        return fail(st);
      for (const auto& path : written) out.report() << "  wrote " << path << " (lengths in m)\n";
    }
    out.report() << "\n";
  }
  print_paper_analyses(out.report(), mechanisms::unit_minimum_switch_points(a.search_points),
                       mechanisms::unit_dexterous_volumes(1.0 / 3.0, 3.0, kVolumeGrid));
  if (Status st = out.write_json(io::orthoglide_designs_to_json(designs, checks, a.search_points)); !st.ok())
    return fail(st);
  return kExitOk;
}

}  // namespace

void add_orthoglide_design(CLI::App* design, Context& ctx) {
  auto args = std::make_shared<DesignArgs>();
  CLI::App* cmd = design->add_subcommand(
      "orthoglide",
      "Orthoglide design strategies of Pashkevich, Wenger, Chablat 2005 (Table 3): link length, joint "
      "limits and cube location for a cubic workspace and transmission factors in [mu, 1/mu]");
  cmd->add_option("--cube", args->cube_mm, "edge of the cubic workspace, in mm (or with a unit: 0.2m, 20cm)")
      ->required()
      ->transform(CLI::AsNumberWithUnit(std::map<std::string, double>{{"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}}));
  cmd->add_option("--mu", args->mu,
                  "lower bound mu of the velocity transmission factors (dimensionless), 0 < mu < 1 (upper: 1/mu)")
      ->required();
  cmd->add_option("--strategy", args->strategy, "design strategy 1, 2 or 3 (default: all three)");
  CLI::Option* vtk = cmd->add_option("--vtk", args->vtk_dir,
                                     "write the joint-bounded workspace and the cube as .vtu files (SI units) to DIR");
  cmd->add_option("--vtk-grid", args->vtk_grid, "joint grid points per axis in the VTK workspace (default 21)")
      ->needs(vtk);
  cmd->add_option("--search-points", args->search_points,
                  "points per face edge of the numerical check of the transmission factors (default 41)");
  cmd->add_option("--encoder-offsets", args->encoder_offsets_mm,
                  "encoder offsets, in mm, whose effect on the cube's factors is reported: every slider that much "
                  "further out than commanded (default 5,10)")
      ->delimiter(',');
  cmd->add_option("--max-points", args->max_points,
                  "refuse --vtk-grid N (N^3 points) or --search-points N (~7 N^2 + N^3/64 points) above this")
      ->capture_default_str();
  add_output_options(*cmd, args->out, "kinestat-orthoglide-design");
  cmd->callback([args, &ctx] { ctx.exit_code = run_design(*args, ctx); });
}

}  // namespace kinestat::cli
