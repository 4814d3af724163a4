#include "kinestat/fea/tet_mesh.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include <fmt/format.h>

#include "fea/sha256.hpp"
#include "kinestat/core/input_checks.hpp"

namespace kinestat::fea {

namespace {

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

}  // namespace

Status check_box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz, double max_elements) {
  if (Status s = check_entries(lo, Quantity::kLength, "lo"); !s.ok()) return s;
  if (Status s = check_entries(hi, Quantity::kLength, "hi"); !s.ok()) return s;
  for (int a = 0; a < 3; ++a)
    if (!(lo(a) < hi(a)))
      return Status::Invalid(
          fmt::format("lo[{0}] = {1:g} m, hi[{0}] = {2:g} m: the box needs lo < hi on every axis", a, lo(a), hi(a)));
  const std::array<std::pair<const char*, int>, 3> cells = {{{"nx", nx}, {"ny", ny}, {"nz", nz}}};
  for (const auto& [name, n] : cells)
    if (n < 1) return Status::Invalid(fmt::format("{} = {}: give at least 1 cell along each axis", name, n));
  return check_size(6.0 * nx * ny * nz, max_elements, fmt::format("box mesh of {} x {} x {} cells", nx, ny, nz),
                    "tetrahedra (6 nx ny nz)", "give fewer cells or raise max_elements");
}

TetMesh make_box_mesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
  TetMesh m;
  m.nodes_per_element = 4;
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.nodes.emplace_back(lo.x() + (hi.x() - lo.x()) * i / nx, lo.y() + (hi.y() - lo.y()) * j / ny,
                             lo.z() + (hi.z() - lo.z()) * k / nz);
  // Kuhn split: one tetrahedron per ordering of the axes, along the path 000 -> 111.
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : kPerm) {
          int c[3] = {0, 0, 0};
          int v[4];
          v[0] = id(i, j, k);
          for (int s = 0; s < 3; ++s) {
            c[p[s]] = 1;
            v[s + 1] = id(i + c[0], j + c[1], k + c[2]);
          }
          if (signed_volume(m.nodes[v[0]], m.nodes[v[1]], m.nodes[v[2]], m.nodes[v[3]]) < 0) std::swap(v[2], v[3]);
          m.connectivity.insert(m.connectivity.end(), v, v + 4);
        }
  return m;
}

TetMesh to_quadratic(const TetMesh& linear) {
  if (linear.quadratic()) return linear;
  TetMesh q;
  q.nodes = linear.nodes;
  q.nodes_per_element = 10;
  q.connectivity.reserve(static_cast<size_t>(linear.num_elements()) * 10);
  std::unordered_map<std::int64_t, int> midpoint;
  const std::int64_t n = linear.num_nodes();
  for (int e = 0; e < linear.num_elements(); ++e) {
    const int* v = linear.element(e);
    q.connectivity.insert(q.connectivity.end(), v, v + 4);
    for (const auto& edge : kTet10Edges) {
      const int a = std::min(v[edge[0]], v[edge[1]]), b = std::max(v[edge[0]], v[edge[1]]);
      auto [it, inserted] = midpoint.try_emplace(a * n + b, q.num_nodes());
      if (inserted) q.nodes.push_back(0.5 * (linear.nodes[a] + linear.nodes[b]));
      q.connectivity.push_back(it->second);
    }
  }
  return q;
}

double element_volume(const TetMesh& mesh, int e) {
  const int* v = mesh.element(e);
  return signed_volume(mesh.nodes[v[0]], mesh.nodes[v[1]], mesh.nodes[v[2]], mesh.nodes[v[3]]);
}

Status validate(const TetMesh& mesh) {
  if (mesh.nodes_per_element != 4 && mesh.nodes_per_element != 10)
    return Status::Invalid(fmt::format("tetrahedral mesh: {} nodes per element; use 4 or 10", mesh.nodes_per_element));
  if (mesh.connectivity.empty() || mesh.connectivity.size() % mesh.nodes_per_element != 0)
    return Status::Invalid(
        "tetrahedral mesh: no elements, or a connectivity length that is not a multiple of the "
        "nodes per element");
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* v = mesh.element(e);
    for (int i = 0; i < mesh.nodes_per_element; ++i)
      if (v[i] < 0 || v[i] >= mesh.num_nodes())
        return Status::Invalid(fmt::format("tetrahedral mesh: element {} refers to node {}, but there are {} nodes", e,
                                           v[i], mesh.num_nodes()));
    if (!(element_volume(mesh, e) > 0.0))
      return Status::Invalid(
          fmt::format("tetrahedral mesh: element {} has volume {:.3g} m^3; its vertices must form "
                      "a right-handed tetrahedron of positive volume",
                      e, element_volume(mesh, e)));
  }
  return Status::Ok();
}

void bounding_box(const TetMesh& mesh, Vec3& lo, Vec3& hi) {
  lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const Vec3& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
}

std::string content_hash(const TetMesh& mesh) {
  Sha256 h;
  h.update(&mesh.nodes_per_element, sizeof(int));
  for (const Vec3& x : mesh.nodes) h.update(x.data(), 3 * sizeof(double));
  h.update(mesh.connectivity.data(), mesh.connectivity.size() * sizeof(int));
  return h.hex_digest();
}

}  // namespace kinestat::fea
