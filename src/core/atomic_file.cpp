#include "kinestat/core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace kinestat {
namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::strerror(error); }

Status cannot_write(const std::string& path, const std::string& why) {
  return Status::Invalid(fmt::format(
      "{}: cannot write the file: {}; check that its folder exists and is writable and has room", path, why));
}

// Writes all of `data` to `fd`, retrying short writes and interruptions; the errno of a failure.
int write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

// A new empty file named like `target` in `folder`, created exclusively (mode 0666 less the umask,
// as an ordinary output file): its path, or the errno of the failure.
std::pair<std::string, int> create_temporary(const fs::path& folder, const std::string& name) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    // The name shortened so that the temporary one stays within NAME_MAX (255) when the final one does.
    const fs::path temp = folder / fmt::format(".{}.tmp-{}-{}", name.substr(0, 200), ::getpid(), counter++);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return {temp.string(), 0};
    }
    if (errno != EEXIST) return {"", errno};
  }
  return {"", EEXIST};
}

// fsync of a written file: delayed write errors (a full disk, a lost network mount) show here.
int sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int error = ::fsync(fd) == 0 ? 0 : errno;
  return ::close(fd) == 0 ? error : (error != 0 ? error : errno);
}

// Copies the file `from` into the existing non-regular file `to` (a device, a FIFO), checking writes.
int copy_into(const std::string& from, const std::string& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return errno;
  // O_APPEND: /dev/stdout may be a regular file the shell opened for appending (>>).
  const int out = ::open(to.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (out < 0) {
    const int error = errno;
    ::close(in);
    return error;
  }
  char buffer[1 << 16];
  int error = 0;
  while (error == 0) {
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno != EINTR) error = errno;
      continue;
    }
    error = write_all(out, buffer, static_cast<std::size_t>(n));
  }
  ::close(in);
  if (::close(out) != 0 && error == 0) error = errno;
  return error;
}

// Removes the temporary file unless it was renamed, also when `write` throws.
struct RemoveUnlessKept {
  std::string path;
  ~RemoveUnlessKept() {
    if (!path.empty()) ::unlink(path.c_str());
  }
};

}  // namespace

Status write_file_atomically(const std::string& path, const std::function<Status(const std::string&)>& write) {
  if (path.empty()) return Status::Invalid("an output file name is empty; give a file name");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // of what a link names: /dev/stdout is a device
  if (fs::is_directory(status)) return cannot_write(path, "it is a folder");
  // /dev/stdout names whatever stdout is, possibly a regular file the shell opened for appending.
  const bool device_name = path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
  const bool special = fs::exists(status) && (!fs::is_regular_file(status) || device_name);
  fs::path target = path;
  // A link to a regular file: the file is replaced, next to itself, and the link kept.
  if (fs::is_regular_file(status) && fs::is_symlink(fs::symlink_status(path, ec))) {
    const fs::path resolved = fs::canonical(path, ec);
    if (!ec) target = resolved;
  }
  // A device or FIFO cannot be renamed over: written through a temporary file elsewhere.
  const fs::path folder = special ? fs::temp_directory_path(ec) : target.parent_path();
  const auto [temp, error] = create_temporary(folder.empty() ? fs::path(".") : folder, target.filename().string());
  if (error != 0)
    return cannot_write(path, fmt::format("no temporary file can be created in {}: {}",
                                          folder.empty() ? "." : folder.string(), reason(error)));
  RemoveUnlessKept guard{temp};
  // A file replaced keeps its permissions (a new one has 0666 less the umask, from open).
  if (fs::is_regular_file(status)) fs::permissions(temp, status.permissions(), ec);
  if (Status s = write(temp); !s.ok()) return s;
  if (special) {
    if (const int e = copy_into(temp, target.string()); e != 0) return cannot_write(path, reason(e));
    return Status::Ok();
  }
  if (const int e = sync_file(temp); e != 0) return cannot_write(path, reason(e));
  if (::rename(temp.c_str(), target.c_str()) != 0) return cannot_write(path, reason(errno));
  guard.path.clear();
  return Status::Ok();
}

Status write_text_file_atomically(const std::string& path, std::string_view content) {
  return write_file_atomically(path, [&](const std::string& temp) {
    const int fd = ::open(temp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) return cannot_write(path, reason(errno));
    int error = write_all(fd, content.data(), content.size());
    if (::close(fd) != 0 && error == 0) error = errno;
    return error == 0 ? Status::Ok() : cannot_write(path, reason(error));
  });
}

}  // namespace kinestat
