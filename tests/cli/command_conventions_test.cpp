// The conventions every command shares: --version, --json FILE and --json - (JSON alone on stdout),
// --quiet, option units (mm-N-s), one failure report with exit status 0 / 1 / 2 / 3 per command,
// refused contradictory options, and VTK files that carry their units.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "kinestat/cli/app.hpp"

namespace kinestat::cli {
namespace {

const std::string kSource = KINESTAT_SOURCE_DIR;
const std::string kModels = kSource + "/models/";
const std::string kBar = kSource + "/meshes/bar.off";
const std::vector<std::string> kBarLink = {"link-stiffness", kBar, "--clamp", "x=0", "--reference", "x=200"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::path(KINESTAT_BINARY_DIR) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

// The field-data "units" strings of a .vtu file.
std::vector<std::string> vtu_units(const std::filesystem::path& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  std::vector<std::string> units;
  auto* a = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("units"));
  if (a)
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i) units.push_back(a->GetValue(i));
  return units;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// A VJM model of one Orthoglide leg alone: its passive joints leave the "platform" free to move.
std::string single_leg_model() {
  const std::string path = std::string(KINESTAT_BINARY_DIR) + "/vjm_single_leg.yaml";
  std::ofstream(path) << R"(units: mm-N-s
chains:
  - name: PUU leg x
    elements:
      - {name: base, rotate: {axis: [0, 0, 1], angle: 180}}
      - {name: actuator, actuator: {type: prismatic, axis: [-1, 0, 0], value: 310.6, stiffness: 2.0e4}}
      - {passive: {type: revolute, axis: [0, 0, 1], q: 0}}
      - {passive: {type: revolute, axis: [0, 1, 0], q: 0}}
      - {translate: [310.6, 0, 0]}
      - {name: leg, spring: {cantilever: {E: 70000, nu: 0.33, section: {type: tube, d: 20, t: 2}, length: 310.6}}}
      - {passive: {type: revolute, axis: [0, 1, 0], q: 0}}
      - {passive: {type: revolute, axis: [0, 0, 1], q: 0}}
)";
  return path;
}

TEST(CommandConventions, VersionNamesKinestatAndTheNumericalLibraries) {
  const CliRun r = run_cli({"--version"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_EQ(r.out.rfind("kinestat 0.", 0), 0u) << r.out;            // project(VERSION) of CMakeLists.txt
  EXPECT_NE(r.out.find("CHOLMOD 3."), std::string::npos) << r.out;  // the loaded SuiteSparse 5 library
  EXPECT_NE(r.out.find("BLAS: "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("no BLAS mapped"), std::string::npos) << r.out;  // CHOLMOD links it: it is loaded
  EXPECT_NE(r.out.find("Eigen 3.4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("VTK 9."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("CGAL 5."), std::string::npos) << r.out;
}

// Every command with `--json -`: stdout is exactly one JSON document of the command's schema, the
// report goes to stderr; with --quiet too, stderr stays empty.
TEST(CommandConventions, JsonToStdoutForEveryCommand) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> commands = {
      {{"solve", kModels + "five_bar.yaml"}, "kinestat-msa-results"},
      {{"buckling", kModels + "euler_column.yaml"}, "kinestat-buckling-results"},
      {{"modes", kModels + "euler_column.yaml"}, "kinestat-modes-results"},
      {{"fivebar", "--theta1", "64", "--theta2", "75"}, "kinestat-msa-results"},
      {{"vjm", kModels + "orthoglide_puu.yaml", "--wrench", "10,0,0,0,0,0"}, "kinestat-vjm-results"},
      {{"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "2", "--search-points", "5"},
       "kinestat-orthoglide-design"},
      {{"identify", kModels + "orthoglide_puu.yaml", kModels + "orthoglide_paper_targets.yaml"},
       "kinestat-identification"},
      {with(kBarLink, {"--size", "20"}), "kinestat-link-stiffness"},
      {{"map", "fivebar", "--step", "25"}, "kinestat-workspace-map"},
  };
  for (const auto& [args, schema] : commands) {
    const CliRun r = run_cli(with(args, {"--json", "-"}));
    ASSERT_EQ(r.code, kExitOk) << args[0] << ": " << r.err;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << args[0] << " wrote more than JSON:\n" << r.out.substr(0, 500);
    EXPECT_EQ(j.at("schema"), schema) << args[0];
    EXPECT_TRUE(j.contains("units")) << args[0];
    EXPECT_FALSE(r.err.empty()) << args[0] << ": the report should be on stderr";

    const CliRun quiet = run_cli(with(args, {"--json", "-", "--quiet"}));
    ASSERT_EQ(quiet.code, kExitOk) << args[0] << ": " << quiet.err;
    EXPECT_EQ(nlohmann::json::parse(quiet.out).at("schema"), schema) << args[0];
    EXPECT_TRUE(quiet.err.empty()) << args[0] << ": " << quiet.err;
  }
}

TEST(CommandConventions, JsonFileIsWrittenWithItsFolderAndAnUnwritablePathIsBadInput) {
  const auto dir = fresh_dir("conventions_json");
  const std::string file = (dir / "sub" / "design.json").string();
  CliRun r = run_cli({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "1", "--json", file});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(file));
  // Strategy 1 at mu = 0.5 for a 200 mm cube: L = 310.6 mm, the Orthoglide prototype's (docs/orthoglide.md).
  EXPECT_NEAR(j.at("designs").at(0).at("link_length").get<double>(), 0.3106, 5e-4);
  EXPECT_NEAR(j.at("cube_size").get<double>(), 0.2, 1e-12);  // SI although --cube is in mm

  r = run_cli({"fivebar", "--theta1", "64", "--theta2", "75", "--json", "/proc/kinestat/five_bar.json"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err.rfind("kinestat fivebar: /proc/kinestat/five_bar.json", 0), 0u) << r.err;
}

// --point of fivebar is in mm like every length option; the JSON gives it back in m.
TEST(CommandConventions, FiveBarPointIsInMillimetres) {
  const CliRun r = run_cli({"fivebar", "--point", "33.338451196,134.483336761", "--mode", "+-", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out).at("five_bar");
  // Table 1 row 14 of Gonçalves et al. 2010: theta1 = 64 deg, theta2 = 75 deg.
  EXPECT_NEAR(j.at("theta1").get<double>() * 180 / std::numbers::pi, 64.0, 1e-6);
  EXPECT_NEAR(j.at("theta2").get<double>() * 180 / std::numbers::pi, 75.0, 1e-6);
  EXPECT_NEAR(j.at("point")[0].get<double>(), 0.033338451196, 1e-12);
}

// --wrench moments are in N mm: 1000 N mm about z turns the 3-PRPaR platform by C_rz,rz * 1 N m (the
// 10 N along x changes it by ~6e-5 relative at Q0; read as N m the rotation would be 1000 times more).
TEST(CommandConventions, VjmWrenchMomentsAreInNewtonMillimetres) {
  const CliRun r = run_cli({"vjm", kModels + "orthoglide_prpar.yaml", "--wrench", "10,0,0,0,0,1000", "--json", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double c = j.at("unloaded").at("compliance")[5][5].get<double>();  // rad/(N m)
  const auto& loaded = j.at("loaded");
  EXPECT_NEAR(loaded.at("moment")[2].get<double>(), 1.0, 1e-9);  // N m in the JSON
  EXPECT_NEAR(loaded.at("rotation")[2].get<double>(), c, 1e-3 * c);
  EXPECT_NE(r.err.find(" N mm"), std::string::npos);  // the report states the unit it prints
}

// E in --material is in MPa: E=210000,nu=0.3 is the built-in steel.
TEST(CommandConventions, LinkStiffnessModulusIsInMegapascals) {
  const CliRun steel = run_cli(with(kBarLink, {"--size", "20", "--material", "steel", "--json", "-", "--quiet"}));
  const CliRun mpa =
      run_cli(with(kBarLink, {"--size", "20", "--material", "E=210000,nu=0.3", "--json", "-", "--quiet"}));
  ASSERT_EQ(steel.code, kExitOk) << steel.err;
  ASSERT_EQ(mpa.code, kExitOk) << mpa.err;
  const auto a = nlohmann::json::parse(steel.out).at("stiffness"), b = nlohmann::json::parse(mpa.out).at("stiffness");
  for (int i = 0; i < 6; ++i)  // the same mesh and matrix, up to the BLAS's threaded round-off
    EXPECT_NEAR(b[i][i].get<double>() / a[i][i].get<double>(), 1.0, 1e-9) << i;
  const CliRun bad = run_cli(with(kBarLink, {"--material", "E=-5,nu=0.3"}));
  EXPECT_EQ(bad.code, kExitBadInput);
  EXPECT_NE(bad.err.find("-5 MPa"), std::string::npos) << bad.err;  // the value in the unit it was written in
}

TEST(CommandConventions, ExitCodeForMapsEveryStatus) {
  EXPECT_EQ(exit_code_for(Status::Ok()), kExitOk);
  EXPECT_EQ(exit_code_for(Status::Invalid("x")), kExitBadInput);
  EXPECT_EQ(exit_code_for(Status::Singular("x")), kExitSingular);
  EXPECT_EQ(exit_code_for(Status::Internal("x")), kExitInternal);
  // Not converging on the user's input is a property of that input (docs/reliability.md).
  EXPECT_EQ(exit_code_for(Status(StatusCode::kNotConverged, "x")), kExitBadInput);
  std::ostringstream out, err;
  Context ctx{out, err};
  EXPECT_EQ(report_failure(ctx, "solve", Status::Internal("CHOLMOD ran out of memory")), kExitInternal);
  EXPECT_EQ(err.str(), "kinestat solve: CHOLMOD ran out of memory\n");
  EXPECT_TRUE(out.str().empty());
}

// Each command's exit statuses through the one report: "kinestat CMD: message" on stderr, nothing
// on stdout for a failure before any result. Exit 1 (internal failure) has no input that causes it
// (ExitCodeForMapsEveryStatus checks the mapping).
TEST(CommandConventions, EveryCommandReportsFailuresTheSameWay) {
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string in_err;  // expected in the message ("" for success)
  };
  const std::string bad_targets = std::string(KINESTAT_BINARY_DIR) + "/conventions_bad_targets.yaml";
  std::ofstream(bad_targets) << "inputs: [actuator_stiffness]\ntargets: []\n";
  const std::vector<Case> cases = {
      {{"solve", kModels + "cantilever.yaml"}, kExitOk, ""},
      {{"solve", kModels + "missing.yaml"}, kExitBadInput, "missing.yaml"},
      {{"solve", kModels + "cantilever.yaml", "--vtk"}, kExitBadInput, "--vtk"},
      {{"solve", kModels + "released_chain.yaml"}, kExitSingular, ""},
      {{"fivebar", "--theta1", "64", "--theta2", "75"}, kExitOk, ""},
      {{"fivebar", "--theta1", "64", "--theta2", "75", "--point", "30,130"}, kExitBadInput, "--point"},
      {{"fivebar", "--theta1", "64", "--theta2", "75", "--mode", "+-"}, kExitBadInput, "--mode"},
      {{"fivebar", "--point", "30,130", "--assembly", "down"}, kExitBadInput, "--assembly"},
      {{"fivebar", "--theta1", "64"}, kExitBadInput, "--theta2"},
      {{"fivebar", "--theta1", "30", "--theta2", "30"}, kExitSingular, ""},
      {{"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "3", "--search-points", "5"},
       kExitOk,
       ""},
      {{"design", "orthoglide", "--cube", "200", "--mu", "1.5"}, kExitBadInput, "--mu"},
      {{"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--vtk-grid", "5"}, kExitBadInput, "--vtk"},
      {{"vjm", kModels + "orthoglide_prpar.yaml"}, kExitOk, ""},
      {{"vjm", kModels + "orthoglide_prpar.yaml", "--wrench", "1,0,0"}, kExitBadInput, "--wrench takes 6 numbers"},
      {{"vjm", single_leg_model()}, kExitSingular, ""},
      {{"identify", kModels + "orthoglide_puu.yaml", bad_targets}, kExitBadInput, "conventions_bad_targets.yaml"},
      {with(kBarLink, {"--size", "20"}), kExitOk, ""},
      {with(kBarLink, {"--unit", "inch"}), kExitBadInput, "--unit"},
      // Clamped along one edge only: the bar turns freely about it.
      {{"link-stiffness", kBar, "--clamp", "box:-1,-11,-16,150,-9,-14", "--reference", "x=200", "--size", "20"},
       kExitSingular,
       ""},
  };
  for (const Case& c : cases) {
    const CliRun r = run_cli(c.args);
    const std::string name = c.args[0] == "design" ? "design orthoglide" : c.args[0];
    EXPECT_EQ(r.code, c.code) << name << " " << c.args.back() << "\nstderr: " << r.err;
    if (c.code == kExitBadInput) {
      EXPECT_EQ(r.err.rfind("kinestat " + name + ": ", 0), 0u) << r.err;
      EXPECT_NE(r.err.find(c.in_err), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
  }
}

// A singular result is explained in the report; with --quiet (no report) the reason still reaches
// stderr, through the same one-line-prefix report as every failure.
TEST(CommandConventions, QuietSingularResultsStillSayWhy) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"solve", kModels + "released_chain.yaml"},
                                               std::vector<std::string>{"fivebar", "--theta1", "30", "--theta2", "30"},
                                               std::vector<std::string>{"vjm", single_leg_model()}}) {
    const CliRun r = run_cli(with(args, {"--quiet"}));
    EXPECT_EQ(r.code, kExitSingular) << args[0];
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("kinestat " + args[0] + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(args[0] == "vjm" ? "zero stiffness" : "free motion 1"), std::string::npos) << r.err;
  }
}

TEST(CommandConventions, VtkFilesCarryTheirUnits) {
  const auto dir = fresh_dir("conventions_vtk");
  ASSERT_EQ(run_cli({"solve", kModels + "cantilever.yaml", "--vtk", dir.string(), "--quiet"}).code, kExitOk);
  const auto msa = vtu_units(dir / "cantilever_case1.vtu");
  EXPECT_TRUE(contains(msa, "coordinates: m")) << msa.size();
  EXPECT_TRUE(contains(msa, "displacement: m"));
  EXPECT_TRUE(contains(msa, "reaction_moment: N m"));

  ASSERT_EQ(run_cli({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "2", "--vtk", dir.string(),
                     "--vtk-grid", "3", "--search-points", "5", "--quiet"})
                .code,
            kExitOk);
  const auto workspace = vtu_units(dir / "orthoglide_s2_cube.vtu");
  EXPECT_TRUE(contains(workspace, "coordinates: m"));
  EXPECT_TRUE(contains(workspace, "mu_min: -"));
}

}  // namespace
}  // namespace kinestat::cli
