#include "msa/singularity_diagnosis.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/solver/null_space.hpp"

namespace kinestat::msa {
namespace {

std::string weak_dof_words(const Structure& s, const ReducedDof& rd) {
  const bool global = rd.frame.isApprox(Mat3::Identity());
  return fmt::format("node '{}' {}{}", s.nodes()[rd.node].id, dof_name(rd.component), global ? "" : " (local frame)");
}

}  // namespace

std::string describe_node_motion(const Vec6& m, double L) {
  const Vec3 t = m.head<3>(), r = m.tail<3>();
  const double scale = std::max(t.norm(), r.norm() * L);
  std::string out;
  if (t.norm() > 0.05 * scale) out += fmt::format("translates along {} ({:.3g})", direction_words(t), t.norm());
  if (r.norm() * L > 0.05 * scale) {
    if (!out.empty()) out += " and ";
    out += fmt::format("rotates about {} ({:.3g} rad{})", direction_words(r), r.norm(), t.norm() > 0 || L != 1.0 ? "/m" : "");
  }
  return out;
}

SingularityDiagnosis diagnose_singularity(const Structure& s, const DofMap& map, const solver::SparseMatrix& Kr,
                                          const solver::FactorizationReport& report, double tolerance,
                                          const solver::SparseCholeskyOptions& options) {
  SingularityDiagnosis d;
  d.singular = true;
  std::vector<int> cols = report.weak_columns;
  if (report.failed_column >= 0) cols.push_back(report.failed_column);
  for (int c : cols) d.weak_dofs.push_back({map.reduced[c].node, map.reduced[c].component});

  const double L = s.length_scale();
  const int nn = static_cast<int>(s.nodes().size());
  std::string text = "The structure is singular: some motion is resisted by no element (a mechanism, a released "
                     "chain, a missing support, or a singular posture).\n";
  if (!cols.empty()) {
    text += "  Elimination found no stiffness at: ";
    for (size_t i = 0; i < cols.size(); ++i) text += (i ? ", " : "") + weak_dof_words(s, map.reduced[cols[i]]);
    text += "\n";
  }

  const int block = std::min<int>(Kr.rows(), static_cast<int>(cols.size()) + 6);
  // Modes count as free up to the pivot tolerance; at least the lowest one is always described.
  auto ns = solver::near_null_space(Kr, block, tolerance, options);
  if (!ns.ok()) {
    d.message = text + "  (the free motions could not be computed: " + ns.status().message() + ")";
    return d;
  }
  for (int k = 0; k < ns->modes.cols(); ++k) {
    const VecX u = map.C * ns->modes.col(k);
    FreeMotion fm;
    fm.rayleigh_ratio = ns->ratios(k);
    fm.node_motion.resize(nn);
    // Scale so that the largest nodal translation is 1 (rotations then read in rad per m of that
    // translation), or the largest rotation when nothing translates; the sign makes the largest
    // component positive, so the printed mode is reproducible.
    double tmax = 0.0, rmax = 0.0;
    int imax = 0;
    for (int i = 0; i < u.size(); ++i) {
      const bool translation = (i % 6) < 3;
      if (translation && std::abs(u(i)) > tmax) tmax = std::abs(u(i)), imax = i;
      if (!translation) rmax = std::max(rmax, std::abs(u(i)));
    }
    if (tmax <= 1e-9 * rmax * L)
      for (int i = 0; i < u.size(); ++i)
        if (std::abs(u(i)) >= rmax) imax = i;
    const double scale = (u(imax) < 0 ? -1.0 : 1.0) / std::abs(u(imax));
    for (int n = 0; n < nn; ++n) fm.node_motion[n] = scale * u.segment<6>(6 * n);
    std::vector<int> order(nn);
    for (int n = 0; n < nn; ++n) order[n] = n;
    const bool rotation_only = tmax <= 1e-9 * rmax * L;
    auto size = [&](int n) {
      const Vec6& m = fm.node_motion[n];
      return rotation_only ? m.tail<3>().norm() : std::max(m.head<3>().norm(), m.tail<3>().norm() * L);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size(a) > size(b); });
    fm.description = fmt::format("free motion {} (stiffness ratio {:.1e}; largest {} scaled to 1):", k + 1,
                                 fm.rayleigh_ratio, rotation_only ? "rotation" : "translation");
    int listed = 0;
    for (int n : order) {
      if (size(n) < 0.05 || listed == 8) break;
      fm.description += fmt::format("\n    node '{}' {}", s.nodes()[n].id,
                                    describe_node_motion(fm.node_motion[n], rotation_only ? 1.0 : L));
      ++listed;
    }
    const int moving = static_cast<int>(std::count_if(order.begin(), order.end(), [&](int n) { return size(n) >= 0.05; }));
    if (moving > listed) fm.description += fmt::format("\n    ... and {} more nodes", moving - listed);
    text += "  " + fm.description + "\n";
    d.modes.push_back(std::move(fm));
  }
  text += "  Fix: add the missing support or stiffness, or move away from the singular posture "
          "(--regularize gives a marked, regularized answer).";
  d.message = text;
  return d;
}

}  // namespace kinestat::msa
