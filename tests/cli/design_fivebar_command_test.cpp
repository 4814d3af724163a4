// kinestat design fivebar: bad ranges and steps exit 2 naming the option; a region no design reaches
// exits 2 and writes nothing; --json - is JSON alone, its best design the one with the largest
// share; --png writes a PNG of the stated size.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

namespace fs = std::filesystem;

// 2 x 2 designs about the paper's five-bar, a coarse region above the base; `changes` replace or
// add options (as "--option=value", which also takes values that start with '-').
std::vector<std::string> small_run(const std::vector<std::pair<std::string, std::string>>& changes = {}) {
  std::vector<std::pair<std::string, std::string>> options = {{"--r1", "80:120"}, {"--r2", "90:130"},
                                                              {"--steps", "2"},   {"--region", "-60:60,80:180"},
                                                              {"--step", "20"},   {"--min-stiffness", "5"}};
  for (const auto& [name, value] : changes) {
    auto it = std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.first == name; });
    if (it != options.end())
      it->second = value;
    else
      options.emplace_back(name, value);
  }
  std::vector<std::string> args = {"design", "fivebar", "--quiet"};
  for (const auto& [name, value] : options) args.push_back(name + "=" + value);
  return args;
}

TEST(DesignFiveBarCommand, BadRangesAndStepsExit2NamingTheOption) {
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      {{"--r1", "abc"}, "--r1 'abc' is not a range in mm"},
      {{"--r1", "120:80"}, "--r1 120:80 is reversed"},
      {{"--r2", "0:100"}, "--r2 0:100 mm: link lengths must be positive"},
      {{"--steps", "1"}, "--steps 1"},
      {{"--region", "60:-60,80:180"}, "--region: the x range 60:-60 is reversed"},
      {{"--region", "-60:60"}, "--region takes 2 ranges"},
      {{"--step", "0"}, "--step 0 mm"},
      {{"--min-stiffness", "-1"}, "--min-stiffness -1 N/mm"},
      {{"--mode", "+x"}, "--mode '+x'"},
      {{"--step", "1e-4"}, "use a larger --step"},
  };
  for (const auto& [change, expected] : cases) {
    const CliRun r = run_cli(small_run({change}));
    EXPECT_EQ(r.code, 2) << expected;
    EXPECT_EQ(r.err.rfind("kinestat design fivebar: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// 1000 x 1000 designs over 10^4 region points is ~10^10 postures, hours: refused at once with the
// estimated time and the option that allows it (issue 21), never started.
TEST(DesignFiveBarCommand, HoursOfPosturesAreRefusedWithTheEstimate) {
  const CliRun r = run_cli(small_run({{"--steps", "1000"}, {"--step", "1"}}));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("1e+06 designs x 12221 region points: about 1.22e+10 postures"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" h on "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--max-postures"), std::string::npos) << r.err;
  const CliRun allowed = run_cli(small_run({{"--max-postures", "-5"}}));
  EXPECT_EQ(allowed.code, 2) << allowed.err;
  EXPECT_NE(allowed.err.find("--max-postures"), std::string::npos) << allowed.err;
}

TEST(DesignFiveBarCommand, UnreachableRegionExits2AndWritesNothing) {
  const std::string json = ::testing::TempDir() + "kinestat_design_unreachable.json";
  fs::remove(json);
  const CliRun r = run_cli({"design", "fivebar", "--r1", "80:120", "--r2", "90:130", "--steps", "2",
                            "--region=500:600,500:600", "--json", json, "--quiet"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no design reaches any point of --region"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(json));
}

TEST(DesignFiveBarCommand, JsonToStdoutNamesTheDesignWithTheLargestShare) {
  const CliRun r = run_cli(small_run({{"--json", "-"}}));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // stdout is the JSON and nothing else
  EXPECT_EQ(j["schema"], "kinestat-five-bar-design-sweep");
  const std::vector<double> share = j["fields"]["share"];
  ASSERT_EQ(share.size(), 4u);
  const auto best = static_cast<std::size_t>(std::max_element(share.begin(), share.end()) - share.begin());
  EXPECT_EQ(j["best"]["index"], best);
  EXPECT_DOUBLE_EQ(j["best"]["share"].get<double>(), share[best]);
  EXPECT_DOUBLE_EQ(j["best"]["r1"].get<double>(), j["fields"]["r1"][best].get<double>());
  EXPECT_DOUBLE_EQ(j["criteria"]["min_stiffness"].get<double>(), 5000.0);  // N/m from 5 N/mm
  EXPECT_EQ(j["region"]["dimensions"], nlohmann::json::array({7, 6, 1}));
  EXPECT_EQ(j["timing"]["postures"], 4 * 42);
}

// As every command's Output: with --json - and no --quiet the report goes to stderr, stdout stays JSON.
TEST(DesignFiveBarCommand, JsonToStdoutSendsTheReportToStderr) {
  std::vector<std::string> args = small_run({{"--json", "-"}});
  std::erase(args, "--quiet");
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["schema"], "kinestat-five-bar-design-sweep");
  EXPECT_NE(r.err.find("best design: r1 = "), std::string::npos) << r.err;
}

TEST(DesignFiveBarCommand, PngOfTheDesignMapHasTheStatedSize) {
  const std::string png = ::testing::TempDir() + "kinestat_design_map.png";
  fs::remove(png);
  std::vector<std::string> args = small_run({{"--png", png}});
  std::erase(args, "--quiet");  // --quiet drops the report
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("best design: r1 = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote " + png), std::string::npos) << r.out;
  // Width and height from the IHDR chunk (bytes 16..23, big-endian).
  std::ifstream in(png, std::ios::binary);
  std::array<unsigned char, 24> h{};
  in.read(reinterpret_cast<char*>(h.data()), h.size());
  ASSERT_TRUE(in);
  auto be32 = [&](int i) { return (h[i] << 24) | (h[i + 1] << 16) | (h[i + 2] << 8) | h[i + 3]; };
  EXPECT_EQ(std::string(&h[1], &h[4]), "PNG");
  EXPECT_EQ(be32(16), 1000);
  EXPECT_EQ(be32(20), 800);
  fs::remove(png);
}

}  // namespace
}  // namespace kinestat::cli
