#include "kinestat/msa/static_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/null_space.hpp"
#include "msa/assembly.hpp"
#include "msa/dof_map.hpp"
#include "msa/singularity_diagnosis.hpp"
#include "msa/solve_progress.hpp"

namespace kinestat::msa {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Everything one posture needs: C, K, K_r (reduced), factorized in the workspace.
struct System {
  DofMap map;
  solver::SparseMatrix K;
  solver::SparseMatrix Kr;
};

StatusOr<System> build_system(const Structure& s) {
  if (Status st = s.validate(); !st.ok()) return st;
  auto map = build_dof_map(s);
  if (!map.ok()) return map.status();
  auto K = assemble_stiffness(s);
  if (!K.ok()) return K.status();
  System sys{std::move(*map), std::move(*K), {}};
  // The product's pattern is structural (zero values are kept), so every posture of one topology
  // has the same pattern and the workspace reuses its symbolic analysis.
  sys.Kr = sys.map.C.transpose() * sys.K * sys.map.C;
  return sys;
}

// Factorizes K_r; on a singular structure fills the diagnosis and, if asked, factorizes K_r + eps D.
Status factorize(const Structure& s, const System& sys, Workspace& ws, const SolveOptions& opt, Solution& sol,
                 std::unique_ptr<solver::SparseCholesky>& regularized) {
  Status st = ws.cholesky().Factorize(sys.Kr, &sol.factorization);
  if (st.ok()) {
    tell(opt, "searching for free motions (inverse iteration on the factor)");
    auto soft = solver::lowest_modes(sys.Kr, ws.cholesky(), std::min<int>(3, sys.Kr.rows()), 6);
    if (!soft.ok()) return soft.status();
    sol.softest_mode_ratio = soft->ratios(0);
    if (sol.softest_mode_ratio >= opt.mechanism_ratio) return st;
    st = Status::Singular("softest mode below the mechanism ratio");
  }
  if (st.code() != StatusCode::kSingular) return st;
  tell(opt, "the stiffness matrix is singular: finding its free motions");
  sol.singularity = diagnose_singularity(s, sys.map, sys.Kr, sol.factorization, opt.mechanism_ratio, opt.cholesky);
  if (!sol.singularity.modes.empty()) sol.softest_mode_ratio = sol.singularity.modes.front().rayleigh_ratio;
  if (!opt.regularize) return Status::Singular(sol.singularity.message);
  solver::SparseMatrix R = sys.Kr;
  const VecX D = solver::stiffness_scaling(R);
  for (int i = 0; i < R.rows(); ++i) R.coeffRef(i, i) += opt.regularization * D(i);
  solver::LinearSolverOptions shifted = opt.cholesky;  // the caller's backend and ordering, no pivot check
  shifted.singular_pivot_ratio = 0.0;
  regularized = solver::make_sparse_cholesky(shifted);
  if (Status r = regularized->Factorize(R, nullptr); !r.ok()) return r;
  sol.regularized = true;
  return Status::Ok();
}

// The residual K u - f with each tied slave's share moved to its master. At a slave, K u - f is the
// force the tie exerts on it; by virtual work (u_s = M u_m in the tied components) the tie exerts
// -M' of it on the master, so the support of a master balances residual_m + M' residual_s. Without
// this a supported master of a rigid link reported no reaction at all. Deepest slaves go first, so
// a chain of ties carries its share all the way to the supported end. `tie_forces` (per tie, its
// frame, the tied components): the force the tie exerts on its slave, its own slaves' shares included.
VecX carry_ties_to_masters(const Structure& s, const DofMap& map, const VecX& residual, std::vector<Vec6>& tie_forces) {
  tie_forces.assign(map.ties.size(), Vec6::Zero());
  VecX carried = residual;
  const std::vector<int> order = tied_nodes_by_depth(map);
  for (auto it = order.rbegin(); it != order.rend(); ++it) {  // the deepest slaves first
    const int n = *it;
    const auto& tie = map.ties[map.slave_of_tie[n]];
    const Mat6 R = rotation6(tie.frame);
    Vec6 tied = R.transpose() * carried.segment<6>(6 * n);
    for (int i = 0; i < 6; ++i)
      if (!tie.mask[i]) tied(i) = 0.0;  // the free components are the slave's own (zero at equilibrium)
    tie_forces[map.slave_of_tie[n]] = tied;
    const Vec6 on_slave = R * tied;
    carried.segment<6>(6 * tie.master) += tie_transfer(s, tie).transpose() * on_slave;
    carried.segment<6>(6 * n) -= on_slave;
  }
  return carried;
}

// `f` includes the equivalent nodal loads of the member loads, whose fixed-end forces `fef` (per
// beam, local; empty: none) are added to k T u to give the members' true end forces. With `g` (the
// second-order solve), the stiffness is K + K_G: the residual, the end forces and the free-dof
// residual use it, and the resultant adds the P-Delta forces -K_G u to the loads, because K_G u has
// a moment (the axial forces on the rotated chords) which K u, self-balanced, has not.
LoadCaseResult post_process(const Structure& s, const System& sys, const LoadCase& lc, const VecX& u, const VecX& f,
                            const VecX& u0, const std::vector<Vec12>& fef, const GeometricStiffness* g = nullptr) {
  LoadCaseResult r;
  r.name = lc.name;
  const int nn = static_cast<int>(s.nodes().size());
  const VecX pdelta = g ? VecX(g->global * u) : VecX::Zero(u.size());  // K_G u
  const VecX applied = f - pdelta;
  const VecX residual = sys.K * u + pdelta - f;        // reactions at supports, constraint forces at tied nodes
  const VecX terms = sys.K.cwiseAbs() * u.cwiseAbs();  // the size of the members' force terms summed in K u
  VecX loop_forces;
  const VecX tree_residual = remove_loop_forces(s, sys.map, residual, loop_forces);
  std::vector<Vec6> tie_forces;
  const VecX support_residual = carry_ties_to_masters(s, sys.map, tree_residual, tie_forces);
  r.displacement.resize(nn);
  r.reaction.assign(nn, Vec6::Zero());
  // Scale of the loads and reactions, each term taken on its own (not their net sum at a node, which
  // is zero where a support takes a load directly), forces times the structure size so that forces
  // and moments share one unit (N m): a pure-moment case then compares the round-off in its
  // resultant force with its moments, not with the round-off reactions themselves. The terms of K u
  // count too (|K| |u|): a rigid settlement leaves loads, reactions and K u at the round-off of
  // those terms, which is what it is measured against.
  const double size = s.length_scale();
  double scale = 0.0;
  for (int n = 0; n < nn; ++n) {
    r.displacement[n] = u.segment<6>(6 * n);
    if (sys.map.supported_node[n]) r.reaction[n] = support_residual.segment<6>(6 * n);
    const double t = r.displacement[n].head<3>().norm();
    if (t > r.max_translation || r.max_translation_node < 0) {
      r.max_translation = t;
      r.max_translation_node = n;
    }
    // Resultant of loads + reactions about the origin: zero for a structure in equilibrium.
    const Vec3& x = s.nodes()[n].position;
    for (const Vec6& w : {Vec6(applied.segment<6>(6 * n)), r.reaction[n]}) {
      r.resultant.head<3>() += w.head<3>();
      r.resultant.tail<3>() += w.tail<3>() + x.cross(w.head<3>());
      scale += w.tail<3>().norm() + (size + x.norm()) * w.head<3>().norm();
    }
    const Vec6 e = terms.segment<6>(6 * n);
    scale += e.tail<3>().norm() + (size + x.norm()) * e.head<3>().norm();
  }
  const double unbalance = size * r.resultant.head<3>().norm() + r.resultant.tail<3>().norm();
  r.equilibrium_error = scale > 0 ? unbalance / scale : 0.0;
  const VecX rr = sys.map.C.transpose() * residual;
  const VecX Kt_u0 = sys.K * u0 + (g ? VecX(g->global * u0) : VecX::Zero(u0.size()));
  const double fn = (sys.map.C.transpose() * (f - Kt_u0)).norm();  // the reduced right-hand side
  r.free_dof_residual = fn > 0 ? rr.norm() / fn : rr.norm();

  for (size_t i = 0; i < s.beams().size(); ++i) {
    const Beam& b = s.beams()[i];
    const auto m = beam_matrices(s, b);  // cannot fail: assembly already succeeded
    Vec12 ue;
    ue << u.segment<6>(6 * b.node1), u.segment<6>(6 * b.node2);
    const Vec12 local_u = m->transform * ue;
    r.beam_end_forces.push_back(m->local * local_u);
    if (g) r.beam_end_forces.back() += g->local[i] * local_u;
    if (!fef.empty()) r.beam_end_forces.back() += fef[i];
  }
  for (size_t j = 0; j < s.joints().size(); ++j) {
    const Joint& jt = s.joints()[j];
    const Mat6 R6 = rotation6(jt.frame);
    const Vec6 rel = R6.transpose() * (u.segment<6>(6 * jt.node2) - u.segment<6>(6 * jt.node1));
    Vec6 force = jt.coupling * rel;  // k (u2 - u1) in the joint frame: positive in tension
    for (int i = 0; i < 6; ++i) force(i) = std::isinf(jt.stiffness(i)) ? 0.0 : force(i) + jt.stiffness(i) * rel(i);
    // Rigid components carry a constraint force: the tied node's equilibrium, its own slaves' shares
    // included (carry_ties_to_masters), or, for a tie that closes a loop, its own (a loop's dependent
    // constraints carry none: their share of the force is not determined).
    for (std::size_t t = 0; t < sys.map.ties.size(); ++t) {
      const auto& tie = sys.map.ties[t];
      if (tie.joint != static_cast<int>(j)) continue;
      const double sign = tie.slave == jt.node2 ? -1.0 : 1.0;
      if (sys.map.slave_of_tie[tie.slave] != static_cast<int>(t)) {
        for (int i = 0; i < 6; ++i)
          if (tie.mask[i]) force(i) = 0.0;
        for (std::size_t k = 0; k < sys.map.loop_rows.size(); ++k)
          if (sys.map.loop_rows[k].tie == static_cast<int>(t))
            force(sys.map.loop_rows[k].component) = sign * loop_forces(static_cast<int>(k));
        continue;
      }
      for (int i = 0; i < 6; ++i)
        if (tie.mask[i]) force(i) = sign * tie_forces[t](i);
    }
    r.joint_forces.push_back(force);
  }
  return r;
}

// One load case's right-hand side: nodal loads plus the member loads' equivalent nodal loads (F),
// prescribed displacements (U0) and the fixed-end forces per beam.
struct CaseLoads {
  VecX F, U0;
  std::vector<Vec12> fef;
};
StatusOr<CaseLoads> case_loads(const Structure& s, const DofMap& map, const LoadCase& lc) {
  auto fef = fixed_end_forces(s, lc);
  if (!fef.ok()) return fef.status();
  CaseLoads c;
  c.F = nodal_loads(s, lc) + equivalent_nodal_loads(s, *fef);
  c.U0 = prescribed_displacements(s, map, lc);
  c.fef = std::move(*fef);
  return c;
}

// Loads and reactions that do not balance mean a wrong answer (a lost reaction, a factor that
// round-off spoiled), never a result to print with a footnote.
Status check_equilibrium(const Structure& s, const std::vector<LoadCaseResult>& cases, double bound) {
  for (const auto& c : cases)
    if (!(c.equilibrium_error <= bound))
      return Status::Internal(at_source(
          s.source(), fmt::format("load case '{}': loads and reactions do not balance (equilibrium error {:.3g}, bound "
                                  "{:.0e}; resultant force ({:.6g}, {:.6g}, {:.6g}) N, moment ({:.6g}, {:.6g}, {:.6g}) "
                                  "N m): the solution is wrong, no result is given; please report this model",
                                  c.name, c.equilibrium_error, bound, c.resultant(0), c.resultant(1), c.resultant(2),
                                  c.resultant(3), c.resultant(4), c.resultant(5))));
  return Status::Ok();
}

StatusOr<CartesianStiffness> node_stiffness(const Structure& s, const System& sys, const solver::SparseCholesky& chol,
                                            int node) {
  MatX E = MatX::Zero(s.num_dofs(), 6);
  for (int i = 0; i < 6; ++i) E(6 * node + i, i) = 1.0;
  MatX Q;
  if (Status st = chol.Solve(sys.map.C.transpose() * E, &Q); !st.ok()) return st;
  // Exact up to round-off (K_r symmetric); symmetrized by cartesian_from_compliance.
  return cartesian_from_compliance((sys.map.C * Q).middleRows<6>(6 * node), s.nodes()[node].position, "global axes");
}

}  // namespace

Workspace::Workspace(const solver::LinearSolverOptions& options) : cholesky_(solver::make_sparse_cholesky(options)) {}

Solution solve(const Structure& s, const SolveOptions& options) {
  Workspace ws(cholesky_options(options));
  return solve(s, ws, options);
}

Solution solve(const Structure& s, Workspace& ws, const SolveOptions& opt) {
  Solution sol;
  sol.backend = ws.cholesky().backend_description();
  sol.mechanism_ratio = opt.mechanism_ratio;
  sol.num_dofs = s.num_dofs();
  sol.structure = SolvedStructure{static_cast<int>(s.nodes().size()), static_cast<int>(s.beams().size()),
                                  static_cast<int>(s.joints().size()), static_cast<int>(s.load_cases().size())};
  const auto t0 = Clock::now();
  tell(opt, fmt::format("assembling the stiffness matrix: {} nodes, {} beams, {} joints ({} dofs)", s.nodes().size(),
                        s.beams().size(), s.joints().size(), s.num_dofs()));
  auto sys = build_system(s);
  sol.assembly_seconds = seconds_since(t0);
  if (!sys.ok()) {
    sol.status = sys.status();
    return sol;
  }
  sol.num_free_dofs = sys->map.num_free();
  if (sol.num_free_dofs == 0) {
    sol.status = Status::Invalid(at_source(s.source(),
                                           "every dof of the structure is supported or tied: nothing to "
                                           "solve; free some dofs of the supports"));
    return sol;
  }
  if (sol.num_free_dofs <= opt.max_dofs_for_global_indices) sol.global_indices = stiffness_indices(MatX(sys->Kr));

  const auto t1 = Clock::now();
  std::unique_ptr<solver::SparseCholesky> regularized;
  sol.status = factorize(s, *sys, ws, opt, sol, regularized);
  if (!sol.status.ok()) return sol;
  const solver::SparseCholesky& chol = regularized ? *regularized : ws.cholesky();

  const int nc = static_cast<int>(s.load_cases().size());
  MatX F(s.num_dofs(), nc), U0(s.num_dofs(), nc);
  std::vector<std::vector<Vec12>> fef(nc);  // per case: member loads' fixed-end forces per beam
  for (int c = 0; c < nc; ++c) {
    auto loads = case_loads(s, sys->map, s.load_cases()[c]);
    if (!loads.ok()) {
      sol.status = loads.status();
      return sol;
    }
    fef[c] = std::move(loads->fef);
    F.col(c) = loads->F;
    U0.col(c) = loads->U0;
  }
  MatX Q;
  if (nc > 0) {
    tell(opt, fmt::format("solving {} load case{} and checking equilibrium", nc, nc == 1 ? "" : "s"));
    if (Status st = chol.Solve(sys->map.C.transpose() * (F - sys->K * U0), &Q); !st.ok()) {
      sol.status = st;
      return sol;
    }
    const MatX U = sys->map.C * Q + U0;
    for (int c = 0; c < nc; ++c)
      sol.cases.push_back(post_process(s, *sys, s.load_cases()[c], U.col(c), F.col(c), U0.col(c), fef[c]));
    // A regularized answer is out of balance along its free motions by construction (and marked).
    if (Status st = check_equilibrium(s, sol.cases, opt.max_equilibrium_error); !sol.regularized && !st.ok()) {
      sol.status = st;
      return sol;
    }
  }
  if (s.report_node()) {
    tell(opt, "the report node's Cartesian stiffness");
    auto c = node_stiffness(s, *sys, chol, *s.report_node());
    if (!c.ok()) {
      sol.status = c.status();
      return sol;
    }
    sol.cartesian = std::move(*c);
  }
  sol.solve_seconds = seconds_since(t1);
  if (sol.regularized)
    sol.status = Status::Singular(
        "REGULARIZED answer of a singular structure (K + eps D): the numbers along the "
        "free motions are arbitrary. " +
        sol.singularity.message);
  return sol;
}

Solution solve_second_order(const Structure& s, const SecondOrderOptions& so, const SolveOptions& opt) {
  Solution sol;
  auto fail = [&sol](Status st) {
    sol.status = std::move(st);
    sol.cases.clear();
    return sol;
  };
  if (opt.regularize)
    return fail(
        Status::Invalid("a second-order analysis of a singular structure cannot be regularized: its "
                        "free motions carry no axial force to iterate on; solve it linearly"));
  if (!(so.tolerance > 0.0 && so.tolerance < 1.0))
    return fail(Status::Invalid(
        fmt::format("second-order tolerance {:g}: give a relative change between 0 and 1 (e.g. 1e-9)", so.tolerance)));
  if (so.max_iterations < 1)
    return fail(
        Status::Invalid(fmt::format("second-order iteration limit {}: give at least 1 (e.g. 50)", so.max_iterations)));
  if (Status st = s.validate(); !st.ok()) return fail(st);

  // The linear solve: the first axial forces, the diagnosis of a singular K, the report node's
  // (elastic) Cartesian stiffness and the indices, all kept.
  Workspace ws(cholesky_options(opt));
  sol = solve(s, ws, opt);
  if (!sol.status.ok()) return sol;
  auto sys = build_system(s);
  if (!sys.ok()) return fail(sys.status());
  const auto t1 = Clock::now();
  SecondOrderReport rep;
  rep.tolerance = so.tolerance;
  rep.max_iterations = so.max_iterations;
  const double size = s.length_scale();
  // Translations in m and rotations times the model's size, so that one norm weighs both as lengths.
  auto as_lengths = [size](const VecX& u) {
    VecX v = u;
    for (Eigen::Index i = 0; i < v.size(); ++i)
      if (i % 6 >= 3) v(i) *= size;
    return v;
  };
  solver::SparseCholesky& chol = ws.cholesky();
  const int nc = static_cast<int>(s.load_cases().size());
  for (int c = 0; c < nc; ++c) {
    const LoadCase& lc = s.load_cases()[c];
    auto loads = case_loads(s, sys->map, lc);
    if (!loads.ok()) return fail(loads.status());
    VecX u_prev(s.num_dofs());
    for (int n = 0; n < static_cast<int>(s.nodes().size()); ++n)
      u_prev.segment<6>(6 * n) = sol.cases[c].displacement[n];
    std::vector<double> N = beam_axial_forces(s, sol.cases[c].beam_end_forces);
    double change = 0.0;
    bool converged = false;
    int k = 0;
    LoadCaseResult r;
    while (!converged && k < so.max_iterations) {
      ++k;
      tell(opt, k == 1 ? fmt::format("load case '{}': second-order iteration 1", lc.name)
                       : fmt::format("load case '{}': second-order iteration {} (relative change {:.2e})", lc.name, k,
                                     change));
      const GeometricStiffness g = assemble_geometric_stiffness(s, N, so.torsion_term);
      const solver::SparseMatrix Ktr = sys->map.C.transpose() * (sys->K + g.global) * sys->map.C;
      if (Status st = chol.Factorize(Ktr, nullptr); !st.ok()) {
        if (st.code() != StatusCode::kSingular) return fail(st);
        // K + K_G of a stable structure is positive definite below the first critical load factor
        // (Sylvester's inertia along K + lambda K_G), so a failed Cholesky means the loads reach it:
        // a load with no equilibrium, a property of the input as in the loaded VJM (exit 2), not a
        // mechanism (K itself passed the singularity checks of the linear solve).
        return fail(Status::NotConverged(at_source(
            lc.source.empty() ? s.source() : lc.source,
            fmt::format("load case '{}': the loads reach or exceed the critical (buckling) load: the tangent "
                        "stiffness K + K_G(N) is not positive definite at second-order iteration {} ({}); no "
                        "second-order equilibrium below buckling exists. Reduce the loads; `kinestat buckling` "
                        "gives the critical load factor of the case",
                        lc.name, k, st.message()))));
      }
      MatX Q;
      const VecX Kt_u0 = sys->K * loads->U0 + g.global * loads->U0;
      if (Status st = chol.Solve(sys->map.C.transpose() * (loads->F - Kt_u0), &Q); !st.ok()) return fail(st);
      const VecX u = sys->map.C * Q.col(0) + loads->U0;
      const double un = as_lengths(u).norm();
      change = un > 0.0 ? as_lengths(u - u_prev).norm() / un : 0.0;
      if (!std::isfinite(change)) break;
      r = post_process(s, *sys, lc, u, loads->F, loads->U0, loads->fef, &g);
      N = beam_axial_forces(s, r.beam_end_forces);
      u_prev = u;
      converged = change <= so.tolerance;
    }
    if (!converged)
      return fail(Status::NotConverged(at_source(
          lc.source.empty() ? s.source() : lc.source,
          fmt::format(
              "load case '{}': the second-order (P-Delta) iteration did not converge in {} iterations (relative "
              "change of the displacements {:.3g}, tolerance {:.3g}); near the critical load the axial forces "
              "keep changing: allow more iterations, or check the loads against `kinestat buckling`",
              lc.name, k, change, so.tolerance))));
    sol.cases[c] = std::move(r);
    rep.iterations.push_back(k);
    rep.relative_change.push_back(change);
    rep.axial_force.push_back(std::move(N));
  }
  if (Status st = check_equilibrium(s, sol.cases, opt.max_equilibrium_error); !st.ok()) return fail(st);
  sol.solve_seconds += seconds_since(t1);
  sol.second_order = std::move(rep);
  return sol;
}

StatusOr<CartesianStiffness> cartesian_stiffness(const Structure& s, Workspace& ws, int node,
                                                 const SolveOptions& options) {
  if (node < 0 || node >= static_cast<int>(s.nodes().size())) return Status::Invalid("no such node");
  auto sys = build_system(s);
  if (!sys.ok()) return sys.status();
  Solution tmp;
  std::unique_ptr<solver::SparseCholesky> regularized;
  if (Status st = factorize(s, *sys, ws, options, tmp, regularized); !st.ok()) return st;
  return node_stiffness(s, *sys, regularized ? *regularized : ws.cholesky(), node);
}

Status check_solution_matches(const Structure& s, const Solution& sol) {
  const SolvedStructure here{static_cast<int>(s.nodes().size()), static_cast<int>(s.beams().size()),
                             static_cast<int>(s.joints().size()), static_cast<int>(s.load_cases().size())};
  auto counts = [](const SolvedStructure& c) {
    return fmt::format("{} nodes, {} beams, {} joints, {} load cases", c.nodes, c.beams, c.joints, c.load_cases);
  };
  auto mismatch = [&](const std::string& what) {
    return Status::Invalid(
        fmt::format("solution: {} do not match the structure's {}; pass the structure the "
                    "solution was solved for, or solve this one",
                    what, counts(here)));
  };
  if (sol.structure && (sol.structure->nodes != here.nodes || sol.structure->beams != here.beams ||
                        sol.structure->joints != here.joints || sol.structure->load_cases != here.load_cases))
    return mismatch("the counts it was solved for (" + counts(*sol.structure) + ")");
  // A hand-made solution has no recorded counts: its arrays are what is read.
  if (!sol.cases.empty() && sol.cases.size() != s.load_cases().size())
    return mismatch(fmt::format("its {} load case results", sol.cases.size()));
  for (const LoadCaseResult& r : sol.cases) {
    if (r.displacement.size() != s.nodes().size() || r.reaction.size() != s.nodes().size() ||
        r.beam_end_forces.size() != s.beams().size() || r.joint_forces.size() != s.joints().size())
      return mismatch(fmt::format("load case '{}': its {} displacements, {} reactions, {} beam and {} joint forces",
                                  r.name, r.displacement.size(), r.reaction.size(), r.beam_end_forces.size(),
                                  r.joint_forces.size()));
    if (r.max_translation_node >= here.nodes)
      return mismatch(
          fmt::format("load case '{}': its largest translation at node {}", r.name, r.max_translation_node));
  }
  if (sol.second_order) {
    const SecondOrderReport& so = *sol.second_order;
    if (so.iterations.size() != sol.cases.size() || so.relative_change.size() != sol.cases.size() ||
        so.axial_force.size() != sol.cases.size())
      return mismatch(fmt::format("its second-order report of {} load cases", so.iterations.size()));
    for (const auto& N : so.axial_force)
      if (N.size() != s.beams().size()) return mismatch(fmt::format("second-order axial forces of {} beams", N.size()));
  }
  for (const FreeMotion& m : sol.singularity.modes)
    if (m.node_motion.size() != s.nodes().size())
      return mismatch(fmt::format("a free motion of {} nodes", m.node_motion.size()));
  if (s.report_node() && (*s.report_node() < 0 || *s.report_node() >= here.nodes))
    return Status::Invalid(fmt::format("report node {}: not a node of the structure (0..{}); set a node of it",
                                       *s.report_node(), here.nodes - 1));
  return Status::Ok();
}

}  // namespace kinestat::msa
