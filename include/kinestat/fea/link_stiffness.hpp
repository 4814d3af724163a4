// Link stiffness from FEA (Pashkevich, Klimchik, Chablat, Wenger 2009, section 4.3): the link is
// clamped at its origin, a pseudo-rigid reference body at its other end carries the unit forces
// Fx, Fy, Fz and torques Mx, My, Mz one at a time; the six displacements (u, theta) of the
// reference are the columns of the 6x6 compliance matrix. Two models of the reference body:
//  - kStiffBody: the paper's auxiliary body far stiffer than the link. The elements lying entirely
//    in the reference region get E_body = stiff_body_ratio * E (same Poisson ratio). The unit
//    wrench is spread over the body's nodes as f = A (A^T A)^-1 w and its motion is the
//    least-squares rigid fit (A^T A)^-1 A^T u (A: rigid-body modes of the nodes about the reference
//    point), so C = F^T K^-1 F is symmetric by construction. The result tends to the rigid
//    coupling as O(1 / stiff_body_ratio).
//  - kRigidCoupling: exact: every node of the reference region follows a 6-dof reference node
//    (eliminated in the assembly) and the unit wrenches act on that node.
// Axes are the mesh (link) frame; the reference point is the point whose motion is reported.
// With options.modes > 0 the same model also gives the link's lowest natural frequencies (docs/fea.md,
// "Natural frequencies"): K q = omega^2 M q with the consistent mass of the elements assembled on K's
// dof map (the clamp fixed, the reference region coupled as for the stiffness; the reference body
// itself adds no mass: what is attached there is not modelled), solved for the largest mu = 1/omega^2
// of M q = mu K q with Spectra's Lanczos on K's CHOLMOD factor.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::fea {

enum class ReferenceModel { kRigidCoupling, kStiffBody };

// The largest stiff-body ratio: above it the body's stiffness drowns the link's in double precision.
inline constexpr double kMaxStiffBodyRatio = 1e12;

struct LinkStiffnessOptions {
  Region clamp;      // nodes fixed in ux, uy, uz (the link's origin)
  Region reference;  // the reference end: coupled nodes, or the pseudo-rigid body's elements
  ReferenceModel reference_model = ReferenceModel::kRigidCoupling;
  // E_body / E_link of the pseudo-rigid body. 1e4 leaves a relative compliance error of order 1e-4
  // and costs ~4 of the ~16 digits to conditioning; beyond ~1e8 the Cholesky pivot check rejects it.
  double stiff_body_ratio = 1e4;        // above 1, at most kMaxStiffBodyRatio
  std::optional<Vec3> reference_point;  // default: centre of the reference nodes' bounding box
  // Displacement and von Mises fields of the six load cases (for VTK output): 6 x (3 per node + 1
  // per element) numbers, so off unless asked for.
  bool keep_fields = false;
  solver::LinearSolverOptions solver;  // the backend (direct or iterative) and its options
  // How many of the lowest natural frequencies and their modes (count, 0: none, at most kMaxLinkModes).
  // Needs material.density > 0 (kg/m^3) and the cholmod backend (the Lanczos iteration solves with
  // the factor of K on one process; the distributed backends are refused).
  int modes = 0;
  std::function<void(const std::string& stage)> progress;  // called before each stage (large meshes)
};

inline constexpr int kMaxLinkModes = 100;
// A mode whose residual ||K q - omega^2 M q|| / ||K q|| exceeds this is an error (kNotConverged):
// the Lanczos tolerance (1e-10 on mu) leaves 1.6e-10 to 4.9e-10 (measured on the bar meshes of
// tests/fea/link_modes_test.cpp).
inline constexpr double kLinkModeResidualLimit = 1e-6;

// One natural vibration mode of the clamped link, mass-normalized: q' M q = 1 (M in kg, kg m, kg m^2).
struct LinkMode {
  double omega = 0.0;      // rad/s
  double frequency = 0.0;  // Hz, omega / (2 pi)
  // Motion (u, theta) of the reference point in the mode (m/sqrt(kg), rad/sqrt(kg)): the reference
  // node's dofs (rigid coupling) or the stiff body's least-squares rigid motion.
  Vec6 reference_motion = Vec6::Zero();
  Vec3 participation = Vec3::Zero();   // Gamma_d = q' M r_d, r_d: the link translated by 1 m along d (sqrt(kg))
  Vec3 effective_mass = Vec3::Zero();  // Gamma_d^2 (kg): of a base excitation along d
  double residual = 0.0;               // ||K q - omega^2 M q|| / ||K q|| on the solved dofs
  // Node displacements of the mass-normalized mode (m/sqrt(kg)); empty unless keep_fields.
  std::vector<Vec3> shape;
};

struct LinkStiffness {
  // The 6x6 of the reference point (cartesian.point, m) along the link frame's (mesh) axes, dofs
  // ux uy uz rx ry rz: the compliance from the six unit load cases, the stiffness its inverse.
  CartesianStiffness cartesian;
  // ||S(C - C^T)S||_F / ||S C S||_F with S = diag(C)^-1/2 of the compliance as solved, before it
  // is symmetrized (unit-free: the SI entries differ by orders of magnitude); likewise for its inverse.
  double compliance_symmetry_error = 0.0;
  double stiffness_symmetry_error = 0.0;
  // Eigenvalues (ascending) of the compliance in SI units (those of the stiffness are in
  // cartesian.indices). They mix units (m/N with rad/(N m)), so they depend on the unit of length;
  // use the 3x3 blocks for physical statements.
  Vec6 compliance_eigenvalues = Vec6::Zero();
  int num_nodes = 0, num_elements = 0, nodes_per_element = 0, num_dofs = 0;
  int num_clamped_nodes = 0, num_reference_nodes = 0, num_stiff_elements = 0;
  ReferenceModel reference_model = ReferenceModel::kRigidCoupling;
  solver::FactorizationReport factorization;  // analysis and factorization times, nnz(L), flops
  solver::SolveReport solve;                  // per load case: iterations and relative residual
  std::string backend;
  // Elements each MPI rank assembled (a distributed backend: docs/fea.md, "Large meshes"); one entry,
  // all elements, on one process.
  std::vector<int> elements_per_rank;
  // Wall time of the assembly and of the six solves (s); the peak resident memory of this process
  // (bytes, after the solves: under MPI, that of the rank that writes the report).
  double assembly_seconds = 0.0, solve_seconds = 0.0;
  double peak_memory_bytes = 0.0;
  // Per load case (Fx Fy Fz Mx My Mz, unit): node displacements (m per N or N m) and element
  // von Mises stress at the centroid (Pa per N or N m). Empty unless keep_fields.
  std::array<std::vector<Vec3>, 6> displacement;
  std::array<std::vector<double>, 6> von_mises;
  // With options.modes: the link's mass (kg, density times the mesh volume, clamped part included),
  // the modes in ascending frequency (the sign of each: its largest node displacement component is
  // positive) and the time of the mass assembly and the eigensolver (s).
  double mass = 0.0;
  std::vector<LinkMode> modes;
  double modes_seconds = 0.0;
};

StatusOr<LinkStiffness> link_stiffness(const TetMesh& mesh, const Material& material,
                                       const LinkStiffnessOptions& options);

// Human-readable summary: model, mesh, solver, then the Cartesian stiffness report (both matrices
// with units, indices), symmetry errors and the compliance's eigenvalues.
std::string link_stiffness_report(const LinkStiffness& r);

// The modes as a table: frequency (Hz), effective masses (% of the link's mass), reference motion,
// residual. Empty without modes.
std::string link_modes_report(const LinkStiffness& r);

// Sets the compliance of the reference point `point` (m) and everything derived from it:
// r.cartesian (stiffness, indices), the symmetry errors and the compliance's eigenvalues.
void set_compliance(LinkStiffness& r, const Mat6& compliance, const Vec3& point);

// The axes of a link stiffness, in words (CartesianStiffness::frame).
inline constexpr const char* kLinkFrame = "axes of the link (mesh) frame";

const char* reference_model_name(ReferenceModel m);
// ||S (A - A^T) S||_F / ||S A S||_F with S = diag(|A|)^-1/2.
double scaled_symmetry_error(const Mat6& A);

}  // namespace kinestat::fea
