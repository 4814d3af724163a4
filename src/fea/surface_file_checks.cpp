#include "fea/surface_file_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include <fmt/format.h>

namespace kinestat::fea {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Every whitespace-separated token of `line` as a finite number; false if one is not.
bool finite_numbers(const std::string& line, std::vector<double>& out) {
  out.clear();
  std::istringstream in(line);
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || !std::isfinite(v)) return false;
    out.push_back(v);
  }
  return true;
}

// As CGAL's skip_comment_OFF: whitespace and '#' comment lines before a record.
void skip_comments(std::istream& in) {
  char c;
  while ((in >> c) && c == '#') in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  if (in) in.putback(c);
}

// A record as CGAL's File_scanner_OFF reads it: one line, without its '#' comment.
bool next_record(std::istream& in, std::string& line) {
  skip_comments(in);
  if (!std::getline(in, line)) return false;
  line = line.substr(0, line.find('#'));
  return true;
}

Status check_off(const std::string& path, std::uintmax_t bytes) {
  std::ifstream in(path, std::ios::binary);
  auto bad = [&](const std::string& what) { return Status::Invalid(fmt::format("{}: {}", path, what)); };
  skip_comments(in);
  std::string keyword;
  char c;
  while (in.get(c) && std::isalnum(static_cast<unsigned char>(c)) && keyword.size() < 40) keyword += c;
  if (keyword != "OFF")
    return bad(
        fmt::format("the OFF header is '{}'; only plain ASCII OFF is read (no binary, colour, normal or texture "
                    "variant): export a plain OFF, STL, OBJ or PLY",
                    keyword));
  long long nv = -1, nf = -1, ne = -1;
  skip_comments(in);
  if (!(in >> nv >> nf >> ne) || nv < 0 || nf < 0 || ne < 0)
    return bad("the OFF header needs three counts (vertices, faces, edges), non-negative integers");
  // Shortest records: "0 0 0\n" and "3 0 1 2\n".
  const double needed = 6.0 * static_cast<double>(nv) + 8.0 * static_cast<double>(nf);
  if (needed > static_cast<double>(bytes) + 8.0)
    return bad(
        fmt::format("the OFF header announces {} vertices and {} faces, more than the file's {} bytes can hold; "
                    "the file is truncated or its header is wrong",
                    nv, nf, bytes));
  std::string line;
  std::vector<double> v;
  for (long long i = 0; i < nv; ++i) {
    if (!next_record(in, line)) return Status::Ok();  // too short: CGAL's reader says so
    if (!finite_numbers(line, v) || v.size() < 3)
      return bad(fmt::format("vertex {}: '{}' is not three finite coordinates", i, line));
  }
  for (long long f = 0; f < nf; ++f) {
    if (!next_record(in, line)) return Status::Ok();
    if (!finite_numbers(line, v) || v.empty())
      return bad(fmt::format("face {}: '{}' is not a list of numbers", f, line));
    const double k = v[0];
    if (!(k >= 1 && k == std::floor(k) && k <= static_cast<double>(v.size()) - 1))
      return bad(fmt::format("face {}: '{}' does not list as many vertex indices as its first number says", f, line));
    for (std::size_t j = 1; j <= static_cast<std::size_t>(k); ++j)
      if (!(v[j] >= 0 && v[j] < static_cast<double>(nv) && v[j] == std::floor(v[j])))
        return bad(
            fmt::format("face {}: vertex index {} is not one of the {} vertices (0 to {})", f, v[j], nv, nv - 1));
  }
  return Status::Ok();
}

Status check_ply(const std::string& path, std::uintmax_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool element_seen = false;
  std::string element;  // the element the properties below belong to
  for (int n = 0; n < 10000 && std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "end_header") return Status::Ok();
    if (first == "element") {
      std::string name, count_text;
      words >> name >> count_text;
      element_seen = true;
      element = name;
      // A count is digits only: CGAL reads "90000001eader" as 90000001 (found by fuzz_surface_mesh).
      const bool digits =
          !count_text.empty() && count_text.size() <= 18 &&
          std::all_of(count_text.begin(), count_text.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!digits)
        return Status::Invalid(
            fmt::format("{}: the PLY element '{}' has the count '{}'; write a whole number", path, name, count_text));
      const double count = std::stod(count_text);
      // Every element takes at least one byte, in any format.
      if (!(count >= 0 && count <= static_cast<double>(bytes)))
        return Status::Invalid(
            fmt::format("{}: the PLY header announces {} '{}' elements, more than the file's {} "
                        "bytes can hold; the file is truncated or its header is wrong",
                        path, count, name, bytes));
    } else if (first == "property") {
      // CGAL attaches a property to the last element read: with none, it reads past an empty vector.
      if (!element_seen)
        return Status::Invalid(
            fmt::format("{}: a PLY property is declared before any element; check the header", path));
      std::string kind, length_type;
      words >> kind >> length_type;
      static const char* kNarrow[] = {"char", "uchar", "int8", "uint8", "short", "ushort", "int16", "uint16"};
      if (kind == "list" &&
          std::none_of(std::begin(kNarrow), std::end(kNarrow), [&](const char* t) { return length_type == t; }))
        return Status::Invalid(
            fmt::format("{}: a PLY list's length is of type '{}'; write uchar (as exporters do): "
                        "wider lengths are not read",
                        path, length_type));
      // CGAL reads a vertex's coordinates and normals as float or double and dereferences anything
      // else as a float (found by fuzz_surface_mesh): refuse other types here.
      static const char* kCoordinates[] = {"x", "y", "z", "nx", "ny", "nz"};
      static const char* kReal[] = {"float", "double", "float32", "float64"};
      const std::string& name = length_type;  // for a scalar property the second word is its name
      if (element == "vertex" && kind != "list" &&
          std::any_of(std::begin(kCoordinates), std::end(kCoordinates), [&](const char* c) { return name == c; }) &&
          std::none_of(std::begin(kReal), std::end(kReal), [&](const char* t) { return kind == t; }))
        return Status::Invalid(
            fmt::format("{}: the PLY vertex property '{}' is of type '{}'; coordinates and "
                        "normals must be float or double",
                        path, name, kind));
    }
  }
  return Status::Ok();  // no end_header: CGAL's reader refuses the file
}

Status check_binary_stl(const std::string& path, std::uintmax_t bytes) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  if (bytes < 84 || !in.read(head, 84)) return Status::Ok();
  if (std::string(head, 5) == "solid") return Status::Ok();  // ASCII STL (or a binary one CGAL sizes itself)
  std::uint32_t count = 0;
  for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(head[80 + i]);  // little endian
  if (84.0 + 50.0 * count > static_cast<double>(bytes))
    return Status::Invalid(
        fmt::format("{}: the binary STL header announces {} triangles, more than the file's {} "
                    "bytes can hold; the file is truncated or not an STL",
                    path, count, bytes));
  return Status::Ok();
}

}  // namespace

Status check_surface_file_structure(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) return Status::Invalid(path + ": cannot read the file's size; check the path");
  const std::string ext = lower_extension(path);
  if (ext == ".off") return check_off(path, bytes);
  if (ext == ".ply") return check_ply(path, bytes);
  if (ext == ".stl") return check_binary_stl(path, bytes);
  return Status::Ok();
}

}  // namespace kinestat::fea
