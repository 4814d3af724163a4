// kinestat solve FILE.3dd --units FORCE-LENGTH: the reader chosen by the extension, the units
// required for .3dd and refused for YAML, a cantilever's tip deflection in SI.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"
#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

const std::string kModels = std::string(KINESTAT_SOURCE_DIR) + "/models/";

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("kinestat_frame3dd_" + name);
  std::ofstream(path) << text;
  return path.string();
}

// A 100 in cantilever, E I = 29000 ksi x 100 in^4, 1 kip down at the tip, in kip and inch.
constexpr const char* kCantilever = R"(cantilever in kip and inch
2   # nodes
1  0 0 0  0
2  100 0 0  0
1   # reactions
1  1 1 1 1 1 1
1   # elements
1 1 2  10 0 0  50 100 100  29000 11500  0  0
0   # shear
0   # geometric stiffness
10  # exaggerate
1   # zoom
-1  # dx
1   # load cases
0 0 0
1   # loaded nodes
2  0 0 -1  0 0 0
0   # uniform loads
0   # trapezoidal loads
0   # concentrated loads
0   # temperature loads
0   # prescribed displacements
2   # dynamic modes
)";

TEST(SolveFrame3dd, ReadsWithUnitsAndReportsSi) {
  const std::string file = write_temp("cantilever.3dd", kCantilever);
  const CliRun r = run_cli({"solve", file, "--units", "kip-in", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  // The modes are not computed: said on stderr with the line.
  expect_contains(r.err, "cantilever.3dd:23: 2 dynamic modes");
  // Tip deflection P L^3 / (3 E I) = 1 x 100^3 / (3 x 29000 x 100) in = 0.1149425 in, in the JSON in m.
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& tip = j.at("load_cases").at(0).at("displacements").at(1);
  ASSERT_EQ(tip.at("node"), "2");
  // Round-off of one 6x6 solve: 1e-12 relative.
  const double expected = -1.0 * 1e6 / (3.0 * 29000.0 * 100.0) * 0.0254;
  EXPECT_NEAR(tip.at("translation").at(2).get<double>(), expected, 1e-12 * std::abs(expected));
  // The rotation P L^2 / (2 E I) rad, the same in any units: 1e4 / (2 x 29000 x 100).
  EXPECT_NEAR(tip.at("rotation").at(1).get<double>(), 1e4 / (2.0 * 29000.0 * 100.0), 1e-15);
}

TEST(SolveFrame3dd, UnitsRequiredForFrame3ddAndRefusedForYaml) {
  const std::string file = write_temp("units.3dd", kCantilever);
  CliRun r = run_cli({"solve", file});
  EXPECT_EQ(r.code, kExitBadInput);
  expect_contains(r.err, "states no units; give them with --units");
  r = run_cli({"solve", file, "--units", "kip-furlong"});
  EXPECT_EQ(r.code, kExitBadInput);
  expect_contains(r.err, "--units kip-furlong");
  r = run_cli({"solve", kModels + "cantilever.yaml", "--units", "N-m"});
  EXPECT_EQ(r.code, kExitBadInput);
  expect_contains(r.err, "--units is for Frame3DD .3dd files");
}

TEST(SolveFrame3dd, RefusalNamesTheLine) {
  const std::string full = kCantilever;
  const std::size_t at = full.find("0   # geometric");
  const std::string text = full.substr(0, at) + "1" + full.substr(at + 1);
  const CliRun r = run_cli({"solve", write_temp("geometric.3dd", text), "--units", "kip-in"});
  EXPECT_EQ(r.code, kExitBadInput);
  expect_contains(r.err, "geometric.3dd:10: geometric stiffness flag");
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace kinestat::cli
