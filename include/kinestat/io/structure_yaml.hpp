// Reading an msa::Structure from a YAML structure file (format: docs/structure-format.md).
// Files may be written in SI (m, N, Pa) or in mm-N-s (mm, N, MPa); the Structure is always SI.
#pragma once

#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::io {

// Parses and validates a structure file. Any problem gives kInvalidInput with one message
// "FILE:LINE: ITEM: what is wrong; what to do" (LINE 1-based; omitted when the file is unreadable).
StatusOr<msa::Structure> read_structure_yaml(const std::string& path);

// The same from text in memory; `display_name` stands for the file name in messages.
StatusOr<msa::Structure> read_structure_yaml_string(const std::string& text, const std::string& display_name);

}  // namespace kinestat::io
