// Bad input by class through the commands (docs/reliability.md): sizes refused before anything is
// allocated, values checked after unit conversion, impossible identifications and loads reported as
// bad input (exit 2) with the item named, never an internal failure (exit 1) or a silent default.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <sys/wait.h>

#include "cli_run.hpp"
#include "kinestat/cli/app.hpp"

namespace kinestat::cli {
namespace {

const std::string kSource = KINESTAT_SOURCE_DIR;
const std::string kBar = kSource + "/meshes/bar.off";
const std::string kPuu = kSource + "/models/orthoglide_puu.yaml";
const std::string kTargets = kSource + "/models/orthoglide_paper_targets.yaml";

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

// Runs the command; expects exit `code`, nothing printed for a refusal, and `parts` in stderr.
void expect_exit(const std::vector<std::string>& args, int code, std::initializer_list<std::string> parts) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.code, code) << r.err;
  for (const std::string& p : parts) expect_contains(r.err, p);
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("kinestat_bad_input_" + name);
  std::ofstream(path) << text;
  return path.string();
}

TEST(BadInput, SizesAreRefusedBeforeAllocatingNamingTheOptionThatRaisesThem) {
  expect_exit({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--vtk-grid", "100000", "--vtk",
               std::filesystem::temp_directory_path() / "kinestat_bad_input_vtk"},
              kExitBadInput, {"--vtk-grid 100000: about 1e+15 grid points", "--max-points"});
  expect_exit({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--search-points", "1000000"}, kExitBadInput,
              {"--search-points 1000000", "--max-points"});
  expect_exit({"link-stiffness", kBar, "--clamp", "x=0", "--reference", "x=200", "--size", "0.3"}, kExitBadInput,
              {"about 1.81e+07 tetrahedra", "--max-elements"});
  expect_exit({"vjm", kPuu, "--max-coordinates", "10"}, kExitBadInput, {"coordinates", "--max-coordinates"});
  expect_exit({"link-stiffness", write_temp("header.off", "OFF\n8 1000000000 0\n0 0 0\n"), "--clamp", "x=0",
               "--reference", "x=1"},
              kExitBadInput, {"announces 8 vertices and 1000000000 faces"});
}

// --stations is estimated before the solve: beams x load cases x stations against --max-stations
// (default 1e6). A cantilever of 101 beams at --stations 10000 is 1.01e6 stations, refused in
// milliseconds (2700 beams grew past 23 GB before). models/loaded_beam.yaml (1 beam, 4 load cases)
// at --stations 11 is 44 stations: refused at --max-stations 43 with the largest --stations that
// fits (10), solved at 44.
TEST(BadInput, StationsAreEstimatedAgainstTheirLimit) {
  std::string yaml = "units: SI\nnodes:\n";
  for (int i = 0; i <= 101; ++i)
    yaml += "  - {id: n" + std::to_string(i) + ", xyz: [" + std::to_string(i) + ", 0, 0]}\n";
  yaml += "materials:\n  - {id: s, E: 210e9, nu: 0.3}\nsections:\n  - {id: t, type: rectangle, b: 0.02, h: 0.03}\n";
  yaml += "beams:\n";
  for (int i = 0; i < 101; ++i)
    yaml += "  - {id: b" + std::to_string(i) + ", nodes: [n" + std::to_string(i) + ", n" + std::to_string(i + 1) +
            "], material: s, section: t}\n";
  yaml += "supports:\n  - {node: n0, fixed: all}\nload_cases:\n  - name: tip\n    loads:\n";
  yaml += "      - {node: n101, force: [0, -10, 0]}\n";
  expect_exit({"solve", write_temp("101_beams.yaml", yaml), "--stations", "10000", "--json", "-"}, kExitBadInput,
              {"--stations 10000: 101 beams x 1 load case x 10000 stations: about 1.01e+06 stations",
               "above the limit of 1e+06", "give a smaller --stations (at most 9900 here), or raise --max-stations"});
  const std::string loaded = kSource + "/models/loaded_beam.yaml";
  expect_exit({"solve", loaded, "--stations", "11", "--max-stations", "43", "--json", "-"}, kExitBadInput,
              {"1 beam x 4 load cases x 11 stations: about 44 stations", "at most 10 here"});
  const CliRun r = run_cli({"solve", loaded, "--stations", "11", "--max-stations", "44", "--json", "-", "--quiet"});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("beam_stations"), std::string::npos);
}

TEST(BadInput, OptionValuesAreCheckedNotReplacedByDefaults) {
  const std::vector<std::string> bar = {"link-stiffness", kBar, "--clamp", "x=0", "--reference", "x=200"};
  auto with = [&](std::initializer_list<std::string> extra) {
    std::vector<std::string> a = bar;
    a.insert(a.end(), extra);
    return a;
  };
  expect_exit(with({"--size", "-5"}), kExitBadInput, {"--size = -5 mm must be positive"});
  expect_exit(with({"--size", "nan"}), kExitBadInput, {"--size = nan mm is not a finite number"});
  expect_exit(with({"--material", "E=210000,nu=0.3,G=80000"}), kExitBadInput, {"unknown item 'G=80000'"});
  expect_exit({"link-stiffness", kBar, "--clamp", "x=1e300", "--reference", "x=200"}, kExitBadInput,
              {"--clamp x=1e300 = 1e+300 mm is too large for a length"});
  expect_exit({"vjm", kPuu, "--point", "nan,0,0"}, kExitBadInput,
              {"--point component 1 = nan mm is not a finite number"});
}

TEST(BadInput, IdentificationThatCannotSucceedIsBadInput) {
  expect_exit({"identify", kPuu, kTargets, "--tolerance", "nan"}, kExitBadInput,
              {"--tolerance: 'nan' is not a finite number above 0"});
  // Targets files in mm-N-s: `inputs` then one target per line of `targets` (lines 4, 5, ...).
  auto targets = [](const std::string& name, const std::string& inputs, std::initializer_list<std::string> lines) {
    std::string text = "units: mm-N-s\ninputs: [" + inputs + "]\ntargets:\n";
    for (const std::string& l : lines) text += "  - {architecture: 3-PUU, " + l + "}\n";
    return write_temp(name, text);
  };
  const std::string q0_x = "point: [0, 0, 0], row: 0, col: 0, value: 2.78e-4";
  const std::string repeated = targets("repeated.yaml", "actuator_stiffness, foot_length", {q0_x, q0_x});
  expect_exit({"identify", kPuu, repeated}, kExitBadInput,
              {repeated + ":5: target 'target #2': the same term as target 'target #1'"});
  const std::string inert = targets("inert.yaml", "actuator_stiffness, parallelogram_width",
                                    {q0_x, "point: [0, 0, 0], row: 3, col: 3, value: 20.9e-7"});
  expect_exit({"identify", kPuu, inert}, kExitBadInput, {"parallelogram width (m) has no effect on the targets"});
  const std::string negative =
      targets("negative.yaml", "actuator_stiffness", {"point: [0, 0, 0], row: 0, col: 0, value: -1e-4"});
  expect_exit({"identify", kPuu, negative}, kExitBadInput, {negative + ":4: target #1: 'value' = -0.0001 mm/N"});
  const std::string far =
      targets("far.yaml", "actuator_stiffness", {"point: [0, 400, 0], row: 0, col: 0, value: 2.78e-4"});
  expect_exit({"identify", kPuu, far}, kExitBadInput, {far + ":4: target 'target #1': ", "out of reach"});
}

TEST(BadInput, ALoadWithNoEquilibriumIsTheUsersLoadNotAnInternalFailure) {
  // 1e9 N on the Orthoglide: far beyond buckling; the equilibrium does not exist.
  const CliRun r = run_cli({"vjm", kPuu, "--wrench", "1e9,0,0,0,0,0"});
  EXPECT_TRUE(r.code == kExitBadInput || r.code == kExitSingular) << r.code << ": " << r.err;
  EXPECT_NE(r.code, kExitInternal);
}

// KINESTAT_ASAN: defined by tests/CMakeLists.txt in the sanitizer build.
TEST(BadInput, OutOfMemoryIsAMessageAndExitOneNotAnAbort) {
#ifdef KINESTAT_ASAN
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#else
  // main() catches std::bad_alloc: 400^3 joint-grid points (~10 GB) under a 1 GB address-space limit.
  const std::string kinestat = std::string(KINESTAT_BINARY_DIR) + "/src/cli/kinestat";
  const std::string err = (std::filesystem::temp_directory_path() / "kinestat_oom.err").string();
  const std::string cmd =
      "ulimit -v 1000000; '" + kinestat +
      "' design orthoglide --cube 200 --mu 0.5 --strategy 1 --vtk-grid 400 --max-points 1e9 --vtk '" +
      (std::filesystem::temp_directory_path() / "kinestat_oom_vtk").string() + "' >/dev/null 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal: " << status;
  EXPECT_EQ(WEXITSTATUS(status), kExitInternal);
  std::ifstream in(err);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  expect_contains(text, "kinestat: out of memory");
#endif
}

}  // namespace
}  // namespace kinestat::cli
