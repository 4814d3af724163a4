#include "io/yaml_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "kinestat/core/units.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"

namespace kinestat::io {

std::string join_keys(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string YamlFields::source(const YAML::Node& at) const {
  const int line = (at.IsDefined() && !at.Mark().is_null()) ? at.Mark().line + 1 : 0;
  return line > 0 ? fmt::format("{}:{}", file_, line) : file_;
}

std::string YamlFields::where(const YAML::Node& at, const std::string& item) const {
  return fmt::format("{}: {}", source(at), item);
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

void YamlFields::check_unique_keys(const YAML::Node& map, const std::string& item) const {
  std::set<std::string> seen;
  for (const auto& kv : map)
    if (!seen.insert(kv.first.Scalar()).second)
      fail(kv.first, item, fmt::format("'{}' is given twice; keep one", kv.first.Scalar()));
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

double YamlFields::value(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
                         const UnitOfInput& unit, Sign sign) const {
  const double x = number(v, item, key);
  if (const Status s = check_quantity(x, q, "'" + key + "'", unit, sign); !s.ok()) fail(v, item, s.message());
  return x * unit.scale;
}

std::string YamlFields::text(const YAML::Node& v, const std::string& item, const std::string& key) const {
  if (!v.IsScalar() || v.Scalar().empty()) fail(v, item, fmt::format("'{}' must be a single word or quoted text", key));
  return v.Scalar();
}

Vec3 YamlFields::vec3(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
                      const UnitOfInput& unit) const {
  if (!v.IsSequence() || v.size() != 3)
    fail(v, item, fmt::format("'{}' must be a list of three numbers [x, y, z]", key));
  return {value(v[0], item, key, q, unit), value(v[1], item, key, q, unit), value(v[2], item, key, q, unit)};
}

Vec3 YamlFields::direction(const YAML::Node& v, const std::string& item, const std::string& key) const {
  if (!v.IsSequence() || v.size() != 3)
    fail(v, item, fmt::format("'{}' must be a list of three numbers [x, y, z]", key));
  const Vec3 d(number(v[0], item, key), number(v[1], item, key), number(v[2], item, key));
  if (const Status s = check_direction(d, "'" + key + "'"); !s.ok()) fail(v, item, s.message());
  return d.stableNormalized();
}

Section YamlFields::shape_section(const YAML::Node& n, const std::string& item, const YAML::Node& type_node,
                                  const FileUnits& units, const std::string& other_form) const {
  const std::string type = text(type_node, item, "type");
  const UnitOfInput lu = units.of(Quantity::kLength);
  const std::string un = lu.name.empty() ? "m" : lu.name;
  auto dim = [&](const char* key) {
    return value(require(n, item, key), item, key, Quantity::kLength, lu, Sign::kPositive);
  };
  // A wall of half the outer size or more leaves no hole (and a negative inner size would still give
  // a positive area): refused rather than computed.
  auto wall = [&](double outer, const char* outer_name) {
    const double t = dim("t");
    if (!(2.0 * t < outer))
      fail(n["t"], item,
           fmt::format("the wall t must be less than half of {} (t = {:g} {}, {} = {:g} {})", outer_name, t / lu.scale,
                       un, outer_name, outer / lu.scale, un));
    return t;
  };
  if (type == "circle") return circle_section(dim("d"));
  if (type == "tube") {
    const double d = dim("d");
    return tube_section(d, wall(d, "d"));
  }
  if (type == "rectangle") {
    const double b = dim("b");
    return rectangle_section(b, dim("h"));
  }
  if (type == "hollow_rectangle") {
    const double b = dim("b"), h = dim("h");
    return hollow_rectangle_section(b, h, wall(std::min(b, h), b < h ? "b" : "h"));
  }
  fail(type_node, item,
       fmt::format("unknown section type '{}'; use circle, tube, rectangle, hollow_rectangle{}", type, other_form));
}

FileUnits YamlFields::units(const YAML::Node& v, bool any_units) const {
  if (!v.IsDefined()) return {};
  const char* forms = any_units ? "SI (m, N, Pa), mm-N-s (mm, N, MPa) or {length: in, force: kip}"
                                : "SI (m, N, Pa) or mm-N-s (mm, N, MPa)";
  if (any_units && v.IsMap()) {
    check_map(v, "units", {"length", "force"});
    const std::string l = text(require(v, "units", "length"), "units", "length");
    const std::string f = text(require(v, "units", "force"), "units", "force");
    const std::optional<double> ls = length_unit(l), fs = force_unit(f);
    if (!ls) fail(v["length"], "units", fmt::format("unknown length unit '{}'; use m, mm, cm, in or ft", l));
    if (!fs) fail(v["force"], "units", fmt::format("unknown force unit '{}'; use N, kN, lbf or kip", f));
    return {*ls, *fs, l, f};
  }
  const std::string u = v.IsScalar() ? v.Scalar() : "";
  if (u == "SI") return {};
  if (u == "mm-N-s") return {units::kMm, 1.0, "mm", "N"};
  fail(v, "units", fmt::format("unknown units '{}'; write {}", u, forms));
}

std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text)
    out += static_cast<unsigned char>(c) < 0x20 ? fmt::format("\\x{:02x}", static_cast<unsigned char>(c))
                                                : std::string(1, c);
  return out;
}

StatusOr<std::string> read_text_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return Status::Invalid(fmt::format("{}: a folder, not the {}; give the file's path", path, what));
  std::ifstream in(path);
  if (!in) return Status::Invalid(fmt::format("{}: cannot open the {}; check the path and permissions", path, what));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace kinestat::io

namespace kinestat::io {

fea::LinkStiffnessRequest fea_request(const YamlFields& y, const YAML::Node& f, const std::string& it,
                                      const FileUnits& u) {
  y.check_map(f, it,
              {"mesh", "material", "E", "nu", "clamp", "reference", "reference_point", "unit", "size", "max_elements",
               "cache"});
  // A path in the file, relative to the file's folder.
  auto path_in_file = [&](const YAML::Node& v, const char* key) {
    return (std::filesystem::path(y.file()).parent_path() / y.text(v, it, key)).string();
  };
  fea::LinkStiffnessRequest r;
  // The mesh file's length unit (also of the regions, reference point and size): the file's by default.
  r.unit_scale = u.length;
  if (const YAML::Node n = f["unit"]; n.IsDefined()) {
    const std::string s = y.text(n, it, "unit");
    if (s != "mm" && s != "m") y.fail(n, it, fmt::format("unknown unit '{}'; write mm or m (the mesh file's unit)", s));
    r.unit_scale = s == "mm" ? units::kMm : 1.0;
  }
  const UnitOfInput mesh_unit{r.unit_scale, r.unit_scale == 1.0 ? "m" : "mm"};
  if (const YAML::Node m = f["material"]; m.IsDefined()) {
    if (f["E"].IsDefined() || f["nu"].IsDefined()) y.fail(m, it, "give either 'material' or 'E' and 'nu', not both");
    StatusOr<Material> parsed = fea::parse_material(y.text(m, it, "material"), "'material: " + m.Scalar() + "'",
                                                    u.of(Quantity::kModulus).scale);
    if (!parsed.ok()) y.fail(m, it, parsed.status().message());
    r.material = *parsed;
  } else {
    const double nu = y.number(y.require(f, it, "nu"), it, "nu");
    if (!(nu > -1.0 && nu < 0.5))
      y.fail(f["nu"], it, fmt::format("'nu' = {} is not in (-1, 0.5); give Poisson's ratio", nu));
    r.material = Material::from_E_nu(
        it, y.value(y.require(f, it, "E"), it, "E", Quantity::kModulus, u.of(Quantity::kModulus), Sign::kPositive), nu);
  }
  auto region = [&](const char* key) {
    const YAML::Node n = y.require(f, it, key);
    StatusOr<fea::Region> parsed =
        fea::parse_region(y.text(n, it, key), r.unit_scale, fmt::format("'{}: {}'", key, n.Scalar()));
    if (!parsed.ok()) y.fail(n, it, parsed.status().message());
    return *parsed;
  };
  r.options.clamp = region("clamp");
  r.options.reference = region("reference");
  if (const YAML::Node p = f["reference_point"]; p.IsDefined())
    r.options.reference_point = y.vec3(p, it, "reference_point", Quantity::kLength, mesh_unit);
  if (const YAML::Node n = f["size"]; n.IsDefined())
    r.mesh_size = y.value(n, it, "size", Quantity::kLength, mesh_unit, Sign::kPositive);
  if (const YAML::Node n = f["max_elements"]; n.IsDefined())  // the estimated tetrahedra allowed
    r.max_elements = y.value(n, it, "max_elements", Quantity::kRatio, {}, Sign::kPositive);
  const YAML::Node mesh = y.require(f, it, "mesh");
  r.mesh_file = path_in_file(mesh, "mesh");
  if (!std::filesystem::is_regular_file(r.mesh_file))
    y.fail(mesh, it, r.mesh_file + ": no such mesh file; the path is relative to the model file's folder");
  if (const YAML::Node c = f["cache"]; c.IsDefined()) r.cache_dir = path_in_file(c, "cache");
  return r;
}

}  // namespace kinestat::io
