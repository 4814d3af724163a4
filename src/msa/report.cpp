// msa::full_report: the human-readable summary printed by `kinestat solve` and `kinestat fivebar`.
#include <cmath>

#include <fmt/format.h>

#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

const char* kDofUnits[6] = {"m", "m", "m", "rad", "rad", "rad"};

}  // namespace

StatusOr<std::string> full_report(const Structure& s, const Solution& sol) {
  // The solution's arrays are indexed by this structure's nodes below.
  if (Status st = check_solution_matches(s, sol); !st.ok()) return st;
  std::string out;
  out += fmt::format("kinestat MSA report{}\n", s.title().empty() ? "" : ": " + s.title());
  out += fmt::format("  model: {} nodes, {} beams, {} joints, {} rigid links, {} supports, {} load cases\n",
                     s.nodes().size(), s.beams().size(), s.joints().size(), s.rigid_links().size(), s.supports().size(),
                     s.load_cases().size());
  out += fmt::format("  dofs: {} total, {} free after supports and constraints\n", sol.num_dofs, sol.num_free_dofs);
  if (sol.second_order)
    out += fmt::format(
        "  analysis: second-order (P-Delta): (K + K_G(N)) u = F iterated on the beams' axial forces N "
        "until the displacements change by less than {:.1e} (at most {} iterations)\n",
        sol.second_order->tolerance, sol.second_order->max_iterations);
  const auto& f = sol.factorization;
  if (f.n > 0) {
    out += fmt::format("  solver: {}\n", sol.backend);
    out += fmt::format(
        "  factorization: {} {} ordering, nnz(K) = {}, nnz(L) = {}, {:.3g} Mflop, symbolic analysis {}, "
        "analyse {:.2e} s, factor {:.2e} s\n",
        f.supernodal ? "supernodal" : "simplicial", f.ordering, f.nnz_matrix, f.nnz_factor, f.flops / 1e6,
        f.reused_symbolic ? "reused" : "new", f.analyze_seconds, f.factor_seconds);
    if (f.min_pivot_column >= 0)
      out += fmt::format(
          "  conditioning: smallest pivot ratio d_j/K_jj = {:.2e}, softest mode u'Ku/u'Du = {:.2e} "
          "(a free motion below {:.0e})\n",
          f.min_pivot_ratio, sol.softest_mode_ratio, sol.mechanism_ratio);
  }
  if (!sol.status.ok()) {
    out += fmt::format("\nSTATUS: {}\n", sol.status.code() == StatusCode::kSingular ? "SINGULAR" : "FAILED");
    out += sol.status.message() + "\n";
    if (!sol.regularized) return out;
  }
  for (size_t ci = 0; ci < sol.cases.size(); ++ci) {
    const LoadCaseResult& c = sol.cases[ci];
    out += fmt::format("\nload case '{}'{}\n", c.name, sol.regularized ? " (REGULARIZED)" : "");
    const bool second = sol.second_order && ci < sol.second_order->iterations.size();
    if (second)
      out += fmt::format("  second-order (P-Delta), {} iterations, last relative change of the displacements {:.1e}\n",
                         sol.second_order->iterations[ci], sol.second_order->relative_change[ci]);
    if (c.max_translation_node >= 0) {
      const Vec6& u = c.displacement[c.max_translation_node];
      out += fmt::format("  max translation {:.4e} m at node '{}' (ux, uy, uz) = ({:.4e}, {:.4e}, {:.4e}) m\n",
                         c.max_translation, s.nodes()[c.max_translation_node].id, u(0), u(1), u(2));
    }
    out += fmt::format(
        "  equilibrium: resultant of loads + reactions{} F = ({:.2e}, {:.2e}, {:.2e}) N, "
        "M = ({:.2e}, {:.2e}, {:.2e}) N m; relative error {:.1e}; free-dof residual {:.1e}\n",
        second ? " + P-Delta forces -K_G u" : "", c.resultant(0), c.resultant(1), c.resultant(2), c.resultant(3),
        c.resultant(4), c.resultant(5), c.equilibrium_error, c.free_dof_residual);
    if (s.report_node()) {
      const Vec6& u = c.displacement[*s.report_node()];
      out += fmt::format("  node '{}':", s.nodes()[*s.report_node()].id);
      for (int i = 0; i < 6; ++i) out += fmt::format(" {}={:.4e} {}", dof_name(i), u(i), kDofUnits[i]);
      out += "\n";
    }
  }
  if (sol.cartesian && s.report_node()) {
    const std::string& node = s.nodes()[*s.report_node()].id;
    out += "\n";  // appended separately: GCC 12 warns falsely (-Wrestrict) about "\n" + std::string&&
    out +=
        cartesian_stiffness_report(*sol.cartesian, "Cartesian stiffness of node '" + node + "' (static condensation" +
                                                       (sol.second_order ? ", elastic K: first order)" : ")"));
  }
  if (sol.global_indices)
    out += "\nindices of the reduced global stiffness matrix:\n" + indices_report(*sol.global_indices);
  return out;
}

}  // namespace kinestat::msa
