#include "io/yaml_fields.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace kinestat::io {

std::string join_keys(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string YamlFields::where(const YAML::Node& at, const std::string& item) const {
  const int line = (at.IsDefined() && !at.Mark().is_null()) ? at.Mark().line + 1 : 0;
  return line > 0 ? fmt::format("{}:{}: {}", file_, line, item) : fmt::format("{}: {}", file_, item);
}

void YamlFields::fail(const YAML::Node& at, const std::string& item, const std::string& what) const {
  throw YamlInputError{fmt::format("{}: {}", where(at, item), what)};
}

void YamlFields::check_map(const YAML::Node& node, const std::string& item,
                           std::initializer_list<const char*> allowed) const {
  if (!node.IsMap())
    fail(node, item,
         fmt::format("expected a map of keys ({}); write it as 'key: value' lines or {{key: value, ...}}",
                     join_keys(allowed)));
  check_keys(node, item, allowed);
}

void YamlFields::check_keys(const YAML::Node& map, const std::string& item,
                            std::initializer_list<const char*> allowed) const {
  std::set<std::string> seen;
  for (const auto& kv : map) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) fail(kv.first, item, fmt::format("unknown key '{}'; allowed keys are: {}", key, join_keys(allowed)));
    if (!seen.insert(key).second) fail(kv.first, item, fmt::format("key '{}' is given twice; keep one", key));
  }
}

YAML::Node YamlFields::require(const YAML::Node& map, const std::string& item, const char* key) const {
  const YAML::Node v = map[key];
  if (!v.IsDefined() || v.IsNull())
    fail(map, item, fmt::format("missing required key '{}'; add it (see {})", key, doc_));
  return v;
}

double YamlFields::number(const YAML::Node& v, const std::string& item, const std::string& key) const {
  double x = 0.0;
  if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x)) {
    fail(v, item,
         fmt::format("'{}' must be a finite number, got '{}'; write e.g. 2.1e11", key,
                     v.IsScalar() ? v.Scalar() : "a list or map"));
  }
  return x;
}

double YamlFields::positive(const YAML::Node& v, const std::string& item, const std::string& key) const {
  const double x = number(v, item, key);
  if (!(x > 0.0))
    fail(v, item, fmt::format("'{}' must be positive, got {}; give a value > 0 in the file's units", key, x));
  return x;
}

std::string YamlFields::text(const YAML::Node& v, const std::string& item, const std::string& key) const {
  if (!v.IsScalar() || v.Scalar().empty()) fail(v, item, fmt::format("'{}' must be a single word or quoted text", key));
  return v.Scalar();
}

Vec3 YamlFields::vec3(const YAML::Node& v, const std::string& item, const std::string& key) const {
  if (!v.IsSequence() || v.size() != 3) fail(v, item, fmt::format("'{}' must be a list of three numbers [x, y, z]", key));
  return {number(v[0], item, key), number(v[1], item, key), number(v[2], item, key)};
}

FileUnits YamlFields::units(const YAML::Node& v) const {
  if (!v.IsDefined()) return {};
  const std::string u = v.IsScalar() ? v.Scalar() : "";
  if (u == "SI") return {};
  if (u == "mm-N-s") return {1e-3, 1.0};
  fail(v, "units", fmt::format("unknown units '{}'; write SI (m, N, Pa) or mm-N-s (mm, N, MPa)", u));
}

StatusOr<std::string> read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) return Status::Invalid(fmt::format("{}: cannot open the {}; check the path and permissions", path, what));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace kinestat::io
