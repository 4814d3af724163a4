// write_file_atomically (core/atomic_file.hpp): the final path holds the complete new file or the
// earlier one, never part of a file, whether the writer fails, throws or the process is killed.
#include "kinestat/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace kinestat {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int file_count(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesTheWholeFileWithOrdinaryPermissions) {
  const fs::path dir = fresh_dir("kinestat_atomic_new");
  const fs::path path = dir / "out.json";
  ASSERT_TRUE(write_text_file_atomically(path.string(), "{\"a\": 1}\n").ok());
  EXPECT_EQ(read_file(path), "{\"a\": 1}\n");
  EXPECT_EQ(file_count(dir), 1);  // no temporary file left
  // The same permissions as a file opened the usual way (0666 less the umask), not mkstemp's 0600.
  std::ofstream(dir / "reference") << "x";
  EXPECT_EQ(fs::status(path).permissions(), fs::status(dir / "reference").permissions());
  // A file replaced keeps its permissions.
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  ASSERT_TRUE(write_text_file_atomically(path.string(), "{}\n").ok());
  EXPECT_EQ(fs::status(path).permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(read_file(path), "{}\n");
  fs::remove_all(dir);
}

// While the writer runs, the final path still holds the earlier file and the content goes to a
// hidden temporary file in the same folder: a kill at that moment leaves the earlier file.
TEST(AtomicFile, TheFinalPathHoldsTheEarlierFileDuringTheWrite) {
  const fs::path dir = fresh_dir("kinestat_atomic_during");
  const fs::path path = dir / "map.json";
  std::ofstream(path) << "earlier";
  const Status s = write_file_atomically(path.string(), [&](const std::string& temp) {
    EXPECT_EQ(fs::path(temp).parent_path(), dir);
    EXPECT_EQ(fs::path(temp).filename().string().rfind(".map.json.tmp-", 0), 0u) << temp;
    std::ofstream(temp) << "half of the new";
    EXPECT_EQ(read_file(path), "earlier");
    return Status::Ok();
  });
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(read_file(path), "half of the new");
  EXPECT_EQ(file_count(dir), 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, AWriterThatFailsMidwayLeavesTheEarlierFile) {
  const fs::path dir = fresh_dir("kinestat_atomic_fail");
  const fs::path path = dir / "result.vtu";
  std::ofstream(path) << "complete earlier result";
  const Status failed = write_file_atomically(path.string(), [&](const std::string& temp) {
    std::ofstream(temp) << "<VTKFile";  // the writer stops here (a full disk, a VTK error)
    return Status::Invalid(path.string() + ": VTK could not write the file");
  });
  EXPECT_EQ(failed.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(read_file(path), "complete earlier result");
  EXPECT_EQ(file_count(dir), 1);  // the temporary file is removed

  // The Status is [[nodiscard]]; here the call throws before returning one.
  EXPECT_THROW(static_cast<void>(write_file_atomically(path.string(),
                                                       [&](const std::string& temp) -> Status {
                                                         std::ofstream(temp) << "<VTK";
                                                         throw std::runtime_error("out of memory");
                                                       })),
               std::runtime_error);
  EXPECT_EQ(read_file(path), "complete earlier result");
  EXPECT_EQ(file_count(dir), 1);
  fs::remove_all(dir);
}

// A process killed (SIGKILL) in the middle of a write: no file at a new path, the earlier content
// at an existing one.
TEST(AtomicFile, AKilledWriterLeavesNoPartialFile) {
  const fs::path dir = fresh_dir("kinestat_atomic_kill");
  for (const bool earlier : {false, true}) {
    const fs::path path = dir / (earlier ? "old.json" : "new.json");
    if (earlier) std::ofstream(path) << "earlier";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      (void)write_file_atomically(path.string(), [](const std::string& temp) {
        std::ofstream(temp) << "{\"truncated\": [1, 2," << std::flush;
        ::raise(SIGKILL);
        return Status::Ok();
      });
      ::_exit(0);  // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    if (earlier)
      EXPECT_EQ(read_file(path), "earlier");
    else
      EXPECT_FALSE(fs::exists(path));
  }
  fs::remove_all(dir);
}

// A device is written into, not replaced; its write errors are errors naming the path.
TEST(AtomicFile, FullDeviceIsAnErrorAndStaysADevice) {
  const Status s = write_text_file_atomically("/dev/full", std::string(100000, 'x'));
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(s.message().rfind("/dev/full: ", 0), 0u) << s.message();
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
  const Status callback = write_file_atomically("/dev/full", [](const std::string& temp) {
    std::ofstream(temp) << "data";
    return Status::Ok();
  });
  EXPECT_EQ(callback.code(), StatusCode::kInvalidInput) << callback.message();
  EXPECT_TRUE(write_text_file_atomically("/dev/null", "discarded").ok());
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// A final name of the longest length allowed still gets a temporary file.
TEST(AtomicFile, LongestFileNameIsWritten) {
  const fs::path dir = fresh_dir("kinestat_atomic_long");
  const fs::path path = dir / (std::string(250, 'n') + ".json");
  ASSERT_TRUE(write_text_file_atomically(path.string(), "{}").ok());
  EXPECT_EQ(read_file(path), "{}");
  fs::remove_all(dir);
}

// A link to a file: the file is replaced beside itself and the link stays a link.
TEST(AtomicFile, ALinkedFileIsReplacedAndTheLinkKept) {
  const fs::path dir = fresh_dir("kinestat_atomic_link");
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "out.json") << "old";
  fs::create_symlink(dir / "real" / "out.json", dir / "link.json");
  ASSERT_TRUE(write_text_file_atomically((dir / "link.json").string(), "new").ok());
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(read_file(dir / "real" / "out.json"), "new");
  EXPECT_EQ(file_count(dir / "real"), 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, MissingFolderOrAFolderAtThePathIsAnError) {
  const Status missing = write_text_file_atomically("/nonexistent/folder/out.json", "x");
  EXPECT_EQ(missing.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(missing.message().rfind("/nonexistent/folder/out.json: ", 0), 0u) << missing.message();
  const fs::path dir = fresh_dir("kinestat_atomic_folder");
  const Status folder = write_text_file_atomically(dir.string(), "x");
  EXPECT_EQ(folder.code(), StatusCode::kInvalidInput);
  EXPECT_TRUE(fs::is_directory(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace kinestat
