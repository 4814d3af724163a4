#include "msa/assembly.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/joint_element.hpp"

namespace kinestat::msa {

namespace {

bool has_releases(const Beam& b) {
  return std::any_of(b.releases.begin(), b.releases.end(), [](bool r) { return r; });
}

}  // namespace

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
  for (const Joint& j : s.joints()) scatter(joint_global_stiffness(j.frame, j.stiffness, j.coupling), j.node1, j.node2);
  solver::SparseMatrix K(s.num_dofs(), s.num_dofs());
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

GeometricStiffness assemble_geometric_stiffness(const Structure& s, const std::vector<double>& axial_force,
                                                bool torsion_term) {
  GeometricStiffness g;
  const bool frame3dd = s.geometric_stiffness_convention() == GeometricStiffnessConvention::kFrame3dd;
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(144 * s.beams().size());
  for (size_t i = 0; i < s.beams().size(); ++i) {
    const Beam& b = s.beams()[i];
    const Section& sec = s.sections()[b.section];
    const double L = s.beam_length(b);
    GeometricStiffnessTerms terms;
    terms.polar_radius2 = torsion_term ? polar_moment(sec) / sec.A : 0.0;
    terms.axial = !frame3dd;
    terms.shear = beam_shear_parameters(s.materials()[b.material], sec, L, b.theory);
    Mat12 kl = beam_local_geometric_stiffness(axial_force[i], L, terms);
    if (has_releases(b)) {
      // With the static shapes of the released dofs, as the elastic matrix (condense_with_releases).
      // assemble_stiffness has condensed the same releases before any K_G is built, so this succeeds.
      auto c =
          condense_with_releases(beam_local_stiffness(s.materials()[b.material], sec, L, b.theory), b.releases, kl);
      if (c.ok()) kl = *c;
    }
    g.local.push_back(kl);
    const Mat12 T = beam_transformation(s.beam_axes(b));
    const Mat12 kg = T.transpose() * g.local.back() * T;
    const int base[2] = {6 * b.node1, 6 * b.node2};
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 6; ++k)
          for (int l = 0; l < 6; ++l) trip.emplace_back(base[a] + k, base[c] + l, kg(6 * a + k, 6 * c + l));
  }
  g.global = solver::SparseMatrix(s.num_dofs(), s.num_dofs());
  g.global.setFromTriplets(trip.begin(), trip.end());
  return g;
}

solver::SparseMatrix assemble_mass(const Structure& s, bool lumped, bool rotary_inertia) {
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(144 * s.beams().size() + 6 * s.masses().size());
  for (const Beam& b : s.beams()) {
    const Mat12 T = beam_transformation(s.beam_axes(b));
    const Material& mat = s.materials()[b.material];
    const Section& sec = s.sections()[b.section];
    const double L = s.beam_length(b);
    Mat12 ml = beam_local_mass(mat, sec, L, lumped, rotary_inertia);
    if (has_releases(b)) {  // as K_G above
      auto c = condense_with_releases(beam_local_stiffness(mat, sec, L, b.theory), b.releases, ml);
      if (c.ok()) ml = *c;
    }
    const Mat12 me = T.transpose() * ml * T;
    const int base[2] = {6 * b.node1, 6 * b.node2};
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 6; ++k)
          for (int l = 0; l < 6; ++l) trip.emplace_back(base[a] + k, base[c] + l, me(6 * a + k, 6 * c + l));
  }
  for (const NodalMass& nm : s.masses())
    for (int d = 0; d < 3; ++d) {
      trip.emplace_back(6 * nm.node + d, 6 * nm.node + d, nm.mass);
      trip.emplace_back(6 * nm.node + 3 + d, 6 * nm.node + 3 + d, nm.inertia(d));
    }
  solver::SparseMatrix M(s.num_dofs(), s.num_dofs());
  M.setFromTriplets(trip.begin(), trip.end());
  return M;
}

std::vector<double> beam_axial_forces(const Structure& s, const std::vector<Vec12>& end_forces) {
  const bool first_end = s.geometric_stiffness_convention() == GeometricStiffnessConvention::kFrame3dd;
  std::vector<double> N;
  N.reserve(end_forces.size());
  // End forces act on the beam: tension is +N2 and -N1; their mean is the axial force at midspan.
  for (const Vec12& f : end_forces) N.push_back(first_end ? -f(0) : 0.5 * (f(6) - f(0)));
  return N;
}

StatusOr<std::vector<Vec12>> fixed_end_forces(const Structure& s, const LoadCase& lc) {
  const bool weight = lc.gravity.squaredNorm() > 0.0;
  if (!weight && lc.member_loads.empty()) return std::vector<Vec12>{};
  const auto& beams = s.beams();
  std::vector<Vec12> fef(beams.size(), Vec12::Zero());
  auto span = [&s](const Beam& b) {
    return BeamSpan{s.materials()[b.material], s.sections()[b.section], s.beam_length(b), b.theory};
  };
  if (weight) {
    for (size_t i = 0; i < beams.size(); ++i) {
      const Beam& b = beams[i];
      const double rho = s.materials()[b.material].density;
      if (rho == 0.0) continue;
      const Vec3 w = rho * s.sections()[b.section].A * lc.gravity;  // N/m, global
      fef[i] += uniform_load_fixed_end_forces(span(b), s.beam_axes(b).transpose() * w);
    }
  }
  for (const MemberLoad& ml : lc.member_loads) {
    const Beam& b = beams[ml.beam];
    const Mat3 axes = s.beam_axes(b);  // columns: local axes in global coordinates
    auto local = [&](const Vec3& v) { return ml.global_axes ? Vec3(axes.transpose() * v) : v; };
    const BeamSpan sp = span(b);
    Vec12& f = fef[ml.beam];
    switch (ml.type) {
      case MemberLoadType::kUniform:
        f += uniform_load_fixed_end_forces(sp, local(ml.w1));
        break;
      case MemberLoadType::kTrapezoidal:
        f += trapezoidal_load_fixed_end_forces(sp, ml.a, ml.b, local(ml.w1), local(ml.w2));
        break;
      case MemberLoadType::kPoint:
        f += point_load_fixed_end_forces(sp, ml.a, local(ml.force), local(ml.moment));
        break;
      case MemberLoadType::kTemperature:
        f += temperature_fixed_end_forces(sp, ml.thermal);
        break;
    }
  }
  for (size_t i = 0; i < beams.size(); ++i) {
    const Beam& b = beams[i];
    bool released = false;
    for (bool r : b.releases) released = released || r;
    if (!released || fef[i].isZero(0.0)) continue;
    const BeamSpan sp = span(b);
    auto c = condense_fixed_end_forces(beam_local_stiffness(sp.material, sp.section, sp.length, b.theory), b.releases,
                                       fef[i]);
    if (!c.ok()) return Status::Invalid(at_source(b.source, fmt::format("beam '{}': {}", b.id, c.status().message())));
    fef[i] = *c;
  }
  return fef;
}

VecX equivalent_nodal_loads(const Structure& s, const std::vector<Vec12>& fef) {
  VecX f = VecX::Zero(s.num_dofs());
  for (size_t i = 0; i < fef.size(); ++i) {
    if (fef[i].isZero(0.0)) continue;
    const Beam& b = s.beams()[i];
    const Vec12 g = -(beam_transformation(s.beam_axes(b)).transpose() * fef[i]);
    f.segment<6>(6 * b.node1) += g.head<6>();
    f.segment<6>(6 * b.node2) += g.tail<6>();
  }
  return f;
}

}  // namespace kinestat::msa
