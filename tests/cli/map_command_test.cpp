// kinestat map: JSON on stdout alone, the summary, the Orthoglide slice, refusals naming the option,
// and an empty region refused without writing a file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::cli {
namespace {

const std::string kSource = KINESTAT_SOURCE_DIR;
const std::string kPuu = kSource + "/models/orthoglide_puu.yaml";

TEST(MapCommand, FiveBarJsonToStdoutIsTheOnlyOutput) {
  const CliRun r = run_cli({"map", "fivebar", "--step", "25", "--mode=+-", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // throws if anything else is on stdout
  EXPECT_EQ(j["schema"], "kinestat-workspace-map");
  const auto& dims = j["grid"]["dimensions"];
  EXPECT_EQ(j["fields"]["k_t_min"].size(), dims[0].get<std::size_t>() * dims[1].get<std::size_t>());
  EXPECT_EQ(dims[2], 1);
  EXPECT_FALSE(j["fields"].contains("deflection_t"));       // no --load
  EXPECT_FALSE(j["fields"].contains("newton_iterations"));  // no loaded mode
  EXPECT_GT(j["summary"]["status_counts"]["ok"].get<int>(), 0);
  EXPECT_NE(j["description"].get<std::string>().find("+-"), std::string::npos);
  // The default region is the workspace box widened to the step: its corners are multiples of 25 mm.
  const double x0 = j["grid"]["origin"][0].get<double>() * 1e3;
  EXPECT_NEAR(x0, 25 * std::round(x0 / 25), 1e-9);
}

TEST(MapCommand, FiveBarSummaryInMillimetres) {
  const CliRun r = run_cli({"map", "fivebar", "--region", "-100:100,50:150", "--step", "50", "--load", "10,0,0,0,0,0",
                            "--min-stiffness", "1"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("grid 5 x 3 x 1 = 15 points, step 50 mm: x -100:100 mm, y 50:150 mm"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("reachable area"), std::string::npos);
  EXPECT_NE(r.out.find("k_t_min >= 1 N/mm"), std::string::npos);
  EXPECT_NE(r.out.find("deflection_t         mm"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // a short run prints no progress
}

TEST(MapCommand, OrthoglideSliceUnderAWrench) {
  const CliRun r =
      run_cli({"map", kPuu, "--box", "-40:40,-40:40,10", "--step", "40", "--wrench", "100,0,0,0,0,500", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["grid"]["dimensions"], nlohmann::json::array({3, 3, 1}));
  EXPECT_DOUBLE_EQ(j["grid"]["origin"][2].get<double>(), 0.01);
  ASSERT_EQ(j["fields"]["deflection_t"].size(), 9u);
  for (const auto& v : j["fields"]["deflection_t"]) {
    ASSERT_TRUE(v.is_number());
    EXPECT_GT(v.get<double>(), 0.0);
  }
  EXPECT_EQ(j["summary"]["status_counts"]["unreachable"], 0);
  // Loaded mode: the equilibrium's Newton steps at every point, at least one per chain.
  ASSERT_EQ(j["fields"]["newton_iterations"].size(), 9u);
  for (const auto& v : j["fields"]["newton_iterations"]) EXPECT_GE(v.get<double>(), 3.0);
}

// Weakest and stiffest direction under a force, from a compliance: 1 / eigenvalues of C_tt.
std::pair<double, double> force_stiffness_range(const Mat6& C) {
  const Vec3 c = Eigen::SelfAdjointEigenSolver<Mat3>(C.topLeftCorner<3, 3>()).eigenvalues();
  return {1 / c(2), 1 / c(0)};
}

// The map's values equal what the single-posture paths give, whichever kernel the command uses.
// The five-bar: its VJM (`kinestat map fivebar --method vjm`'s model by the other method, exact for
// beams and well conditioned) to 1e-9 + 2e-15 cond(K) (round-off of any solve); `kinestat fivebar`'s
// msa::solve to 1e-5, its own accuracy: the 2e11 N/m joint springs cost the nodal 36x36 ~7 digits
// (posture_kernels_test.cpp). The Orthoglide: `kinestat vjm`'s path.
TEST(MapCommand, ValuesEqualTheSinglePostureCommands) {
  const Vec6 load = (Vec6() << 3.0, -2.0, 0.0, 0.0, 0.0, 0.0).finished();
  const CliRun r = run_cli(
      {"map", "fivebar", "--region", "-100:100,0:150", "--step", "25", "--load", "3,-2,0,0,0,0", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const mechanisms::FiveBarParams params;
  int compared = 0;
  for (std::size_t i = 0; i < j["status"].size(); ++i) {
    if (j["status"][i] != 0) continue;  // ok points: the others may sit on a threshold
    const double x = -0.1 + 0.025 * static_cast<double>(i % 9), y = 0.025 * static_cast<double>(i / 9);
    auto q = mechanisms::inverse_kinematics(params, mechanisms::Vec2(x, y), mechanisms::WorkingMode{1, 1});
    ASSERT_TRUE(q.ok());
    auto vjm = vjm::platform_unloaded_stiffness(mechanisms::five_bar_vjm_chains(params, *q));
    const msa::Solution sol = msa::solve(mechanisms::make_five_bar_structure(params, *q));
    ASSERT_TRUE(vjm.ok() && vjm->compliance_defined && sol.cartesian && sol.cartesian->stiffness_defined);
    const double tol = 1e-9 + 2e-15 * j["fields"]["condition_number"][i].get<double>();
    const Mat6& C = vjm->compliance;
    const auto [k_min, k_max] = force_stiffness_range(C);
    const double d = (C * load).head<3>().norm();
    const double map_k_min = j["fields"]["k_t_min"][i].get<double>();
    EXPECT_NEAR(map_k_min, k_min, tol * k_min) << i;
    EXPECT_NEAR(j["fields"]["k_t_max"][i].get<double>(), k_max, tol * k_max) << i;
    EXPECT_NEAR(j["fields"]["deflection_t"][i].get<double>(), d, tol * d) << i;
    EXPECT_NEAR(map_k_min, force_stiffness_range(sol.cartesian->compliance).first, 1e-5 * k_min) << i;
    ++compared;
  }
  EXPECT_GT(compared, 20);

  const CliRun o = run_cli({"map", kPuu, "--box", "-40:40,-40:40,10", "--step", "40", "--json", "-"});
  ASSERT_EQ(o.code, kExitOk) << o.err;
  const nlohmann::json m = nlohmann::json::parse(o.out);
  auto model = io::read_vjm_model_yaml(kPuu);
  ASSERT_TRUE(model.ok());
  for (std::size_t i = 0; i < 9; ++i) {
    const Vec3 p(-0.04 + 0.04 * static_cast<double>(i % 3), -0.04 + 0.04 * static_cast<double>(i / 3), 0.01);
    auto chains = io::vjm_model_chains(*model, p);
    ASSERT_TRUE(chains.ok());
    auto K = vjm::platform_unloaded_stiffness(*chains);
    ASSERT_TRUE(K.ok() && K->compliance_defined);
    const auto [k_min, k_max] = force_stiffness_range(K->compliance);
    EXPECT_NEAR(m["fields"]["k_t_min"][i].get<double>(), k_min, 1e-9 * k_min) << i;
    EXPECT_NEAR(m["fields"]["k_t_max"][i].get<double>(), k_max, 1e-9 * k_max) << i;
  }
}

struct BadCase {
  std::vector<std::string> args;
  std::string option;  // the message must name it
};

TEST(MapCommand, BadOptionsExitTwoNamingTheOption) {
  const std::vector<BadCase> cases = {
      {{"map", "fivebar", "--step", "0"}, "--step"},
      {{"map", "fivebar", "--step", "-5"}, "--step"},
      {{"map", "fivebar", "--region", "100:0,0:200"}, "--region"},
      {{"map", "fivebar", "--region", "a:b,0:200"}, "--region"},
      {{"map", "fivebar", "--region", "0:100"}, "--region"},
      {{"map", "fivebar", "--mode", "+x"}, "--mode"},
      {{"map", "fivebar", "--assembly", "left"}, "--assembly"},
      {{"map", "fivebar", "--method", "fem"}, "--method"},
      {{"map", "fivebar", "--field", "stiffness"}, "--field"},
      {{"map", "fivebar", "--field", "deflection_t"}, "--field"},
      {{"map", "fivebar", "--load", "1,2"}, "--load"},
      {{"map", "fivebar", "--min-stiffness", "-1"}, "--min-stiffness"},
      {{"map", "fivebar", "--step", "0.01"}, "--max-points"},
      {{"map", "fivebar", "--step", "0.01", "--threads", "2"}, "min on 2 threads), more than --max-points"},
      {{"map", "fivebar", "--box", "0:1,0:1,0:1"}, "--box"},
      {{"map", "fivebar", "--wrench", "1,0,0,0,0,0"}, "--wrench"},
      {{"map", kPuu, "--step", "10"}, "--box"},
      {{"map", kPuu, "--box", "0:10,0:10,0"}, "--step"},
      {{"map", kPuu, "--box", "0:10,0:10", "--step", "5"}, "--box"},
      {{"map", kPuu, "--box", "0:10,0,0", "--step", "5"}, "--box"},
      {{"map", kPuu, "--box", "0:10,0:10,0", "--step", "5", "--region", "0:1,0:1"}, "--region"},
      {{"map", kPuu, "--box", "0:10,0:10,0", "--step", "5", "--mode", "+-"}, "--mode"},
      {{"map", kPuu, "--box", "0:10,0:10,0", "--step", "5", "--load", "1,1"}, "--load"},
      // Loads range-checked as lengths are (issue 21): 1e300 N is no load, a typo; a size_t option
      // took -1 as 2^64 - 1.
      {{"map", "fivebar", "--load", "1e300,0,0,0,0,0"}, "--load component 1"},
      {{"map", kPuu, "--box", "0:10,0:10,0", "--step", "5", "--wrench", "0,0,0,0,0,1e300"}, "--wrench component 6"},
      {{"map", kPuu, "--box", "0:10,0:10,0", "--step", "5", "--load", "0,0,1e12,0,0,0"}, "--load component 3"},
      {{"map", "fivebar", "--max-points", "-1"}, "--max-points"},
      // No NaN through, no DBL_MAX printed in full; no more threads than the cores (the scheduler
      // ignored them with a warning).
      {{"map", "fivebar", "--max-points", "0"}, "--max-points: '0' is not a finite number above 0;"},
      {{"map", "fivebar", "--threads", "100000"}, "--threads 100000: this process may run"},
  };
  for (const BadCase& c : cases) {
    const CliRun r = run_cli(c.args);
    std::string line;
    for (const std::string& a : c.args) line += a + " ";
    EXPECT_EQ(r.code, kExitBadInput) << line << "\n" << r.err;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << line << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << line;
  }
}

TEST(MapCommand, ChainsModelIsRefused) {
  const CliRun r = run_cli({"map", kSource + "/tests/io/data/vjm_puu_q0.yaml", "--box", "0:10,0:10,0", "--step", "5"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("mechanism: orthoglide"), std::string::npos) << r.err;
}

TEST(MapCommand, EmptyRegionExitsTwoAndWritesNothing) {
  const auto dir = std::filesystem::temp_directory_path() / "kinestat_map_empty";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "m.json").string(), vti = (dir / "m.vti").string();
  const CliRun r =
      run_cli({"map", "fivebar", "--region", "500:600,500:600", "--step", "20", "--json", json, "--vti", vti});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("no reachable point"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--region"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(json));
  EXPECT_FALSE(std::filesystem::exists(vti));
  std::filesystem::remove_all(dir);
}

// A load that buckles every posture (issue 21): not a summary of NaN with exit 0, but the reason,
// exit 2, and no file.
TEST(MapCommand, EveryPointFailedIsAnErrorAndWritesNothing) {
  const auto dir = std::filesystem::temp_directory_path() / "kinestat_map_all_failed";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "m.json").string();
  const CliRun r = run_cli({"map", kPuu, "--box", "-10:10,-10:10,0", "--step", "10", "--wrench", "0,0,-1e9,0,0,0",
                            "--json", json, "--quiet"});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("no point of --box"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("9 failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("buckling"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(json));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kinestat::cli

namespace kinestat::cli {
namespace {

// A robot file maps with no option but the step (the region is its `workspace:`), and the JSON's
// values are those of the library's kernel at the same point.
TEST(MapCommand, RobotFileWithItsWorkspace) {
  const std::string file = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/planar_3rpr.yaml";
  const CliRun r = run_cli({"map", file, "--step", "50", "--json", "-"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NE(j.dump().find("planar 3-RPR"), std::string::npos);
  // --orientation on a robot without orientation in its task, --region on a robot: exit 2.
  const std::string delta = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/delta.yaml";
  CliRun bad = run_cli({"map", delta, "--step", "50", "--orientation", "0,0,5"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("commands no orientation"), std::string::npos) << bad.err;
  bad = run_cli({"map", delta, "--step", "50", "--region", "0:1,0:1"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--region"), std::string::npos) << bad.err;
  // A 3-PRS commands no x or y: a box that spans x is refused with the form to use.
  bad = run_cli({"map", std::string(KINESTAT_SOURCE_DIR) + "/models/robots/prs_head.yaml", "--step", "5", "--box",
                 "-10:10,0,300:400"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("commands no x"), std::string::npos) << bad.err;
}

// A map over orientation angles: the grid's axes are rx, ry (rad in JSON, deg on the command line)
// and each point's k_t_min is the kernel's at the pose (--position, the point's angles).
TEST(MapCommand, RobotOrientationMap) {
  const std::string file = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/hexapod.yaml";
  const CliRun r = run_cli(
      {"map", file, "--angles", "-10:10,-10:10,5", "--angle-step", "10", "--position", "20,0,820", "--json", "-"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["grid"]["axis_names"][0], "rx");
  EXPECT_EQ(j["grid"]["axis_units"][1], "rad");
  EXPECT_EQ(j["summary"]["reachable"]["unit"], "rad^2");
  auto model = io::read_robot_model(file);
  ASSERT_TRUE(model.ok());
  mechanisms::RobotKernelOptions o;
  o.model = std::make_shared<const mechanisms::RobotModel>(std::move(*model));
  const auto kernel = mechanisms::make_robot_kernel(o);
  const double deg = M_PI / 180.0;
  // Point (i, j) = (2, 0): rx = 10 deg, ry = -10 deg.
  mechanisms::RobotKernelOptions at = o;
  at.task = (VecX(6) << 0.02, 0.0, 0.82, 10 * deg, -10 * deg, 5 * deg).finished();
  const mechanisms::PostureResult p = mechanisms::make_robot_kernel(at)->evaluate(Vec3(0.02, 0.0, 0.82));
  ASSERT_EQ(p.status, mechanisms::PostureStatus::kOk);
  // k_t_min = lambda_min(C_tt^-1) (docs/maps.md).
  const double kt =
      Eigen::SelfAdjointEigenSolver<Mat3>(Mat3(p.compliance.topLeftCorner<3, 3>()).inverse()).eigenvalues()(0);
  EXPECT_NEAR(j["fields"]["k_t_min"][2].get<double>(), kt, 1e-9 * kt);
  // Without a workspace of angles in the file, --angle-step alone is refused; --step with --angles too.
  CliRun bad = run_cli({"map", file, "--angles", "-10:10,-10:10,0", "--step", "5"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--angle-step"), std::string::npos) << bad.err;
}

// A robot file without its `robot:` name is read as a robot file and the reader names the key; a
// folder is named as one, not read as an empty file.
TEST(MapCommand, MissingRobotKeyAndFolderAreNamed) {
  const std::string dir = ::testing::TempDir() + "/kinestat_map_robot_key";
  std::filesystem::create_directories(dir);
  const std::string file = dir + "/no_name.yaml";
  std::ofstream(file) << "task: [x, y, z]\ntool: [0, 0, 0]\nlegs: []\n";
  CliRun r = run_cli({"map", file, "--step", "10"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("missing required key 'robot'"), std::string::npos) << r.err;
  r = run_cli({"map", dir, "--step", "10"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("a folder, not the"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

// Task values the robot does not command are refused, not dropped (the 3-PRS head commands z, rx,
// ry: its legs set x and y), on `map` and `vjm` alike; 0 there is accepted. A position 1e6 m away
// (within the range of a length) ends at once: a head whose legs start with sliders has no reach
// bound, and its walk from home towards it took a minute per 1e6 mm before.
TEST(MapCommand, RobotTaskValuesNotCommandedAreRefused) {
  const std::string head = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/prs_head.yaml";
  const std::string delta = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/delta.yaml";
  CliRun r = run_cli({"map", head, "--angle-step", "5", "--position", "50,50,320", "--quiet"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--position: 3-PRS head does not command x"), std::string::npos) << r.err;
  r = run_cli({"vjm", head, "--point", "10,0,320"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--point: 3-PRS head does not command x"), std::string::npos) << r.err;
  r = run_cli({"vjm", delta, "--orientation", "0,10,0"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--orientation: Delta (Clavel) commands no orientation"), std::string::npos) << r.err;
  r = run_cli({"vjm", head, "--point", "0,0,320"});
  EXPECT_EQ(r.code, 0) << r.err;
  r = run_cli({"vjm", head, "--point", "0,0,1e9"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("too far to follow the closure"), std::string::npos) << r.err;
}

// --method msa on a robot file (docs/robots.md, "Stiffness"): the map's description names MSA, also
// on the hexapod (loops of exact ties); a load with MSA and an unknown method are refused, exit 2.
TEST(MapCommand, RobotFileByMsa) {
  const std::string robots = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/";
  const CliRun r = run_cli({"map", robots + "planar_3rpr.yaml", "--step", "50", "--method", "msa", "--json", "-"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(MSA, unloaded)"), std::string::npos);
  const CliRun hexapod = run_cli({"map", robots + "hexapod.yaml", "--step", "100", "--method", "msa", "--json", "-"});
  ASSERT_EQ(hexapod.code, 0) << hexapod.err;
  EXPECT_NE(hexapod.out.find("(MSA, unloaded)"), std::string::npos);
  CliRun bad = run_cli({"map", robots + "delta.yaml", "--step", "100", "--method", "msa", "--wrench", "0,0,-50,0,0,0"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("VJM only"), std::string::npos) << bad.err;
  bad = run_cli({"map", robots + "delta.yaml", "--step", "100", "--method", "fea"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("must be msa or vjm"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace kinestat::cli
