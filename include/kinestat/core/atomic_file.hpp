// Output files that are either complete or absent: every file kinestat writes (JSON, VTK, PNG, the
// FEA result cache) goes through write_file_atomically, so a killed run or a full disk never leaves
// a truncated file that looks complete at the final path, nor destroys an earlier complete result.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "kinestat/core/status.hpp"

namespace kinestat {

// Writes the file `path` as a whole. `write` fills a new temporary file whose path it is given
// (".NAME.tmp-PID-N" in the folder of `path`, so that the rename cannot cross file systems); that
// file is then flushed to disk (fsync) and renamed over `path`. On any failure (`write`'s Status or
// exception, fsync, rename) the temporary file is removed and `path` is left as it was. A file
// replaced keeps its permissions; a new one gets 0666 less the umask, as with an ordinary open.
// A `path` that exists and is not a regular file (/dev/full, a FIFO), or is under /dev or /proc
// (/dev/stdout, whatever stdout is), cannot be replaced:
// the content is written to a temporary file in the system's temporary folder and then copied into
// it, every write checked. A symbolic link is followed (the file it names is replaced).
// kInvalidInput naming `path` and the system's reason when it cannot be written.
Status write_file_atomically(const std::string& path, const std::function<Status(const std::string& temp_path)>& write);

// write_file_atomically for content already in memory.
Status write_text_file_atomically(const std::string& path, std::string_view content);

}  // namespace kinestat
