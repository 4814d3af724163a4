#include "kinestat/msa/buckling.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/solver/generalized_eigen.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "msa/assembly.hpp"
#include "msa/dof_map.hpp"

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
  double max_abs = 0.0, max_compression = 0.0;
  res.axial_force = beam_axial_forces(s, r.beam_end_forces);
  for (double N : res.axial_force) {
    max_abs = std::max(max_abs, std::abs(N));
    max_compression = std::max(max_compression, -N);
  }
  // Compression below round-off of the largest axial force (1e-12) is no compression.
  if (!(max_compression > 1e-12 * max_abs) || max_abs == 0.0) {
    res.status = Status::Invalid(at_source(
        lc.source.empty() ? s.source() : lc.source,
        fmt::format("load case '{}' compresses no beam: nothing can buckle (the critical load factor is infinite); "
                    "load the structure so that some beam is in compression",
                    lc.name)));
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
  auto chol = solver::make_sparse_cholesky(opt.solve.cholesky);
  if (Status st = chol->Factorize(Kr, nullptr); !st.ok()) {
    res.status = st;
    return res;
  }
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
