#include "kinestat/msa/buckling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/solver/generalized_eigen.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "msa/assembly.hpp"
#include "msa/dof_map.hpp"
#include "msa/solve_progress.hpp"

namespace kinestat::msa {

BucklingResult buckling(const Structure& s, const BucklingOptions& opt) {
  BucklingResult res;
  res.load_case = opt.load_case;
  const int nc = static_cast<int>(s.load_cases().size());
  if (opt.load_case < 0 || opt.load_case >= nc) {
    res.status = Status::Invalid(at_source(
        s.source(), nc == 0 ? std::string("the structure has no load case: buckling needs one (its loads are scaled "
                                          "by the load factor); add a load case")
                            : fmt::format("load case index {} out of range (the structure has {}: 0..{})",
                                          opt.load_case, nc, nc - 1)));
    return res;
  }
  if (opt.count < 1) {
    res.status = Status::Invalid(fmt::format("count {}: ask for at least one load factor", opt.count));
    return res;
  }
  const LoadCase& lc = s.load_cases()[opt.load_case];
  res.load_case_name = lc.name;

  res.linear = solve(s, opt.solve);
  if (!res.linear.status.ok()) {
    res.status = res.linear.status;
    return res;
  }
  const LoadCaseResult& r = res.linear.cases[opt.load_case];
  res.axial_force = beam_axial_forces(s, r.beam_end_forces);
  // Which beams are compressed, against a scale that does not come from N: N is E A / L times the
  // change of length computed from the nodes' displacements (round-off about eps (E A / L) |u|), plus
  // what member loads put into it (about eps times the loads, which the reactions and nodal loads
  // carry). Compression below 1e-12 of that is round-off: a cantilever loaded across its axis has
  // -N ~ 5e-17 of it, a freely expanding heated column 2e-16; the bundled models' compressions are
  // 4e-4 (models/five_bar.yaml) to 0.1 of it. The largest |N| is no scale: there it is itself
  // round-off, and its 1e-12 let lambda ~ 1e13 through.
  double u_max = 0.0, load_max = 0.0;
  const double length = s.length_scale();
  for (const Vec6& u : r.displacement) u_max = std::max(u_max, u.head<3>().norm());
  for (const Vec6& f : r.reaction) load_max = std::max({load_max, f.head<3>().norm(), f.tail<3>().norm() / length});
  for (const NodalLoad& l : lc.loads)
    load_max = std::max({load_max, l.wrench.head<3>().norm(), l.wrench.tail<3>().norm() / length});
  constexpr double kRoundOff = 1e-12;
  int most_compressed = -1;  // the beam with the largest compression relative to its round-off scale
  double largest_ratio = 0.0;
  for (std::size_t i = 0; i < s.beams().size(); ++i) {
    const Beam& b = s.beams()[i];
    const double axial_stiffness = s.materials()[b.material].E * s.sections()[b.section].A / s.beam_length(b);
    const double scale = axial_stiffness * u_max + load_max;
    const double ratio = scale > 0.0 ? -res.axial_force[i] / scale : 0.0;
    if (ratio > largest_ratio) {
      largest_ratio = ratio;
      most_compressed = static_cast<int>(i);
    }
  }
  if (!(largest_ratio > kRoundOff)) {
    const std::string roundoff =
        most_compressed < 0
            ? std::string()
            : fmt::format(
                  " (its largest compression, N = {:.3g} N in beam '{}', is {:.2g} of E A / L times the "
                  "largest displacement plus the largest load: round-off)",
                  res.axial_force[static_cast<std::size_t>(most_compressed)],
                  s.beams()[static_cast<std::size_t>(most_compressed)].id, largest_ratio);
    res.status = Status::Invalid(at_source(
        lc.source.empty() ? s.source() : lc.source,
        fmt::format("load case '{}' compresses no beam{}: nothing can buckle (the critical load factor is infinite); "
                    "load the structure so that some beam is in compression",
                    lc.name, roundoff)));
    return res;
  }

  auto map = build_dof_map(s);
  auto K = assemble_stiffness(s);
  if (!map.ok() || !K.ok()) {  // cannot happen: solve() built both
    res.status = Status::Internal("buckling: the assembly failed after the static solve succeeded");
    return res;
  }
  const solver::SparseMatrix KG = assemble_geometric_stiffness(s, res.axial_force, opt.torsion_term).global;
  const solver::SparseMatrix& C = map->C;
  const solver::SparseMatrix Kr = C.transpose() * *K * C;
  const solver::SparseMatrix KGr = C.transpose() * KG * C;
  res.num_free_dofs = static_cast<int>(Kr.rows());

  // Solved as -K_G q = mu K q, mu = 1/lambda: the smallest positive lambdas are the largest mu
  // (solver/generalized_eigen.hpp says why this form; Euler's column: mu_2/mu_1 = 1/4, well apart).
  auto chol = solver::make_sparse_cholesky(cholesky_options(opt.solve));
  if (Status st = chol->Factorize(Kr, nullptr); !st.ok()) {
    res.status = st;
    return res;
  }
  tell(opt.solve, fmt::format("the {} lowest critical load factor{} (Krylov eigensolver on the factor of K, {} dofs)",
                              opt.count, opt.count == 1 ? "" : "s", Kr.rows()));
  const solver::SparseMatrix minus_KGr = -KGr;
  auto eig = solver::largest_generalized_eigenpairs(minus_KGr, Kr, *chol, opt.count);
  if (!eig.ok()) {
    res.status = eig.status();
    return res;
  }
  const auto& [mu, Q] = *eig;
  for (int k = 0; k < mu.size(); ++k) {
    if (!(mu(k) > 0.0)) continue;  // tension-only directions: no positive load factor
    BucklingMode m;
    m.load_factor = 1.0 / mu(k);
    const VecX q = Q.col(k);
    const VecX Kq = Kr * q;
    m.residual = (Kq + m.load_factor * (KGr * q)).norm() / Kq.norm();
    const VecX u = C * q;
    const int nn = static_cast<int>(s.nodes().size());
    // Normalized to max translation 1 (a mode without translation, e.g. twist: max rotation 1 rad),
    // signed so that its largest translation (rotation) component is positive.
    double tmax = 0.0, rmax = 0.0;
    for (int i = 0; i < nn; ++i) {
      tmax = std::max(tmax, u.segment<3>(6 * i).norm());
      rmax = std::max(rmax, u.segment<3>(6 * i + 3).norm());
    }
    const bool by_translation = tmax > 1e-9 * rmax * s.length_scale();
    const double scale = by_translation ? tmax : rmax;
    double largest = 0.0;
    for (int i = 0; i < nn; ++i)
      for (int k = by_translation ? 0 : 3; k < (by_translation ? 3 : 6); ++k)
        if (std::abs(u(6 * i + k)) > std::abs(largest)) largest = u(6 * i + k);
    const double sign = largest < 0 ? -1.0 : 1.0;
    for (int i = 0; i < nn; ++i) m.shape.push_back(sign / scale * u.segment<6>(6 * i));
    res.modes.push_back(std::move(m));
  }
  std::sort(res.modes.begin(), res.modes.end(),
            [](const BucklingMode& a, const BucklingMode& b) { return a.load_factor < b.load_factor; });
  if (res.modes.empty())
    res.status = Status::Invalid(at_source(
        s.source(), fmt::format("load case '{}': no positive critical load factor: the compressed beams are braced "
                                "against every buckling motion",
                                lc.name)));
  return res;
}

}  // namespace kinestat::msa
