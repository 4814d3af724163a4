// Test helper: changes one compliance term of a stored cache entry and writes a correct checksum
// for the changed content, as a careful forger (or a bug elsewhere) would: only the checks on the
// values themselves can then reject it.
#pragma once

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fea/sha256.hpp"

namespace kinestat::fea::testing {

inline void set_entry_compliance_term(const std::string& path, int row, int col, double value) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  in.close();
  // Lines: header, key, counts, reference point, six compliance rows, checksum.
  std::istringstream terms(lines.at(4 + row));
  std::vector<std::string> t(6);
  for (std::string& s : t) terms >> s;
  t.at(col) = fmt::format("{:.17g}", value);
  lines[4 + row] = fmt::format("{} {} {} {} {} {}", t[0], t[1], t[2], t[3], t[4], t[5]);
  std::string body;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) body += lines[i] + "\n";
  std::ofstream(path, std::ios::binary | std::ios::trunc) << body << "sha256 " << sha256_hex(body) << "\n";
}

}  // namespace kinestat::fea::testing
