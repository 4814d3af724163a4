#include "msa/assembly.hpp"

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/elements/joint_element.hpp"

namespace kinestat::msa {

StatusOr<BeamMatrices> beam_matrices(const Structure& s, const Beam& b) {
  const double L = (s.nodes()[b.node2].position - s.nodes()[b.node1].position).norm();
  const Mat12 k = beam_local_stiffness(s.materials()[b.material], s.sections()[b.section], L, b.theory);
  auto condensed = condense_releases(k, b.releases);
  if (!condensed.ok())
    return Status::Invalid(at_source(b.source, fmt::format("beam '{}': {}", b.id, condensed.status().message())));
  return BeamMatrices{*condensed, beam_transformation(s.beam_axes(b))};
}

StatusOr<solver::SparseMatrix> assemble_stiffness(const Structure& s) {
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(144 * (s.beams().size() + s.joints().size()));
  auto scatter = [&trip](const Mat12& Ke, int n1, int n2) {
    const int base[2] = {6 * n1, 6 * n2};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) trip.emplace_back(base[a] + i, base[b] + j, Ke(6 * a + i, 6 * b + j));
  };
  for (const Beam& b : s.beams()) {
    auto m = beam_matrices(s, b);
    if (!m.ok()) return m.status();
    // Eq. (4) writes [T][k][T]^T with T mapping local to global; here T maps global to local.
    scatter(m->transform.transpose() * m->local * m->transform, b.node1, b.node2);
  }
  for (const Joint& j : s.joints()) scatter(joint_global_stiffness(j.frame, j.stiffness), j.node1, j.node2);
  solver::SparseMatrix K(s.num_dofs(), s.num_dofs());
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

}  // namespace kinestat::msa
