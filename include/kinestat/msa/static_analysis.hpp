// Linear static analysis of an msa::Structure: assembly, one sparse Cholesky factorization (the
// backend SolveOptions::cholesky chooses: CHOLMOD by default) for all load cases, reactions, member
// end forces and along-member results, the equilibrium check (a failed one is an error), Cartesian
// stiffness of the report node, stiffness indices, and the diagnosis of singular structures.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/msa/singularity.hpp"
#include "kinestat/msa/structure.hpp"
#include "kinestat/solver/sparse_cholesky.hpp"

namespace kinestat::msa {

struct SolveOptions {
  solver::LinearSolverOptions cholesky;
  // For a singular structure, solve K + eps D instead (D = diag K, eps = regularization) and mark
  // the result as regularized. Off by default: a singular structure gets a diagnosis, no numbers.
  bool regularize = false;
  // A motion whose stiffness ratio u'Ku / u'Du (D = diag K) is below this is free. A mechanism gives
  // ~1e-16 (round-off); the five-bar's softest real mode next to its 2e11 joint springs ~1e-11.
  // After a factorization that passes the pivot check, the softest modes are found by inverse
  // iteration with the same factor, because a null pivot spoiled by round-off can look regular.
  double mechanism_ratio = 1e-13;
  double regularization = 1e-10;
  // A load case whose equilibrium error (LoadCaseResult::equilibrium_error) exceeds this fails the
  // solve with kInternal. Round-off gives 1e-16 to 1e-12 on the bundled models; a lost reaction ~1.
  double max_equilibrium_error = 1e-6;
  // Indices of the reduced global matrix need a dense eigen-decomposition: skipped above this size.
  int max_dofs_for_global_indices = 2000;
  // Told, when set, what the solve is about to do: the assembly, the factorization (the Cholesky's
  // own stage, where cholesky.progress is unset), the search for free motions, the load cases, the
  // report node, each second-order iteration. For large models: the caller prints it on stderr.
  std::function<void(const std::string& stage)> progress = nullptr;
};

// Second-order (P-Delta) analysis: how it went (Solution::second_order; docs/stability-and-modes.md).
struct SecondOrderOptions {
  // Iterations stop when the relative change of the displacements between two iterations,
  // ||u_k - u_k-1|| / ||u_k|| (rotations times the structure's size, so that both are lengths), is
  // below `tolerance`; kNotConverged after `max_iterations` solves of K + K_G(N) without that.
  double tolerance = 1e-9;
  int max_iterations = 50;
  bool torsion_term = true;  // the Wagner term of K_G, as BucklingOptions::torsion_term
};

struct SecondOrderReport {
  double tolerance = 0.0;
  int max_iterations = 0;
  std::vector<int> iterations;                   // per load case: solves of K + K_G(N) until converged
  std::vector<double> relative_change;           // per load case: the last ||u_k - u_k-1|| / ||u_k||
  std::vector<std::vector<double>> axial_force;  // [case][beam], N, tension positive: the converged N
};

struct LoadCaseResult {
  std::string name;
  std::vector<Vec6> displacement;  // per node, global: ux uy uz (m), rx ry rz (rad)
  std::vector<Vec6> reaction;      // per node, global: forces (N) and moments (N m); zero off supports
  // per beam, local axes: N1 Vy1 Vz1 T1 My1 Mz1 N2 ... (force on the beam); second order: (k + k_G(N)) T u + FEF
  std::vector<Vec12> beam_end_forces;
  std::vector<Vec6> joint_forces;  // per joint, joint frame: spring force/moment acting on node2
  // Sum of loads and reactions (force, moment about origin): ~0. Second order: of loads, reactions and
  // the P-Delta forces -K_G u (their moment is that of the axial forces on the deflected members).
  Vec6 resultant = Vec6::Zero();
  double equilibrium_error = 0.0;  // |resultant| / (|loads| + |reactions| + |K| |u|), forces times the model size
  double free_dof_residual = 0.0;  // ||C'(K u - f)|| / ||C' f||
  double max_translation = 0.0;
  int max_translation_node = -1;
};

// The counts of the structure a Solution was solved for: solve() records them, so that the solution
// is never read against another structure (check_solution_matches).
struct SolvedStructure {
  int nodes = 0, beams = 0, joints = 0, load_cases = 0;
};

struct Solution {
  Status status;  // kSingular: see `singularity`; cases are empty unless regularized
  bool regularized = false;
  int num_dofs = 0;       // 6 per node
  int num_free_dofs = 0;  // after supports and constraints
  solver::FactorizationReport factorization;
  double softest_mode_ratio = 0.0;  // lowest u'Ku/u'Du found by inverse iteration
  double mechanism_ratio = 0.0;     // the threshold it was judged by (SolveOptions::mechanism_ratio)
  std::string backend;
  SingularityDiagnosis singularity;
  std::vector<LoadCaseResult> cases;
  std::optional<CartesianStiffness> cartesian;     // of the report node (point: its position, global axes)
  std::optional<StiffnessIndices> global_indices;  // of the reduced global matrix
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
  std::optional<SolvedStructure> structure;  // set by solve(); unset in a Solution built by hand
  // Set by solve_second_order: the cases are the P-Delta equilibria (the Cartesian stiffness and the
  // indices stay those of the elastic K).
  std::optional<SecondOrderReport> second_order;
};

// Mutable workspace reused across solves of structures with the same topology (a posture sweep):
// it keeps the sparse Cholesky object, so the symbolic analysis is done once.
class Workspace {
 public:
  explicit Workspace(const solver::LinearSolverOptions& options = {});
  solver::SparseCholesky& cholesky() { return *cholesky_; }
  int num_symbolic_analyses() const { return cholesky_->num_symbolic_analyses(); }

 private:
  std::unique_ptr<solver::SparseCholesky> cholesky_;
};

// Solves every load case. Validates the structure first (kInvalidInput with the message).
Solution solve(const Structure& s, Workspace& ws, const SolveOptions& options = {});
Solution solve(const Structure& s, const SolveOptions& options = {});

// Second-order (P-Delta) static analysis of every load case: a linear solve gives each beam's axial
// force N; then (K + K_G(N)) u = F is solved (K_G: elements/beam_element.hpp, as buckling uses it),
// N recomputed from the new end forces, and so on until the displacements change by less than
// options.tolerance. Joints and rigid links carry no K_G. Fails as solve() does (kInvalidInput,
// kSingular with the diagnosis of the elastic K), and kNotConverged when a case's loads reach its critical (buckling)
// load (K + K_G not positive definite: the iteration would find an unstable equilibrium) or after
// options.max_iterations without convergence. Not with SolveOptions::regularize (kInvalidInput).
Solution solve_second_order(const Structure& s, const SecondOrderOptions& options = {},
                            const SolveOptions& solve_options = {});

// Compliance/stiffness of one node (static condensation onto its 6 dofs) without load cases; the
// point is the node's position, the axes global.
StatusOr<CartesianStiffness> cartesian_stiffness(const Structure& s, Workspace& ws, int node,
                                                 const SolveOptions& options = {});

// Internal forces and displacements along one beam for one solved load case, in the beam's local
// axes, at `count` (>= 2) equally spaced stations x_k = k L / (count - 1) from its first node.
// forces: N Vy Vz T My Mz, the force on the +x face of the part [0, x] (so the values at x = L are
// the end forces at the second end, those at x = 0 the negated end forces at the first end; at a
// point load's station, the value just after it). displacement: ux uy uz (m) of the beam axis and
// rx (twist), ry, rz (cross-section rotations, rad), local axes. Both are exact for Euler-Bernoulli
// and Timoshenko beams under the member loads (equilibrium of [0, x] and the integrated curvature,
// thermal curvature and shear strain, by Gauss quadrature exact for these polynomial fields),
// end releases included (the field is fitted to the end translations, not to a released rotation).
struct BeamStations {
  struct Extreme {
    double max = 0.0, x_at_max = 0.0, min = 0.0, x_at_min = 0.0;  // over the stations (first one on ties)
  };
  std::vector<double> x;
  std::vector<Vec6> forces;
  std::vector<Vec6> displacement;
  std::array<Extreme, 12> extremes{};  // forces N..Mz, then displacement ux..rz
};
StatusOr<BeamStations> beam_stations(const Structure& s, const LoadCase& lc, const LoadCaseResult& r, int beam,
                                     int count);
// Every beam of every solved load case: [case][beam]. Fails as beam_stations does.
StatusOr<std::vector<std::vector<BeamStations>>> all_beam_stations(const Structure& s, const Solution& sol, int count);

// kInvalidInput unless `sol` belongs to `s`: the counts solve() recorded (when set) equal the
// structure's, and every per-node, per-beam, per-joint and per-load-case array has the structure's
// size. Readers of a Solution (full_report, io::solution_to_json, io::write_vtk) check it first:
// they index the arrays by the structure's items.
Status check_solution_matches(const Structure& s, const Solution& sol);

// A full human-readable report (as Ceres' Summary::FullReport): model size, solver, per load case
// max displacement and equilibrium, Cartesian stiffness with units, indices, singularity diagnosis.
// kInvalidInput (check_solution_matches) for a solution of another structure.
StatusOr<std::string> full_report(const Structure& s, const Solution& sol);

}  // namespace kinestat::msa
