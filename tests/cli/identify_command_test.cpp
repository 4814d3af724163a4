// kinestat identify: from a nominal start model, the paper's declared targets file gives back the
// inputs of the bundled model files (which the library's identification produced, tests/io); bad input
// exits with 2.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "kinestat/cli/app.hpp"

namespace kinestat::cli {
namespace {

const std::string kSource = KINESTAT_SOURCE_DIR;
const std::string kTargets = kSource + "/models/orthoglide_paper_targets.yaml";

// The number printed after "key: " in the model-file lines of the report.
double printed_value(const std::string& out, const std::string& key) {
  const std::size_t at = out.find("  " + key + ": ", out.find("as model-file values"));
  return at == std::string::npos ? std::nan("") : std::stod(out.substr(at + key.size() + 4));
}

// The nominal inputs of docs/vjm.md (the C++ defaults) with a 50 mm platform offset guess.
std::string nominal_start(bool with_offset = true) {
  const std::string path =
      std::string(KINESTAT_BINARY_DIR) + (with_offset ? "/identify_nominal_start.yaml" : "/identify_no_offset.yaml");
  std::ofstream(path) << R"(units: mm-N-s
mechanism: orthoglide
orthoglide:
  architecture: 3-PRPaR
  link_length: 310.6
  parallelogram_width: 80
)" << (with_offset ? "  platform_offset: 50\n" : "")
                      << R"(  actuator_stiffness: 2.0e4
  bar: {E: 70000, nu: 0.33, section: {type: tube, d: 20, t: 2}}
  foot: {E: 210000, nu: 0.3, section: {type: hollow_rectangle, b: 60, h: 60, t: 5}, length: 100}
)";
  return path;
}

TEST(IdentifyCommand, NominalStartGivesTheBundledModelsInputs) {
  const CliRun r = run_cli({"identify", nominal_start(), kTargets});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  // models/orthoglide_prpar.yaml, to its 5 printed digits.
  EXPECT_NEAR(printed_value(r.out, "actuator_stiffness"), 4170.3, 0.1);
  EXPECT_NEAR(printed_value(r.out, "parallelogram_width"), 26.050, 0.001);
  EXPECT_NEAR(printed_value(r.out, "platform_offset"), 28.523, 0.001);
  EXPECT_NEAR(printed_value(r.out, "foot length"), 632.75, 0.01);
  // The bar: tube 20 x 2 scaled to 14.873 x 1.4873.
  const std::size_t bar = r.out.find("every dimension of the model file's times ");
  ASSERT_NE(bar, std::string::npos);
  EXPECT_NEAR(std::stod(r.out.substr(bar + 42)), 14.873 / 20, 3e-5);  // the file rounds d to 0.0005 mm
  EXPECT_NE(r.out.find("Levenberg-Marquardt"), std::string::npos);
}

TEST(IdentifyCommand, BadInputExitsWith2) {
  CliRun r = run_cli({"identify", kSource + "/models/five_bar.yaml", kTargets});
  EXPECT_EQ(r.code, kExitBadInput);
  r = run_cli({"identify", kSource + "/tests/io/data/vjm_puu_q0.yaml", kTargets});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("needs a model with 'mechanism: orthoglide'"), std::string::npos) << r.err;
  r = run_cli({"identify", kSource + "/models/orthoglide_puu.yaml", "/nonexistent/targets.yaml"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("/nonexistent/targets.yaml"), std::string::npos) << r.err;
  // Without the key the platform offset is 0: no start for its logarithm.
  r = run_cli({"identify", nominal_start(false), kTargets});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("start value of the platform offset (m) must be positive"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kinestat::cli
