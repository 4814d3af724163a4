#include "fea/elasticity_assembly.hpp"

#include <atomic>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/huge_page_allocator.hpp"
#include "kinestat/fea/tet_element.hpp"

namespace kinestat::fea {

DofMap make_dof_map(const TetMesh& mesh, const std::vector<int>& clamped, const std::vector<int>& coupled,
                    const Vec3& reference_point) {
  enum : char { kFree, kClamped, kCoupled };
  std::vector<char> kind(mesh.num_nodes(), kFree);
  for (int n : clamped) kind[n] = kClamped;
  for (int n : coupled) kind[n] = kCoupled;
  DofMap map;
  map.terms.resize(3 * static_cast<size_t>(mesh.num_nodes()));
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (kind[n] == kFree)
      for (int d = 0; d < 3; ++d) map.terms[3 * n + d] = {1, {map.num_dofs++, 0, 0}, {1.0, 0.0, 0.0}};
  if (coupled.empty()) return map;
  map.reference_dof = map.num_dofs;
  map.num_dofs += 6;
  for (int n : coupled) {
    // u_node = u_ref + theta x r = [I, -[r]x] (u_ref, theta)
    const Mat3 minus_skew = -skew(mesh.nodes[n] - reference_point);
    for (int d = 0; d < 3; ++d) {
      DofMap::Terms& t = map.terms[3 * n + d];
      t.index[t.count] = map.reference_dof + d;
      t.coef[t.count++] = 1.0;
      for (int r = 0; r < 3; ++r)
        if (minus_skew(d, r) != 0.0) {
          t.index[t.count] = map.reference_dof + 3 + r;
          t.coef[t.count++] = minus_skew(d, r);
        }
    }
  }
  return map;
}

DofMap free_dof_map(const TetMesh& mesh) { return make_dof_map(mesh, {}, {}, Vec3::Zero()); }

std::vector<Vec3> expand(const DofMap& map, const Eigen::Ref<const VecX>& reduced) {
  std::vector<Vec3> u(map.terms.size() / 3, Vec3::Zero());
  for (size_t i = 0; i < map.terms.size(); ++i) {
    const DofMap::Terms& t = map.terms[i];
    for (int k = 0; k < t.count; ++k) u[i / 3](i % 3) += t.coef[k] * reduced(t.index[k]);
  }
  return u;
}

std::pair<int, int> element_range(int num_elements, int rank, int ranks) {
  auto first = [&](int r) { return static_cast<int>(static_cast<long>(num_elements) * r / ranks); };
  return {first(rank), first(rank + 1)};
}

StatusOr<solver::SparseMatrix> assemble_stiffness(const TetMesh& mesh, const std::vector<Mat6>& D,
                                                  const std::vector<int>& material, const DofMap& map,
                                                  std::pair<int, int> elements) {
  using Triplet = Eigen::Triplet<double, int>;
  // Hundreds of MB at 100k dofs: huge pages (core/huge_page_allocator.hpp).
  using Triplets = std::vector<Triplet, HugePageAllocator<Triplet>>;
  const int npe = mesh.nodes_per_element, ndof = 3 * npe;
  tbb::enumerable_thread_specific<Triplets> local;
  std::atomic<int> bad_element{-1};
  const int last = elements.second < 0 ? mesh.num_elements() : elements.second;
  tbb::parallel_for(tbb::blocked_range<int>(elements.first, last, 512), [&](const tbb::blocked_range<int>& range) {
    Triplets& out = local.local();
    std::array<Vec3, 10> x;
    for (int e = range.begin(); e != range.end(); ++e) {
      const int* v = mesh.element(e);
      for (int a = 0; a < npe; ++a) x[a] = mesh.nodes[v[a]];
      const MatX Ke = tet_stiffness(x.data(), npe, D[material.empty() ? 0 : material[e]]);
      if (Ke.size() == 0) {
        bad_element = e;
        continue;
      }
      // Scatter K_reduced += T_e^T K_e T_e term by term; keep the lower triangle only (all the
      // Cholesky factorization reads).
      for (int i = 0; i < ndof; ++i) {
        const DofMap::Terms& ti = map.terms[3 * v[i / 3] + i % 3];
        for (int j = 0; j < ndof; ++j) {
          const DofMap::Terms& tj = map.terms[3 * v[j / 3] + j % 3];
          for (int a = 0; a < ti.count; ++a)
            for (int b = 0; b < tj.count; ++b)
              if (ti.index[a] >= tj.index[b])
                out.emplace_back(ti.index[a], tj.index[b], ti.coef[a] * tj.coef[b] * Ke(i, j));
        }
      }
    }
  });
  if (bad_element >= 0)
    return Status::Invalid(fmt::format("tetrahedral mesh: element {} has a non-positive Jacobian (inverted or "
                                       "degenerate); remesh the link",
                                       bad_element.load()));
  Triplets all;
  size_t total = 0;
  for (const auto& part : local) total += part.size();
  all.reserve(total);
  for (auto& part : local) {
    all.insert(all.end(), part.begin(), part.end());
    Triplets().swap(part);
  }
  solver::SparseMatrix K(map.num_dofs, map.num_dofs);
  K.setFromTriplets(all.begin(), all.end());
  return K;
}

}  // namespace kinestat::fea
