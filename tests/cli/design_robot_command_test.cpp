// kinestat design ROBOT.yaml: the best design's stiff volume equals that of the map of the same
// design built directly (io::read_robot_model with the parameters, make_robot_kernel,
// compute_workspace_map) to 1e-12; a --param naming no parameter exits 2; a design whose drawing
// cannot be built is reported in the table, not fatal, unless every design fails; the cost check
// states its time; the subcommands fivebar and orthoglide are still reached.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::cli {
namespace {

const std::string kDelta = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/delta.yaml";
// A coarse box in the Delta's reach, and a threshold inside its k_t_min range there, so that the
// designs' stiff volumes differ.
const std::vector<std::string> kRegion = {"--box=-300:300,-300:300,-950:-650", "--step", "150", "--min-stiffness", "3"};

std::vector<std::string> delta_design(const std::vector<std::string>& params,
                                      const std::vector<std::string>& more = {}) {
  std::vector<std::string> args = {"design", kDelta};
  for (const std::string& p : params) args.insert(args.end(), {"--param", p});
  args.insert(args.end(), kRegion.begin(), kRegion.end());
  args.insert(args.end(), more.begin(), more.end());
  args.push_back("--quiet");
  return args;
}

// The map of one design as `kinestat map` builds it, with the same region and threshold (and,
// for the loaded mode, a wrench in N, N m).
mechanisms::WorkspaceMap direct_map(const io::ParamOverrides& params, std::optional<Vec6> wrench = std::nullopt,
                                    const std::array<mechanisms::MapRange, 3>& box = {mechanisms::MapRange{-0.3, 0.3},
                                                                                      {-0.3, 0.3},
                                                                                      {-0.95, -0.65}},
                                    double step = 0.15) {
  using namespace mechanisms;
  auto model = io::read_robot_model(kDelta, params);
  EXPECT_TRUE(model.ok()) << model.status().message();
  RobotKernelOptions o;
  o.model = std::make_shared<const RobotModel>(std::move(*model));
  o.task = o.model->home_task();
  o.wrench = wrench;
  auto grid = make_map_grid(box, step, 1000000);
  EXPECT_TRUE(grid.ok()) << grid.status().message();
  MapOptions options;
  options.min_stiffness = 3e3;  // N/m
  options.with_deflection = options.with_iterations = wrench.has_value();
  auto map = compute_workspace_map(*make_robot_kernel(o), *grid, options);
  EXPECT_TRUE(map.ok()) << map.status().message();
  return std::move(*map);
}

TEST(DesignRobotCommand, BestDesignEqualsItsDirectMap) {
  const CliRun r = run_cli(delta_design({"arm=250:350", "forearm=700:900"}, {"--steps", "2", "--json", "-"}));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], "kinestat-robot-design-sweep");
  EXPECT_EQ(j["measure_unit"], "m^3");
  EXPECT_NE(j["parameter_units"].get<std::string>().find("lengths in mm"), std::string::npos) << j["parameter_units"];
  const auto& table = j["designs_table"];
  ASSERT_EQ(table.size(), 4u);
  // The best is the largest stiff volume, the first of equal ones.
  std::size_t best = 0;
  for (std::size_t k = 0; k < table.size(); ++k) {
    ASSERT_EQ(table[k]["status"], "ok") << table[k];
    if (table[k]["stiff_measure"].get<double>() > table[best]["stiff_measure"].get<double>()) best = k;
  }
  EXPECT_EQ(j["best"]["index"].get<std::size_t>(), best);
  const double arm = j["best"]["parameters"]["arm"], forearm = j["best"]["parameters"]["forearm"];
  // Every design, not only the best, equals its direct map.
  for (std::size_t k = 0; k < table.size(); ++k) {
    const double a = table[k]["values"][0], f = table[k]["values"][1];
    const mechanisms::WorkspaceMap map = direct_map({{"arm", a}, {"forearm", f}});
    ASSERT_GT(map.stiff_measure, 0.0);
    EXPECT_NEAR(table[k]["stiff_measure"].get<double>(), map.stiff_measure, 1e-12 * map.stiff_measure)
        << "arm " << a << ", forearm " << f;
    EXPECT_NEAR(table[k]["reachable_measure"].get<double>(), map.reachable_measure, 1e-12 * map.reachable_measure);
    if (k == best) {
      EXPECT_TRUE(a == arm && f == forearm);
    }
  }
  // The designs differ: the criterion chose.
  EXPECT_NE(table[0]["stiff_measure"], table[3]["stiff_measure"]);
}

// The loaded mode (--wrench): each design's stiff volume is that of its loaded map.
TEST(DesignRobotCommand, LoadedModeEqualsItsDirectMap) {
  const CliRun r =
      run_cli({"design", kDelta, "--param", "arm=250:350", "--steps", "2", "--box=-100:100,-100:100,-750:-650",
               "--step", "100", "--min-stiffness", "3", "--wrench", "0,0,-200,0,0,5000", "--json", "-", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["description"].get<std::string>().find("loaded under a wrench"), std::string::npos) << j["description"];
  Vec6 wrench;
  wrench << 0, 0, -200, 0, 0, 5;  // N, N m
  for (const auto& design : j["designs_table"]) {
    ASSERT_EQ(design["status"], "ok") << design;
    const mechanisms::WorkspaceMap map =
        direct_map({{"arm", design["values"][0].get<double>()}}, wrench,
                   {mechanisms::MapRange{-0.1, 0.1}, {-0.1, 0.1}, {-0.75, -0.65}}, 0.1);
    ASSERT_GT(map.stiff_measure, 0.0);
    EXPECT_NEAR(design["stiff_measure"].get<double>(), map.stiff_measure, 1e-12 * map.stiff_measure);
  }
}

TEST(DesignRobotCommand, TableNamesTheBestAndTheUnits) {
  std::vector<std::string> args = delta_design({"arm=250:350"}, {"--steps", "2"});
  std::erase(args, "--quiet");  // --quiet drops the report
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("parameters in the units of"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lengths in mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("best design: arm = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(best)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stiff (mm^3)"), std::string::npos) << r.out;
}

TEST(DesignRobotCommand, ParamNamingNoParameterExits2) {
  const CliRun r = run_cli(delta_design({"arm=250:350", "elbow=1:2"}, {"--steps", "2"}));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no parameter 'elbow'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("arm, forearm"), std::string::npos) << r.err;  // the file's parameters listed
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(DesignRobotCommand, BadOptionsExit2NamingThem) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--param", "arm"}, "--param 'arm': write NAME=LO:HI"},
      {{"--param", "arm=350:250"}, "is reversed"},
      {{"--param", "arm=x:3"}, "is not a range"},
      {{"--param", "arm=250:350", "--steps", "1"}, "--steps 1"},
      {{"--param", "arm=250:350", "--param", "arm=260:300"}, "swept twice"},
  };
  for (const auto& [params, expected] : cases) {
    std::vector<std::string> args = {"design", kDelta};
    args.insert(args.end(), params.begin(), params.end());
    args.insert(args.end(), kRegion.begin(), kRegion.end());
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 2) << expected << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  }
}

// forearm 500 cannot reach from arm 600 (the file's height is the square root of a negative
// number): that design is failed in the table, the others are mapped.
TEST(DesignRobotCommand, ABadDesignIsReportedNotFatal) {
  const CliRun r = run_cli(delta_design({"arm=250:600", "forearm=500:800"}, {"--steps", "2", "--json", "-"}));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto& table = j["designs_table"];
  ASSERT_EQ(table.size(), 4u);
  EXPECT_EQ(table[1]["status"], "failed");
  EXPECT_NE(table[1]["message"].get<std::string>().find("height"), std::string::npos) << table[1];
  EXPECT_EQ(table[0]["status"], "ok");
  EXPECT_NE(j["best"]["index"], 1);
  std::vector<std::string> args = delta_design({"arm=250:600", "forearm=500:800"}, {"--steps", "2"});
  std::erase(args, "--quiet");  // --quiet drops the report
  const CliRun text = run_cli(args);
  EXPECT_NE(text.out.find("failed: "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("1 design failed"), std::string::npos) << text.out;
}

TEST(DesignRobotCommand, EveryDesignFailingExits2WithTheFirstReason) {
  const CliRun r = run_cli(delta_design({"arm=700:800", "forearm=500"}, {"--steps", "2"}));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("every design failed; the first (arm = 700, forearm = 500)"), std::string::npos) << r.err;
}

// Designs that all run but none with a point that has a stiffness: no "best" of NaN scores. A
// region beyond every design's reach is bad input (exit 2); a load that buckles every posture
// leaves no stiffness (exit 3); neither writes a file.
TEST(DesignRobotCommand, NoPointWithAStiffnessIsAnError) {
  const std::string json = ::testing::TempDir() + "/no_stiffness_design.json";
  std::filesystem::remove(json);
  CliRun r = run_cli({"design", kDelta, "--param", "arm=250:350", "--steps", "2", "--box=2000:2100,0:100,-800:-700",
                      "--step", "50", "--min-stiffness", "1", "--json", json, "--quiet"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("none of the 2 designs reaches a point of the region"), std::string::npos) << r.err;
  r = run_cli({"design", kDelta, "--param", "arm=250:350", "--steps", "2", "--box=-100:100,-100:100,-750:-650",
               "--step", "100", "--min-stiffness", "1", "--wrench", "0,0,-1e9,0,0,0", "--json", json, "--quiet"});
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("no design has a point with a stiffness in the region"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(json));
}

TEST(DesignRobotCommand, CostAboveTheLimitIsRefusedWithItsTime) {
  const CliRun r = run_cli({"design", kDelta, "--param", "arm=250:350", "--param", "forearm=700:900", "--steps", "100",
                            "--step", "20", "--min-stiffness", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("10000 designs x 43706 region points"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" h on "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--max-postures"), std::string::npos) << r.err;
}

TEST(DesignRobotCommand, NotARobotFileAndNoTargetExit2) {
  const CliRun none = run_cli({"design", "--param", "arm=1:2", "--step", "10", "--min-stiffness", "1"});
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("give a robot file"), std::string::npos) << none.err;
  const CliRun model = run_cli({"design", std::string(KINESTAT_SOURCE_DIR) + "/models/orthoglide_puu.yaml", "--param",
                                "arm=1:2", "--step", "10", "--min-stiffness", "1"});
  EXPECT_EQ(model.code, 2);
  EXPECT_NE(model.err.find("not a robot file"), std::string::npos) << model.err;
}

}  // namespace
}  // namespace kinestat::cli
