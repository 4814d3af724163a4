// Regenerates the link geometry of meshes/ as closed, outward-oriented triangle surfaces (OFF,
// millimetres, in each link's own frame). Dimensions are listed in docs/fea.md.
//   kinestat_make_meshes [OUTPUT_DIR]   (default: the current directory)
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct P2 {
  double u, v;
};

// Prism: the simple polygon `outline` (in the plane normal to `axis`: for axis x the (y, z)
// plane, for y the (z, x) plane, for z the (x, y) plane) swept from w0 to w1 along the axis.
Mesh extrude(std::vector<P2> outline, int axis, double w0, double w1) {
  double area = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const P2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
    area += a.u * b.v - b.u * a.v;
  }
  if (area < 0) std::reverse(outline.begin(), outline.end());  // counter-clockwise: outward sides
  auto point = [axis](const P2& p, double w) {
    if (axis == 0) return Point(w, p.u, p.v);
    if (axis == 1) return Point(p.v, w, p.u);
    return Point(p.u, p.v, w);
  };
  const size_t n = outline.size();
  std::vector<Point> points;
  for (const P2& p : outline) points.push_back(point(p, w0));
  for (const P2& p : outline) points.push_back(point(p, w1));
  std::vector<std::vector<size_t>> faces;
  std::vector<size_t> bottom, top;
  for (size_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  faces.push_back(bottom);
  faces.push_back(top);
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, faces, m);
  PMP::triangulate_faces(m);
  if (!PMP::is_outward_oriented(m)) PMP::reverse_face_orientations(m);
  return m;
}

std::vector<P2> rectangle(double u0, double u1, double v0, double v1) {
  return {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
}

std::vector<P2> circle(double uc, double vc, double r, int segments) {
  std::vector<P2> c;
  for (int i = 0; i < segments; ++i) {
    const double t = 2.0 * std::numbers::pi * i / segments;
    c.push_back({uc + r * std::cos(t), vc + r * std::sin(t)});
  }
  return c;
}

Mesh unite(Mesh a, Mesh b) {
  Mesh out;
  if (!PMP::corefine_and_compute_union(a, b, out)) throw std::runtime_error("union failed");
  return out;
}

Mesh subtract(Mesh a, Mesh b) {
  Mesh out;
  if (!PMP::corefine_and_compute_difference(a, b, out)) throw std::runtime_error("difference failed");
  return out;
}

bool write(const std::string& dir, const std::string& name, const Mesh& m) {
  const std::string path = dir + "/" + name;
  const bool ok = CGAL::IO::write_OFF(path, m, CGAL::parameters::stream_precision(12));
  std::cout << (ok ? "wrote " : "FAILED ") << path << " (" << m.number_of_faces() << " triangles)\n";
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  constexpr int kSegments = 48;  // facets on a full circle
  bool ok = true;
  // Prismatic bar 200 x 20 x 30 mm along x (beam-theory validation).
  ok &= write(dir, "bar.off", extrude(rectangle(-10, 10, -15, 15), 0, 0, 200));
  // Hollow tube along x: outer diameter 40 mm, wall 4 mm, length 300 mm.
  ok &= write(
      dir, "tube.off",
      subtract(extrude(circle(0, 0, 20, kSegments), 0, 0, 300), extrude(circle(0, 0, 16, kSegments), 0, -1, 301)));
  // Orthoglide-like foot: an L-shaped bracket (base 120 x 50 x 15 mm, a step up to 45 mm over the
  // last 35 mm), swept along y, with a 16 mm bore along y through the step for the leg's joint.
  const std::vector<P2> profile = {{0, 0}, {0, 120}, {45, 120}, {45, 85}, {15, 85}, {15, 0}};  // (z, x)
  ok &= write(dir, "foot.off",
              subtract(extrude(profile, 1, -25, 25), extrude(circle(30, 102.5, 8, kSegments), 1, -30, 30)));
  // Parallelogram bar: 20 x 10 mm bar along x between two bosses (diameter 30 mm, height 16 mm,
  // bore 12 mm, axes along z) 310.6 mm apart (the Orthoglide prototype's leg length).
  const double L = 310.6;
  Mesh bar = extrude(rectangle(0, L, -10, 10), 2, -5, 5);
  Mesh bosses = unite(extrude(circle(0, 0, 15, kSegments), 2, -8, 8), extrude(circle(L, 0, 15, kSegments), 2, -8, 8));
  Mesh bores = unite(extrude(circle(0, 0, 6, kSegments), 2, -10, 10), extrude(circle(L, 0, 6, kSegments), 2, -10, 10));
  ok &= write(dir, "parallelogram_bar.off", subtract(unite(bar, bosses), bores));
  return ok ? 0 : 1;
}
