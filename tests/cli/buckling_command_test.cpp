// kinestat buckling on models/euler_column.yaml (pinned-pinned, L = 2 m, EI = 4200 N m^2, P = 1 kN):
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
  const CliRun r = run_cli({"buckling", kModels + "euler_column.yaml", "--count", "2", "--json", json, "--vtk",
                            (dir / "vtk").string()});
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
  for (const char* f : {"euler_column_buckling_mode1.vtu", "euler_column_buckling_mode2.vtu",
                        "euler_column_buckling.pvd"})
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
  EXPECT_NE(r.err.find("out of range"), std::string::npos) << r.err;
  r = run_cli({"buckling", file, "--count", "0"});
  EXPECT_EQ(r.code, kExitBadInput);
  // The cantilever's cases bend or twist it: no beam in compression.
  r = run_cli({"buckling", kModels + "cantilever.yaml"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("compresses no beam"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kinestat::cli
