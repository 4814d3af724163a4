// The user-facing inputs of a link stiffness analysis written as text, shared by the
// `link-stiffness` command (--material, --clamp, --reference, --reference-point) and the
// `fea:` spring of VJM model files (docs/fea.md, docs/vjm.md), plus what both need to find a
// cached result: one syntax and one cache key for the same link wherever it is named.
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/surface_mesher.hpp"

namespace kinestat::fea {

// `count` comma-separated finite numbers; kInvalidInput "WHAT: ..." otherwise.
StatusOr<std::vector<double>> parse_numbers(const std::string& text, size_t count, const std::string& what);

// "X,Y,Z" in the mesh file's unit, converted to m with `scale`, each in the range of a length.
StatusOr<Vec3> parse_point(const std::string& text, double scale, const std::string& what);

// "x=V" (plane normal to x at V; likewise y, z), "plane:PX,PY,PZ,NX,NY,NZ", "box:X0,Y0,Z0,X1,Y1,Z1";
// lengths in the mesh file's unit, converted to m with `scale`. Messages start with `what`.
StatusOr<Region> parse_region(const std::string& text, double scale, const std::string& what);

// "steel" (E 210 GPa, nu 0.3, density 7850 kg/m^3), "aluminium" (70 GPa, 0.33, 2700 kg/m^3) or
// "E=VALUE,nu=V[,rho=KG_M3]" with E in units of `modulus_unit` Pa (1e6: MPa, the command line's unit; a
// model file's stress unit) and the density rho in kg/m^3 (absent: 0, no mass; only modes need it).
// Messages start with `what`.
inline constexpr double kSteelDensity = 7850.0;      // kg/m^3
inline constexpr double kAluminiumDensity = 2700.0;  // kg/m^3
StatusOr<Material> parse_material(const std::string& text, const std::string& what, double modulus_unit = 1.0);

// Default tetrahedron size (m): 1/20 of the surface's largest extent.
double default_mesh_size(const SurfaceInfo& surface, double unit_scale);

// What identifies the tetrahedral mesh of a surface file for the result cache: the file's bytes and
// the meshing options that change the mesh. kInvalidInput naming the path if it cannot be read.
StatusOr<std::string> surface_mesh_identity(const std::string& path, const MeshingOptions& meshing);

}  // namespace kinestat::fea
