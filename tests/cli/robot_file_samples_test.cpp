// The sample runs in the header comments of the robot library (models/robots/*.yaml, issue 19: "each
// file commented with its source and a sample run"): every file has at least one, and each runs, exits 0
// and writes the output files it names (to a temporary folder instead of the working directory). A sample
// is a comment line whose text starts with `kinestat `, continued on the next comment line after a
// trailing backslash; a remark in parentheses after it is not part of the command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace kinestat::cli {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// The samples of one file, each as its words (without the leading `kinestat`).
std::vector<std::vector<std::string>> samples(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> out;
  std::string line, command;
  bool continued = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '#') {
      continued = false;
      continue;
    }
    std::string text = trim(line.substr(1));
    if (!continued) {
      if (text.rfind("kinestat ", 0) != 0) continue;
      command.clear();
    }
    if (const auto remark = text.find(" ("); remark != std::string::npos) text = trim(text.substr(0, remark));
    continued = !text.empty() && text.back() == '\\';
    if (continued) text.pop_back();
    command += " " + text;
    if (continued) continue;
    std::istringstream words(command);
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    args.erase(args.begin());  // kinestat
    out.push_back(args);
  }
  return out;
}

TEST(RobotFileSamples, EveryRobotFileHasSampleRunsThatSucceed) {
  const fs::path source = KINESTAT_SOURCE_DIR;
  const fs::path outputs = fs::temp_directory_path() / "kinestat_robot_file_samples";
  fs::create_directories(outputs);
  const std::set<std::string> output_options = {"--png", "--vti", "--vtk", "--json"};
  int files = 0;
  for (const auto& entry : fs::directory_iterator(source / "models" / "robots")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const auto runs = samples(entry.path());
    EXPECT_FALSE(runs.empty()) << entry.path() << " has no sample run in its header comments";
    for (std::vector<std::string> args : runs) {
      std::string shown = "kinestat";
      for (const std::string& a : args) shown += " " + a;
      std::vector<fs::path> written;  // the sample's output files, redirected
      for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i].rfind("models/", 0) == 0) args[i] = (source / args[i]).string();
        if (output_options.count(args[i]) && i + 1 < args.size()) {
          written.push_back(outputs / fs::path(args[i + 1]).filename());
          fs::remove_all(written.back());
          args[++i] = written.back().string();
        }
      }
      args.push_back("--quiet");
      const CliRun r = run_cli(args);
      EXPECT_EQ(r.code, 0) << entry.path().filename() << ": " << shown << "\n" << r.err;
      // Exit 0 with an output missing or empty would still be a broken sample.
      for (const fs::path& f : written)
        EXPECT_TRUE(fs::exists(f) && (fs::is_directory(f) ? !fs::is_empty(f) : fs::file_size(f) > 0))
            << shown << ": " << f << " not written";
    }
  }
  EXPECT_GE(files, 7);  // the bundled library (docs/robots.md)
  fs::remove_all(outputs);
}

}  // namespace
}  // namespace kinestat::cli
