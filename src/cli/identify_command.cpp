// kinestat identify MODEL TARGETS [--tolerance T] [--json FILE|-] [--quiet]
// Identifies an Orthoglide model's unknown inputs from measured (or published) compliance terms
// (mechanisms/orthoglide_identification.hpp; formats in docs/vjm.md, "Identifying inputs"):
// the start values come from the model file, the terms and the inputs to adjust from TARGETS.
// Sample run (the paper's declared calibration; the bundled models hold its result):
//   kinestat identify models/orthoglide_puu.yaml models/orthoglide_paper_targets.yaml
#include <memory>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/identification_yaml.hpp"
#include "kinestat/io/orthoglide_results_json.hpp"
#include "kinestat/io/vjm_yaml.hpp"

namespace kinestat::cli {
namespace {

using units::kMm;

struct IdentifyArgs {
  std::string model, targets;
  double tolerance = 1e-8;
  OutputOptions out;
};

// The identified inputs in the bundled model files' units (mm-N-s), ready to paste.
std::string model_file_lines(const std::vector<mechanisms::OrthoglideInput>& inputs,
                             const mechanisms::OrthoglideIdentification& id) {
  std::string out = "identified inputs as model-file values (mm-N-s):\n";
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const double v = id.values[k];
    switch (inputs[k]) {
      case mechanisms::OrthoglideInput::kActuatorStiffness:
        out += fmt::format("  actuator_stiffness: {:.5g}   # N/mm\n", v * kMm);  // N/m in N/mm
        break;
      case mechanisms::OrthoglideInput::kBarScale:
        out += fmt::format("  bar section: every dimension of the model file's times {:.5g}\n", v);
        break;
      case mechanisms::OrthoglideInput::kParallelogramWidth:
        out += fmt::format("  parallelogram_width: {:.5g}   # mm\n", v / kMm);
        break;
      case mechanisms::OrthoglideInput::kPlatformOffset:
        out += fmt::format("  platform_offset: {:.5g}   # mm\n", v / kMm);
        break;
      case mechanisms::OrthoglideInput::kFootLength:
        out += fmt::format("  foot length: {:.5g}   # mm\n", v / kMm);
        break;
    }
  }
  return out;
}

int run_identify(const IdentifyArgs& a, Context& ctx) {
  auto bad = [&](const Status& s) { return report_failure(ctx, "identify", s); };
  StatusOr<io::VjmModel> model = io::read_vjm_model_yaml(a.model);
  if (!model.ok()) return bad(model.status());
  if (!model->orthoglide)
    return bad(Status::Invalid(a.model + ": identification needs a model with 'mechanism: orthoglide'"));
  StatusOr<io::IdentificationTargets> t = io::read_identification_targets_yaml(a.targets);
  if (!t.ok()) return bad(t.status());
  StatusOr<mechanisms::OrthoglideIdentification> id =
      mechanisms::identify_orthoglide_inputs(*model->orthoglide, t->inputs, t->targets, a.tolerance);
  if (!id.ok()) return bad(id.status());
  Output out(ctx, a.out);
  out.report() << fmt::format("kinestat identification: start {}, targets {}\n", a.model, a.targets) << id->report
               << model_file_lines(t->inputs, *id);
  if (Status s = out.write_json(io::identification_to_json(t->inputs, t->targets, *id)); !s.ok()) return bad(s);
  return kExitOk;
}

}  // namespace

void register_identify_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd =
      app.add_subcommand("identify",
                         "identify an Orthoglide model's unknown inputs from compliance targets (docs/vjm.md): "
                         "Levenberg-Marquardt from the model file's values (both files in their own 'units:')");
  cmd->add_option("model", args->model, "start model (VJM model file with 'mechanism: orthoglide')")->required();
  cmd->add_option("targets", args->targets, "targets file (YAML: inputs and compliance terms)")->required();
  cmd->add_option("--tolerance", args->tolerance, "largest relative residual accepted (dimensionless, default 1e-8)")
      ->check(positive_number());
  add_output_options(*cmd, args->out, "kinestat-identification");
  cmd->callback([args, &ctx] { ctx.exit_code = run_identify(*args, ctx); });
}

}  // namespace kinestat::cli
