// kinestat buckling and modes on models/euler_column.yaml (pinned-pinned, L = 2 m, EI = 4200 N m^2, P = 1 kN):
// the load factor, JSON, VTK and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

const std::string kModels = std::string(KINESTAT_SOURCE_DIR) + "/models/";

TEST(BucklingCommand, EulerColumnLoadFactorJsonAndVtk) {
  const auto dir = std::filesystem::path(KINESTAT_BINARY_DIR) / "test_buckling_out";
  std::filesystem::remove_all(dir);
  const std::string json = (dir / "b.json").string();
  const CliRun r = run_cli(
      {"buckling", kModels + "euler_column.yaml", "--count", "2", "--json", json, "--vtk", (dir / "vtk").string()});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("Critical load factors"), std::string::npos) << r.out;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("schema"), "kinestat-buckling-results");
  EXPECT_EQ(j.at("load_case"), "axial");
  ASSERT_EQ(j.at("modes").size(), 2u);
  // pi^2 EI / L^2 / P; 8 cubic beams overestimate it by 3.28e-5 (tests/msa/buckling_test.cpp): asserted
  // within twice that.
  const double exact = std::numbers::pi * std::numbers::pi * 210e9 * 2e-8 / 4.0 / 1000.0;
  const double l1 = j["modes"][0].at("load_factor").get<double>();
  EXPECT_GT(l1, exact);
  EXPECT_NEAR(l1, exact, 2 * 3.28e-5 * exact);
  EXPECT_NEAR(j["modes"][0]["most_compressed_beam"].at("critical_axial_force").get<double>(), -1000.0 * l1,
              1e-9 * 1000.0 * l1);
  // Mode 1: midspan (node n4) moves 1 m along y at the normalized scale.
  EXPECT_NEAR(j["modes"][0]["shape"][4]["translation"][1].get<double>(), 1.0, 1e-12);
  for (const char* f :
       {"euler_column_buckling_mode1.vtu", "euler_column_buckling_mode2.vtu", "euler_column_buckling.pvd"})
    EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / f)) << f;
}

TEST(BucklingCommand, CaseSelectionAndRefusals) {
  const std::string file = kModels + "euler_column.yaml";
  CliRun r = run_cli({"buckling", file, "--case", "axial", "--count", "1", "--quiet"});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  r = run_cli({"buckling", file, "--case", "nope"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("no load case named 'nope'"), std::string::npos) << r.err;
  r = run_cli({"buckling", file, "--case-index", "4"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--case-index 4: the file has 1 load case; give an index from 0 to 0, or a case's name with "
                       "--case"),
            std::string::npos)
      << r.err;
  r = run_cli({"buckling", file, "--count", "0"});
  EXPECT_EQ(r.code, kExitBadInput);
  // The cantilever's cases bend or twist it: no beam in compression.
  r = run_cli({"buckling", kModels + "cantilever.yaml"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("compresses no beam"), std::string::npos) << r.err;
  // A singular structure: the static solve's diagnosis, exit 3, no load factors.
  r = run_cli({"buckling", kModels + "released_chain.yaml"});
  EXPECT_EQ(r.code, kExitSingular);
  EXPECT_NE(r.err.find("singular"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("Critical load factors"), std::string::npos) << r.out;
}

// kinestat modes on the same column (rho = 7850 kg/m^3, A = 6e-4 m^2, r^2 = Iz / A = 3.33e-5 m^2).
// Euler-Bernoulli: f_1 = pi^2 sqrt(EI / (rho A L^4)) / (2 pi) = 11.72665 Hz. The command's default
// consistent mass includes the rotary inertia: a Rayleigh beam, f_1 / sqrt(1 + (pi r / L)^2)
// (Timoshenko, Vibration Problems in Engineering, rotary-inertia correction) = 11.72617 Hz; 8 beams
// are 1.64e-5 above the closed form (tests/msa/modes_test.cpp, measured 1.6e-5 here too): asserted
// within twice that. The first mode carries 8/pi^2 = 81.06 % of the mass.
TEST(SolveSecondOrder, YamlColumnReportAndJson) {
  // The column carries its 1 kN whatever it deflects (statically determinate): the second solve
  // repeats the first, 2 iterations, and every beam's converged axial force is -1000 N.
  const CliRun r = run_cli({"solve", kModels + "euler_column.yaml", "--second-order", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("analysis: second-order (P-Delta)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("second-order (P-Delta), 2 iterations"), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("analysis").at("order"), "second");
  EXPECT_EQ(j.at("analysis").at("tolerance").get<double>(), 1e-9);
  const nlohmann::json& so = j.at("load_cases")[0].at("second_order");
  EXPECT_EQ(so.at("iterations"), 2);
  ASSERT_EQ(so.at("axial_force").size(), 8u);
  for (const auto& b : so.at("axial_force")) EXPECT_NEAR(b.at("N").get<double>(), -1000.0, 1e-9);
  // --tolerance reaches the iteration: a tolerance of 1 is refused (a relative change below 1).
  const CliRun bad = run_cli({"solve", kModels + "euler_column.yaml", "--second-order", "--tolerance", "1"});
  EXPECT_EQ(bad.code, kExitBadInput);
  EXPECT_NE(bad.err.find("second-order tolerance 1"), std::string::npos) << bad.err;
}

TEST(ModesCommand, ColumnFrequencyJsonAndVtk) {
  const auto dir = std::filesystem::path(KINESTAT_BINARY_DIR) / "test_modes_out";
  std::filesystem::remove_all(dir);
  const std::string json = (dir / "m.json").string();
  const CliRun r = run_cli(
      {"modes", kModels + "euler_column.yaml", "--count", "2", "--json", json, "--vtk", (dir / "vtk").string()});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("Natural frequencies"), std::string::npos) << r.out;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("schema"), "kinestat-modes-results");
  ASSERT_EQ(j.at("modes").size(), 2u);
  const double pi = std::numbers::pi;
  const double euler_bernoulli = pi * pi * std::sqrt(210e9 * 2e-8 / (7850 * 6e-4 * 16.0)) / (2 * pi);
  const double exact = euler_bernoulli / std::sqrt(1 + pi * pi * (2e-8 / 6e-4) / 4.0);
  const double f1 = j["modes"][0].at("frequency").get<double>();
  EXPECT_GT(f1, exact);
  EXPECT_NEAR(f1, exact, 2 * 1.64e-5 * exact);
  // Effective mass along y: 8/pi^2 of the continuum; 8 beams put 1/16 of it on the pinned nodes,
  // which do not move along y: measured 81.050 % of the total (asserted 81.06 +- 0.05 %).
  EXPECT_NEAR(j["modes"][0]["effective_mass"][1].get<double>() / 9.42, 8 / (pi * pi), 5e-4);
  EXPECT_NEAR(j.at("total_mass")[1].get<double>(), 7850 * 6e-4 * 2.0, 1e-12 * 9.42);
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "euler_column_modes_mode1.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "euler_column_modes.pvd"));

  const CliRun lumped = run_cli({"modes", kModels + "euler_column.yaml", "--count", "1", "--lumped", "--json", "-"});
  ASSERT_EQ(lumped.code, kExitOk) << lumped.err;
  // Lumped masses carry no rotary inertia: below the Euler-Bernoulli value (measured 11.7265 Hz).
  EXPECT_LT(nlohmann::json::parse(lumped.out)["modes"][0].at("frequency").get<double>(), euler_bernoulli);
}

TEST(ModesCommand, WithoutDensityIsRefused) {
  const CliRun r = run_cli({"modes", kModels + "cantilever.yaml"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("has no density"), std::string::npos) << r.err;
}

// models/euler_column.yaml with `from` replaced by `to` and `more` appended, written to the build tree as NAME.
std::string column_with(const std::string& name, const std::string& from, const std::string& to,
                        const std::string& more = "") {
  std::ifstream in(kModels + "euler_column.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  text += more;
  const auto path = std::filesystem::path(KINESTAT_BINARY_DIR) / name;
  std::ofstream(path) << text;
  return path.string();
}

// The column (48 free dofs: the Lanczos path) with no mass (density 0 and a zero nodal mass, which
// passes the density check) or a negligible one: exit 2 naming what to check. Both exited 1 from
// Spectra before ("TridiagEigen: eigen decomposition failed").
TEST(ModesCommand, NoOrNegligibleMassIsBadInputNotAnInternalFailure) {
  CliRun r = run_cli({"modes", column_with("massless_column.yaml", "density: 7850", "density: 0",
                                           "masses:\n  - {node: n4, mass: 0}\n")});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("no free dof has mass"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Spectra"), std::string::npos) << r.err;
  r = run_cli({"modes", column_with("feather_column.yaml", "density: 7850", "density: 1e-300")});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("the mass is negligible against the stiffness"), std::string::npos) << r.err;
}

// The column heated on one beam and free to expand at its roller: its axial forces are round-off
// (N ~ -7e-12 N). Before, exit 0 with lambda_1 = 3e15.
TEST(BucklingCommand, RoundOffCompressionIsNoCompression) {
  const CliRun r =
      run_cli({"buckling", column_with("heated_column.yaml", "loads:\n      - {node: n8, force: [-1000, 0, 0]}",
                                       "member_loads:\n      - {beam: b3, type: temperature, alpha: "
                                       "1.2e-5, dT: 30}")});
  EXPECT_EQ(r.code, kExitBadInput) << r.out;
  EXPECT_NE(r.err.find("load case 'axial' compresses no beam"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("Critical load factors"), std::string::npos) << r.out;
}

// The column at a density of 1e-6 kg/m^3: its frequencies are the steel column's times
// sqrt(7850 / 1e-6) (measured to 1e-15). Before, exit 0 with f_1 2.9 % high (residual 0.82).
TEST(ModesCommand, ALightColumnKeepsItsScaledFrequencies) {
  const CliRun steel = run_cli({"modes", kModels + "euler_column.yaml", "--count", "2", "--json", "-"});
  const CliRun light = run_cli(
      {"modes", column_with("light_column.yaml", "density: 7850", "density: 1e-6"), "--count", "2", "--json", "-"});
  ASSERT_EQ(steel.code, kExitOk) << steel.err;
  ASSERT_EQ(light.code, kExitOk) << light.err;
  const auto s = nlohmann::json::parse(steel.out), l = nlohmann::json::parse(light.out);
  for (int k = 0; k < 2; ++k) {
    const double f = s["modes"][k].at("frequency").get<double>() * std::sqrt(7850.0 / 1e-6);
    EXPECT_NEAR(l["modes"][k].at("frequency").get<double>(), f, 1e-9 * f) << "mode " << k + 1;
  }
}

}  // namespace
}  // namespace kinestat::cli
