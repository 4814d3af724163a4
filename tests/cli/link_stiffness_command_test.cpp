// kinestat link-stiffness on the bundled bar: matrices against beam theory, exit codes, cache.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"
#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

const std::string kBar = std::string(KINESTAT_SOURCE_DIR) + "/meshes/bar.off";

CliRun run_link_stiffness(std::vector<std::string> args) {
  args.insert(args.begin(), "link-stiffness");
  return run_cli(args);
}

TEST(LinkStiffnessCommand, BarJsonMatchesBeamTheoryAndCacheReproducesIt) {
  const auto tmp = std::filesystem::temp_directory_path() / "kinestat_link_stiffness_cli";
  std::filesystem::remove_all(tmp);
  std::filesystem::create_directories(tmp);
  const std::string json = (tmp / "bar.json").string(), cache = (tmp / "cache").string();
  const std::vector<std::string> args = {kBar, "--material", "steel", "--clamp", "x=0", "--reference", "x=200",
                                         "--size", "7", "--json", json, "--cache", cache};
  CliRun r = run_link_stiffness(args);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("[N/m"), std::string::npos) << r.out;  // units are printed
  nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  // Axial stiffness EA / L of the 20 x 30 mm steel bar, 200 mm long: 630 MN/m (the solid's
  // clamped ends make it ~0.1-1 % stiffer).
  const double ea_l = 210e9 * 0.02 * 0.03 / 0.2;
  EXPECT_NEAR(j["stiffness"][0][0].get<double>() / ea_l, 1.0, 0.02);
  EXPECT_FALSE(j["from_cache"].get<bool>());
  EXPECT_LT(j["symmetry_error"]["stiffness"].get<double>(), 1e-6);

  // Second run: from the cache, same numbers.
  CliRun again = run_link_stiffness(args);
  ASSERT_EQ(again.code, kExitOk) << again.err;
  EXPECT_NE(again.out.find("from cache"), std::string::npos);
  nlohmann::json j2 = nlohmann::json::parse(std::ifstream(json));
  EXPECT_TRUE(j2["from_cache"].get<bool>());
  EXPECT_EQ(j2["compliance"], j["compliance"]);
  std::filesystem::remove_all(tmp);
}

TEST(LinkStiffnessCommand, BadInputExitsWith2AndSaysWhatToFix) {
  CliRun r = run_link_stiffness({kBar, "--clamp", "x=0", "--reference", "q=1"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--reference q=1"), std::string::npos) << r.err;
  r = run_link_stiffness({kBar, "--clamp", "x=-50", "--reference", "x=200", "--size", "20"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("clamp region"), std::string::npos) << r.err;
  r = run_link_stiffness({kBar, "--material", "wood", "--clamp", "x=0", "--reference", "x=200"});
  EXPECT_EQ(r.code, kExitBadInput);
  const auto open = std::filesystem::temp_directory_path() / "kinestat_open_surface.off";
  std::ofstream(open) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  r = run_link_stiffness({open.string(), "--clamp", "x=0", "--reference", "x=1"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find(open.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not closed"), std::string::npos) << r.err;
}

TEST(LinkStiffnessCommand, ConvergenceStudyOfTheBar) {
  const CliRun r = run_link_stiffness({kBar, "--material", "steel", "--clamp", "x=0", "--reference", "x=200", "--size",
                                       "10", "--convergence"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto at = r.out.find("Mesh convergence of the compliance diagonal");
  ASSERT_NE(at, std::string::npos) << r.out;
  // Three meshes (20, 14.1, 10 mm); the finest row's axial compliance is L/EA of the 20 x 30 mm
  // steel bar within 2 % (the solid's clamped ends make it slightly stiffer).
  std::istringstream rows(r.out.substr(at));
  std::string line;
  std::getline(rows, line);  // title
  std::getline(rows, line);  // column names
  double size = 0, dofs = 0, ux = 0;
  for (int i = 0; i < 3; ++i) {
    std::getline(rows, line);
    std::istringstream(line) >> size >> dofs >> ux;
  }
  EXPECT_NEAR(size, 0.01, 1e-9);
  EXPECT_NEAR(ux / (0.2 / (210e9 * 0.02 * 0.03)), 1.0, 0.02);
  EXPECT_NE(r.out.find("change, last 2 meshes"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::cli
