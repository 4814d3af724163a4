#include "kinestat/msa/modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/solver/generalized_eigen.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "msa/assembly.hpp"
#include "msa/dof_map.hpp"
#include "msa/solve_progress.hpp"

namespace kinestat::msa {

ModalResult modal_analysis(const Structure& s, const ModalOptions& opt) {
  ModalResult res;
  if (opt.count < 1) {
    res.status = Status::Invalid(fmt::format("count {}: ask for at least one mode", opt.count));
    return res;
  }
  // Without nodal masses every beam needs a density (a forgotten one would give a massless beam and
  // wrong frequencies without a word); with them, a beam without density is massless on purpose.
  const bool nodal_masses = !s.masses().empty();
  for (const Beam& b : s.beams()) {
    if (!nodal_masses && b.material >= 0 && b.material < static_cast<int>(s.materials().size()) &&
        !(s.materials()[b.material].density > 0.0)) {
      res.status = Status::Invalid(at_source(
          b.source, fmt::format("beam '{}': its material '{}' has no density, so the beam has no mass; give the "
                                "material a density (kg/m^3) for modal analysis, or give the structure nodal 'masses:'",
                                b.id, s.materials()[b.material].id)));
      return res;
    }
  }
  if (s.beams().empty() && !nodal_masses) {
    res.status = Status::Invalid(at_source(s.source(),
                                           "the structure has no beams and no nodal masses, so no mass: "
                                           "nothing vibrates; add 'masses:' or beams with a density"));
    return res;
  }
  const int nc = static_cast<int>(s.load_cases().size());
  const LoadCase* prestress_case = nullptr;
  if (opt.prestress) {
    const int c = opt.prestress->load_case;
    if (c < 0 || c >= nc) {
      res.status = Status::Invalid(at_source(
          s.source(), nc == 0 ? std::string("a prestress needs a load case (its axial forces stress the structure), "
                                            "and the structure has none; add one, or ask for no prestress")
                              : fmt::format("prestress: load case index {} out of range (the structure has {}: 0..{})",
                                            c, nc, nc - 1)));
      return res;
    }
    prestress_case = &s.load_cases()[static_cast<std::size_t>(c)];
  }
  const bool second_order = opt.prestress && opt.prestress->second_order;
  res.linear =
      second_order ? solve_second_order(s, opt.prestress->second_order_options, opt.solve) : solve(s, opt.solve);
  if (!res.linear.status.ok()) {
    res.status = res.linear.status;
    // The second-order solve's own failures (loads at the critical load, no convergence) name their
    // case; they are said to be the prestress's.
    if (second_order && res.status.code() == StatusCode::kNotConverged)
      res.status = Status::NotConverged("prestress: " + res.status.message());
    return res;
  }
  auto map = build_dof_map(s);
  auto K = assemble_stiffness(s);
  if (!map.ok() || !K.ok()) {  // cannot happen: solve() built both
    res.status = Status::Internal("modes: the assembly failed after the static solve succeeded");
    return res;
  }
  if (opt.prestress) {
    // K + K_G(N): the tangent stiffness of the structure under the case's loads (the K_G of buckling
    // and of the second-order solve, msa/assembly.hpp).
    ModalPrestressReport pre;
    pre.load_case = opt.prestress->load_case;
    pre.load_case_name = prestress_case->name;
    pre.second_order = second_order;
    pre.axial_force =
        second_order ? res.linear.second_order->axial_force[static_cast<std::size_t>(pre.load_case)]
                     : beam_axial_forces(s, res.linear.cases[static_cast<std::size_t>(pre.load_case)].beam_end_forces);
    *K += assemble_geometric_stiffness(s, pre.axial_force, opt.prestress->second_order_options.torsion_term).global;
    res.prestress = std::move(pre);
  }
  const solver::SparseMatrix M = assemble_mass(s, opt.lumped, opt.rotary_inertia);
  const solver::SparseMatrix& C = map->C;
  const solver::SparseMatrix Kr = C.transpose() * *K * C;
  const solver::SparseMatrix Mr = C.transpose() * M * C;
  res.num_free_dofs = static_cast<int>(Kr.rows());

  const int nn = static_cast<int>(s.nodes().size());
  MatX R = MatX::Zero(s.num_dofs(), 3);  // rigid unit translations along x, y, z
  for (int i = 0; i < nn; ++i)
    for (int d = 0; d < 3; ++d) R(6 * i + d, d) = 1.0;
  const MatX MR = M * R;
  for (int d = 0; d < 3; ++d) res.total_mass(d) = R.col(d).dot(MR.col(d));

  // M q = mu K q, mu = 1/omega^2: the lowest frequencies are the largest mu (solver/generalized_eigen.hpp).
  auto chol = solver::make_sparse_cholesky(cholesky_options(opt.solve));
  if (Status st = chol->Factorize(Kr, nullptr); !st.ok()) {
    // The elastic K passed the static solve's checks, so a failed K + K_G is the prestress's: by
    // Sylvester's inertia along K + lambda K_G it is positive definite exactly below the case's first
    // critical load factor, and the structure would buckle under that prestress, not vibrate.
    if (opt.prestress && st.code() == StatusCode::kSingular)
      st = Status::Invalid(at_source(
          prestress_case->source.empty() ? s.source() : prestress_case->source,
          fmt::format("prestress of load case '{}': its loads are at or past the critical (buckling) load: K + K_G "
                      "is not positive definite ({}), so the prestressed structure has no natural frequencies (the "
                      "first would be 0 or imaginary); reduce the loads or choose another case (`kinestat buckling` "
                      "gives the critical load factor of a YAML file's case)",
                      prestress_case->name, st.message())));
    res.status = st;
    return res;
  }
  // A zero or negligible mass has no frequency to compute (the eigensolver would only see round-off):
  // refused with what to check. M_ii / K_ii of a free dof is 1/omega^2 of that dof alone, and the
  // largest is a lower bound of 1/omega_1^2. The extremes of the input ranges (a 1 nm beam, E 1e15 Pa,
  // density 1e-6 kg/m^3) give about 1e-40 s^2; below 1e-60 the mass stands for none.
  constexpr double kNegligibleMassRatio = 1e-60;  // s^2
  double mass_ratio = 0.0;
  for (int i = 0; i < Kr.rows(); ++i) mass_ratio = std::max(mass_ratio, Mr.coeff(i, i) / Kr.coeff(i, i));
  if (!(mass_ratio >= kNegligibleMassRatio)) {
    res.status = Status::Invalid(at_source(
        s.source(),
        mass_ratio == 0.0
            ? std::string("no free dof has mass (the densities and nodal masses are 0, or the masses sit on "
                          "supported dofs only), so nothing vibrates; give the materials a density or the free "
                          "nodes a mass")
            : fmt::format("the mass is negligible against the stiffness: the largest ratio of a free dof's mass to "
                          "its stiffness, M_ii / K_ii, is {:.3g} s^2 (below {:g} s^2), so no frequency can be "
                          "computed; check the materials' densities and the nodal masses, and their units",
                          mass_ratio, kNegligibleMassRatio)));
    return res;
  }
  tell(opt.solve, fmt::format("the {} lowest natural frequenc{} (Krylov eigensolver on the factor of K, {} dofs)",
                              opt.count, opt.count == 1 ? "y" : "ies", Kr.rows()));
  auto eig = solver::largest_generalized_eigenpairs(Mr, Kr, *chol, opt.count);
  if (!eig.ok()) {
    res.status = eig.status();
    if (res.status.code() == StatusCode::kNotConverged)
      res.status = Status::NotConverged(at_source(
          s.source(),
          "modes: " + res.status.message() + "; check the materials' densities and the nodal masses, and their units"));
    return res;
  }
  const auto& [mu, Q] = *eig;
  for (int k = 0; k < mu.size(); ++k) {
    // mu = 0: a massless motion (lumped masses leave the bending rotations without mass): no frequency.
    if (!(mu(k) > 1e-12 * mu(0))) continue;
    VibrationMode m;
    m.omega = 1.0 / std::sqrt(mu(k));
    m.frequency = m.omega / (2 * std::numbers::pi);
    VecX q = Q.col(k);
    q /= std::sqrt(q.dot(Mr * q));  // mass-normalized
    const VecX Kq = Kr * q;
    m.residual = (Kq - m.omega * m.omega * (Mr * q)).norm() / Kq.norm();
    // A converged pair has ~1e-13; an inaccurate one is refused rather than printed (as the FEA's
    // link modes are, at the same limit).
    if (!(m.residual <= opt.max_residual)) {
      res.status = Status::NotConverged(at_source(
          s.source(),
          fmt::format("mode {} ({:.6g} Hz) has the residual ||K q - omega^2 M q|| / ||K q|| = {:.2e}, above {:g}: the "
                      "eigensolver did not converge to it, and its frequency would be wrong; ask for fewer modes, "
                      "and check the model's units (stiffness and mass of very different sizes on different dofs)",
                      k + 1, m.frequency, m.residual, opt.max_residual)));
      res.modes.clear();
      return res;
    }
    const VecX u = C * q;
    // The sign is arbitrary: the largest translation component is made positive.
    double largest = 0.0;
    for (int i = 0; i < nn; ++i)
      for (int d = 0; d < 3; ++d)
        if (std::abs(u(6 * i + d)) > std::abs(largest)) largest = u(6 * i + d);
    const double sign = largest < 0 ? -1.0 : 1.0;
    for (int i = 0; i < nn; ++i) m.shape.push_back(sign * u.segment<6>(6 * i));
    m.participation = sign * (MR.transpose() * u);
    m.effective_mass = m.participation.cwiseAbs2();
    res.modes.push_back(std::move(m));
  }
  std::sort(res.modes.begin(), res.modes.end(),
            [](const VibrationMode& a, const VibrationMode& b) { return a.omega < b.omega; });
  if (res.modes.empty())
    res.status = Status::Invalid(at_source(s.source(), "no mode with mass was found; check the densities"));
  return res;
}

}  // namespace kinestat::msa
