// Output that cannot be written is a failed run (exit 2, the path named), never a success with the
// result lost: a full disk (/dev/full) under --json, --png, --vti, --vtk, and stdout on a full disk.
// That a failed or killed write leaves the earlier file is tested on the shared writer
// (tests/core/atomic_file_test.cpp), which every output file goes through.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

const std::string kModels = std::string(KINESTAT_SOURCE_DIR) + "/models/";
const std::vector<std::string> kSmallMap = {"map", "fivebar", "--region", "-100:100,50:150", "--step", "50"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(WriteErrors, FullDiskUnderEachOutputOptionExitsWith2NamingThePath) {
  const std::vector<std::vector<std::string>> runs = {
      with(kSmallMap, {"--json", "/dev/full"}),
      with(kSmallMap, {"--png", "/dev/full"}),
      with(kSmallMap, {"--vti", "/dev/full"}),
      {"solve", kModels + "cantilever.yaml", "--json", "/dev/full"},
  };
  for (const auto& args : runs) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, kExitBadInput) << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/full"));  // written into, never replaced
}

// --vtk names a directory: a regular file (or /dev/null) there is refused saying so, and left as it
// was. Before: "cannot create the output directory (Not a directory)".
TEST(WriteErrors, VtkGivenAFileSaysToGiveADirectory) {
  const auto file = std::filesystem::path(KINESTAT_BINARY_DIR) / "vtk_is_a_file.txt";
  std::ofstream(file) << "keep me\n";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"solve", kModels + "cantilever.yaml", "--quiet", "--vtk", file.string()},
        std::vector<std::string>{"modes", kModels + "euler_column.yaml", "--quiet", "--vtk", file.string()},
        std::vector<std::string>{"solve", kModels + "cantilever.yaml", "--quiet", "--vtk", "/dev/null"}}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, kExitBadInput) << args.front() << ": " << r.err;
    EXPECT_NE(r.err.find(args.back() + ": exists and is not a directory"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("give a directory path (it is made if missing)"), std::string::npos) << r.err;
  }
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "keep me");
}

// stdout on a full disk: the JSON (--json -) or the report is lost, so the run fails.
TEST(WriteErrors, StdoutOnAFullDiskExitsWith2) {
  for (const auto& args : {with(kSmallMap, {"--json", "-"}), kSmallMap,
                           std::vector<std::string>{"solve", kModels + "cantilever.yaml", "--json", "-"},
                           std::vector<std::string>{"solve", kModels + "cantilever.yaml"}}) {
    std::ofstream full("/dev/full");
    ASSERT_TRUE(full.is_open());
    std::ostringstream err;
    const int code = run(args, full, err);
    EXPECT_EQ(code, kExitBadInput) << args.back() << ": " << err.str();
    EXPECT_NE(err.str().find("stdout"), std::string::npos) << err.str();
  }
}

// A failed rewrite leaves the earlier complete result in place (and no temporary file beside it).
TEST(WriteErrors, AFailedRunKeepsTheEarlierResult) {
  const auto dir = std::filesystem::temp_directory_path() / "kinestat_write_errors";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "map.json").string();
  ASSERT_EQ(run_cli(with(kSmallMap, {"--json", json, "--quiet"})).code, kExitOk);
  std::stringstream before;
  before << std::ifstream(json).rdbuf();
  // The second run fails on its PNG (written before the JSON): the first JSON stays as it was.
  const CliRun r =
      run_cli({"map", "fivebar", "--region", "-100:100,0:150", "--step", "50", "--png", "/dev/full", "--json", json});
  EXPECT_EQ(r.code, kExitBadInput);
  std::stringstream after;
  after << std::ifstream(json).rdbuf();
  EXPECT_EQ(after.str(), before.str());
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kinestat::cli
