#include "kinestat/fea/link_stiffness_inputs.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"

namespace kinestat::fea {

StatusOr<std::vector<double>> parse_numbers(const std::string& text, size_t count, const std::string& what) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      return Status::Invalid(fmt::format("{}: '{}' is not a number", what, item));
    }
    // stod reads "nan" and "inf" (and overflows to inf): not a value of any option.
    if (!std::isfinite(v.back())) return Status::Invalid(fmt::format("{}: '{}' is not a finite number", what, item));
  }
  if (v.size() != count || (!text.empty() && text.back() == ','))
    return Status::Invalid(fmt::format("{}: expected {} comma-separated numbers", what, count));
  return v;
}

namespace {

// Lengths written in the mesh unit (`scale` m), returned in m and checked in range.
StatusOr<Vec3> lengths(const std::vector<double>& v, size_t first, double scale, const std::string& what) {
  const UnitOfInput unit{scale, scale == 1.0 ? "m" : scale == units::kMm ? "mm" : ""};
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    const double x = v[first + static_cast<size_t>(k)];
    if (Status s = check_quantity(x, Quantity::kLength, what, unit); !s.ok()) return s;
    p[k] = x * scale;
  }
  return p;
}

}  // namespace

StatusOr<Vec3> parse_point(const std::string& text, double scale, const std::string& what) {
  auto v = parse_numbers(text, 3, what);
  if (!v.ok()) return v.status();
  return lengths(*v, 0, scale, what);
}

StatusOr<Region> parse_region(const std::string& text, double scale, const std::string& what) {
  if (text.size() > 2 && text[1] == '=' && (text[0] == 'x' || text[0] == 'y' || text[0] == 'z')) {
    auto v = parse_numbers(text.substr(2), 1, what);
    if (!v.ok()) return v.status();
    const int axis = text[0] - 'x';
    std::vector<double> xyz(3, 0.0);
    xyz[static_cast<size_t>(axis)] = (*v)[0];
    StatusOr<Vec3> point = lengths(xyz, 0, scale, what);
    if (!point.ok()) return point.status();
    return Region::plane(*point, Vec3::Unit(axis));
  }
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  if (colon == std::string::npos || (kind != "plane" && kind != "box"))
    return Status::Invalid(what +
                           ": give x=V, y=V, z=V, plane:PX,PY,PZ,NX,NY,NZ or box:X0,Y0,Z0,X1,Y1,Z1 (mesh units)");
  auto v = parse_numbers(text.substr(colon + 1), 6, what);
  if (!v.ok()) return v.status();
  StatusOr<Vec3> a = lengths(*v, 0, scale, what);
  if (!a.ok()) return a.status();
  if (kind == "plane") {
    const Vec3 n((*v)[3], (*v)[4], (*v)[5]);
    if (Status s = check_direction(n, what + ": the plane's normal"); !s.ok()) return s;
    return Region::plane(*a, n.stableNormalized());
  }
  StatusOr<Vec3> b = lengths(*v, 3, scale, what);
  if (!b.ok()) return b.status();
  if ((b->array() < a->array()).any()) return Status::Invalid(what + ": the box's first corner must be its minimum");
  return Region::box(*a, *b);
}

StatusOr<Material> parse_material(const std::string& text, const std::string& what, double modulus_unit) {
  auto with_density = [](Material m, double density) {
    m.density = density;
    return m;
  };
  if (text == "steel") return with_density(Material::from_E_nu("steel", 210e9, 0.3), kSteelDensity);
  if (text == "aluminium" || text == "aluminum")
    return with_density(Material::from_E_nu("aluminium", 70e9, 0.33), kAluminiumDensity);
  const std::string unit = modulus_unit == units::kMPa ? "MPa"
                           : modulus_unit == 1.0       ? "Pa"
                                                       : fmt::format("x {:g} Pa", modulus_unit);
  const std::string form = fmt::format(
      "give steel, aluminium or E=VALUE,nu=V[,rho=KG_M3] (E > 0 in {}, -1 < nu < 0.5, density rho > 0 in kg/m^3)",
      unit);
  std::optional<double> E, nu, rho;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq);
    if (eq == std::string::npos || (key != "E" && key != "nu" && key != "rho"))
      return Status::Invalid(fmt::format("{}: unknown item '{}'; {}", what, item, form));
    std::optional<double>& slot = key == "E" ? E : key == "nu" ? nu : rho;
    if (slot) return Status::Invalid(fmt::format("{}: '{}' is given twice; give it once", what, key));
    auto value = parse_numbers(item.substr(eq + 1), 1, fmt::format("{}: {}", what, key));
    if (!value.ok()) return value.status();
    slot = (*value)[0];
  }
  if (!E || !nu || text.back() == ',') return Status::Invalid(fmt::format("{}: {}", what, form));
  if (Status s = check_quantity(*E, Quantity::kModulus, what + ": E", {modulus_unit, unit}, Sign::kPositive); !s.ok())
    return s;
  if (!(*nu > -1.0 && *nu < 0.5))
    return Status::Invalid(fmt::format("{}: nu = {:g} is not in (-1, 0.5); give Poisson's ratio", what, *nu));
  if (rho)
    if (Status s = check_quantity(*rho, Quantity::kDensity, what + ": rho", {1.0, "kg/m^3"}, Sign::kPositive); !s.ok())
      return s;
  return with_density(Material::from_E_nu(text, *E * modulus_unit, *nu), rho.value_or(0.0));
}

double default_mesh_size(const SurfaceInfo& surface, double unit_scale) {
  return (surface.hi - surface.lo).maxCoeff() * unit_scale / 20.0;
}

StatusOr<std::string> surface_mesh_identity(const std::string& path, const MeshingOptions& meshing) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Invalid(path + ": cannot read the surface file");
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // The same text as the cache keys written before this function existed, so old entries stay valid.
  return bytes +
         fmt::format("|size {:.17g} unit {:.17g} quadratic {}", meshing.size, meshing.unit_scale, meshing.quadratic);
}

}  // namespace kinestat::fea
