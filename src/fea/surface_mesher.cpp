// All of CGAL Mesh_3 lives in this one translation unit: it compiles slowly.
#include "kinestat/fea/surface_mesher.hpp"

#include <cmath>
#include <filesystem>

#include <limits>
#include <map>
#include <unordered_map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <fmt/format.h>

#include "fea/surface_file_checks.hpp"
#include "kinestat/core/input_checks.hpp"

namespace kinestat::fea {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<Kernel, Surface>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string point_text(const Point& p) { return fmt::format("({:g}, {:g}, {:g})", p.x(), p.y(), p.z()); }

// Edge use counts of the soup: closed, manifold, consistently oriented <=> every undirected edge
// is used by exactly two triangles, once in each direction.
Status check_edges(const std::string& path, const std::vector<Point>& points,
                   const std::vector<std::vector<std::size_t>>& triangles) {
  std::map<std::pair<std::size_t, std::size_t>, std::array<int, 2>> uses;  // (min, max) -> uses a->b, b->a
  for (const auto& t : triangles)
    for (std::size_t i = 0; i < t.size(); ++i) {
      const std::size_t a = t[i], b = t[(i + 1) % t.size()];
      ++uses[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1];
    }
  for (const auto& [edge, count] : uses) {
    const std::string where = "the edge " + point_text(points[edge.first]) + " - " + point_text(points[edge.second]);
    const int total = count[0] + count[1];
    if (total == 1)
      return Status::Invalid(path + ": the surface is not closed: " + where +
                             " bounds only one triangle (a hole); close the surface in the CAD export");
    if (total > 2)
      return Status::Invalid(
          fmt::format("{}: the surface is not manifold: {} is shared by {} triangles", path, where, total));
    if (count[0] != 1)
      return Status::Invalid(path + ": inconsistent orientation: the two triangles at " + where +
                             " run the same way round; orient all faces outward");
  }
  return Status::Ok();
}

// Coordinates beyond this (in the file's unit, m or mm) are refused before any geometry runs on them:
// 1e6 m in mm. Predicates on them would still be exact, but the mesher's constructions overflow.
constexpr double kMaxCoordinate = 1e9;
// estimate_tetrahedra's coefficients, fitted to the bundled bar (sizes 3 to 10 mm, 883 to 20 012
// tetrahedra); the tube and the foot then come out 1 to 1.7 times their real counts (docs/reliability.md).
constexpr double kTetsPerVolume = 4.0, kTetsPerArea = 1.3;
// A solid thinner on average (3 V / A: the radius of a ball, 1.5 x a plate's thickness) than this share
// of its bounding-box diagonal is a needle or a sheet: Mesh_3 would protect its close feature edges
// with ever smaller balls for minutes and make no usable tetrahedron.
constexpr double kMinThicknessRatio = 1e-4;

StatusOr<Surface> read_checked_surface(const std::string& path) {
  // Checked here because CGAL's reader prints its own complaint about a missing file to stdout.
  if (std::error_code ec; !std::filesystem::is_regular_file(path, ec))
    return Status::Invalid(path + ": no such file; check the mesh path");
  if (Status s = check_surface_file_structure(path); !s.ok()) return s;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons))
    return Status::Invalid(path + ": cannot read a triangle surface (STL, OFF, OBJ or PLY) from this file");
  if (polygons.empty())
    return Status::Invalid(path + ": the file has no face; export the part's closed surface (STL, OFF, OBJ or PLY)");
  for (const auto& p : polygons) {
    if (p.size() != 3)
      return Status::Invalid(fmt::format("{}: a face has {} vertices; triangulate the surface", path, p.size()));
    for (std::size_t v : p)
      if (v >= points.size())
        return Status::Invalid(
            fmt::format("{}: a face refers to vertex {} of {}; repair the file", path, v, points.size()));
  }
  for (const Point& p : points)
    if (!(std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate && std::abs(p.z()) <= kMaxCoordinate))
      return Status::Invalid(
          fmt::format("{}: the vertex {} is not finite or beyond {:g} (mm or m); check the file's "
                      "unit and content",
                      path, point_text(p), kMaxCoordinate));
  // STL repeats every vertex per triangle: merge duplicates first (this also drops degenerate faces).
  PMP::repair_polygon_soup(points, polygons);
  if (Status s = check_edges(path, points, polygons); !s.ok()) return s;
  Surface surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  // A face with no area and a flat solid are self-intersections to CGAL: said as what they are first.
  for (const auto f : faces(surface))
    if (PMP::is_degenerate_triangle_face(f, surface)) {
      std::string corners;
      for (const auto v : vertices_around_face(halfedge(f, surface), surface))
        corners += (corners.empty() ? "" : ", ") + point_text(surface.point(v));
      return Status::Invalid(fmt::format(
          "{}: the triangle with corners {} has no area (they lie on one line); repair the surface", path, corners));
    }
  // The enclosed volume (signed by the faces' orientation, which is fixed below) and the area.
  const double volume = std::abs(PMP::volume(surface)), area = PMP::area(surface);
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  if (!(volume > 0.0 && 3.0 * volume >= kMinThicknessRatio * diagonal * area))
    return Status::Invalid(
        fmt::format("{}: the solid is {:.3g} thick on average (3 volume / area) for a size of {:.3g} "
                    "(file units): a needle or a sheet that tetrahedra cannot resolve; model it as "
                    "a beam or thicken it",
                    path, 3.0 * volume / area, diagonal));
  if (PMP::does_self_intersect(surface))
    return Status::Invalid(path + ": the surface intersects itself; repair the geometry (no overlapping solids)");
  if (!PMP::is_outward_oriented(surface)) PMP::reverse_face_orientations(surface);
  return surface;
}

SurfaceInfo surface_info(const Surface& s) {
  SurfaceInfo info;
  info.triangles = static_cast<int>(s.number_of_faces());
  info.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  info.hi = -info.lo;
  for (auto v : s.vertices()) {
    const Point& p = s.point(v);
    info.lo = info.lo.cwiseMin(Vec3(p.x(), p.y(), p.z()));
    info.hi = info.hi.cwiseMax(Vec3(p.x(), p.y(), p.z()));
  }
  info.volume = PMP::volume(s);
  info.area = PMP::area(s);
  return info;
}

}  // namespace

StatusOr<SurfaceInfo> check_surface_file(const std::string& path) {
  StatusOr<Surface> s = read_checked_surface(path);
  if (!s.ok()) return s.status();
  return surface_info(*s);
}

double estimate_tetrahedra(const SurfaceInfo& surface, double unit_scale, double size) {
  // Walls thinner than the size are still filled with tetrahedra: the mesher refines to 2 V / A, the
  // thickness of a plate or a tube's wall.
  const double h = std::min(size / unit_scale, 2.0 * surface.volume / surface.area);  // in the file's unit
  return kTetsPerVolume * surface.volume / (h * h * h) + kTetsPerArea * surface.area / (h * h);
}

StatusOr<TetMesh> mesh_surface_file(const std::string& path, const MeshingOptions& o) {
  if (!(o.unit_scale > 0.0) || !(o.size > 0.0) || o.facet_distance < 0.0 ||
      !(o.facet_angle > 0.0 && o.facet_angle <= 30.0) || !(o.cell_radius_edge_ratio >= 2.0))
    return Status::Invalid(
        fmt::format("meshing options: need unit scale > 0, size > 0 m, facet distance >= 0 m, "
                    "0 < facet angle <= 30 deg, radius-edge ratio >= 2 (got {:g}, {:g}, {:g}, {:g}, {:g})",
                    o.unit_scale, o.size, o.facet_distance, o.facet_angle, o.cell_radius_edge_ratio));
  if (Status st = check_quantity(o.size, Quantity::kLength, path + ": mesh size", {}, Sign::kPositive); !st.ok())
    return st;
  StatusOr<Surface> surface = read_checked_surface(path);
  if (!surface.ok()) return surface.status();
  const SurfaceInfo info = surface_info(*surface);
  for (int k = 0; k < 3; ++k)
    for (double x : {info.lo[k], info.hi[k]})
      if (Status st = check_quantity(x * o.unit_scale, Quantity::kLength, path + ": a vertex coordinate"); !st.ok())
        return st;
  if (Status st = check_size(estimate_tetrahedra(info, o.unit_scale, o.size), o.max_elements,
                             fmt::format("{}: meshing with size {:g} m", path, o.size),
                             "tetrahedra (volume / size^3 and area / size^2, docs/reliability.md)",
                             "give a larger size, or raise the limit (link-stiffness --max-elements, max_elements in a "
                             "model file's fea spring)");
      !st.ok())
    return st;
  for (auto v : surface->vertices()) {
    const Point& p = surface->point(v);
    surface->point(v) = Point(p.x() * o.unit_scale, p.y() * o.unit_scale, p.z() * o.unit_scale);
  }
  CGAL::get_default_random() = CGAL::Random(o.random_seed);
  Domain domain(*surface);
  domain.detect_features(o.feature_angle);
  namespace params = CGAL::parameters;
  const double distance = o.facet_distance > 0.0 ? o.facet_distance : o.size / 10.0;
  Criteria criteria(params::edge_size = o.size, params::facet_angle = o.facet_angle, params::facet_size = o.size,
                    params::facet_distance = distance, params::cell_radius_edge_ratio = o.cell_radius_edge_ratio,
                    params::cell_size = o.size);
  const Complex c3t3 = o.optimize
                           ? CGAL::make_mesh_3<Complex>(domain, criteria, params::no_perturb(), params::exude())
                           : CGAL::make_mesh_3<Complex>(domain, criteria, params::no_perturb(), params::no_exude());

  TetMesh mesh;
  std::unordered_map<Complex::Vertex_handle, int> index;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    int v[4];
    for (int i = 0; i < 4; ++i) {
      auto [it, inserted] = index.try_emplace(c->vertex(i), mesh.num_nodes());
      if (inserted) {
        const auto& p = c->vertex(i)->point();
        mesh.nodes.emplace_back(p.x(), p.y(), p.z());
      }
      v[i] = it->second;
    }
    mesh.connectivity.insert(mesh.connectivity.end(), v, v + 4);
    const int e = mesh.num_elements() - 1;
    const double volume = element_volume(mesh, e);
    // Mesh_3 with inexact constructions can leave a flat sliver (four coplanar points in double
    // precision) that exudation does not remove. It has no volume, hence no stiffness, and its
    // nodes and edges belong to its neighbours too: drop it rather than refuse the mesh.
    if (std::abs(volume) <= 1e-12 * o.size * o.size * o.size) {
      mesh.connectivity.resize(mesh.connectivity.size() - 4);
      continue;
    }
    if (volume < 0.0) std::swap(mesh.connectivity[4 * e + 2], mesh.connectivity[4 * e + 3]);
  }
  if (mesh.num_elements() == 0)
    return Status::Invalid(
        fmt::format("{}: meshing produced no tetrahedra; is the size {:g} m larger than the part?", path, o.size));
  return o.quadratic ? to_quadratic(mesh) : mesh;
}

}  // namespace kinestat::fea
