#include "kinestat/fea/link_stiffness_inputs.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

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
  }
  if (v.size() != count) return Status::Invalid(fmt::format("{}: expected {} comma-separated numbers", what, count));
  return v;
}

StatusOr<Region> parse_region(const std::string& text, double scale, const std::string& what) {
  if (text.size() > 2 && text[1] == '=' && (text[0] == 'x' || text[0] == 'y' || text[0] == 'z')) {
    auto v = parse_numbers(text.substr(2), 1, what);
    if (!v.ok()) return v.status();
    const int axis = text[0] - 'x';
    Vec3 p = Vec3::Zero();
    p(axis) = (*v)[0] * scale;
    return Region::plane(p, Vec3::Unit(axis));
  }
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  if (colon == std::string::npos || (kind != "plane" && kind != "box"))
    return Status::Invalid(what + ": give x=V, y=V, z=V, plane:PX,PY,PZ,NX,NY,NZ or box:X0,Y0,Z0,X1,Y1,Z1 (mesh units)");
  auto v = parse_numbers(text.substr(colon + 1), 6, what);
  if (!v.ok()) return v.status();
  const Vec3 a = Vec3((*v)[0], (*v)[1], (*v)[2]), b = Vec3((*v)[3], (*v)[4], (*v)[5]);
  if (kind == "plane") {
    if (b.norm() == 0.0) return Status::Invalid(what + ": the plane's normal is zero");
    return Region::plane(a * scale, b);
  }
  if ((b.array() < a.array()).any()) return Status::Invalid(what + ": the box's first corner must be its minimum");
  return Region::box(a * scale, b * scale);
}

StatusOr<Material> parse_material(const std::string& text, const std::string& what, double modulus_unit) {
  if (text == "steel") return Material::from_E_nu("steel", 210e9, 0.3);
  if (text == "aluminium" || text == "aluminum") return Material::from_E_nu("aluminium", 70e9, 0.33);
  double E = 0.0, nu = -2.0;
  if (std::sscanf(text.c_str(), "E=%lf,nu=%lf", &E, &nu) == 2 && E > 0.0 && nu > -1.0 && nu < 0.5)
    return Material::from_E_nu(text, E * modulus_unit, nu);
  const std::string unit = modulus_unit == 1e6 ? "MPa" : modulus_unit == 1.0 ? "Pa" : fmt::format("{:g} Pa", modulus_unit);
  return Status::Invalid(
      fmt::format("{}: give steel, aluminium or E=VALUE,nu=V (E > 0 in {}, -1 < nu < 0.5)", what, unit));
}

double default_mesh_size(const SurfaceInfo& surface, double unit_scale) {
  return (surface.hi - surface.lo).maxCoeff() * unit_scale / 20.0;
}

StatusOr<std::string> surface_mesh_identity(const std::string& path, const MeshingOptions& meshing) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Invalid(path + ": cannot read the surface file");
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // The same text as the cache keys written before this function existed, so old entries stay valid.
  return bytes + fmt::format("|size {:.17g} unit {:.17g} quadratic {}", meshing.size, meshing.unit_scale,
                             meshing.quadratic);
}

}  // namespace kinestat::fea
