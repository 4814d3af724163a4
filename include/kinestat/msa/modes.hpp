// Natural frequencies and mode shapes of an msa::Structure: K phi = omega^2 M phi on the reduced
// dofs u = C q of the static solve (supports and rigid ties), M assembled from the beams' density
// (elements/beam_element.hpp: consistent or lumped) and the structure's nodal masses and rotary
// inertias. With ModalOptions::prestress, K is the tangent stiffness K + K_G(N) of one load case's
// axial forces (the prestressed structure, as Frame3DD's modal analysis with its geometric stiffness
// flag). Documented in docs/stability-and-modes.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {

// The prestress of the vibrating structure: K_G of one load case's axial forces (the K_G of buckling
// and solve_second_order, msa/buckling.hpp) is added to K. Tension raises the frequencies, compression
// lowers them; at the case's critical load the first one reaches 0 (beyond it: kInvalidInput).
struct ModalPrestress {
  int load_case = 0;  // index into Structure::load_cases()
  // The axial forces of solve_second_order (every load case is solved so, as Frame3DD does with its
  // geometric stiffness flag 1) instead of the linear solve's.
  bool second_order = false;
  // Its tolerance and iterations; torsion_term (the Wagner term of K_G) counts with either solve.
  SecondOrderOptions second_order_options;
};

struct ModalOptions {
  SolveOptions solve;                       // of the factorization of K (and its singularity diagnosis)
  int count = 6;                            // how many of the lowest frequencies
  bool lumped = false;                      // lumped instead of consistent beam masses
  bool rotary_inertia = true;               // the cross-sections' rotary inertia in the consistent mass
  std::optional<ModalPrestress> prestress;  // none: the unstressed structure
  // A mode whose residual (VibrationMode::residual) is above this is not returned: kNotConverged.
  // Converged modes have ~1e-13; the default is the limit of the FEA's link modes.
  double max_residual = 1e-6;
};

// What prestressed the structure (ModalResult::prestress).
struct ModalPrestressReport {
  int load_case = 0;
  std::string load_case_name;
  bool second_order = false;
  std::vector<double> axial_force;  // per beam, N (tension positive), the N of K_G: (N2 - N1) / 2, or -N1 (kFrame3dd)
};

struct VibrationMode {
  double omega = 0.0;                  // rad/s
  double frequency = 0.0;              // Hz, omega / (2 pi)
  std::vector<Vec6> shape;             // per node, global; mass-normalized: phi' M phi = 1 (m/sqrt(kg), rad/sqrt(kg))
  Vec3 participation = Vec3::Zero();   // Gamma_d = phi' M r_d, r_d: unit translation along global d (sqrt(kg))
  Vec3 effective_mass = Vec3::Zero();  // Gamma_d^2 (kg)
  double residual = 0.0;               // ||K q - omega^2 M q|| / ||K q|| on the reduced dofs
};

struct ModalResult {
  // kInvalidInput (bad model, a beam without density in a structure without nodal masses, no or a
  // negligible mass on the free dofs, a prestress at or beyond its case's critical load), kSingular
  // (K singular: see `linear.singularity`), kNotConverged (the eigensolver, a mode's residual above
  // ModalOptions::max_residual, or the second-order solve of a prestress: its message says which),
  // kInternal.
  Status status;
  // The static solve (its checks and diagnosis; load cases if any); solve_second_order's with a
  // second-order prestress.
  Solution linear;
  std::optional<ModalPrestressReport> prestress;  // set when ModalOptions::prestress is
  int num_free_dofs = 0;
  Vec3 total_mass = Vec3::Zero();    // r_d' M r_d over every node (supported ones included), kg
  std::vector<VibrationMode> modes;  // ascending frequency
};

ModalResult modal_analysis(const Structure& s, const ModalOptions& options = {});

}  // namespace kinestat::msa
